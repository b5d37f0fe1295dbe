% Normal modes: a wall, a spring K, a mass M1, a spring K and a mass M2 in a line. The
% eigenvalues of INV(MM)*KM are the squared natural frequencies and its eigenvectors the mode
% shapes; the stiffness matrix alone is symmetric, with orthonormal eigenvectors.
NEWTONIAN N
CONSTANTS K = 3, M1 = 1.5, M2 = 0.5
KM = [2*K, -K; -K, K]
MM = [M1, 0; 0, M2]
EIG(INV(MM)*KM, W2, MODES)
W1SQ = W2[1]
W2SQ = W2[2]
OMEGA1 = SQRT(W2[1])
X11 = MODES[1, 1]
X21 = MODES[2, 1]
X12 = MODES[1, 2]
X22 = MODES[2, 2]
EIG(KM, KV, KS)
KV1 = KV[1]
KV2 = KV[2]
S11 = KS[1, 1]
S21 = KS[2, 1]
S12 = KS[1, 2]
S22 = KS[2, 2]
