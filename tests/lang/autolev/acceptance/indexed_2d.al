% Two coordinates coupled through a symmetric stiffness matrix K{2,2} (K11, K12, K21, K22),
% in units where the masses are 1.
CONSTANTS K{2,2}
VARIABLES X{2}''
X1'' = -K11*X1 - K12*X2
X2'' = -K21*X1 - K22*X2
INPUT K11 = 5, K12 = -2, K21 = -2, K22 = 3
INPUT X1 = 0.1, X2 = 0, X1' = 0, X2' = 0.2
INPUT TFINAL = 3
