# draw takes transforms, rotations, screw axes, twists, points and vectors.
draw(3)
draw(mech < links 4; joints 4R; planar >)
R = Rotz(1)
draw(2 * [k for k in 0:2])
