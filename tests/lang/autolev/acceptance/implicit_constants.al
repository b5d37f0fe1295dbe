% A compound pendulum whose mass and inertia are named only in MASS and INERTIA,
% which declare them, as Autolev does.
NEWTONIAN N
BODIES B
CONSTANTS H, G
VARIABLES Q''
SIMPROT(N, B, 3, Q)
P_NO_BO> = -H*B2>
V_BO_N> = DT(P_NO_BO>, N)
MASS B = MB
INERTIA B, I1, I2, I3
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT H = 0.4, G = 9.81, MB = 3, I1 = 0.1, I2 = 0.1, I3 = 0.05
INPUT Q = 0.5, Q' = 0
