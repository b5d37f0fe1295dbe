% A1PT: a slider P at R along the arm B, which turns by Q about N3> at O, the point of a cart
% moving along N1>: P moves on B, and O is fixed on B.
NEWTONIAN N
FRAMES B
POINTS O, P
VARIABLES X'', Q'', R''
SIMPROT(N, B, 3, Q)
P_NO_O> = X*N1>
V_O_N> = DT(P_NO_O>, N)
A_O_N> = DT(V_O_N>, N)
P_O_P> = R*B1>
V_P_B> = DT(P_O_P>, B)
A_P_B> = DT(V_P_B>, B)
V1PT(N, B, O, P)
A1PT(N, B, O, P)
AR = DOT(A_P_N>, B1>)
AT = DOT(A_P_N>, B2>)
AZ = DOT(A_P_N>, N3>)
