% Kinematics alone, without NEWTONIAN: a slider P at distance R along an arm B turning in A.
FRAMES A, B
POINTS O, P
VARIABLES Q'', R''
SIMPROT(A, B, 3, Q)
P_O_P> = R*B1>
V_O_A> = 0>
V_P_A> = DT(P_O_P>, A)
A_P_A> = DT(V_P_A>, A)
VR = DOT(V_P_A>, B1>)
VT = DOT(V_P_A>, B2>)
AR = DOT(A_P_A>, B1>)
AT = DOT(A_P_A>, B2>)
AX = DOT(A_P_A>, A1>)
