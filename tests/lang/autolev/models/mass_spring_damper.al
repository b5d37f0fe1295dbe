% A block P on a smooth floor, tied to the wall at NO by a spring (natural length LN)
% and a dashpot, pushed along N1> by a specified force F.
NEWTONIAN N
PARTICLES P
CONSTANTS M, K, C, LN
VARIABLES X''
SPECIFIED F
P_NO_P> = X*N1>
V_P_N> = X'*N1>
MASS P = M
FORCE_P> = (F - K*(X - LN) - C*X')*N1>
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 2, K = 50, C = 3, LN = 0.4
