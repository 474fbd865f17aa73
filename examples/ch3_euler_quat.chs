# Modern Robotics, chapter 3, §3.2.1.3 "Other Representations of
# Orientations" (the book defers them to its Appendix B, which the seed text
# omits; the conventions here are LANGUAGE.md §8's):
#   rot_zyx(α, β, γ) = Rot(ẑ, α) Rot(ŷ, β) Rot(x̂, γ), euler_zyx(R) → (α, β, γ),
#     β ∈ [−π/2, π/2];
#   rot_zxz(α, β, γ) = Rot(ẑ, α) Rot(x̂, β) Rot(ẑ, γ), euler_zxz(R) → (α, β, γ),
#     β ∈ [0, π];
#   rot_rpy(roll, pitch, yaw) = Rot(ẑ, yaw) Rot(ŷ, pitch) Rot(x̂, roll),
#     rpy(R) → (roll, pitch, yaw);
#   quat(R) → (w, x, y, z) = (cos θ/2, ŵ sin θ/2), w ≥ 0; rot_quat(q);
#     quat_mul(q, p), the Hamilton product: rot_quat(quat_mul(q, p)) = R_q R_p;
#   cayley(R) → r = ŵ tan(θ/2); rot_cayley(r).
#
# Applied to the rotation of Example 3.1, R = Rot(ŵ, 30°) with
# ŵ = (0, √3/2, 1/2). Expected values (numpy):
#   euler_zyx(R) = (0.2810, 0.4478, 0.0644) rad = (16.10°, 25.66°, 3.69°)
#   rpy(R)       = (0.0644, 0.4478, 0.2810)   (the same angles, reversed)
#   euler_zxz(R) = (1.7040, 0.4521, −1.4376) rad = (97.63°, 25.91°, −82.37°)
#   quat(R)      = (0.9659, 0, 0.2241, 0.1294)
#   cayley(R)    = (0, 0.2321, 0.1340)
#   quat_mul(quat(R), quat(Rot(ẑ, 90°))) = (0.5915, 0.1585, 0.1585, 0.7745)
#   rot_zyx(10°, 20°, 30°) = [0.9254 0.018 0.3785; 0.1632 0.8826 -0.441; -0.342 0.4698 0.8138]
# Every representation maps back to the same R.

R = Rot((0, sqrt(3)/2, 0.5), 30 deg)

# --- ZYX Euler angles and roll-pitch-yaw --------------------------------------
(alpha, beta, gamma) = euler_zyx(R)
(alpha, beta, gamma) / (1 deg)  # in degrees: (16.10, 25.66, 3.69)
rot_zyx(alpha, beta, gamma)     # R again
Rotz(alpha) * Roty(beta) * Rotx(gamma)   # the definition
(roll, pitch, yaw) = rpy(R)
rot_rpy(roll, pitch, yaw)       # R again
rot_zyx(10 deg, 20 deg, 30 deg)

# --- ZXZ Euler angles ----------------------------------------------------------
(a, b, c) = euler_zxz(R)
rot_zxz(a, b, c)                # R again

# --- Unit quaternion -----------------------------------------------------------
q = quat(R)                     # (cos 15°, ŵ sin 15°)
(cos(15 deg), 0, sqrt(3)/2 * sin(15 deg), 0.5 sin(15 deg))   # the same, by hand
rot_quat(q)                     # R again
p = quat(Rot(z, 90 deg))        # (0.7071, 0, 0, 0.7071)
quat_mul(q, p)                  # (0.5915, 0.1585, 0.1585, 0.7745)
rot_quat(quat_mul(q, p))        # = R Rot(ẑ, 90°) ...
R * Rot(z, 90 deg)              # ... this

# --- Cayley-Rodrigues parameters ----------------------------------------------
r = cayley(R)                   # ŵ tan 15° = (0, 0.2321, 0.134)
rot_cayley(r)                   # R again

# --- The expected values, checked ---------------------------------------------
assert round((alpha, beta, gamma), 4) == (0.281, 0.4478, 0.0644)
assert round((roll, pitch, yaw), 4) == (0.0644, 0.4478, 0.281)
assert round((a, b, c), 4) == (1.704, 0.4521, -1.4376)
assert round(q, 4) == (0.9659, 0, 0.2241, 0.1294)
assert q ≈ (cos(15 deg), 0, sqrt(3)/2 * sin(15 deg), 0.5 sin(15 deg))
assert round(r, 4) == (0, 0.2321, 0.134)
assert round(quat_mul(q, p), 4) == (0.5915, 0.1585, 0.1585, 0.7745)
assert round(rot_zyx(10 deg, 20 deg, 30 deg), 4) == [0.9254, 0.018, 0.3785; 0.1632, 0.8826, -0.441; -0.342, 0.4698, 0.8138]
assert rot_zyx(alpha, beta, gamma) ≈ R
assert rot_rpy(roll, pitch, yaw) ≈ R
assert rot_zxz(a, b, c) ≈ R
assert rot_quat(q) ≈ R
assert rot_cayley(r) ≈ R
assert rot_quat(quat_mul(q, p)) ≈ R * Rot(z, 90 deg)
