% A block on a spring with a Coulomb friction force written with SIGN(), and its kinetic
% energy taken with KE(), neither of which the script has a counterpart of. The friction
% force is left out, so the equations of motion are said to lack it; the energy and what is
% worked out from it are left out in turn.
NEWTONIAN N
PARTICLES P
CONSTANTS M, K, MU, G
VARIABLES X''
P_NO_P> = X*N1>
V_P_N> = X'*N1>
MASS P = M
FORCE_P> = -K*X*N1>
FORCE_P> += -MU*M*G*SIGN(X')*N1>
E = KE()
H = E + K*X^2/2
OUTPUT T, X, H
S = K*X^2/2
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 2, K = 8, MU = 0.1, G = 9.81
INPUT X = 0.3, X' = 0
