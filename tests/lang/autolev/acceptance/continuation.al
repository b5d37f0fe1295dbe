% A particle on a rod pinned at NO, the rod's angle Q from the downward vertical;
% statements continued with '&'.
NEWTONIAN N
FRAMES A
PARTICLES P
CONSTANTS L, M, &
          G                 % gravity
VARIABLES Q''
SIMPROT(N, A, 3, Q)
P_NO_P> = -L*A2>
V_P_N> = DT(P_NO_P>, &
            N)
MASS P = M
GRAVITY(-G*N2>)
ZERO = FR() &
       + FRSTAR()
KANE()
INPUT L = 0.9, M = 0.5, G = 9.81, Q = 25 DEG, Q' = 0
