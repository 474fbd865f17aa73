# Modern Robotics, Exercise 10 (§2.7, Figure 2.20): the 6×SS platform, six legs of
# fixed length with spherical joints at both ends.
# N = 8, J = 12: dof = 6(8 − 1 − 12) + 12·3 = 6. All six are the legs' idle spins
# about their own axes; the upper platform itself cannot move (generically).
ss6 = mech < legs 6 SS; spatial >
dof(ss6)
ss6

# --- The expected values, checked ---------------------------------------------
assert dof(ss6) == 6
