# Modern Robotics, Example 2.6 (§2.2.2): the Stewart–Gough platform, six UPS legs.
# N = 14, J = 18 (6 U, 6 P, 6 S): dof = 6(14 − 1 − 18) + 6·1 + 6·2 + 6·3 = 6.
# Written as links and joints, and as legs between a fixed and a moving platform.
# With S joints in place of the U joints (SPS legs) the formula gives 12: each leg
# gains an idle spin about its own axis that does not move the platform.
stewart = mech < links 14; joints 6U 6P 6S; spatial >
dof(stewart)
stewartlegs = mech < legs 6 UPS; spatial >
dof(stewartlegs)
stewartlegs
sps = mech < legs 6 SPS; spatial >
dof(sps)

# --- The expected values, checked ---------------------------------------------
assert dof(stewart) == 6
assert dof(stewartlegs) == 6
