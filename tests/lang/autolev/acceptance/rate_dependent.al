% A particle on a circle about NO, in the Cartesian coordinates X and Y, without speeds of
% its own: a massless rod keeps its velocity across the rod, X X' + Y Y' = 0, and Y' is the
% dependent rate.
NEWTONIAN N
PARTICLES P
CONSTANTS M, G
VARIABLES X'', Y''
P_NO_P> = X*N1> + Y*N2>
V_P_N> = DT(P_NO_P>, N)
DEPENDENT[1] = X*X' + Y*Y'
CONSTRAIN(DEPENDENT[Y'])
MASS P = M
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 0.7, G = 9.81
INPUT X = 0.6, Y = -0.8, X' = 1.2, Y' = 0.9
