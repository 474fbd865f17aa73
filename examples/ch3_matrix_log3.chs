# Modern Robotics, chapter 3, §3.2.3.3 "Matrix Logarithm of Rotations"
# (Eqs. 3.53–3.61, the algorithm, and Figure 3.12).
#
# Runs the book's algorithm on one rotation for each of its cases:
#   (i)   R = I: θ = 0 and ŵ undefined, so log R = 0;
#   (ii)  tr R = −1: θ = π, ŵ from (3.58), or (3.59) when r33 = −1, or (3.60)
#         when also r22 = −1;
#   (iii) otherwise θ = acos((tr R − 1)/2), [ŵ] = (R − R^T) / (2 sin θ).
# and shows that at θ = π both r and −r are logarithms (Figure 3.12: two
# antipodal points on the surface of the ball of radius π).
#
# The book prints no numbers in this section. Expected values (by hand from
# (3.58)–(3.61), checked with numpy):
#   (i)   MatrixLog3(I) = (0, 0, 0); AxisAng3 of it: θ = 0, ŵ undefined (zeros)
#   (ii)  R_sb of §3.3.1.2 = [0 0 1; 0 -1 0; 1 0 0]: (3.58) gives ŵ = (1, 0, 1)/√2,
#         ŵθ = (2.2214, 0, 2.2214)
#         Rot(ŷ, π) = diag(−1, 1, −1): r33 = −1, (3.59) gives ŵ = (0, 1, 0)
#         Rot((1,−1,0)/√2, π): r33 = −1, (3.59) gives ŵ = (−1, 1, 0)/√2,
#         ŵθ = (−2.2214, 2.2214, 0)
#         Rot(x̂, π) = diag(1, −1, −1): r33 = r22 = −1, (3.60) gives ŵ = (1, 0, 0)
#   (iii) Example 3.1's R: ŵθ = (0, 0.4534, 0.2618), θ = 30°
#         Rot((1,2,2)/3, 2 rad): tr R = 0.1677, ŵθ = (0.6667, 1.3333, 1.3333)
# At θ = π the sign of ŵ is a choice (both are correct); the values above are
# the signs the book's formulas (3.58)–(3.60) give.

# --- (i) R = I ---------------------------------------------------------------
MatrixLog3(eye(3))               # (0, 0, 0)
log(eye(3))                      # the zero so(3) matrix
AxisAng3(MatrixLog3(eye(3)))     # θ = 0 and no axis: zeros, with a note that ŵ is undefined

# --- (ii) tr R = −1, θ = π ---------------------------------------------------
R1 = [0, 0, 1; 0, -1, 0; 1, 0, 0]
trace(R1)                        # −1
MatrixLog3(R1)                   # π (1, 0, 1)/√2 = (2.2214, 0, 2.2214)
# the formula (3.58) by hand
(R1[1, 3], R1[2, 3], 1 + R1[3, 3]) / sqrt(2 * (1 + R1[3, 3]))   # (0.7071, 0, 0.7071)

MatrixLog3(Rot(y, pi))           # r33 = −1, so (3.59): π (0, 1, 0)
MatrixLog3(Rot((1, -1, 0) / sqrt(2), pi))   # (3.59): (−2.2214, 2.2214, 0)
MatrixLog3(Rot(x, pi))           # r33 = r22 = −1, so (3.60): π (1, 0, 0)

# Figure 3.12: on the surface of the ball, r and −r give the same rotation
r = MatrixLog3(R1)
norm(r)                          # π
MatrixExp3(r)                    # R1
MatrixExp3(-r)                   # R1 again

# --- (iii) the general case --------------------------------------------------
R2 = Rot((0, sqrt(3)/2, 0.5), 30 deg)   # Example 3.1
theta = acos((trace(R2) - 1) / 2)      # 0.5236 = 30°
(R2 - R2.T) / (2 sin(theta))           # [ŵ] by Eq. (3.61)
MatrixLog3(R2)                         # (0, 0.4534, 0.2618)

R3 = Rot((1, 2, 2) / 3, 2)
trace(R3)                        # 0.1677 = 1 + 2 cos 2
MatrixLog3(R3)                   # 2 (1, 2, 2)/3 = (0.6667, 1.3333, 1.3333)
(omghat, th) = AxisAng3(MatrixLog3(R3))   # ((0.3333, 0.6667, 0.6667), 2)
exp(log(R3))                     # R3 again

# --- Near the edges of the cases: no loss of accuracy -------------------------
MatrixLog3(Rot((1, 2, 2) / 3, 1e-7)) / 1e-7     # (0.3333, 0.6667, 0.6667)
norm(MatrixLog3(Rot((1, 2, 2) / 3, pi - 1e-7)))  # 3.1416 (= π − 1e-7)

# --- The expected values, checked ---------------------------------------------
assert MatrixLog3(eye(3)) == (0, 0, 0)
assert MatrixLog3(R1) ≈ pi * (1, 0, 1) / sqrt(2)                 # (3.58)
assert MatrixLog3(Rot(y, pi)) ≈ pi * (0, 1, 0)                   # (3.59)
assert MatrixLog3(Rot((1, -1, 0) / sqrt(2), pi)) ≈ pi * (-1, 1, 0) / sqrt(2)   # (3.59)
assert MatrixLog3(Rot(x, pi)) ≈ pi * (1, 0, 0)                   # (3.60)
assert MatrixExp3(-r) ≈ R1
assert theta ≈ pi/6
assert MatrixLog3(R2) ≈ (0, sqrt(3)/2, 0.5) * pi/6
assert MatrixLog3(R3) ≈ 2 * (1, 2, 2) / 3
assert th ≈ 2
