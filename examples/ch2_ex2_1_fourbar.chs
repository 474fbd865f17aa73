# Modern Robotics, Example 2.1 (§2.2.2, Figure 2.4(a)): the planar four-bar linkage.
# N = 4 links (ground included), J = 4 revolute joints, m = 3.
# Expected: dof = 3(4 − 1 − 4) + 4·1 = 1 (a closed chain: a lower bound).
fourbar = mech < links 4; joints R R R R; planar >
dof(fourbar)
# The same with a count: 4R is four separate R joints.
fourbar4 = mech < links 4; joints 4R; planar >
dof(fourbar4)

# --- The expected values, checked ---------------------------------------------
assert dof(fourbar) == 1
assert dof(fourbar4) == 1
