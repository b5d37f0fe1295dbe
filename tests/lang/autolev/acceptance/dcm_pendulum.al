% A rod pendulum oriented by its direction cosine matrix rather than SIMPROT.
NEWTONIAN N
BODIES A
CONSTANTS L, M, G
VARIABLES Q''
N_A = [COS(Q), -SIN(Q), 0; SIN(Q), COS(Q), 0; 0, 0, 1]
P_NO_AO> = -L/2*A2>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = M
INERTIA A, 0, 0, M*L^2/12
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 1.1, M = 2, G = 9.81, Q = 0.7, Q' = 0
