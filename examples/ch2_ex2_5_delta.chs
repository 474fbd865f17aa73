# Modern Robotics, Example 2.5 (§2.2.2, Figure 2.8): the Delta robot.
# Naively, N = 17, J = 21 revolute joints, spatial (m = 6):
#   dof = 6(17 − 1 − 21) + 21·1 = −9.
# Book slip: the seed prints "17(17 − 1 − 21) + 21 = −9"; the factor is m = 6, and
# only with 6 does the result come to −9.
# Each leg is kinematically an RUU chain: N = 8, J = 9 (three R, six U):
#   dof = 6(8 − 1 − 9) + 3·1 + 6·2 = 3 (the book: "3(1) + 6(2)").
deltanaive = mech < links 17; joints 21R; spatial >
dof(deltanaive)
delta = mech < links 8; joints 3R 6U; spatial >
dof(delta)
deltalegs = mech < legs 3 RUU; spatial >
dof(deltalegs)

# --- The expected values, checked ---------------------------------------------
assert dof(deltanaive) == -9
assert dof(delta) == 3
assert dof(deltalegs) == 3
