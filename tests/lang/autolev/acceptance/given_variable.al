% A cart pushed by a force O*COS(2*T), O a variable that is no coordinate and no speed:
% a given quantity.
NEWTONIAN N
PARTICLES P
CONSTANTS M, C
VARIABLES X', U'
VARIABLES O
X' = U
P_NO_P> = X*N1>
V_P_N> = U*N1>
MASS P = M
FORCE_P> = (O*COS(2*T) - C*U)*N1>
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 3, C = 0.2, O = 1.5, X = 0, U = 0.1
