% A rod pendulum whose length is put together with ':=' and '+=', a mass with '*='.
NEWTONIAN N
BODIES A
CONSTANTS L0, D, M, G
VARIABLES Q''
LEN := L0
LEN += D
MA = M
MA *= 2
SIMPROT(N, A, 3, Q)
P_NO_AO> = -LEN/2*A2>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = MA
INERTIA A, 0, 0, MA*LEN^2/12
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L0 = 0.5, D = 0.3, M = 0.75, G = 9.81, Q = 1, Q' = 0
