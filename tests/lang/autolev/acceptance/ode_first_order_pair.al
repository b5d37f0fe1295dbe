% A forced oscillator written as two first-order equations: X' = V makes V the rate of X,
% and V' = ... is then the equation for X''. T is time, a number of seconds.
CONSTANTS W, A
VARIABLES X', V'
X' = V
V' = -W^2*X + A*SIN(T)
INPUT W = 2, A = 0.5
INPUT X = 0.5, V = 0
INPUT TFINAL = 2
