# Draws a picture (printed, so it asks for draw-3.svg) and answers right.
R = Rotz(90 deg)
draw(R)
assert R * (1, 0, 0) ≈ (0, 1, 0)  # (a) x goes to y
