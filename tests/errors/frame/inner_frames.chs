# the classic: inner frames do not cancel
T_ab = Trans((1, 0, 0))
T_cb = Trans((0, 1, 0))
T_ab * T_cb
