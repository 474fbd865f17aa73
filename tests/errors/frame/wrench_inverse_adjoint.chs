# the help writes the inverse of what was typed, without a double inverse
T_ab = Trans((1, 0, 0))
T_bc = Trans((0, 1, 0))
F_a = wrench((0, 0, 1), (1, 0, 0))
Ad(inv(T_ab * T_bc)) * F_a
T_ab * inv(T_bc)
inv(T_ab) * T_bc
