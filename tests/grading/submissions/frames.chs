# Frames that do not cancel: the product is refused, later parts are not run.
T_ab = Trans((1, 0, 0))
T_cb = Trans((0, 1, 0))
assert T_ab[1, 4] == 1  # (a) the offset
T_ac = T_ab * T_cb
assert T_ac[2, 4] == -1  # (b) the chain [3 pts]
