% A particle P on a massless rod of length L turned by Q about N3> from N1>; the rod's
% tension T, pulling P towards the pin, is brought out by the auxiliary speed U2 along the rod.
NEWTONIAN N
FRAMES A
PARTICLES P
CONSTANTS L, M, G
MOTIONVARIABLES' Q', U{2}'
SPECIFIED T
SIMPROT(N, A, 3, Q)
Q' = U1
P_NO_P> = L*A1>
V_P_N> = L*U1*A2> + U2*A1>
MASS P = M
GRAVITY(-G*N2>)
FORCE(P, -T*A1>)
AUXILIARY[1] = U2
CONSTRAIN(AUXILIARY[U2])
ZERO = FR() + FRSTAR()
KANE(T)
INPUT L = 1.5, M = 2, G = 9.81
INPUT Q = -0.5, U1 = 1
