# Modern Robotics, Example 2.1 (§2.2.2, Figure 2.4(b)): the slider-crank, read two ways.
# (i) three R joints and one P joint, four links: dof = 3(4 − 1 − 4) + 4·1 = 1.
# (ii) two R joints and one RP joint (one joint, f = 2), three links:
#      dof = 3(3 − 1 − 3) + 2·1 + 1·2 = 1.
slidercrank = mech < links 4; joints R R R P; planar >
dof(slidercrank)
slidercrank2 = mech < links 3; joints 2R RP; planar >
dof(slidercrank2)

# --- The expected values, checked ---------------------------------------------
assert dof(slidercrank) == 1
assert dof(slidercrank2) == 1
