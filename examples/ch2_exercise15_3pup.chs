# Modern Robotics, Exercise 15 (§2.7, Figure 2.25): the 3×PUP platform.
# N = 8, J = 9 (six P, three U): dof = 6(8 − 1 − 9) + 6·1 + 3·2 = 0, a structure by
# the formula; the exercise asks why the real mechanism moves (its constraints are
# dependent, so Grübler's count is only a lower bound).
pup = mech < legs 3 PUP; spatial >
dof(pup)
pup

# --- The expected values, checked ---------------------------------------------
assert dof(pup) == 0
