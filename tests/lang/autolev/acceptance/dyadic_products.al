% The dot product of two dyadics and the time derivative of a dyadic in a frame.
NEWTONIAN N
FRAMES B
CONSTANTS A, K
VARIABLES Q'
SIMPROT(N, B, 3, Q)
D>> = A*N1>*B1> + B2>*N3>
E>> = K*B1>*N2> + N3>*B3>
F>> = DOT(D>>, E>>)
F12 = DOT(N1>, DOT(F>>, N2>))
F23 = DOT(B2>, DOT(F>>, B3>))
F11 = DOT(N1>, DOT(F>>, N1>))
G>> = DT(B1>*B1>, N)
G12 = DOT(B1>, DOT(G>>, B2>))
G11 = DOT(N1>, DOT(G>>, N1>))
H>> = DT(D>>, B)
H21 = DOT(N2>, DOT(H>>, B1>))
H23 = DOT(B2>, DOT(H>>, N3>))
