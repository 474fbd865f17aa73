# Modern Robotics, exercise 3.48 (§3.8): a rigid body {b} follows a screw
# motion, drawn at θ/4 steps, and the screw axis that brings it back.
#
# Test values: q = (0, 2, 0), ŝ = ẑ, h = 2, θ = π, and T with {b} at (2, 0, 0).
# S = (ŝ, −ŝ × q + hŝ) = (0, 0, 1, 2, 0, 2) (§3.3.2.2). Rotating by π about
# the axis through q takes (2, 0, 0) to (−2, 4, 0), and hθ = 2π lifts it:
#   T₁ = e^{[S]θ} T = [Rot(ẑ, π), (−2, 4, 2π)].
# Back to the origin: e^{[S₁]θ₁} T₁ = I, so [S₁]θ₁ = log(T₁⁻¹) with
# T₁⁻¹ = [Rot(ẑ, π), (−2, 4, −2π)]: a half turn (θ₁ = π) about the vertical
# axis through q₁ = (−1, 2, 0) (it takes the origin to (−2, 4, 0)) with
# pitch h₁ = −2π/π = −2 about +ẑ: S₁ = (0, 0, 1, 2, 1, −2), as the log
# gives it at θ₁ = π by (3.58) (§3.2.3.3; −ω̂ with h₁ = 2 is the same motion).

T_sb = [1, 0, 0, 2; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1]
S = ScrewToAxis((0, 2, 0), (0, 0, 1), 2)
theta = pi

# {b} at θ = 0, θ/4, θ/2, 3θ/4, θ: a list of five configurations.
path = [exp([S] k theta/4) T_sb for k in 0:4]
T_1 = path[5]

# The screw S₁ and distance θ₁ from T₁ back to the origin.
(S_1, theta_1) = AxisAng6(se3ToVec(log(untag(inv(T_1)))))
exp([S_1] * theta_1) * T_1

pic = draw(path, S, S_1)
save(pic, "docs/ch3_exercise48_screw_motion.svg")
