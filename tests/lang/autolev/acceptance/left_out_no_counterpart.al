% A pendulum (body A, its mass M at its centre AO, L from the pivot, no inertia of its own)
% held by a torsion spring K at the pivot, beside statements the script has no counterpart
% of: COMPLEX ON, SQR(), names and an array of three indices. They are left out, the model not.
COMPLEX ON
NEWTONIAN N
BODIES A
INERTIA A, 0, 0, 0
CONSTANTS L, M, G, K, C{2,2,2}
VARIABLES Q''
SIMPROT(N, A, 3, Q)
P_NO_AO> = L*A1>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = M
GRAVITY(-G*N2>)
TORQUE(N/A, -K*Q*A3>)
R = SQR(L)
E[1, 2, 1] = L*Q
H = M*L^2*Q'^2/2 + M*G*L*SIN(Q) + K*Q^2/2
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.9, M = 1.2, G = 9.81, K = 3
INPUT Q = 40 DEG, Q' = 0
