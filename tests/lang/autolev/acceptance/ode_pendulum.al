% The pendulum's equation without its geometry: TH'' = -G/L*SIN(TH).
NEWTONIAN N
CONSTANTS G, L
VARIABLES TH''
TH'' = -G/L*SIN(TH)
INPUT G = 9.81, L = 0.6
INPUT TH = 40 DEG, TH' = 0
INPUT TFINAL = 2
