% A body A turned by a variable also called A, and a particle L beside a constant L:
% Autolev names frames apart from values.
NEWTONIAN N
BODIES A
CONSTANTS L, M, G
PARTICLES L
VARIABLES A''
SIMPROT(N, A, 3, A)
P_NO_AO> = -L/2*A2>
P_NO_L> = -L*A2>
V_AO_N> = DT(P_NO_AO>, N)
V_L_N> = DT(P_NO_L>, N)
MASS A = M, L = M
INERTIA A, 0, 0, M*L^2/12
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.8, M = 1.1, G = 9.81, A = 0.3, A' = 0
