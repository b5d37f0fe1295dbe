% Kinematics of a two-link arm printed, no dynamics: positions, velocities and measures.
NEWTONIAN N
FRAMES A, B
POINTS P, Q
CONSTANTS L1, L2
VARIABLES Q1', Q2'
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 3, Q2)
P_NO_P> = L1*A1>
P_P_Q> = L2*B1>
R> = P_NO_P> + P_P_Q>
X = DOT(R>, N1>)
Y = DOT(R>, N2>)
D = MAG(R>)
V> = DT(R>, N)
VX = DOT(V>, N1>)
H = DOT(CROSS(R>, V>), N3>)
C = DOT(UNITVEC(R>), EXPRESS(A1>, N))
