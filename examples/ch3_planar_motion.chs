# Modern Robotics, chapter 3, §3.1 "Rigid-Body Motions in the Plane"
# (Figure 3.2 and Figure 3.4).
#
# Computes:
#   1. The planar body frame {b} of Figure 3.2: p = (2, 1), θ = 60°, as an
#      SE(2) matrix, and its unit axes x̂_b, ŷ_b (the columns of P).
#   2. The planar screw motion of Figure 3.4: following the planar twist
#      V = (ω, v_x, v_y) = (1, 2, 0) for t = π/2 gives the displacement,
#      whose exponential coordinates are V t = (π/2, π, 0); the fixed point
#      s of the rotation is recovered from V.
#
# Book's printed answers:
#   Figure 3.2: x̂_b = (cos θ, sin θ) = (0.5, 1/√2), ŷ_b = (−sin θ, cos θ) = (−1/√2, 0.5)
#   Figure 3.4: V = (1, 2, 0) (a point at the origin of {s} moves at 2 units/s
#               in +x̂_s), exponential coordinates V t = (π/2, π, 0), β = 90°.
#
# BOOK SLIP (Figure 3.2 caption): sin 60° = √3/2 = 0.866, not 1/√2 = 0.707.
#   The correct axes are x̂_b = (0.5, 0.866) and ŷ_b = (−0.866, 0.5), which is
#   what this script prints.
# The book gives no numbers for (P, p) in Figure 3.4; the displacement printed
#   below is the one its twist determines: rotation by 90° and p = (2, 2),
#   a rotation about the point s = (0, 2).

# --- Figure 3.2: the configuration of a planar body ------------------------
theta = 60 deg
T_sb = SE2(theta, 2, 1)
P = T_sb.R                 # the rotation matrix P = [x̂_b ŷ_b] of Eq. (3.5)
P[:, 1]                    # x̂_b = (cos θ, sin θ)  = (0.5, 0.866)
P[:, 2]                    # ŷ_b = (−sin θ, cos θ) = (−0.866, 0.5)
det(P)                     # 1: a right-handed planar frame

# --- Figure 3.4: a planar displacement as a screw motion -------------------
V = (1, 2, 0)              # planar twist (ω, v_x, v_y)
t = pi/2
D = exp(se2(1, 2, 0) * t)  # displacement obtained by following V for t = π/2
L = log(D)                 # the se(2) matrix [V] t
(L[2, 1], L[1, 3], L[2, 3])   # exponential coordinates V t = (π/2, π, 0)
q = (-V[3] / V[1], V[2] / V[1])  # the fixed point s of the rotation: (0, 2)
D * (q[1], q[2], 1)        # s is not moved by the displacement: (0, 2, 1)

# --- The book's printed answers, checked -------------------------------------
# BOOK SLIP (Figure 3.2 caption): the book prints sin 60° as 1/√2; it is √3/2.
assert P[:, 1] ≈ (0.5, sqrt(3)/2)
assert P[:, 2] ≈ (-sqrt(3)/2, 0.5)
assert (L[2, 1], L[1, 3], L[2, 3]) ≈ (pi/2, pi, 0)
assert D * (q[1], q[2], 1) ≈ (0, 2, 1)
