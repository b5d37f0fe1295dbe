% A pendulum in Cartesian coordinates X, Y; the rod keeps P's velocity perpendicular to
% P_NO_P>, written as an auxiliary constraint solved for U2, so that its equation gives the
% rod's tension T (along the rod, towards the pin).
NEWTONIAN N
PARTICLES P
CONSTANTS L, M, G
MOTIONVARIABLES' X', Y', U{2}'
SPECIFIED T
P_NO_P> = X*N1> + Y*N2>
V_P_N> = U1*N1> + U2*N2>
X' = U1
Y' = U2
MASS P = M
GRAVITY(-G*N2>)
FORCE(P, -T*P_NO_P>/L)
AUXILIARY[1] = DOT(V_P_N>, P_NO_P>)
CONSTRAIN(AUXILIARY[U2])
ZERO = FR() + FRSTAR()
KANE(T)
INPUT L = 1.2, M = 0.5, G = 9.81
INPUT X = 0.6, Y = -1.03923048454133, U1 = 0.5
