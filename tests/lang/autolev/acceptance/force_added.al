% Loads given in parts: FORCE_P> then '+=' and '-=', and FORCE(P, ...).
NEWTONIAN N
PARTICLES P
CONSTANTS M, K, C, F0
VARIABLES X''
P_NO_P> = X*N1>
V_P_N> = X'*N1>
MASS P = M
FORCE_P> = -K*X*N1>
FORCE_P> += -C*X'*N1>
FORCE_P> -= F0*N1>
FORCE(P, F0/2*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 1.5, K = 20, C = 0.7, F0 = 2, X = 0.1, X' = 0
