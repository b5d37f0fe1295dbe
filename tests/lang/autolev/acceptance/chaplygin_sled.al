% The Chaplygin sled: a body B on the N1>-N2> plane, heading TH, resting on a knife edge at P
% (at X, Y) that cannot slide along B2>; its mass centre A ahead of P along B1>. Speeds: U1
% the speed of P along B1>, U2 the turn rate, U3 the speed of P along B2>, which the knife
% edge makes dependent (zero).
NEWTONIAN N
BODIES B
POINTS P
CONSTANTS M, IZ, A
MOTIONVARIABLES' X', Y', TH', U{3}'
SIMPROT(N, B, 3, TH)
W_B_N> = U2*B3>
P_NO_P> = X*N1> + Y*N2>
V_P_N> = U1*B1> + U3*B2>
P_P_BO> = A*B1>
V2PTS(N, B, P, BO)
X' = U1*COS(TH) - U3*SIN(TH)
Y' = U1*SIN(TH) + U3*COS(TH)
TH' = U2
DEPENDENT[1] = DOT(V_P_N>, B2>)
CONSTRAIN(DEPENDENT[U3])
MASS B = M
INERTIA B, IZ, IZ, IZ
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 3, IZ = 0.2, A = 0.4
INPUT U1 = -0.5, U2 = 2
INPUT TFINAL = 3, INTEGSTP = 0.1
OUTPUT U1, U2
CODE DYNAMICS() sled.c
