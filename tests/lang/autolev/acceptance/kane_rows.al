% Two carts on springs, Kane's equations used by element: ZERO[1] and ZERO[2] are Fr + Fr*
% of the first and second speed, in the order the variables are declared.
NEWTONIAN N
PARTICLES P1, P2
CONSTANTS M1, M2, K1, K2
VARIABLES X1'', X2''
P_NO_P1> = X1*N1>
P_NO_P2> = X2*N1>
V_P1_N> = X1'*N1>
V_P2_N> = X2'*N1>
MASS P1 = M1, P2 = M2
FORCE_P1> = (-K1*X1 + K2*(X2 - X1))*N1>
FORCE_P2> = -K2*(X2 - X1)*N1>
ZERO = FR() + FRSTAR()
E1 = ZERO[1]
E2 = ZERO[2]
S = ZERO[1] + 2*ZERO[2]
KANE()
INPUT M1 = 1, M2 = 2, K1 = 30, K2 = 20, X1 = 0.1, X2 = -0.05
INPUT TFINAL = 2
