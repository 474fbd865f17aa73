# Modern Robotics, chapter 3, §3.3.1 "Homogeneous Transformation Matrices":
# §3.3.1.1 properties (Props. 3.10–3.13) and §3.3.1.2 "Uses of
# Transformation Matrices" (Figures 3.13 and 3.14).
#
# Frames {a}, {b}, {c} of Figure 3.13, with {s} coincident with {a}, and the
# point v with v_b = (0, 0, 1.5).
#
# Computes the three uses of T:
#   (i)   representing a configuration: T_sa, T_sb, T_sc from (R, p);
#   (ii)  changing the reference frame: T_bc = T_bs T_sc, T_ab v_b = v_a,
#         T_de = T_ed^-1;
#   (iii) displacing a frame: with T = (Rot(ẑ, 90°), (0, 2, 0)),
#         T_sb' = T T_sb (fixed frame) and T_sb'' = T_sb T (body frame);
# and Props. 3.10 (inverse), 3.13 (distances kept).
#
# Book's printed answers:
#   R_sa = I, R_sb = [0 0 1; 0 -1 0; 1 0 0], R_sc = [-1 0 0; 0 0 1; 0 1 0]
#   p_sa = (0, 0, 0), p_sb = (0, -2, 0), p_sc = (-1, 1, 0);  T_sa = I
#   R_bc = [0 1 0; 0 0 -1; -1 0 0], p_bc = (0, -3, -1)
#   T  = [0 -1 0 0; 1 0 0 2; 0 0 1 0; 0 0 0 1]
#   T_sb  = [0 0 1 0; 0 -1 0 -2; 1 0 0 0; 0 0 0 1]
#   T_sb' = T T_sb = [0 1 0 2; 0 0 1 2; 1 0 0 0; 0 0 0 1]
#   T_sb''= T_sb T = [0 0 1 0; -1 0 0 -4; 0 -1 0 0; 0 0 0 1]
# The book prints no v_a or v_c; by the cancellation rule
#   v_a = T_ab v_b = (1.5, -2, 0) and v_c = T_cb v_b = (-2.5, 0, -3).
# BOOK SLIP (wording): "T_bc = (R_bc, p_bc) represents {b} relative to {c}"
#   should read "{c} relative to {b}" (the book's own convention, and the
#   numbers it prints are those of {c} in {b}, i.e. T_bs T_sc).

# --- (i) Representing a configuration -----------------------------------------
R_sa = [1, 0, 0; 0, 1, 0; 0, 0, 1]
R_sb = [0, 0, 1; 0, -1, 0; 1, 0, 0]
R_sc = [-1, 0, 0; 0, 0, 1; 0, 1, 0]
p_sa = (0, 0, 0)
p_sb = (0, -2, 0)
p_sc = (-1, 1, 0)
T_sa = RpToTrans(R_sa, p_sa)     # I: {a} is collocated with {s}
T_sb = RpToTrans(R_sb, p_sb)
T_sc = SE3(R_sc, p_sc)           # the same construction, as SE3(R, p)
[R_sc, p_sc; 0, 0, 0, 1]         # and as a block matrix (Eq. 3.62)

# --- (ii) Changing the reference frame -------------------------------------
T_bc = inv(T_sb) * T_sc          # {c} relative to {b}
(R_bc, p_bc) = TransToRp(T_bc)   # R_bc = [0 1 0; 0 0 -1; -1 0 0], p_bc = (0, -3, -1)
T_cb = inv(T_bc)                 # T_de = T_ed^-1
T_bc * T_cb                      # I
T_sb * T_bc                      # = T_sc (subscript cancellation)
T_ab = inv(T_sa) * T_sb          # = T_sb, since {a} = {s}

given v_a, v_b, v_c : point      # v names a velocity elsewhere; here the book's point
v_b = (0, 0, 1.5)                # the point v of Figure 3.13, in {b}
v_a = T_ab * v_b                 # (1.5, -2, 0)
v_c = T_cb * v_b                 # (-2.5, 0, -3)
inv(T_sc) * T_sa * v_a           # v_c again, by way of {s}

# Prop. 3.10: T^-1 = [R^T, −R^T p; 0, 1]
[R_sb.T, -R_sb.T * p_sb; 0, 0, 0, 1]
TransInv(T_sb)                   # the same

# Prop. 3.13: T keeps distances between points
x = (1, 2, 3)
y = (-1, 0, 2)
norm(T_sb * x - T_sb * y)        # 3
norm(x - y)                      # 3

# --- (iii) Displacing a frame (Figure 3.14) ---------------------------------
T = SE3(Rot((0, 0, 1), 90 deg), (0, 2, 0))   # (Rot(ŵ, θ), p) with ŵ = ẑ, θ = 90°
T_sb' = T * T_sb                 # fixed frame: rotate about ẑ_s, then translate in {s}
T_sb'' = T_sb * T                # body frame: translate in {b}, then rotate about ẑ_b

# --- The book's printed answers, checked -------------------------------------
assert T_sa == eye(4)
assert R_bc == [0, 1, 0; 0, 0, -1; -1, 0, 0]
assert p_bc == (0, -3, -1)
assert T ≈ [0, -1, 0, 0; 1, 0, 0, 2; 0, 0, 1, 0; 0, 0, 0, 1]
assert T_sb == [0, 0, 1, 0; 0, -1, 0, -2; 1, 0, 0, 0; 0, 0, 0, 1]
assert T_sb' ≈ [0, 1, 0, 2; 0, 0, 1, 2; 1, 0, 0, 0; 0, 0, 0, 1]
assert T_sb'' ≈ [0, 0, 1, 0; -1, 0, 0, -4; 0, -1, 0, 0; 0, 0, 0, 1]
assert v_a ≈ (1.5, -2, 0)
assert v_c ≈ (-2.5, 0, -3)
assert T_sb * T_bc ≈ T_sc
