# Modern Robotics, Example 2.4 (§2.2.2, Figure 2.7(a)): the parallelogram linkage.
# N = 5, J = 6 revolute joints: dof = 3(5 − 1 − 6) + 6·1 = 0, a structure by the
# formula; with equal parallel links it moves with one dof, so Grübler's formula
# is only a lower bound here (dependent constraints).
parallelogram = mech < links 5; joints 6R; planar >
dof(parallelogram)
parallelogram

# --- The expected values, checked ---------------------------------------------
assert dof(parallelogram) == 0
