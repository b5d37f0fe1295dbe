% A wheel turned by a motor torque from the ground and braked by a torque TORQUE(N/A, ...).
NEWTONIAN N
BODIES A
CONSTANTS IA, TM, B
VARIABLES Q''
SIMPROT(N, A, 3, Q)
W_A_N> = Q'*N3>
V_AO_N> = 0>
MASS A = 1
INERTIA A, IA, IA, IA
TORQUE_A> = TM*N3>
TORQUE(N/A, -B*Q'*N3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT IA = 0.02, TM = 0.3, B = 0.05, Q = 0, Q' = 0
