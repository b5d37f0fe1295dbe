% Terms and coefficients: the energy of a pendulum on a torsion spring taken apart by EXCLUDE
% and INCLUDE (a symbol inside COS counts), and the coefficients of a cubic by POLYNOMIAL of an
% expression, highest power first, put back together by POLYNOMIAL of the row.
NEWTONIAN N
CONSTANTS M, G, L, K
VARIABLES Q', U'
Q' = U
E = M*L^2*U^2/2 - M*G*L*COS(Q) + K*Q^2/2
KE = INCLUDE(E, U)
PE = EXCLUDE(E, U)
GRAV = INCLUDE(PE, G)
SPRING = EXCLUDE(E, U, G)
MT = INCLUDE([E; K*Q + G], Q)
T1 = MT[1]
T2 = MT[2]
P = (Q - 1)*(Q - 2)*(K*Q + M)
C = POLYNOMIAL(P, Q)
C1 = C[1]
C2 = C[2]
C3 = C[3]
C4 = ELEMENT(C, 1, 4)
RT = ROOTS(POLYNOMIAL(Q^2 - 5*Q + 6, Q))
R2 = RT[2]
BACK = POLYNOMIAL(C, Q) - P
