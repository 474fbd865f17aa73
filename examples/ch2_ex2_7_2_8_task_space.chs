# Modern Robotics, Examples 2.7 and 2.8 (§2.5, Figures 2.13, 2.14): C-space
# against task space.
#
# Example 2.7, the SCARA robot: an RRRP open chain. Its C-space has
# dimension 4, topology T^3 × R^1 (§2.3.1); its task space, (x, y, z, φ),
# is R^3 × S^1, also of dimension 4.
# Expected: dof = 6(5 − 1 − 4) + 4·1 = 4, C-space T^3 × R^1.
scara = mech < links 5; joints R R R P; spatial >
dof(scara)
#
# Example 2.8, the spray-painting 6R arm: C-space T^6 (dimension 6); the
# nozzle's task space, position and pointing direction, is R^3 × S^2
# (dimension 5): rotations about the nozzle axis do not matter, so one
# degree of freedom is left over for the task.
# Expected: dof = 6(7 − 1 − 6) + 6·1 = 6, C-space T^6; 6 − 5 = 1.
painter = mech < links 7; joints 6R; spatial >
dof(painter) - 5

# --- The expected values, checked ---------------------------------------------
assert dof(scara) == 4
assert dof(painter) == 6
