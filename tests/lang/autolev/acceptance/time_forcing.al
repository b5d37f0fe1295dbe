% A pendulum whose pivot torque is a function of time: T is a number of seconds.
NEWTONIAN N
BODIES A
CONSTANTS L, M, G, T0, W
VARIABLES Q''
SIMPROT(N, A, 3, Q)
P_NO_AO> = -L/2*A2>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = M
INERTIA A, 0, 0, M*L^2/12
GRAVITY(-G*N2>)
TORQUE_A> = T0*SIN(W*T)*N3>
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.6, M = 1, G = 9.81, T0 = 0.4, W = 3, Q = 0, Q' = 0
