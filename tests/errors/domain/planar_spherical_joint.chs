# a planar mechanism cannot have a spherical joint (Table 2.1)
mech < links 4; joints R R S R; planar >
