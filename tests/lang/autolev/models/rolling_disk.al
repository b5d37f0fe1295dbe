% A thin disk D (radius R) rolling without slip on the N1>-N2> plane, N3> up. Heading Q1,
% lean Q2, spin Q3; the ground contact C at (X, Y). Speeds: D's angular velocity in B (U1..U3)
% and the rates of X and Y (U4, U5), which rolling makes dependent.
NEWTONIAN N
FRAMES A, B
BODIES D
POINTS C, DC                    % DC: the point of D at the contact
CONSTANTS R, M, G
MOTIONVARIABLES' Q{3}', X', Y', U{5}'
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 1, Q2)
SIMPROT(B, D, 2, Q3)
W_D_N> = U1*B1> + U2*B2> + U3*B3>
P_NO_C> = X*N1> + Y*N2>
P_C_DO> = R*B3>
P_DO_DC> = -R*B3>
V_DO_N> = DT(P_NO_DO>, N)
V2PTS(N, D, DO, DC)
Q1' = U3/COS(Q2)
Q2' = U1
Q3' = U2 - U3*TAN(Q2)
X' = U4
Y' = U5
DEPENDENT[1] = DOT(V_DC_N>, N1>)
DEPENDENT[2] = DOT(V_DC_N>, N2>)
CONSTRAIN(DEPENDENT[U4, U5])
MASS D = M
INERTIA D, M*R^2/4, M*R^2/2, M*R^2/4
GRAVITY(-G*N3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT R = 0.3, M = 2, G = 9.81
