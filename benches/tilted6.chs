# A 6-joint chain with tilted axes (issue 21's size benchmark): the
# product of exponentials with symbolic joint angles, then its adjoint.
given t1, t2, t3, t4, t5, t6 : scalar
w1 = (0, 0, 1)
w2 = (0, 0.6, 0.8)
w3 = (0.6, 0, 0.8)
w4 = (0.8, 0.6, 0)
w5 = (0, 0.8, 0.6)
w6 = (0.6, 0.8, 0)
S1 = [w1; -cross(w1, (0, 0, 0))]
S2 = [w2; -cross(w2, (0.1, 0, 0.2))]
S3 = [w3; -cross(w3, (0.3, 0, 0.2))]
S4 = [w4; -cross(w4, (0.5, 0.1, 0.2))]
S5 = [w5; -cross(w5, (0.6, 0.1, 0.3))]
S6 = [w6; -cross(w6, (0.7, 0, 0.3))]
T = exp([S1] t1) exp([S2] t2) exp([S3] t3) exp([S4] t4) exp([S5] t5) exp([S6] t6)
A = Ad(T)
