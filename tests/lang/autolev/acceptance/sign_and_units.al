% A particle pendulum with a positive length, gravity given with its unit, the angle in degrees.
NEWTONIAN N
FRAMES A
PARTICLES P
CONSTANTS L+, M+
CONSTANTS G = 9.81 M/S^2
VARIABLES Q''
SIMPROT(N, A, 3, Q)
P_NO_P> = -L*A2>
V_P_N> = DT(P_NO_P>, N)
MASS P = M
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.7, M = 1
INPUT Q = 30 DEG, Q' = 0
OUTPUT T, Q DEG
