# Values made over given symbols, then numbers bound (LANGUAGE.md §7):
# each is what typing the numbers first gives.

# The rate of a rotation about an axis that is no unit vector (Rot
# normalizes it): diff through Rot at the numbers, by the chain rule.
given a
R = Rot((1, a, 2), a)
D = diff(R, a)
a = 0.3
D

# A closed form singular where the expression is defined: the inverse of
# exp([S] b) with a non-unit screw divides by b, yet at b = 0 it is I.
given b, c
Y = exp([(b, 2b, b, b*c, b, 2)] b)^-1;
b = 0
Y

# Angles with square roots add as angles (proven, not rounded).
s = sqrt(2)
Rotz(s) * Rotz(s) == Rotz(2 s)
cos(2 s) == cos(s)^2 - sin(s)^2

# The rotation block of a transform is its rotation, with its frames.
T_ab = RpToTrans(Rotz(pi/6), (1, 2, 3))
R_ab = T_ab[1:3, 1:3]
