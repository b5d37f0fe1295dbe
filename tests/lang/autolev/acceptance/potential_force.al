% A particle in a quartic well: the force is minus the derivative of the potential, D(V, X).
NEWTONIAN N
PARTICLES P
CONSTANTS M, K, C
VARIABLES X''
V = K*X^2/2 + C*X^4/4
P_NO_P> = X*N1>
V_P_N> = X'*N1>
MASS P = M
FORCE_P> = -D(V, X)*N1>
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 0.5, K = 2, C = 8, X = 0.4, X' = 0
INPUT TFINAL = 2
