% Inertia dyadics: a body B turned by Q1 about N3> (frame A), then by Q2 about A1>, its mass
% centre BO at L along B3> from the fixed point NO, and a particle P at R along A1>. The
% angular momentum about BO, the kinetic energy of rotation, the inertia about NO by the
% parallel-axis transfer, the particle's inertia about NO, the inertia of both about NO
% (INERTIA(NO)), and measures of them in frames.
NEWTONIAN N
FRAMES A
BODIES B
PARTICLES P
CONSTANTS L, R, M, MP, I1, I2, I3
VARIABLES Q1', Q2'
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 1, Q2)
P_NO_BO> = L*B3>
P_NO_P> = R*A1>
MASS B = M, P = MP
INERTIA B, I1, I2, I3
H> = DOT(I_B_BO>>, W_B_N>)
H1 = DOT(H>, B1>)
H2 = DOT(H>, B2>)
H3 = DOT(H>, B3>)
KE = DOT(W_B_N>, DOT(W_B_N>, I_B_BO>>))/2
IO>> = I_B_NO>>
J1 = DOT(B1>, DOT(IO>>, B1>))
J3 = DOT(B3>, DOT(IO>>, B3>))
HO> = DOT(IO>>, W_B_N>)
HO2 = DOT(HO>, B2>)
IC = MATRIX(N, I_B_BO>>)
TRACE = IC[1,1] + IC[2,2] + IC[3,3]
IPA = MATRIX(A, I_P_NO>>)
P11 = IPA[1,1]
P22 = IPA[2,2]
P12 = IPA[1,2]
IS>> = INERTIA(NO)
IS11 = DOT(A1>, DOT(IS>>, A1>))
IS22 = DOT(A2>, DOT(IS>>, A2>))
IB>> = INERTIA(BO, B)
IB33 = DOT(B3>, DOT(IB>>, B3>))
