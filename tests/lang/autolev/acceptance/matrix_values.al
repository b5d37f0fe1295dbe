% Matrices as values: a rotation by Q applied by hand to the column [A; B], element by element.
NEWTONIAN N
CONSTANTS A, B
VARIABLES Q''
M = [COS(Q), -SIN(Q); SIN(Q), COS(Q)]
C = [A; B]
X = M[1,1]*C[1] + M[1,2]*C[2]
Y = M[2,1]*C[1] + M[2,2]*C[2]
R = X^2 + Y^2
