# Modern Robotics, chapter 3, §3.3.2.2 "The Screw Interpretation of a Twist"
# (Figure 3.18, Definition 3.7).
#
# Computes:
#   1. The screw axis of the car of Example 3.3: S = V/‖ω‖, θ̇ = ‖ω‖,
#      the pitch h = ŵ^T v / θ̇ and the point q on the axis; and back with
#      ScrewToAxis(q, ŝ, h) (v = −ŝ × q + h ŝ); S_b = [Ad_T_bs] S_s.
#   2. A screw with pitch: q = (3, 0, 0), ŝ = ẑ, h = 2 (the §3.6
#      ScrewToAxis example of the book's software).
#   3. A pure translation (ω = 0): S = V/‖v‖, θ̇ = ‖v‖, h = ∞.
#
# Expected values (the book states the car's axis in words: a pure rotation,
# h = 0, about the axis through r_s = (2, −1, 0) out of the page):
#   1. S_s = (0, 0, 1, −1, −2, 0), θ̇ = 2, q = (2, −1, 0), ŝ = (0, 0, 1), h = 0
#      S_b = (0, 0, −1, 1.4, 2, 0)
#   2. ScrewToAxis((3,0,0), (0,0,1), 2) = (0, 0, 1, 0, −3, 2)
#   3. V = (0, 0, 0, 0, 3, 4): S = (0, 0, 0, 0, 0.6, 0.8), θ̇ = 5, h = inf, q = 0
# screw_params returns for q the point of the axis nearest the origin
# (LANGUAGE.md §8); the book allows any point of the axis.

# --- 1. The car of Example 3.3 ---------------------------------------------------
T_sb = [-1, 0, 0, 4; 0, 1, 0, 0.4; 0, 0, -1, 0; 0, 0, 0, 1]
V_s = twist((0, 0, 2), (-2, -4, 0))
thetadot = norm(V_s.w)           # 2 rad/s
S_s = V_s / thetadot             # (0, 0, 1, −1, −2, 0)
dot(S_s.w, V_s.v) / thetadot     # the pitch h = ŵ^T v / θ̇ = 0
(q, s_hat, h) = screw_params(S_s)   # q = (2, −1, 0) = r_s, ŝ = (0, 0, 1), h = 0
ScrewToAxis(q, s_hat, h)         # S_s again
-cross(s_hat, q) + h * s_hat     # its v part, from Figure 3.18
S_b = Ad(inv(T_sb)) * S_s        # (0, 0, −1, 1.4, 2, 0): the same axis seen in {b}
S_b * thetadot                   # = V_b of Example 3.3

# --- 2. A screw with pitch 2 -------------------------------------------------
S1 = ScrewToAxis((3, 0, 0), (0, 0, 1), 2)   # (0, 0, 1, 0, −3, 2)
screw((3, 0, 0), (0, 0, 1), 2)             # the same, under its short name
(q1, s1, h1) = screw_params(S1)             # ((3, 0, 0), (0, 0, 1), 2)

# --- 3. A pure translation: infinite pitch -----------------------------------
V = twist((0, 0, 0), (0, 3, 4))
thetadot2 = norm(V.v)            # 5
S2 = V / thetadot2               # (0, 0, 0, 0, 0.6, 0.8)
(q2, s2, h2) = screw_params(S2)  # ((0, 0, 0), (0, 0.6, 0.8), inf)

# --- The expected values, checked ---------------------------------------------
assert thetadot == 2
assert S_s ≈ (0, 0, 1, -1, -2, 0)
assert q ≈ (2, -1, 0)
assert s_hat ≈ (0, 0, 1)
assert h == 0
assert S_b ≈ (0, 0, -1, 1.4, 2, 0)
assert S1 ≈ (0, 0, 1, 0, -3, 2)
assert (q1, s1, h1) ≈ ((3, 0, 0), (0, 0, 1), 2)
assert S2 ≈ (0, 0, 0, 0, 0.6, 0.8)
assert thetadot2 == 5
assert h2 == inf
