% A harmonic oscillator given by its differential equation alone (no NEWTONIAN).
CONSTANTS K, M
VARIABLES X''
X'' = -K/M*X
INPUT K = 4, M = 1
INPUT X = 1, X' = 0
INPUT TFINAL = 3, INTEGSTP = 0.1
OUTPUT T, X
