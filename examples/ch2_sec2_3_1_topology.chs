# Modern Robotics, §2.3.1 (configuration space topology) for open chains.
# PR arm: R^1 × S^1 (dof 2).  2R arm: S^1 × S^1 = T^2 (dof 2).
# RRRP arm: T^3 × R^1 (dof 4).
# A free planar rigid body: R^2 × S^1 (dof 3). A free spatial rigid body: dof 6;
# the book writes R^3 × S^2 × S^1, chasles writes the rotations as SO(3)
# (Chapter 3), giving R^3 × SO(3), and says so in a note.
pr = mech < links 3; joints P R; planar >
pr
twor = mech < links 3; joints R R; planar >
twor
rrrp = mech < links 5; joints R R R P; spatial >
rrrp
freeplanar = mech < links 2; planar >
freeplanar
freespatial = mech < links 2; spatial >
freespatial

# --- The expected values, checked ---------------------------------------------
assert dof(pr) == 2
assert dof(twor) == 2
assert dof(rrrp) == 4
assert dof(freeplanar) == 3
