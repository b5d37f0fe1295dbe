% Gyroscope: a symmetric rotor D on a fixed pivot at NO, its mass centre at distance L along
% its spin axis; precession Q1 about N3> (up), nutation Q2, spin Q3 (body-fixed 3-1-3 angles).
NEWTONIAN N
FRAMES A, B
BODIES D
CONSTANTS L, M, IT, IS, G
MOTIONVARIABLES' Q{3}', U{3}'
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 1, Q2)
SIMPROT(B, D, 3, Q3)
P_NO_DO> = L*D3>
V_DO_N> = CROSS(W_D_N>, P_NO_DO>)
MASS D = M
INERTIA D, IT, IT, IS
Q1' = U1
Q2' = U2
Q3' = U3
GRAVITY(-G*N3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.05, M = 0.3, IT = 4e-4, IS = 6e-4, G = 9.81
INPUT Q2 = 30 DEG, U3 = 200
