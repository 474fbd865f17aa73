# Modern Robotics, exercise 2.25 (§2.7): the workspaces of two planar 3R
# open chains, the tip only, drawn side by side.
#
# (a) links 5, 2, 1 from the base: the tip reaches 5 + 2 + 1 = 8 at most and
#     5 − 2 − 1 = 2 at least: the annulus 2 ≤ r ≤ 8.
# (b) links 1, 2, 5: at most 8 again, and at least 5 − 2 − 1 = 2 (the
#     long last link folded back over the other two): the same annulus.
# Neither workspace is larger. (c) Lengthening the last link alone does not
# reach every point reached before: once it is longer than the other links
# together (1 + 2 = 3 in (b)), the hole in the middle grows with it and the
# points near the base are lost.
#
# The joints are sampled at 30°, 45° and 90° steps: 12 × 8 × 4 tips each.

tip_a(t1, t2, t3) = (5 cos(t1) + 2 cos(t1 + t2) + cos(t1 + t2 + t3), 5 sin(t1) + 2 sin(t1 + t2) + sin(t1 + t2 + t3))
tip_b(t1, t2, t3) = (cos(t1) + 2 cos(t1 + t2) + 5 cos(t1 + t2 + t3), sin(t1) + 2 sin(t1 + t2) + 5 sin(t1 + t2 + t3))

Wa = [tip_a(a, b, c) for a in 0:pi/6:11*pi/6, b in 0:pi/4:7*pi/4, c in 0:pi/2:3*pi/2]
Wb = [tip_b(a, b, c) for a in 0:pi/6:11*pi/6, b in 0:pi/4:7*pi/4, c in 0:pi/2:3*pi/2]
len(Wa)

# The reach of each: least and greatest distance of the tip from the base.
(min([norm(p) for p in Wa]), max([norm(p) for p in Wa]))
(min([norm(p) for p in Wb]), max([norm(p) for p in Wb]))

workspaces = beside(draw(Wa, "(a) links 5, 2, 1"), draw(Wb, "(b) links 1, 2, 5"))
