# A wrong answer in (a); (b) is right.
R = Rotz(30 deg)
assert R[1, 1] ≈ 0.5  # (a) cos 30° [2 pts]
assert R[2, 1] ≈ 0.5  # (b) sin 30°
