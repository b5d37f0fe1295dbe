% Dyadics as values: a dyad sum D>> = 3 N1>N1> + N2>N2> + 2 N3>N3>, its matrix in B (B turned
% by Q about N3>), dotted with a vector made from measures in B on either side, the unit
% dyadic, a dyad of two frames' unit vectors, and vectors to and from their measures.
NEWTONIAN N
FRAMES B
CONSTANTS X1, X2, X3
VARIABLES Q'
SIMPROT(N, B, 3, Q)
D>> = 3*N1>*N1> + N2>*N2> + 2*N3>*N3>
MB = MATRIX(B, D>>)
B11 = MB[1,1]
B12 = MB[1,2]
B22 = MB[2,2]
B33 = ELEMENT(MB, 3, 3)
E>> = EXPRESS(D>>, B)
E12 = DOT(B1>, DOT(E>>, B2>))
V> = VECTOR(B, [X1; X2; X3])
W> = DOT(D>>, V>)
WN = MATRIX(N, W>)
W1 = WN[1]
W2 = WN[2]
W3 = WN[3]
VD1 = DOT(DOT(V>, D>>), N1>)
U1 = DOT(DOT(1>>, V>), B1>)
F>> = (N1>*B2> - 0.5*B2>*N1>)/2
S = DOT(N1>, DOT(F>>, B2>))
Z>> = D>> - EXPRESS(D>>, B) + 0>>
Z11 = DOT(N1>, DOT(Z>>, N1>))
VR> = VECTOR(N, [1, 2, 3])
R2 = DOT(VR>, N2>)
BACK> = VECTOR(N, MATRIX(N, V>)) - V>
BACK1 = DOT(BACK>, B1>)
