# a twist is in one frame: T_ab [V_b] is Ṫ_ab, a map {b} → {a}, not [V_a]
T_ab = RpToTrans(Rotz(pi/2), (1, 2, 0))
V_b = twist((0, 0, 1), (1, 0, 0))
se3ToVec(T_ab * [V_b] * inv(T_ab))
se3ToVec(T_ab * [V_b])
