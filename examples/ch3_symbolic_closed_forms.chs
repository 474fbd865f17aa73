# Modern Robotics, chapter 3 with symbols: the book's closed forms computed
# from the definitions, not typed in (LANGUAGE.md §7).
#
# Covers:
#   - Rot(ẑ, θ) (§3.2.3.1) and Rot(ŵ, θ) for the unit axis ŵ = (1, 2, 2)/3 by
#     Rodrigues' formula (3.51); R Rᵀ = I and det R = 1 with no numbers;
#   - e^{[S]θ} by Proposition 3.16 (G(θ) of (3.88)) for a pure rotation about
#     an axis through q = (0, 2, 0), a screw of pitch h = 1/2 about the same
#     axis, and a pure translation (ω = 0);
#   - planar 2R and 3R arms (T2R, T3R) as products of exponentials: the tip at
#     L1 cos θ1 + L2 cos(θ1 + θ2), …, with angle sums folded;
#   - Example 3.3 (§3.3.2.1): T_sb(t) of the car turning about r_s = (2, -1, 0),
#     ω_s from Ṙ Rᵀ (§3.2.2), V_s from Ṫ T⁻¹ and V_b from T⁻¹ Ṫ (3.71, 3.74);
#     with θ̇ = 2 rad/s they are the book's ω_s = (0, 0, 2), v_s = (-2, -4, 0),
#     ω_b = (0, 0, -2), v_b = (2.8, 4, 0);
#   - identities decided by `==` without numbers: R Rᵀ = I, det R = 1,
#     e^{[ω]a} e^{[ω]b} = e^{[ω](a+b)}, [Ad_{T1 T2}] = [Ad_{T1}][Ad_{T2}], and
#     the power V_aᵀ F_a = V_bᵀ F_b (3.98);
#   - `--short` prints the book's shorthand (c₁, s₁₂), `--latex` LaTeX.

given theta, a, b : scalar
given t1, t2, t3, L1, L2, L3 : scalar

# --- Rotations: Rot(ẑ, θ) and Rodrigues (3.51) ------------------------------------
Rot(z, theta)
w = (1, 2, 2)/3
R = Rot(w, theta)
R R^T == I                                   # true: Rᵀ = R⁻¹ (3.23), no numbers
det(R) == 1                                  # true
exp([w] a) exp([w] b) == exp([w] (a + b))    # true: the angles add

# --- e^{[S]θ} by Proposition 3.16 ----------------------------------------------------
S_rot = screw((0, 2, 0), (0, 0, 1), 0)       # pure rotation about ẑ through q = (0, 2, 0)
exp([S_rot] theta)
S_pitch = screw((0, 2, 0), (0, 0, 1), 0.5)   # the same axis, pitch h = 1/2
exp([S_pitch] theta)
S_trans = (0, 0, 0, 0, 0.6, 0.8)             # pure translation along (0, 0.6, 0.8)
exp([S_trans] theta)

# --- Planar arms: products of exponentials -----------------------------------------
S1 = (0, 0, 1, 0, 0, 0)
S2 = (0, 0, 1, 0, -L1, 0)
S3 = (0, 0, 1, 0, -(L1 + L2), 0)
M2 = [1, 0, 0, L1 + L2; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1]
T2R = exp([S1] t1) exp([S2] t2) M2
M3 = [1, 0, 0, L1 + L2 + L3; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1]
T3R = exp([S1] t1) exp([S2] t2) exp([S3] t3) M3
T3R[1, 4]                                    # x of the tip

# --- Example 3.3: velocities from T_sb(t) --------------------------------------------
given phi(t) : scalar
S_car = screw((2, -1, 0), (0, 0, 1), 0)      # rotation about r_s = (2, -1, 0)
T0 = [-1, 0, 0, 4; 0, 1, 0, 0.4; 0, 0, -1, 0; 0, 0, 0, 1]
T_sb = exp([S_car] phi) T0                   # T_sb(t)
R_sb = T_sb.R
w_s = so3ToVec(diff(R_sb, t) R_sb^T)         # ω_s = (0, 0, φ̇), in {s}
w_b = so3ToVec(R_sb^T diff(R_sb, t))         # ω_b = (0, 0, -φ̇), in {b}
V_s = se3ToVec(diff(T_sb, t) inv(T_sb))      # (0, 0, φ̇, -φ̇, -2φ̇, 0)
V_b = se3ToVec(inv(T_sb) diff(T_sb, t))      # (0, 0, -φ̇, 1.4φ̇, 2φ̇, 0)

# --- Identities, no numbers ---------------------------------------------------------
T1 = exp([S_pitch] a)
T2 = exp([S2] b)
Ad(T1 T2) == Ad(T1) Ad(T2)                   # true
given w1, w2, w3, v1, v2, v3, m1, m2, m3, f1, f2, f3 : scalar
V_1 = (w1, w2, w3, v1, v2, v3)
F_1 = (m1, m2, m3, f1, f2, f3)
V_0 = Ad(T1) V_1
F_0 = Ad(inv(T1))^T F_1
V_0^T F_0 == V_1^T F_1                       # true: the power is frame-free (3.98)

# --- Numbers later: φ̇ = 2 rad/s gives the book's twists -----------------------------
phi' = 2
V_s                                          # (0, 0, 2, -2, -4, 0)
V_b                                          # (0, 0, -2, 2.8, 4, 0)
assert V_s == (0, 0, 2, -2, -4, 0)           # the book's ω_s and v_s = r_s × ω_s
assert V_b ≈ (0, 0, -2, 2.8, 4, 0)           # the book's ω_b and v_b
