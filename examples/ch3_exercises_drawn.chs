# Modern Robotics, the exercises of §3.8 that ask for a drawing. Each
# picture is printed, so it is written as NAME.svg (into --draw-dir when
# given) and the printed line says where.
#
# Exercise 3.1(h): {a} has x̂_a = (0, 0, 1) and ŷ_a = (−1, 0, 0) in {s}, so
#   ẑ_a = x̂_a × ŷ_a = (0, −1, 0) and R_sa = [x̂_a, ŷ_a, ẑ_a]. tr R_sa = 0, so
#   θ = acos(−1/2) = 2π/3 = 2.0944 and ω̂ = (1, −1, 1)/√3 = (0.5774, −0.5774, 0.5774).
#   The drawing: {s}, the frame {a} it rotates to, and ω̂.
# Exercise 3.1(i): ω̂θ = (1, 2, 0): θ = √5 = 2.2361, ω̂ = (1, 2, 0)/√5; the
#   frame R = e^{[ω̂]θ} drawn with its rotation axis ω̂.
# Exercise 3.26: q = (3, 0, 0), ŝ = ẑ, h = 2: S = (0, 0, 1, 0, −3, 2), the
#   vertical line through (3, 0, 0), pitch 2.
# Exercise 3.27: V = (0, 2, 2, 4, 0, 0): ŝ = (0, 1, 1)/√2, h = ω·v/‖ω‖² = 0,
#   q = ω × v/‖ω‖² = (0, 1, −1): a pure rotation about that line.

# --- 3.1(h) ------------------------------------------------------------------
R_sa = [0, -1, 0; 0, 0, -1; 1, 0, 0]
(w_hat, theta) = AxisAng3(so3ToVec(MatrixLog3(R_sa)))
ex3_1h = draw(R_sa, arrow(w_hat))

# --- 3.1(i) ------------------------------------------------------------------
R = MatrixExp3((1, 2, 0))
(w_hat2, theta2) = AxisAng3((1, 2, 0))
ex3_1i = draw(R, arrow(w_hat2))

# --- 3.26 --------------------------------------------------------------------
S = ScrewToAxis((3, 0, 0), (0, 0, 1), 2)
ex3_26 = draw(S)

# --- 3.27 --------------------------------------------------------------------
V = (0, 2, 2, 4, 0, 0)
(q, s_hat, h) = screw_params(V)
ex3_27 = draw(V)
