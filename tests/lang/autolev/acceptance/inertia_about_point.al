% A rod pendulum whose inertia is given about its pivot NO, before its mass and before the
% position of its mass centre from the pivot: INERTIA A(NO).
NEWTONIAN N
BODIES A
CONSTANTS L, M, G
VARIABLES Q''
SIMPROT(N, A, 3, Q)
INERTIA A(NO), M*L^2/3, 0, M*L^2/3
MASS A = M
P_NO_AO> = -L/2*A2>
V_AO_N> = DT(P_NO_AO>, N)
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.8, M = 1.5, G = 9.81
INPUT Q = 20 DEG, Q' = 0
