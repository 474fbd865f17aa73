# Modern Robotics, Exercise 11(a) (§2.7, Figure 2.21): the 3×UPU platform.
# N = 8, J = 9 (six U, three P): dof = 6(8 − 1 − 9) + 3·1 + 6·2 = 3.
upu = mech < legs 3 UPU; spatial >
dof(upu)
upu

# --- The expected values, checked ---------------------------------------------
assert dof(upu) == 3
