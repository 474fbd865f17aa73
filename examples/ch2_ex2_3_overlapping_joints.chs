# Modern Robotics, Example 2.3 (§2.2.2, Figure 2.6): a planar mechanism with two
# overlapping joints, read two ways.
# (i) eight links, eight R joints and one P joint: dof = 3(8 − 1 − 9) + 9·1 = 3
#     (the book writes "+ 9(1)").
# (ii) the lower-right revolute-prismatic pair as one two-dof joint RP: seven links,
#      seven R joints and one RP joint: dof = 3(7 − 1 − 8) + 7·1 + 1·2 = 3.
overlap = mech < links 8; joints 8R P; planar >
dof(overlap)
overlap2 = mech < links 7; joints 7R RP; planar >
dof(overlap2)

# --- The expected values, checked ---------------------------------------------
assert dof(overlap) == 3
assert dof(overlap2) == 3
