# Modern Robotics, Exercise 12(a) (§2.7, Figure 2.22(a)): six identical squares in a
# single closed loop, joined serially by revolute joints, the bottom one fixed.
# Spatial Grübler: N = 6, J = 6: dof = 6(6 − 1 − 6) + 6·1 = 0, a structure by the
# formula (a lower bound: special geometry can let such a loop move).
squares = mech < links 6; joints 6R; spatial >
dof(squares)

# --- The expected values, checked ---------------------------------------------
assert dof(squares) == 0
