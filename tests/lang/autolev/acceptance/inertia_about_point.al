% A rod pendulum whose inertia is given about its pivot NO, before its mass: INERTIA A(NO).
NEWTONIAN N
BODIES A
CONSTANTS L, M, G
VARIABLES Q''
SIMPROT(N, A, 3, Q)
P_NO_AO> = -L/2*A2>
V_AO_N> = DT(P_NO_AO>, N)
INERTIA A(NO), M*L^2/3, 0, M*L^2/3
MASS A = M
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.8, M = 1.5, G = 9.81
INPUT Q = 20 DEG, Q' = 0
