# Counts in a mechanism may be names and expressions, but whole numbers;
# contact joints exist in planar and spatial mechanisms, not spherical ones.
n = 2.5
mech < links n; joints 4R; planar >
k = 4
mech < links k; joints (k)R; planar >
mech < links 3; joints 2R, rolling; spherical >
# A joint connects two links: the ground alone (links 1) has nothing to join.
mech < links 1; joints R; planar >
