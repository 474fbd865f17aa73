# Modern Robotics, chapter 3 — a student's second hour with frames, typed as
# the book writes it (issue 22): points and free vectors, the axes of a
# frame, twists and wrenches from their parts, and a matrix that looks like
# a transform but is not one.
#
# The book keeps points (p, q, r) apart from free vectors: an angular
# velocity ω (typed w or ω), a linear velocity v, a force f, a moment m and
# an axis ω̂, ŝ, x̂ only rotate (ω_s = R_sb ω_b, (3.35)); a transform moves
# points, T p = R p + p (3.65). chasles reads which is which from the name
# (or from `given u : free`), and T * ω is an error naming R * ω.
#
# Exercise 3.1: x̂_a = (0, 0, 1), ŷ_a = (−1, 0, 0), x̂_b = (1, 0, 0),
#   ŷ_b = (0, 0, −1) in {s}. The axis names x_a, y_a are the axes *of* {a},
#   written in {s}: untagged, so R_sa = [x_a, y_a, z_a] is {s}←{a}.
#   R_sa = [0 −1 0; 0 0 −1; 1 0 0], R_sb = [1 0 0; 0 0 1; 0 −1 0];
#   (f) p_s = R_sb p_b = (1, 3, −2) for p_b = (1, 2, 3);
#   (h) ω_a = R_saᵀ ω_s = (1, −3, −2) for ω_s = (3, 2, 1).
# Exercise 3.16: {a} at (3, 0, 0), {b} at (0, 2, 0):
#   (f) p_s = T_sb p_b = (1, 5, −2) (a point: the translation is added);
#   an angular velocity ω_b = (1, 2, 3) is ω_s = R_sb ω_b = (1, 3, −2)
#   (T_sb ω_b would give (1, 5, −2), the translation added to a velocity);
#   (g) V_s = (ω_s, v_s) = (3, 2, 1, −1, −2, −3): V_a = [Ad_T_as] V_s,
#   ω_a = R_as ω_s = (1, −3, −2), v_a = R_as v_s + [p_as] R_as ω_s with
#   p_as = −R_as p_sa = (0, 3, 0): (−3, 1, 2) + (−6, 0, −3) = (−9, 1, −1).
# Exercise 3.28: ω_s = (1, 2, 3), R = R_sb = [0 −1 0; 0 0 −1; 1 0 0]:
#   ω_b = Rᵀ ω_s = (3, −1, −2).
# Exercise 3.2: p = (1/√3, −1/√6, 1/√2) rotated about the fixed x̂ by 30°,
#   ŷ by 135°, ẑ by −120°: p' = Rz Ry Rx p (fixed axes premultiply, §3.2.3.3).
#   Named R_x, the rotations would be tagged {x}, {y}, {z}: write Rx, Ry, Rz.
# Exercise 3.31: F_e = (m_e, f_e) with f_e = (0, 0, 10) N: (0, 0, 0, 0, 0, 10).
# Exercise 3.25(a): BOOK SLIP. A as printed has r₃₃ = 1, so its rotation block
#   [0 0 1; 0 1 0; −1 0 1] is no rotation (A is not in SE(3)); chasles warns
#   at binding with the distance, 1.7321 (DistanceToSE3). With r₃₃ = 0, A is
#   Rot(ŷ, 90°) with p = (0, 1, 0), and AX = XB gives B = X⁻¹ A X
#   = [0 0 1 −1; 0 1 0 1; −1 0 0 −1; 0 0 0 1].

# --- Exercise 3.1: the axes of {a} and {b}, written in {s} --------------------
x_a = (0, 0, 1)
y_a = (-1, 0, 0)
z_a = cross(x_a, y_a)                # (0, -1, 0)
R_sa = [x_a, y_a, z_a]
x_b = (1, 0, 0)
y_b = (0, 0, -1)
z_b = cross(x_b, y_b)
R_sb = [x_b, y_b, z_b]
p_b = (1, 2, 3)
p_s = R_sb p_b                       # (f): (1, 3, -2)
ω_s = (3, 2, 1)
ω_a = R_sa.T ω_s                     # (h): (1, -3, -2)
assert R_sa == [0, -1, 0; 0, 0, -1; 1, 0, 0]
assert p_s == (1, 3, -2)
assert ω_a == (1, -3, -2)

# --- Exercise 3.16: a point moves with T, a velocity only rotates -------------
T_sa = SE3(R_sa, (3, 0, 0))
T_sb = SE3(Rotx(-pi/2), (0, 2, 0))
assert T_sb ≈ SE3(R_sb, (0, 2, 0))
p_s = T_sb p_b                       # (f): the point, (1, 5, -2)
ω_b = (1, 2, 3)
ω_s = T_sb.R ω_b                     # (1, 3, -2); T_sb ω_b is an error
assert p_s ≈ (1, 5, -2)
assert ω_s ≈ (1, 3, -2)
w_s = (3, 2, 1)
v_s = (-1, -2, -3)
V_s = (w_s, v_s)                     # named as a twist: the 6-vector (ω, v)
V_a = Ad(inv(T_sa)) V_s              # (g): (1, -3, -2, -9, 1, -1)
assert V_a ≈ (1, -3, -2, -9, 1, -1)
given n_b : free                     # a name that does not say it
n_b = (0, 0, 1)
n_s = T_sb.R n_b                     # (0, 1, 0); T_sb n_b is an error
assert n_s ≈ (0, 1, 0)

# --- Exercise 3.28: ω_b from ω_s -------------------------------------------------
R_sb = [0, -1, 0; 0, 0, -1; 1, 0, 0]    # the book's R: {b} in {s}
ω_s = (1, 2, 3)
ω_b = R_sb.T ω_s                     # (3, -1, -2)
assert ω_b == (3, -1, -2)

# --- Exercise 3.2: rotations about fixed axes, named without a frame -----------
p = (1/sqrt(3), -1/sqrt(6), 1/sqrt(2))
Rx = Rotx(30 deg)
Ry = Roty(135 deg)
Rz = Rotz(-120 deg)
p' = Rz Ry Rx p
assert norm(p') ≈ 1
commutes_x = Rx Ry == Ry Rx          # a bool: no frames from its name
ok_a = R_sa R_sa.T ≈ eye(3)

# --- Exercise 3.31: a wrench from its moment and force --------------------------
m_e = (0, 0, 0)
f_e = (0, 0, 10)
F_e = (m_e, f_e)
assert F_e == (0, 0, 0, 0, 0, 10)

# --- Exercise 3.25(a): the misprint, and the matrix the book meant --------------
X = [1, 0, 0, 1; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1]
A = [0, 0, 1, 0; 0, 1, 0, 1; -1, 0, 1, 0; 0, 0, 0, 1]    # warns: r₃₃ = 1
A = [0, 0, 1, 0; 0, 1, 0, 1; -1, 0, 0, 0; 0, 0, 0, 1]    # r₃₃ = 0: in SE(3)
B = inv(X) A X
assert A X == X B
assert B == [0, 0, 1, -1; 0, 1, 0, 1; -1, 0, 0, -1; 0, 0, 0, 1]
