% The direction cosine matrix of A in N used as a value, its rate, the angular velocity's
% matrix made from them, an array EQN assigned by element, and a factored polynomial.
DEGREES OFF
NEWTONIAN N
FRAMES A
CONSTANTS W
VARIABLES Q'
SIMPROT(N, A, 3, Q)
R = N_A
S = TRANSPOSE(R)*DT(R)
EQN[1] = S[2, 1]
EQN[2] = S[1, 2] + DOT(W_A_N>, N3>)
F = FACTOR(W^2*Q^2 - W^2)
