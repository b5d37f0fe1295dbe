% A particle on a spring along a slope at 30 degrees, pushed up the slope by F*COS(60).
% No DEGREES line: Autolev's default, DEGREES ON, reads the angles written as numbers in degrees.
NEWTONIAN N
FRAMES B
PARTICLES P
CONSTANTS M, K, G, F
VARIABLES X''
SIMPROT(N, B, 3, 30)
P_NO_P> = X*B1>
V_P_N> = X'*B1>
MASS P = M
GRAVITY(-G*N2>)
FORCE_P> = (-K*X + F*COS(60))*B1>
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 2, K = 20, G = 9.81, F = 3, X = 0.3, X' = 0
INPUT TFINAL = 2
