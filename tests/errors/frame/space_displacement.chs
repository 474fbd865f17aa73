# a displacement written the wrong way round
T_sb = Trans((1, 0, 0))
T_sc = Trans((0, 1, 0))
T_sc * inv(T_sb)
