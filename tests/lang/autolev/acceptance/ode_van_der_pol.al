% The van der Pol oscillator: a damping that feeds energy in near rest and takes it out far away.
CONSTANTS MU
VARIABLES Y''
Y'' = MU*(1 - Y^2)*Y' - Y
INPUT MU = 1.5, Y = 2, Y' = 0, TFINAL = 5
