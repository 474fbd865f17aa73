# A book value checked against chasles: the book's T_sb rounded to three
# digits is not within 1e-9 of the exact product, so ≈ fails and shows both.
R_sb = Rotz(30 deg)
assert R_sb ≈ [0.866, -0.5, 0; 0.5, 0.866, 0; 0, 0, 1]
