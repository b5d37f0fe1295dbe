% Pendulum in Cartesian coordinates: particle P at (X, Y) on a massless rod from NO;
% the rod keeps P's velocity perpendicular to P_NO_P>, so the speed U2 depends on U1.
NEWTONIAN N
PARTICLES P
CONSTANTS L, M, G
MOTIONVARIABLES' X', Y', U{2}'
P_NO_P> = X*N1> + Y*N2>
V_P_N> = U1*N1> + U2*N2>
X' = U1
Y' = U2
DEPENDENT[1] = DOT(V_P_N>, P_NO_P>)
CONSTRAIN(DEPENDENT[U2])
MASS P = M
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 1.2, M = 0.5, G = 9.81
INPUT X = 0.6, Y = -1.03923, U1 = 0, U2 = 0
