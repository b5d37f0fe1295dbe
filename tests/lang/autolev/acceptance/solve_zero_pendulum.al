% A particle pendulum whose equation of motion SOLVE takes from ZERO = FR() + FRSTAR(), and its
% small-oscillation period from the solved acceleration's series.
NEWTONIAN N
FRAMES A
PARTICLES P
CONSTANTS L, M, G
VARIABLES Q', U'
Q' = U
SIMPROT(N, A, 3, Q)
P_NO_P> = -L*A2>
V_P_N> = DT(P_NO_P>, N)
MASS P = M
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
SOLVE(ZERO, U')
ACC = U'
PERIOD = 2*PI*SQRT(-1/COEF(TAYLOR(U', 0:1, Q = 0), Q))
INPUT L = 0.8, M = 1.5, G = 9.81, Q = 0.6, U = 0
INPUT TFINAL = 2
