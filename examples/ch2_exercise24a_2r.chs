# Modern Robotics, Exercise 24(a) (§2.7, Figure 2.32): the two-link planar 2R chain.
# dof = 3(3 − 1 − 2) + 2·1 = 2; its configuration space is S^1 × S^1 = T^2.
arm2R = mech < links 3; joints R R; planar >
dof(arm2R)
arm2R

# --- The expected values, checked ---------------------------------------------
assert dof(arm2R) == 2
