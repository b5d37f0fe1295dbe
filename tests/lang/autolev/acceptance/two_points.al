% A rod hanging from NO, pushed sideways at its tip P by a constant force; V2PTS fixes P on it.
NEWTONIAN N
BODIES A
POINTS P
CONSTANTS L, M, G, F
VARIABLES Q''
SIMPROT(N, A, 3, Q)
W_A_N> = Q'*N3>
P_NO_AO> = -L/2*A2>
P_NO_P> = -L*A2>
V_AO_N> = CROSS(W_A_N>, P_NO_AO>)
V2PTS(N, A, AO, P)
MASS A = M
INERTIA A, 0, 0, M*L^2/12
GRAVITY(-G*N2>)
FORCE_P> = F*N1>
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 1, M = 1.5, G = 9.81, F = 2, Q = 0, Q' = 0
