# Modern Robotics, chapter 3, §3.2.2 "Angular Velocity"
# (Definition 3.3, Propositions 3.5 and 3.6, Eqs. 3.29–3.38).
#
# The book has no numerical example in this section; this script applies its
# equations to a concrete motion. A body starts at R_0 = Rot(x̂, 90°) and
# turns about the fixed axis ŵ = (0, √3/2, 1/2) of Example 3.1 at
# θ̇ = 2 rad/s; we look at the instant θ = 30°, where
#   R(t) = Rot(ŵ, θ(t)) R_0   and   Ṙ = [ŵ] θ̇ R.
#
# Computes and checks:
#   [u] (Eq. 3.30) and [u] = −[u]^T;
#   [ω_s] = Ṙ R^-1 (3.37) and [ω_b] = R^-1 Ṙ (3.38);
#   ω_s = ŵ θ̇ = (0, 1.7321, 1) and ω_b = R^T ω_s = (0, 1, −1.7321);
#   ω_s = R_sb ω_b (subscript cancellation) and R[ω]R^T = [Rω] (Prop. 3.5);
#   Ṙ by a finite difference, to show what Ṙ means.
# Expected values (computed with numpy; the book prints none here):
#   R   = [0.866 0.433 0.25; 0.25 0.058 -0.9665; -0.433 0.8995 -0.058]
#   Ṙ   = [-1 1.5 0.866; 0.866 0.433 0.25; -1.5 -0.75 -0.433]
#   ω_s = (0, 1.7321, 1),   ω_b = (0, 1, −1.7321)

# --- The skew-symmetric matrix [x] (Definition 3.3) ---------------------------
u = (1, 2, 3)
[u]                           # [0 -3 2; 3 0 -1; -2 1 0]
[u] + [u].T                   # zero: [u] = −[u]^T
cross(u, (4, 5, 6))           # u × y ...
[u] * (4, 5, 6)               # ... = [u] y = (−3, 6, −3)

# --- A rotating body ---------------------------------------------------------
w_hat = (0, sqrt(3)/2, 0.5)
theta = 30 deg
theta_dot = 2                 # rad/s
R_0 = Rot(x, 90 deg)
R = Rot(w_hat, theta) * R_0   # R(t) at this instant
R_dot = [w_hat] theta_dot * R # Ṙ = [ŵ] θ̇ R

# Ṙ is the time derivative of R: compare with a finite difference
dt = 1e-6
(Rot(w_hat, theta + theta_dot * dt) * R_0 - R) / dt

# --- Proposition 3.6 ---------------------------------------------------------
R_dot * inv(R)                # [ω_s] = Ṙ R^-1  (3.37)
inv(R) * R_dot                # [ω_b] = R^-1 Ṙ  (3.38)
so3ToVec(R_dot * R.T)         # ω_s = ŵ θ̇ = (0, 1.7321, 1)
vee(R.T * R_dot)              # ω_b = (0, 1, −1.7321)

# --- Changing the frame of an angular velocity: ω_s = R_sb ω_b ---------------
R_sb = R
ω_s = w_hat * theta_dot       # the fixed-frame angular velocity
ω_b = R_sb.T * ω_s            # Eq. (3.35): ω_b = R^T ω_s = (0, 1, −1.7321)
R_sb * ω_b                    # back to ω_s
[ω_b]                         # = R^-1 Ṙ above

# --- Proposition 3.5: R [ω] R^T = [R ω] (plain numbers, no frames) ------------
R * [u] * R.T
[R * u]

# --- The expected values, checked ---------------------------------------------
assert [u] == [0, -3, 2; 3, 0, -1; -2, 1, 0]
assert [u] + [u].T == zeros(3, 3)
assert [u] * (4, 5, 6) == (-3, 6, -3)
assert round(R, 4) == [0.866, 0.433, 0.25; 0.25, 0.058, -0.9665; -0.433, 0.8995, -0.058]
assert round(R_dot, 4) == [-1, 1.5, 0.866; 0.866, 0.433, 0.25; -1.5, -0.75, -0.433]
assert so3ToVec(R_dot * R.T) ≈ (0, sqrt(3), 1)
assert vee(R.T * R_dot) ≈ (0, 1, -sqrt(3))
assert ω_b ≈ (0, 1, -sqrt(3))
assert R_sb * ω_b ≈ ω_s
assert R * [u] * R.T ≈ [R * u]
