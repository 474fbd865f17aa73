# Modern Robotics, Exercise 13(a) (§2.7, Figure 2.23): the spherical four-bar
# linkage. All joint axes meet at one point, so every link only rotates about it:
# m = 3. dof = 3(4 − 1 − 4) + 4·1 = 1.
sphfourbar = mech < links 4; joints 4R; spherical >
dof(sphfourbar)

# --- The expected values, checked ---------------------------------------------
assert dof(sphfourbar) == 1
