# Modern Robotics, chapter 3, §3.3.3 "Exponential Coordinate Representation
# of Rigid-Body Motions" (Prop. 3.16, Eqs. 3.87–3.96, the SE(3) log algorithm).
#
# The book has no spatial numerical example here (Example 3.4 is planar, see
# ch3_ex3_4_se2_log.chs). This script applies the section to transforms from
# the chapter:
#   1. Prop. 3.16 with ‖ω‖ = 1: the car of Example 3.3 turns a quarter turn
#      about its screw axis S_s = (0, 0, 1, −1, −2, 0):
#      e^{[S]θ} = [e^{[ω]θ}, G(θ)v; 0, 1], G(θ) = Iθ + (1 − cos θ)[ω] + (θ − sin θ)[ω]^2,
#      applied in {s} (premultiply) and, with S_b, in {b} (postmultiply).
#   2. Prop. 3.16 with ω = 0: a pure translation, e^{[S]θ} = [I, vθ; 0, 1].
#   3. The log algorithm, case (iii): T = (Rot(ẑ, 90°), (0, 2, 0)) of Figure 3.14.
#   4. Case (ii), tr R = −1: T_sb of §3.3.1.2 (a half turn, θ = π).
#   5. Case (i), R = I: a pure translation.
#
# Expected values (numpy, and by hand from Prop. 3.16 / Eqs. 3.92–3.96):
#   1. G(π/2) v = (1, −3, 0);  e^{[S_s]π/2} = [0 -1 0 1; 1 0 0 -3; 0 0 1 0; 0 0 0 1]
#      T_sb' = [0 -1 0 0.6; -1 0 0 1; 0 0 -1 0; 0 0 0 1]
#      (the car's origin (4, 0.4) turned 90° about r_s = (2, −1) lands at (0.6, 1))
#   2. e^{[S]2} with S = (0, 0, 0, 0, 0, 1): translation by (0, 0, 2)
#   3. MatrixLog6(T) = (0, 0, 1.5708, 1.5708, 1.5708, 0): S = (0, 0, 1, 1, 1, 0),
#      θ = π/2, a pure rotation (h = 0) about the vertical axis through q = (−1, 1, 0)
#   4. MatrixLog6(T_sb) = (2.2214, 0, 2.2214, −2.2214, 0, 2.2214): θ = π,
#      S = (1/√2, 0, 1/√2, −1/√2, 0, 1/√2), h = 0, q = (0, −1, 0)
#      (at θ = π, −S with θ = π is an equally valid answer)
#   5. MatrixLog6 = (0, 0, 0, 3, 0, 4): S = (0, 0, 0, 0.6, 0, 0.8), θ = 5

# --- 1. A screw motion with pitch 0: the car turns a quarter turn ---------------
T_sb = [-1, 0, 0, 4; 0, 1, 0, 0.4; 0, 0, -1, 0; 0, 0, 0, 1]
S_s = twist((0, 0, 1), (-1, -2, 0))
S_b = Ad(inv(T_sb)) * S_s
theta = pi/2
exp([S_s] theta)                 # the displacement, in {s}
w = untag(S_s.w)                 # plain numbers for the formula
v = untag(S_s.v)
G = theta * eye(3) + (1 - cos(theta)) * [w] + (theta - sin(theta)) * [w]^2   # (3.88)
G * v                            # (1, −3, 0): the translation part of e^{[S]θ}
MatrixExp6(S_s * theta)          # the same, from exponential coordinates
T_sb' = exp([S_s] theta) * T_sb  # premultiply: screw axis S_s in {s}
T_sb * exp([S_b] theta)          # postmultiply by the same axis written in {b}: the same frame

# --- 2. Pitch ∞: a pure translation (3.90) -----------------------------------
S_trans = twist((0, 0, 0), (0, 0, 1))
exp([S_trans] 2)                 # [I, (0, 0, 2); 0, 1]

# --- 3. Matrix logarithm, case (iii) ------------------------------------------
T = SE3(Rot(z, 90 deg), (0, 2, 0))
expc = MatrixLog6(T)             # (0, 0, 1.5708, 1.5708, 1.5708, 0)
log(T)                           # [S]θ ∈ se(3)
(S, th) = AxisAng6(expc)         # S = (0, 0, 1, 1, 1, 0), θ = π/2
screw_params(S)                  # q = (−1, 1, 0), ŝ = (0, 0, 1), h = 0
MatrixExp6(expc)                 # T again

# --- 4. Case (ii), tr R = −1 -----------------------------------------------
T_sb2 = [0, 0, 1, 0; 0, -1, 0, -2; 1, 0, 0, 0; 0, 0, 0, 1]   # T_sb of §3.3.1.2
trace(T_sb2.R)                   # −1
expc2 = MatrixLog6(T_sb2)        # (2.2214, 0, 2.2214, −2.2214, 0, 2.2214)
(S2, th2) = AxisAng6(expc2)      # θ = π
screw_params(S2)                 # q = (0, −1, 0), ŝ = (0.7071, 0, 0.7071), h = 0
exp(log(T_sb2))                  # T_sb2 again

# --- 5. Case (i), R = I --------------------------------------------------------
expc3 = MatrixLog6(Trans((3, 0, 4)))   # (0, 0, 0, 3, 0, 4)
AxisAng6(expc3)                  # ((0, 0, 0, 0.6, 0, 0.8), 5)

# --- The expected values, checked ---------------------------------------------
assert G * v ≈ (1, -3, 0)
assert exp([S_s] theta) ≈ [0, -1, 0, 1; 1, 0, 0, -3; 0, 0, 1, 0; 0, 0, 0, 1]
assert T_sb' ≈ [0, -1, 0, 0.6; -1, 0, 0, 1; 0, 0, -1, 0; 0, 0, 0, 1]
assert exp([S_trans] 2) ≈ Trans((0, 0, 2))
assert expc ≈ (0, 0, pi/2, pi/2, pi/2, 0)
assert S ≈ (0, 0, 1, 1, 1, 0)
assert th ≈ pi/2
# θ = π: the book's formula (3.58) gives ω̂ = (1, 0, 1)/√2 (−S is as valid).
assert expc2 ≈ pi * (1/sqrt(2), 0, 1/sqrt(2), -1/sqrt(2), 0, 1/sqrt(2))
assert th2 ≈ pi
assert expc3 == (0, 0, 0, 3, 0, 4)
assert screw_params(S) ≈ ((-1, 1, 0), (0, 0, 1), 0)
assert screw_params(S2) ≈ ((0, -1, 0), (1, 0, 1) / sqrt(2), 0)
assert AxisAng6(expc3) ≈ ((0, 0, 0, 0.6, 0, 0.8), 5)
assert exp(log(T_sb2)) ≈ T_sb2
