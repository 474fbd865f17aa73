# `explain` at the hard cases of chapter 3's algorithms (LANGUAGE.md §14):
# θ = 0, θ = π with each of the book's sub-cases (3.58), (3.59), (3.60),
# θ → π and θ → 0 (where chasles says which formula it used instead of the
# book's and why), a pure translation, gimbal lock, and the orientation
# conversions.

# --- θ = 0: case (i), R = I -----------------------------------------------
explain log(eye(3))
explain MatrixLog6(Trans((3, 0, 4)))     # R = I: a pure translation, θ = ‖p‖
explain MatrixExp6((0, 0, 0, 3, 0, 4))   # ω = 0: (3.90)

# --- θ = π: case (ii), each sub-case --------------------------------------
explain log(Rotz(pi))                    # 1 + r₃₃ ≠ 0: (3.58)
explain log(Roty(pi))                    # 1 + r₃₃ = 0: (3.59)
explain log(Rotx(pi))                    # 1 + r₃₃ = 1 + r₂₂ = 0: (3.60)
explain log([Rotx(pi), (1, 2, 3); 0, 1]) # §3.3.3.2 case (ii): G⁻¹(π)

# --- θ → π and θ → 0 ------------------------------------------------------
explain MatrixLog3(Rot((1, 2, 2)/3, pi - 1e-7))
explain MatrixLog3(Rot((1, 2, 2)/3, 1e-9))
explain MatrixLog6([Rot((1, 2, 2)/3, 1e-6), (1, 2, 3); 0, 1])

# --- gimbal lock and the other representations ----------------------------
explain euler_zyx(rot_zyx(0.3, 0.4, 0.2))
explain euler_zyx(rot_zyx(0.3, pi/2, 0.2))
explain rpy(rot_rpy(0.1, -pi/2, 0.5))
explain euler_zxz(rot_zxz(0.3, 0, 0.2))
explain quat(Rot((1, 2, 2)/3, 2.5))
explain cayley(Rot((1, 2, 2)/3, 1))
