# Modern Robotics, Exercise 5(b), (c) (§2.7, Figure 2.16): mobile manipulators
# opening a refrigerator door. Reading: the parked base is ground, the hand's rigid
# grasp makes the last arm link one body with the door, the door is hinged (R) to
# ground.
# (b) one 6R arm: N = 7 (ground, five arm links, door), J = 6 + 1 = 7:
#     dof = 6(7 − 1 − 7) + 7·1 = 1.
# (c) a second 6R arm grasps the same handle: N = 12, J = 13:
#     dof = 6(12 − 1 − 13) + 13·1 = 1.
onearm = mech < links 7; joints 7R; spatial >
dof(onearm)
twoarms = mech < links 12; joints 13R; spatial >
dof(twoarms)

# --- The expected values, checked ---------------------------------------------
assert dof(onearm) == 1
assert dof(twoarms) == 1
