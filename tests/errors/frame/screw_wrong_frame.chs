# a screw in {s} applied to a transform from {c}
S_s = (0, 0, 1, 0, 0, 0)
T_cb = Trans((1, 0, 0))
exp([S_s] (pi/2)) * T_cb
