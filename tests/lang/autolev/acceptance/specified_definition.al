% A mass on a spring and a dashpot, their forces given as definitions of specified
% quantities, and the stretch as a variable's definition.
NEWTONIAN N
PARTICLES P
CONSTANTS M, K, C, L0
VARIABLES X''
VARIABLES S = X - L0
SPECIFIED FS = -K*S, FD = -C*X'
P_NO_P> = X*N1>
V_P_N> = X'*N1>
MASS P = M
FORCE_P> = (FS + FD)*N1>
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 2, K = 30, C = 0.5, L0 = 0.4, X = 0.6, X' = 0
