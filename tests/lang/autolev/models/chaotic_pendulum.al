% Rod-and-plate chaotic pendulum: a uniform rod A swings about N1> at NO; a square plate B
% (side S) spins about the rod's axis A3> at the rod's end. N3> up.
NEWTONIAN N
BODIES A, B
CONSTANTS LA, LB, MA, MB, S, G
MOTIONVARIABLES' THETA', PHI', OMEGA', ALPHA'
SIMPROT(N, A, 1, THETA)
SIMPROT(A, B, 3, PHI)
W_A_N> = OMEGA*A1>
W_B_A> = ALPHA*A3>
P_NO_AO> = -LA/2*A3>
P_NO_BO> = -LB*A3>
V_AO_N> = DT(P_NO_AO>, N)
V_BO_N> = DT(P_NO_BO>, N)
MASS A = MA, B = MB
INERTIA A, MA*LA^2/12, MA*LA^2/12, 0
INERTIA B, MB*S^2/12, MB*S^2/6, MB*S^2/12
THETA' = OMEGA
PHI' = ALPHA
GRAVITY(-G*N3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT LA = 0.6, LB = 0.45, MA = 0.8, MB = 1.3, S = 0.3, G = 9.81
INPUT THETA = 90 DEG, PHI = 1 DEG, OMEGA = 0, ALPHA = 0
