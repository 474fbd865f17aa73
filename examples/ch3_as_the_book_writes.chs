# Modern Robotics, chapter 3, in the book's own notation: Rodrigues'
# formula (3.51), the closed form of e^{[S]θ} in Proposition 3.16 (3.89),
# a product of exponentials, and the power invariance V_bᵀ F_b = V_aᵀ F_a
# (3.98). Products are written side by side, sin θ without parentheses,
# transposes as superscripts, I takes the size it needs, and a lone 0 in a
# block matrix is the zero block that fits.
#
# Expected values (numpy, from the book's formulas):
#   Figure 3.11: ω̂ = (0, 0.866, 0.5), θ = 30°:
#     R = [0.866 -0.25 0.433; 0.25 0.9665 0.058; -0.433 0.058 0.8995]
#   S = (0, 0, 1, 0, -2, 0) (a screw about ẑ through (2, 0, 0)), θ = π/2:
#     e^{[S]θ} = [0 -1 0 2; 1 0 0 -2; 0 0 1 0; 0 0 0 1]
#   2R arm, L1 = L2 = 1, θ1 = 30°, θ2 = 45°:
#     p = (cos θ1 + cos(θ1 + θ2), sin θ1 + sin(θ1 + θ2)) = (1.1248, 1.4659)
#   T_sb = [Rotz(30°), (1, 2, 0); 0, 1], V_b = (0, 0, 1, 1, 0, 0),
#   F_s = (0, 0, 2, 1, 3, 0): V_bᵀ F_b = V_sᵀ F_s = 2 + 2.866 − 1.5 = 3.366

# A rotation pasted from numpy, row by row, and from MATLAB.
R_sb = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]
R_sb = [0 -1 0; 1 0 0; 0 0 1]
R_sbᵀ R_sb
R_sb^{-1} - R_sb^T

# Rodrigues' formula (3.51): e^{[ω̂]θ} = I + sin θ [ω̂] + (1 − cos θ)[ω̂]²,
# for the rotation of Figure 3.11.
w = (0, 0.866, 0.5)
θ = 30°
R = I + sin θ [w] + (1 - cos θ)[w]^2
e^([w] θ)
Rot(w, θ)

# Proposition 3.16 (3.89): e^{[S]θ} = [e^{[ω]θ}, (Iθ + (1 − cos θ)[ω]
# + (θ − sin θ)[ω]²) v; 0, 1].
S = (0, 0, 1, 0, -2, 0)
ω = S.w
v = S.v
θ = pi/2
G = I θ + (1 - cos θ)[ω] + (θ - sin θ)[ω]^2
[e^([ω] θ), G v; 0, 1]
e^([S] θ)

# A product of exponentials: a planar 2R arm with unit links, its screw
# axes in {s} and its home configuration M.
S1 = (0, 0, 1, 0, 0, 0)
S2 = (0, 0, 1, 0, -1, 0)
M = [I, (2, 0, 0); 0, 1]
θ1 = 30°
θ2 = 45°
T = exp([S1] θ1) exp([S2] θ2) M
(cos θ1 + cos(θ1 + θ2), sin θ1 + sin(θ1 + θ2))

# Power is the same in every frame (3.98): V_s = [Ad_T_sb] V_b and
# F_b = [Ad_T_sb]ᵀ F_s.
T_sb = [Rotz(30°), (1, 2, 0); 0, 1]
V_b = (0, 0, 1, 1, 0, 0)
F_s = (0, 0, 2, 1, 3, 0)
V_s = Ad(T_sb) V_b
F_b = Ad(T_sb)^T F_s
P_b = V_b^T F_b
P_s = V_s^T F_s
P_b - P_s

# The expected values, checked (written as the book writes them too).
assert R_sbᵀ R_sb == I
assert round(R, 4) == [0.866, -0.25, 0.433; 0.25, 0.9665, 0.058; -0.433, 0.058, 0.8995]
assert round(e^([w] 30°), 3) == round(R, 3)       # w is the book's rounded ω̂
assert [e^([ω] θ), G v; 0, 1] ≈ [0, -1, 0, 2; 1, 0, 0, -2; 0, 0, 1, 0; 0, 0, 0, 1]
assert e^([S] θ) ≈ [e^([ω] θ), G v; 0, 1]
assert T.p ≈ (cos θ1 + cos(θ1 + θ2), sin θ1 + sin(θ1 + θ2), 0)
assert round(T.p, 4) == (1.1248, 1.4659, 0)
assert P_b ≈ P_s
assert P_s ≈ 2 + (2 + sqrt(3)/2) - 1.5          # 3.366
