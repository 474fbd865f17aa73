# Modern Robotics, Exercise 18(a) (§2.7, Figure 2.28(a)): a caterpillar robot hanging
# by its tail: eight rigid links (tail, six body links, head) connected serially by
# seven revolute-prismatic pairs, each one RP joint with f = 2; the tail is ground.
# N = 8, J = 7: dof = 3(8 − 1 − 7) + 7·2 = 14 (an open chain: the same in space),
# C-space T^7 × R^7.
caterpillar = mech < links 8; joints 7RP; planar >
dof(caterpillar)
caterpillar

# --- The expected values, checked ---------------------------------------------
assert dof(caterpillar) == 14
