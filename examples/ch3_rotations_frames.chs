# Modern Robotics, chapter 3, §3.2.1 "Rotation Matrices" and §3.2.1.2
# "Uses of Rotation Matrices" (Figures 3.6, 3.7, 3.8).
#
# Computes, for the frames {a}, {b}, {c} of Figure 3.6 ({s} is aligned with {a}):
#   - the three uses of a rotation matrix: representing an orientation
#     (R_sa, R_sb, R_sc), changing the reference frame (R_ac = R_ab R_bc,
#     R_ab p_b = p_a), and rotating a frame or a vector (R = Rot(ŵ, θ),
#     premultiply = rotate about a fixed-frame axis, postmultiply = about a
#     body-frame axis);
#   - the properties of SO(3): R^T R = I, det R = 1, R^-1 = R^T, lengths kept.
#
# Book's printed answers:
#   R_a = I, R_b = [0 -1 0; 1 0 0; 0 0 1], R_c = [0 -1 0; 0 0 -1; 1 0 0]
#   p_a = (1, 1, 0), p_b = (1, -1, 0), p_c = (0, -1, -1)
#   {b} is {a} rotated about ẑ_a by 90°; {c} is {b} rotated about ŷ_b by −90°
#   R_ac = [0 -1 0; 0 0 -1; 1 0 0], R_ca = [0 0 1; -1 0 0; 0 -1 0],
#   R_ac R_ca = I
# The book writes R_a, R_b, R_c for the orientations relative to {s}; it says
#   itself these are R_sa, R_sb, R_sc, the names used here.
# The book gives no numbers for the frame of Figure 3.8; the fixed-frame vs
#   body-frame rotation is shown here on {c} of Figure 3.6 with the figure's
#   operator R = Rot(ẑ, 90°): R R_sc = [0 0 1; 0 -1 0; 1 0 0] and
#   R_sc R = [-1 0 0; 0 0 -1; 0 -1 0] (different, as the figure shows).

# --- Representing an orientation --------------------------------------------
R_sa = [1, 0, 0; 0, 1, 0; 0, 0, 1]
R_sb = [0, -1, 0; 1, 0, 0; 0, 0, 1]
R_sc = [0, -1, 0
        0, 0, -1
        1, 0, 0]

# SO(3): R^T R = I and det R = 1 (Definition 3.1); R^-1 = R^T (Prop. 3.1)
R_sc.T * R_sc
det(R_sc)
inv(R_sc)
RotInv(R_sc)

# {b} is {a} rotated by 90° about ẑ_a; {c} is {b} rotated by −90° about ŷ_b
Rot(z, 90 deg)                # = R_sb
R_sb * Rot(y, -90 deg)        # = R_sc (postmultiply: about the body axis ŷ_b)

# --- Changing the reference frame: subscript cancellation -----------------
R_ac = inv(R_sa) * R_sc       # {s} = {a}, so R_ac = R_sc
R_ca = R_ac.T                 # [0 0 1; -1 0 0; 0 -1 0]
R_ac * R_ca                   # I
R_ab = R_sa.T * R_sb
R_bc = R_sb.T * R_sc          # {c} in {b}: Rot(ŷ, −90°) = [0 0 -1; 0 1 0; 1 0 0]
R_ab * R_bc                   # = R_ac (Eq. 3.22)

p_a = (1, 1, 0)
p_b = (1, -1, 0)
p_c = (0, -1, -1)
R_ab * p_b                    # = p_a = (1, 1, 0)
R_ac * p_c                    # = p_a
R_bc * p_c                    # = p_b = (1, -1, 0)
R_ca * p_a                    # = p_c = (0, -1, -1)

# --- Rotating a frame (Figure 3.8) -----------------------------------------
R = Rot(z, 90 deg)            # the rotation operator Rot(ẑ, 90°)
R_sc' = R * R_sc              # rotate {c} about the fixed axis ẑ_s (Eq. 3.23)
R_sc'' = R_sc * R             # rotate {c} about its own body axis ẑ_c

# Rot(ŵ, θ) for a general unit axis (the matrix above Figure 3.7)
Rot((0, 0, 1), 90 deg)        # the same as Rot(z, 90 deg)
Rot((1, 1, 1) / sqrt(3), 120 deg)   # permutes the axes: [0 0 1; 1 0 0; 0 1 0]

# --- Rotating a vector: v' = R v, in the one frame v is written in ----------
v = (1, 2, 3)
R * v                         # (−2, 1, 3)
norm(R * v) - norm(v)         # 0: rotations keep lengths (Prop. 3.4)

# --- The book's printed answers, checked -------------------------------------
assert R_sb ≈ Rot(z, 90 deg)
assert untag(R_sb * Rot(y, -90 deg)) ≈ R_sc   # {b} moved is {c}
assert R_ac == [0, -1, 0; 0, 0, -1; 1, 0, 0]
assert R_ca == [0, 0, 1; -1, 0, 0; 0, -1, 0]
assert R_ac * R_ca == eye(3)
assert R_ab * p_b == p_a
assert R_ac * p_c == p_a
assert R_bc * p_c == p_b
assert R_ca * p_a == p_c
assert R_sc' ≈ [0, 0, 1; 0, -1, 0; 1, 0, 0]
# (This header once printed R_sc R with +1 in its last row, which has det −1.)
assert R_sc'' ≈ [-1, 0, 0; 0, 0, -1; 0, -1, 0]
