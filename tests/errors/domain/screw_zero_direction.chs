# ScrewToAxis normalises a non-unit direction with a warning; the zero
# vector has no direction.
S = ScrewToAxis((0, 0, 0), (0, 0, 2), 0.5)
S0 = ScrewToAxis((0, 0, 0), (0, 0, 0), 0.5)
