% Simple pendulum: a uniform rod A of length L swinging about a pin at NO,
% Q measured from the downward vertical, N2> up.
NEWTONIAN N
BODIES A
CONSTANTS L, M, G
VARIABLES Q''
SIMPROT(N, A, 3, Q)
P_NO_AO> = -L/2*A2>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = M
INERTIA A, 0, 0, M*L^2/12
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.8, M = 1.5, G = 9.81
INPUT Q = 20 DEG, Q' = 0
CODE DYNAMICS() pendulum.c
