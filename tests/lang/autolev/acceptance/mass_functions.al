% Mass functions: a rod A turned by Q about NO and two particles; the total mass, the
% mass centre of all and of some, and the rod's angular velocity.
NEWTONIAN N
BODIES A
PARTICLES P1, P2
CONSTANTS L, M1, M2, MA
VARIABLES Q''
SIMPROT(N, A, 3, Q)
P_NO_AO> = L/2*A1>
P_NO_P1> = L*A1>
P_NO_P2> = 2*L*N2>
MASS A = MA, P1 = M1, P2 = M2
INERTIA A, 0, 0, MA*L^2/12
MT = MASS(A, P1, P2)
MALL = MASS()
R> = CM(NO)
RX = DOT(R>, N1>)
RY = DOT(R>, N2>)
S> = CM(P2, A, P1)
SX = DOT(S>, N1>)
SY = DOT(S>, N2>)
W> = ANGVEL(N, A)
WZ = DOT(W>, N3>)
