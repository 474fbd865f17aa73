# A student's second hour (issue 22): chapters 2 and 3 typed as the book
# writes them, each answer checked against the book or its definition.

# ---- Chapter 2: Grübler's formula (2.4) with contacts ----------------------
# Exercise 2.18(a): a caterpillar of 8 links (head, tail, six body links)
# joined serially by 7 revolute-prismatic pairs, hanging by its tail.
hanging = mech < links 8; joints 7RP; planar >
assert dof(hanging) == 14
# 2.18(b): all six body links touch the leaf, each a frictionless point
# contact (a planar sliding contact, f = 2).
crawling = mech < links 8; joints 7RP, 6 sliding; planar >
assert dof(crawling) == 8
# 2.18(c): only the first and last body links touch the leaf.
assert dof(mech < links 8; joints 7RP, 2 sliding; planar >) == 12

# Exercise 2.19(a): a palm with four URR fingers, k fingertips in sliding
# point contact with the table (f = 5 each). N = table + palm + 4·3 links.
N = 1 + 1 + 4 * 3
hand = [dof(mech < links N; joints 4U, 8R, (k) sliding; spatial >) for k in 1:4]
assert hand[1] == 21
assert hand[end] == 18
# 2.19(c): the palm is fixed and the fingertips grasp an object with no
# slip (rolling point contacts, f = 3): N = palm + 12 finger links + object.
grasp = mech < links 1 + 12 + 1; joints 4U 8R 4 rolling; spatial >
assert dof(grasp) == 10
# Counts may be names: Example 2.6's Stewart–Gough platform with n legs.
n = 6
assert dof(mech < legs n UPS; spatial >) == 6

# ---- Chapter 3 --------------------------------------------------------------
# The inverse of a transform, (3.64): [Rᵀ, −Rᵀp; 0, 1].
R = Rotz(pi/6) Rotx(pi/4)
p = (1, 2, 3)
T_inv = [R^T, -R^T (p); 0, 1]
assert T_inv ≈ inv(frame(R, p))
# A rotation applied to a vector as the book writes it, R (1, 0, 0).
Rz = Rotz(pi/2)
assert Rz (1, 0, 0) ≈ (0, 1, 0)
# so(n) has n (n − 1)/2 dimensions: 3 for so(3), 2 (n − 1) more in se(n).
n = 3
assert n (n - 1)/2 == 3
assert n (n - 1)/2 + n == 6

# Exponential coordinates: θ from the trace, (3.54), never beyond π.
θ = acos((trace(R) - 1)/2)
assert θ <= pi
assert θ > 0
# What --exact prints parses back: cos(π/4) = 1/√2, sin(π/3) = √3/2.
assert cos(pi/4) ≈ 1/√2
assert sin(pi/3) ≈ √3/2
assert √(1 + 3) == 2

# A screw axis from q, ŝ and h (3.71): v = −ŝ × q + h ŝ, and h = ŝ·v.
ŝ = (0, 0, 1)
q = (3, 0, 0)
h = 2
v = -ŝ × q + h ŝ
assert v ≈ (0, -3, 2)
assert ŝ·v == h
S = ScrewToAxis(q, ŝ, h)
assert S[1:3] == ŝ
assert S[4:6] ≈ v
assert S[end] == 2

# The position and rotation blocks of a transform by ranges.
T_sb = frame(Rotz(pi/2), (1, 2, 3))
assert T_sb[1:3, 4] == T_sb.p
assert T_sb[1:3, 1:3] ≈ T_sb.R
T_ab = Trans(2, 2, 0)
assert T_ab.p == (2, 2, 0)

# Symbols as scalars: given α, β (no type needed).
given α, β
assert Rotz(α) Rotz(β) == Rotz(α + β)

# Habits: diag, linspace, nested comprehensions as Python writes them.
G = diag(2, 3, 4)
assert trace(G) == 9
angles = linspace(0, pi/2, 3)
assert angles[end] ≈ pi/2
pairs = [a + 10 b for a in 1:2 for b in 1:2]
assert pairs[2] == 21
assert pairs[end] == 22

# Within rounding of the domain, acos clamps (with a note): a unit vector
# with itself gives an angle of 0.
u = Normalize((1, 1, 1))
angle = acos(dot(u, u))
assert angle == 0

# Points of a path drawn as a list of point pictures.
path = [point(Rotz(t) (1, 0, 0)) for t in linspace(0, pi/2, 5)]
draw(path, view(30 deg, 20 deg))
