# [V_a] = T_ab [V_b] T_ab⁻¹ (3.77): conjugation by T_ab takes a quantity in
# {b} to {a}; the one in {a} is refused, the one in {b} gives [V_a] in {a}
T_ab = RpToTrans(Rotz(pi/2), (1, 2, 0))
V_b = twist((0, 0, 1), (1, 0, 0))
V_a = Ad(T_ab) * V_b
T_ab * [V_b] * inv(T_ab)
se3ToVec(T_ab * [V_b] * inv(T_ab)) - V_a
T_ab * [V_a] * inv(T_ab)
