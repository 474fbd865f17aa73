# The UR5 of Modern Robotics chapter 4 (shared/data/ur5.md): forward
# kinematics as a product of exponentials with symbolic joint angles,
# printed simplified (benches/symbolic.rs, tests/symbolic.rs).
given t1, t2, t3, t4, t5, t6 : scalar
W1 = 0.109; W2 = 0.082; L1 = 0.425; L2 = 0.392; H1 = 0.089; H2 = 0.095
M = [-1, 0, 0, L1 + L2; 0, 0, 1, W1 + W2; 0, 1, 0, H1 - H2; 0, 0, 0, 1]
S1 = (0, 0, 1, 0, 0, 0)
S2 = (0, 1, 0, -H1, 0, 0)
S3 = (0, 1, 0, -H1, 0, L1)
S4 = (0, 1, 0, -H1, 0, L1 + L2)
S5 = (0, 0, -1, -W1, L1 + L2, 0)
S6 = (0, 1, 0, H2 - H1, 0, L1 + L2)
T = exp([S1] * t1) * exp([S2] * t2) * exp([S3] * t3) * exp([S4] * t4) * exp([S5] * t5) * exp([S6] * t6) * M
