% Four-bar linkage in a vertical plane (N2> up): crank A pinned at NO, coupler B, rocker C
% pinned at the ground point D; a motor torque TA on the crank from the ground. The loop
% closes at the coupler-rocker pin, so U2 and U3 depend on U1.
NEWTONIAN N
BODIES A, B, C
POINTS D, AB, BC, CB            % AB: crank-coupler pin; BC and CB: the closing pin on B and on C
CONSTANTS LA, LB, LC, LN, MA, MB, MC, G
MOTIONVARIABLES' Q{3}', U{3}'
SPECIFIED TA
SIMPROT(N, A, 3, Q1)
SIMPROT(N, B, 3, Q2)
SIMPROT(N, C, 3, Q3)
W_A_N> = U1*N3>
W_B_N> = U2*N3>
W_C_N> = U3*N3>
P_NO_D> = LN*N1>
P_NO_AO> = LA/2*A1>
P_NO_AB> = LA*A1>
P_AB_BO> = LB/2*B1>
P_AB_BC> = LB*B1>
P_D_CO> = LC/2*C1>
P_D_CB> = LC*C1>
V_D_N> = 0>
V2PTS(N, A, NO, AO)
V2PTS(N, A, NO, AB)
V2PTS(N, B, AB, BO)
V2PTS(N, B, AB, BC)
V2PTS(N, C, D, CO)
V2PTS(N, C, D, CB)
Q1' = U1
Q2' = U2
Q3' = U3
DEPENDENT[1] = DOT(V_BC_N> - V_CB_N>, N1>)
DEPENDENT[2] = DOT(V_BC_N> - V_CB_N>, N2>)
CONSTRAIN(DEPENDENT[U2, U3])
MASS A = MA, B = MB, C = MC
INERTIA A, 0, 0, MA*LA^2/12
INERTIA B, 0, 0, MB*LB^2/12
INERTIA C, 0, 0, MC*LC^2/12
GRAVITY(-G*N2>)
TORQUE(N/A, TA*N3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT LA = 0.2, LB = 0.5, LC = 0.4, LN = 0.45, MA = 1, MB = 2, MC = 1.5, G = 9.81
