% Two particles on massless rods, angles from the downward vertical, speeds as rates.
NEWTONIAN N
FRAMES A, B
PARTICLES P1, P2
CONSTANTS L1, L2, M1, M2, G
MOTIONVARIABLES' Q{2}', U{2}'
Q1' = U1
Q2' = U2
SIMPROT(N, A, 3, Q1)
SIMPROT(N, B, 3, Q2)
W_A_N> = U1*N3>
W_B_N> = U2*N3>
P_NO_P1> = -L1*A2>
P_P1_P2> = -L2*B2>
V_P1_N> = CROSS(W_A_N>, P_NO_P1>)
V_P2_N> = V_P1_N> + CROSS(W_B_N>, P_P1_P2>)
MASS P1 = M1, P2 = M2
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L1 = 1, L2 = 0.8, M1 = 1.2, M2 = 0.7, G = 9.81
INPUT Q1 = 40 DEG, Q2 = -20 DEG, U1 = 0, U2 = 1
