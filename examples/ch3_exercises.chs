# Modern Robotics, chapter 3 exercises that are pure computation (§3.8).
# The answers in the comments were worked by hand and checked against the
# book's own Python library (modern_robotics 1.1.1).
#
# Exercise 3.5: exponential coordinates of R below. tr R = 0, so
#   θ = acos(−1/2) = 2π/3 and ω̂ = (1, −1, 1)/√3: ω̂θ = (1.2092, −1.2092, 1.2092).
# Exercise 3.6: R = Rot(x̂, π/2) Rot(ẑ, π) has trace −1, so θ = π; the
#   axis is ±(0, 1, −1)/√2 (both are logarithms; one is returned).
# Exercise 3.7(a): tr R = −1 again: θ = π about ω̂ = (1, 0, 1)/√2, i.e. the
#   entries of [ω̂]θ are ±π/√2 = ±2.2214. (θ = π is the only angle in
#   [0, 2π]: the axis may be either sign.)
# Exercise 3.28: ω_b = R_sbᵀ ω_s = (3, −1, −2).
# Exercise 3.26: the screw axis of q = (3, 0, 0), ŝ = ẑ, h = 2:
#   S = (ŝ, −ŝ × q + hŝ) = (0, 0, 1, 0, −3, 2).
# Exercise 3.27: V = (0, 2, 2, 4, 0, 0): h = ω·v/‖ω‖² = 0 (a pure
#   rotation), q = ω × v/‖ω‖² = (0, 1, −1), ŝ = (0, 1, 1)/√2.
# Exercise 3.31: a 1 kg block pulled at 10 N along ẑ_e: F_e = (0, 0, 0, 0, 0, 10),
#   and in the hand frame F_c = [Ad_T_ec]ᵀ F_e with T_ec = T_de⁻¹ T_db T_bc
#   (Example 3.2's transforms): F_c = (0, 800√2, 1300√2, 10, 0, 0)
#   = (0, 1131.3708, 1838.4776, 10, 0, 0), moments in N times the book's
#   length unit.

# --- 3.5 ---------------------------------------------------------------------
R = [0, -1, 0; 0, 0, -1; 1, 0, 0]
MatrixLog3(R)

# --- 3.6 ---------------------------------------------------------------------
R6 = Rotx(pi/2) * Rotz(pi)
(w6, th6) = AxisAng3(MatrixLog3(R6))

# --- 3.7(a) ------------------------------------------------------------------
R7 = [0, 0, 1; 0, -1, 0; 1, 0, 0]
log(R7)

# --- 3.28 --------------------------------------------------------------------
R_sb = [0, -1, 0; 0, 0, -1; 1, 0, 0]
w_s = (1, 2, 3)
w_b = R_sb.T * w_s

# --- 3.26 and 3.27 -----------------------------------------------------------
S = ScrewToAxis((3, 0, 0), (0, 0, 1), 2)
V = (0, 2, 2, 4, 0, 0)
(q, s_hat, h) = screw_params(V)

# --- 3.31 --------------------------------------------------------------------
T_db = [ 0,  0, -1,  250; 0, -1,  0, -150; -1,  0,  0,  200; 0,  0,  0,    1]
T_de = [ 0,  0, -1,  300; 0, -1,  0,  100; -1,  0,  0,  120; 0,  0,  0,    1]
T_bc = [ 0, -1/sqrt(2), -1/sqrt(2),  30
         0,  1/sqrt(2), -1/sqrt(2), -40
         1,  0,          0,          25
         0,  0,          0,           1]
F_e = wrench((0, 0, 0), (0, 0, 10))
T_ec = inv(T_de) * T_db * T_bc
F_c = Ad(T_ec).T * F_e
F_c / sqrt(2)                    # (0, 800, 1300, 7.0711, 0, 0)

# --- The expected values, checked ---------------------------------------------
assert MatrixLog3(R) ≈ (2 pi / 3) * (1, -1, 1) / sqrt(3)                # 3.5
# 3.6 and 3.7(a), θ = π: the axis the book's (3.58) gives (−ω̂ is as valid).
assert th6 ≈ pi
assert w6 ≈ (0, -1, 1) / sqrt(2)
assert log(R7) ≈ [(1, 0, 1) / sqrt(2)] pi
assert w_b == (3, -1, -2)                                              # 3.28
assert S == (0, 0, 1, 0, -3, 2)                                        # 3.26
assert (q, s_hat, h) ≈ ((0, 1, -1), (0, 1, 1) / sqrt(2), 0)            # 3.27
assert F_c ≈ (0, 800 sqrt(2), 1300 sqrt(2), 10, 0, 0)                  # 3.31
