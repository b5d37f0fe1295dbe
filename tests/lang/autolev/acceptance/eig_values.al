% EIG(M, VALUES): the eigenvalues alone, as a column in ascending order.
NEWTONIAN N
CONSTANTS K1 = 2, K2 = 1
KM = [K1 + K2, -K2; -K2, K2]
EIG(KM, W2)
W2A = W2[1]
W2B = W2[2]
EIG([4, 1; 2, 3], EV)
E1 = EV[1]
E2 = EV[2]
