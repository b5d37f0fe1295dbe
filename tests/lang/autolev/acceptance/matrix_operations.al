% Matrix operations: a plate's planar inertia turned by Q, a 2 by 2 linear system solved
% with INV, the rows and columns of matrices, the eigenvalues and roots of numbers, and powers
% of a matrix (a rotation cubed, an inverse as the power -1).
NEWTONIAN N
CONSTANTS A, B, C, Q
R = [COS(Q), -SIN(Q); SIN(Q), COS(Q)]
J = DIAGMAT(2, A) + [0, 0; 0, B]
JN = R*J*TRANSPOSE(R)
JXX = JN[1,1]
JXY = ELEMENT(JN, 1, 2)
TR = JN[1,1] + JN[2,2]
DJ = DET(JN)
K = [A, B; B, C]
KI = INV(K)
X = KI*[1; 2]
X1 = X[1]
X2 = X[2]
NR = ROWS(K) + COLS(TRANSPOSE([A; B; C]))
TOP = ROWS(K, 1)
T12 = TOP[1, 2]
SIDE = COLS(J, 2:2)
S22 = SIDE[2]
EV = EIG([2, 1; 1, 2])
E1 = EV[1]
E2 = EV[2]
P = POLYNOMIAL([1, -6, 11, -6], Q)
RT = ROOTS(P, Q)
RSUM = RT[1] + RT[2] + RT[3]
RL = ROOTS([2, -3])
R1 = RL[1]
ROW = [DET(K), ELEMENT(K, 1, 2)]
RB = ROW[2]
R3 = R^3
R3C = R3[1,1]
KM = K^-1
KM12 = KM[1,2]
