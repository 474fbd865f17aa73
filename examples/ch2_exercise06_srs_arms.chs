# Modern Robotics, Exercise 6 (§2.7, Figure 2.17): SRS arms grasping a common object,
# a parallel mechanism between ground and the object.
# (a) three arms: N = 8, J = 9: dof = 6(8 − 1 − 9) + 3·1 + 6·3 = 9
#     (3 of these are idle spins of each arm about its shoulder-wrist line).
# (b) n arms: N = 2 + 2n, J = 3n, dof = 6(1 − n) + 7n = n + 6; here n = 5 gives 11.
# (c) wrist S replaced by U (SRU arms): dof = 6(1 − n) + 6n = 6 for every n.
srs3 = mech < legs 3 SRS; spatial >
dof(srs3)
srs5 = mech < legs 5 SRS; spatial >
dof(srs5)
sru3 = mech < legs 3 SRU; spatial >
dof(sru3)

# --- The expected values, checked ---------------------------------------------
assert dof(srs3) == 9
assert dof(srs5) == 11
assert dof(sru3) == 6
