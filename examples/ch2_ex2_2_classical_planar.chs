# Modern Robotics, Example 2.2 (§2.2.2, Figure 2.5): classical planar mechanisms.
# k-link serial chain (kR robot), here k = 3: dof = 3(4 − 1 − 3) + 3·1 = 3, C-space T^3.
# Five-bar linkage: dof = 3(5 − 1 − 5) + 5·1 = 2.
# Stephenson and Watt six-bar linkages: dof = 3(6 − 1 − 7) + 7·1 = 1.
robot3R = mech < links 4; joints 3R; planar >
dof(robot3R)
robot3R
fivebar = mech < links 5; joints 5R; planar >
dof(fivebar)
stephenson = mech < links 6; joints 7R; planar >
dof(stephenson)
watt = mech < links 6; joints 7R; planar >
dof(watt)

# --- The expected values, checked ---------------------------------------------
assert dof(robot3R) == 3
assert dof(fivebar) == 2
assert dof(stephenson) == 1
assert dof(watt) == 1
