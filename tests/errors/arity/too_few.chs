# too few arguments (RpToTrans(R) alone is now frame(R), p = 0)
ScrewToAxis((0, 0, 0), (0, 0, 1))
