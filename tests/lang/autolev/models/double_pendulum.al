% Double pendulum of two uniform links A and B hanging from a pin at NO;
% angles from the downward vertical, N2> up; speeds are the angular rates.
MOTIONVARIABLES' Q{2}', U{2}'
CONSTANTS L{2}, M{2}, G
NEWTONIAN N
BODIES A, B
POINTS J                        % the pin between the links
SIMPROT(N, A, 3, Q1)
SIMPROT(N, B, 3, Q2)
W_A_N> = U1*N3>
W_B_N> = U2*N3>
P_NO_AO> = -L1/2*A2>
P_NO_J> = -L1*A2>
P_J_BO> = -L2/2*B2>
V_AO_N> = CROSS(W_A_N>, P_NO_AO>)
V2PTS(N, A, NO, J)
V2PTS(N, B, J, BO)
MASS A = M1, B = M2
INERTIA A, 0, 0, M1*L1^2/12
INERTIA B, 0, 0, M2*L2^2/12
Q1' = U1
Q2' = U2
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L1 = 1, L2 = 0.7, M1 = 2, M2 = 1.2, G = 9.81
INPUT Q1 = 30 DEG, Q2 = 10 DEG, U1 = 0, U2 = 0
INPUT TFINAL = 5, INTEGSTP = 0.01
OUTPUT T, Q1 DEG, Q2 DEG
