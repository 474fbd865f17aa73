# Modern Robotics, Exercise 14 (§2.7, Figure 2.24): a parallel surgical robot.
# (a) leg A is RRRP, legs B and C are RRRUR, between ground and the end-effector:
#     N = 2 + 3 + 4 + 4 = 13, J = 4 + 5 + 5 = 14 (11 R, 1 P, 2 U):
#     dof = 6(13 − 1 − 14) + 12·1 + 2·2 = 4.
# (c) three identical RRRR legs, all R axes through point A: a spherical mechanism
#     (m = 3), N = 11, J = 12: dof = 3(11 − 1 − 12) + 12·1 = 6.
surgical = mech < links 13; joints 11R P 2U; spatial >
dof(surgical)
surgicalsph = mech < legs 3 RRRR; spherical >
dof(surgicalsph)

# --- The expected values, checked ---------------------------------------------
assert dof(surgical) == 4
assert dof(surgicalsph) == 6
