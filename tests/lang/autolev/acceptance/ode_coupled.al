% Two equal masses between three equal springs, in units where the masses are 1.
CONSTANTS K
VARIABLES X1'', X2''
X1'' = -2*K*X1 + K*X2
X2'' = K*X1 - 2*K*X2
INPUT K = 3
INPUT X1 = 0.2, X2 = -0.1, X1' = 0, X2' = 0.4
INPUT TFINAL = 4
