# Example 3.2 (the camera): a correct submission.
T_db = [0, 0, -1, 250; 0, -1, 0, -150; -1, 0, 0, 200; 0, 0, 0, 1]
T_de = [0, 0, -1, 300; 0, -1, 0, 100; -1, 0, 0, 120; 0, 0, 0, 1]
T_ad = [0, 0, -1, 400; 0, -1, 0, 50; -1, 0, 0, 300; 0, 0, 0, 1]
T_bc = [0, -1/sqrt(2), -1/sqrt(2), 30; 0, 1/sqrt(2), -1/sqrt(2), -40; 1, 0, 0, 25; 0, 0, 0, 1]
T_ce = inv(T_ad * T_db * T_bc) * T_ad * T_de
assert T_ce[1, 4] ≈ -75  # (a) the object, x in {c} [2 pts]
assert det(T_ce[1:3, 1:3]) ≈ 1  # (b) a rotation
