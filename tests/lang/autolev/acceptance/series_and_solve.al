% Coefficients, substitutions, series, FLOOR and a linear SOLVE: a pendulum's restoring moment
% and two springs in series pulled by a hanging weight.
DEGREES OFF
NEWTONIAN N
CONSTANTS K1, K2, M, G, L
VARIABLES Q, X1, X2
MOM = -M*G*L*SIN(Q)
LIN = TAYLOR(MOM, 0:1, Q = 0)         % the small-angle moment
CUBIC = TAYLOR(MOM, 3:3, Q = 0)       % its term of order 3 alone
STIFF = COEF(LIN, Q)
SQUARE = COEF(EXPAND((1 + L*Q)^3), Q^2)
SLOPE = EVALUATE(D(MOM, Q), Q = 0)
SIDE = REPLACE(MOM, Q = PI/6, L = 2*L)
TURNS = FLOOR(19/3)
% the node X1 between the springs K1 (to the wall) and K2, the weight M*G on X2
EQ = [K1*X1 - K2*(X2 - X1); K2*(X2 - X1) - M*G]
SOLVE(EQ, X1, X2)
STRETCH = X2 - X1
P1 = X1
P2 = X2
