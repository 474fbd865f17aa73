# Numbered frames are frames like any other (LANGUAGE.md §2): T_01 is
# {0}←{1}, T_12 is {1}←{2}, so T_01 * T_21 does not cancel.
T_01 = Trans((1, 0, 0))
T_12 = Trans((0, 1, 0))
T_02 = T_01 * T_12
T_21 = inv(T_12)
T_01 * T_21
S_1 = (0, 0, 1, 0, 0, 0)
p_{1} = (1, 2, 3)
T_01 * p_{1}
T_12 * p_{1}
