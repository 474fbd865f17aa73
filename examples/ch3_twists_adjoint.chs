# Modern Robotics, chapter 3, §3.3.2 "Twists" and §3.3.2.1 "Summary of
# Results on Twists" (Eqs. 3.68–3.85, Definition 3.6, Props. 3.14 and 3.15).
#
# The book has no numerical example here before Example 3.3 (see
# ch3_ex3_3_car_twist.chs); this script applies its equations to the frames
# {s}, {b}, {c} of §3.3.1.2 (Figure 3.13) and a body twist chosen for the
# purpose: V_b = (ω_b, v_b) = (0, 0, 1, 1, 0, 0), i.e. {b} spins about its own
# ẑ_b axis at 1 rad/s while its origin moves along x̂_b at 1 unit/s.
#
# Computes:
#   [V_b] ∈ se(3) (3.72), Ṫ = T [V_b], and back: T^-1 Ṫ = [V_b] (3.82),
#   Ṫ T^-1 = [V_s] (3.83);
#   v_s = ṗ − ω_s × p (3.74): the velocity of the body point at the {s} origin;
#   [Ad_T] = [R 0; [p]R R] (Definition 3.6) and V_s = [Ad_T_sb] V_b (3.84),
#   V_b = [Ad_T_bs] V_s (3.85), V_c = [Ad_T_cs] V_s = [Ad_T_cb] V_b;
#   Prop. 3.14: [Ad_T1][Ad_T2] = [Ad_T1T2] and [Ad_T]^-1 = [Ad_T^-1].
# Expected values (numpy; the book prints none for this twist):
#   ω_s = (1, 0, 0), ṗ = (0, 0, 1), v_s = (0, 0, 3), V_s = (1, 0, 0, 0, 0, 3)
#   V_c = (−1, 0, 0, 0, 4, 0)
#   [Ad_T_sb] = [0 0 1 0 0 0; 0 -1 0 0 0 0; 1 0 0 0 0 0;
#                -2 0 0 0 0 1; 0 0 0 0 -1 0; 0 0 2 1 0 0]

T_sb = [0, 0, 1, 0; 0, -1, 0, -2; 1, 0, 0, 0; 0, 0, 0, 1]
T_sc = [-1, 0, 0, -1; 0, 0, 1, 1; 0, 1, 0, 0; 0, 0, 0, 1]
T_bc = inv(T_sb) * T_sc

V_b = twist((0, 0, 1), (1, 0, 0))
[V_b]                            # [[ω_b] v_b; 0 0]

# --- T^-1 Ṫ and Ṫ T^-1 (Prop. 3.15), with plain matrices -----------------------
T = untag(T_sb)                  # T(t) at this instant, as a plain operator
T_dot = T * untag([V_b])         # Ṫ, from [V_b] = T^-1 Ṫ
inv(T) * T_dot                   # [V_b]
se3ToVec(T_dot * inv(T))         # V_s = (1, 0, 0, 0, 0, 3)

# v_s is not ṗ: it is the velocity of the body point now at the {s} origin
R = untag(T_sb.R)
p = untag(T_sb.p)
p_dot = (T_dot[1, 4], T_dot[2, 4], T_dot[3, 4])   # ṗ = (0, 0, 1)
ω_s = T_sb.R * V_b.w             # (1, 0, 0)
p_dot - cross(ω_s, p)            # v_s = ṗ − ω_s × p = (0, 0, 3)   (3.74)

# --- The adjoint map ---------------------------------------------------------
Ad(T_sb)                         # [R 0; [p]R R]
[R, zeros(3, 3); [p] * R, R]     # Definition 3.6 by hand
V_s = Ad(T_sb) * V_b             # (1, 0, 0, 0, 0, 3)   (3.84)
Ad(inv(T_sb)) * V_s              # V_b again            (3.85)
V_c = Ad(inv(T_sc)) * V_s        # (−1, 0, 0, 0, 4, 0)
Ad(inv(T_bc)) * V_b              # V_c again: a twist's {c} representation
                                 # does not depend on the route

# Prop. 3.14
Ad(T_sb) * Ad(T_bc)              # = Ad(T_sb T_bc) = Ad(T_sc)
Ad(T_sc)
inv(Ad(T_sb))                    # = Ad(T_sb^-1)
Ad(inv(T_sb))

# [V'] = T [V] T^-1 is the matrix form of V' = [Ad_T] V
T * untag([V_b]) * inv(T)        # = [V_s]
[V_s]

# --- The expected values, checked ---------------------------------------------
assert inv(T) * T_dot ≈ untag([V_b])
assert ω_s ≈ (1, 0, 0)
assert p_dot ≈ (0, 0, 1)
assert p_dot - cross(ω_s, p) ≈ (0, 0, 3)
assert V_s ≈ (1, 0, 0, 0, 0, 3)
assert V_c ≈ (-1, 0, 0, 0, 4, 0)
assert Ad(inv(T_bc)) * V_b ≈ V_c
assert Ad(T_sb) ≈ [0, 0, 1, 0, 0, 0; 0, -1, 0, 0, 0, 0; 1, 0, 0, 0, 0, 0; -2, 0, 0, 0, 0, 1; 0, 0, 0, 0, -1, 0; 0, 0, 2, 1, 0, 0]
assert Ad(T_sb) ≈ [R, zeros(3, 3); [p] * R, R]
assert Ad(T_sb) * Ad(T_bc) ≈ Ad(T_sc)                                  # Prop. 3.14
assert inv(Ad(T_sb)) ≈ Ad(inv(T_sb))
