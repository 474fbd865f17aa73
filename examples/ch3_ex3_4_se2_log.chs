# Modern Robotics, chapter 3, §3.3.3.2, Example 3.4 (Figure 3.19):
# the matrix logarithm on SE(2).
#
# Two planar frames, T_sb (30°, at (1, 2)) and T_sc (60°, at (2, 1)). Find
# the screw motion, expressed in {s}, that displaces {b} to {c}:
#   T_sc = e^{[S]θ} T_sb,  so  e^{[S]θ} = T_sc T_sb^-1,
# with S = (ω3, v1, v2) a planar screw of zero pitch about ẑ_s.
#
# T_sc T_sb^-1 does not cancel frames (it is not a change of frame but a
# displacement in {s}); chasles spells it displacement(T_sb, T_sc)
# (LANGUAGE.md §6). The body-frame counterpart T_sb^-1 T_sc = T_bc is shown too.
#
# Book's printed answers:
#   [S] = [0 -1 3.37; 1 0 -3.37; 0 0 0],  S = (ω3, v1, v2) = (1, 3.37, −3.37),
#   θ = π/6 rad (30°); the axis passes through q = (3.37, 3.37).
# Rounding: 3.37 is the book's 2-decimal rounding of v1 = −v2 = 1.7624/0.5236
#   = 3.3660, and q = (3.3660, 3.3660). No slip.
# Cross-check: the same displacement lifted to SE(3) gives
#   S = (0, 0, 1, 3.366, −3.366, 0), θ = π/6, h = 0, q = (3.366, 3.366, 0).

T_sb = [cos(30 deg), -sin(30 deg), 1
        sin(30 deg),  cos(30 deg), 2
        0,            0,           1]
T_sc = [cos(60 deg), -sin(60 deg), 2
        sin(60 deg),  cos(60 deg), 1
        0,            0,           1]
SE2(30 deg, 1, 2)                # the same T_sb, built directly

D = displacement(T_sb, T_sc)     # T_sc T_sb^-1: [0.866 -0.5 2.134; 0.5 0.866 -1.2321; 0 0 1]
D * T_sb                         # = T_sc
L = log(D)                       # [S]θ = [0 -0.5236 1.7624; 0.5236 0 -1.7624; 0 0 0]
theta = L[2, 1]                  # θ = 0.5236 = π/6 (ω3 = 1)
theta / (1 deg)                  # 30
L / theta                        # [S] = [0 -1 3.366; 1 0 -3.366; 0 0 0]
S = (L[2, 1], L[1, 3], L[2, 3]) / theta   # (ω3, v1, v2) = (1, 3.366, −3.366)
q = (-S[3], S[2]) / S[1]         # the point the axis passes through: (3.366, 3.366)
exp(se2(S[1], S[2], S[3]) * theta)        # = D again

# The body-frame version of the same motion: T_bc = T_sb^-1 T_sc
inv(T_sb) * T_sc

# Cross-check in SE(3): lift both frames into the x̂_s–ŷ_s plane
T3_sb = SE3(Rot(z, 30 deg), (1, 2, 0))
T3_sc = SE3(Rot(z, 60 deg), (2, 1, 0))
expc = MatrixLog6(displacement(T3_sb, T3_sc))   # (0, 0, 0.5236, 1.7624, −1.7624, 0)
(S6, th) = AxisAng6(expc)        # S = (0, 0, 1, 3.366, −3.366, 0), θ = 0.5236
screw_params(S6)                 # q = (3.366, 3.366, 0), ŝ = ẑ, h = 0

# --- The book's printed answers, checked -------------------------------------
# The book rounds v1 = −v2 = 3.3660 and q to two decimals: 3.37.
assert theta ≈ pi/6
assert round(L / theta, 2) == [0, -1, 3.37; 1, 0, -3.37; 0, 0, 0]
assert round(S, 2) == (1, 3.37, -3.37)
assert round(q, 2) == (3.37, 3.37)
assert th ≈ pi/6
assert S6 ≈ (0, 0, 1, S[2], S[3], 0)
