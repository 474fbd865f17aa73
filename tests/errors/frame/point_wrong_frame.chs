# a point in the wrong frame
T_ab = Trans((1, 0, 0))
p_c = (1, 2, 3)
T_ab * p_c
