% Arrays assigned element by element and then used whole, as Autolev's own examples write
% their equations: ZERO[1] = ..., then SOLVE(ZERO, ...).
NEWTONIAN N
FRAMES A
POINTS P
CONSTANTS M1, M2, K1, K2, C, L, H, M, G
VARIABLES X1'', X2'', Q'', P1, P2
% two masses between springs, each equation built up by element (-= and += read it back)
ZERO[1] = -K1*X1 + K2*(X2 - X1)
ZERO[2] = -K2*(X2 - X1)
ZERO[1] -= M1*X1''
ZERO[2] += -C*X2' - M2*X2''
SOLVE(ZERO, X1'', X2'')
A1 = X1''
A2 = X2''
% a stiffness matrix by its elements, used whole by DET, then an element assigned again
KM[1, 1] = K1 + K2
KM[1, 2] = -K2
KM[2, 1] = -K2
KM[2, 2] = K2
DK = DET(KM)
KM[2, 2] = K2 + C
DK2 = DET(KM)
TK = KM[1, 1] + KM[2, 2]
% a configuration to solve for
CONFIG[1] = P1 + P2 - L
CONFIG[2] = P1 - P2 - H
SOLVE(CONFIG, P1, P2)
S1 = P1
S2 = P2
% a pendulum's equation by Newton and Euler, an array of one element
SIMPROT(N, A, 3, Q)
P_NO_P> = L*A1>
V_P_N> = DT(P_NO_P>, N)
A_P_N> = DT(V_P_N>, N)
NE[1] = DOT(-M*G*N2> - M*A_P_N>, A2>)
SOLVE(NE, Q'')
QDD = Q''
