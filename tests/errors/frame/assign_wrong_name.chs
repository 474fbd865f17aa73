# a name that claims the wrong frames
T_ab = Trans((1, 0, 0))
T_bc = Trans((0, 1, 0))
T_ad = T_ab * T_bc
