# a typo in a variable
T_ab = Trans((1, 2, 3))
T_ba = inv(T_ac)
