# Modern Robotics, chapter 3, §3.2.3.2 "Exponential Coordinates of
# Rotations", Example 3.1 (Figure 3.11), with Proposition 3.9 (Rodrigues).
#
# {b} is obtained by rotating {s} about the unit axis ŵ = (0, 0.866, 0.5)
# by θ = 30° = 0.524 rad.
#
# Computes:
#   R = e^{[ŵ]θ} = I + sin θ [ŵ] + (1 − cos θ) [ŵ]^2, three ways
#   (exp, Rodrigues' formula, Rot);
#   the exponential coordinates ŵθ, and back with MatrixLog3 / AxisAng3;
#   R' = e^{−[ŵ]θ} R (rotate back about the fixed-frame axis) and
#   R'' = R e^{−[ŵ]θ} (rotate back about the body-frame axis);
#   the book's 3-decimal R, accepted with a projection warning.
#
# Book's printed answers:
#   sin θ = 0.5, 1 − cos θ = 0.134
#   R = [0.866 -0.250 0.433; 0.250 0.967 0.058; -0.433 0.058 0.900]
#   ŵθ = (0, 0.453, 0.262)
#   R' = I;   R'' = R e^{−[ŵ]θ} ≠ I
#
# BOOK SLIP: R'' = R e^{−[ŵ]θ} is I, not ≠ I. The axis ŵ of a rotation is
#   unchanged by that rotation (R ŵ = ŵ), so ŵ has the same coordinates in
#   {b} as in {s}, and rotating about it in the body frame undoes R exactly as
#   in the fixed frame (e^{[ŵ]θ} and e^{−[ŵ]θ} commute). The point the book
#   wants (body-frame and fixed-frame rotations differ) needs an axis other
#   than ŵ; the last lines show one: about ẑ the two results differ.
# Rounding: the book's 0.866 is √3/2 rounded; this script uses √3/2 so that ŵ
#   is exactly unit. With it r22 = 0.9665 and r33 = 0.8995, which the book
#   rounds to 0.967 and 0.900.

w_hat = (0, sqrt(3)/2, 0.5)      # the book's (0, 0.866, 0.5)
norm(w_hat)                      # 1
theta = 30 deg                   # 0.5236 rad
sin(theta)                       # 0.5
1 - cos(theta)                   # 0.134
[w_hat]                          # [0 -0.5 0.866; 0.5 0 0; -0.866 0 0]

R_sb = exp([w_hat] theta)
eye(3) + sin(theta) * [w_hat] + (1 - cos(theta)) * [w_hat]^2   # Rodrigues (3.51)
Rot(w_hat, theta)                # the same rotation, Rot(ŵ, θ)
MatrixExp3(w_hat * theta)        # the same, from the exponential coordinates

# Exponential coordinates of {b}
expc = w_hat * theta             # ŵθ = (0, 0.4534, 0.2618)
MatrixLog3(R_sb)                 # the same, from R
log(R_sb)                        # [ŵ]θ ∈ so(3)
(omghat, th) = AxisAng3(expc)    # ŵ = (0, 0.866, 0.5), θ = 0.5236

# Rotating {b} back by −θ about ŵ
R_sb' = exp(-[w_hat] theta) * R_sb     # about ŵ in the fixed frame: I
R_sb'' = R_sb * exp(-[w_hat] theta)    # about ŵ in the body frame: also I (see slip)

# Fixed-frame and body-frame rotations do differ for an axis not fixed by R:
R_sb * Rot(z, -30 deg)           # about ẑ_b: [0.875 0.2165 0.433; -0.2667 0.962 0.058; -0.404 -0.1663 0.8995]
Rot(z, -30 deg) * R_sb           # about ẑ_s: [0.875 0.2667 0.404; -0.2165 0.962 -0.1663; -0.433 0.058 0.8995]

# The book's rounded R (3 decimals) is 0.0013 from SO(3): it is projected to
# the nearest rotation with a warning, and its log is ŵθ to 3 decimals.
R_book = [ 0.866, -0.250, 0.433
           0.250,  0.967, 0.058
          -0.433,  0.058, 0.900]
DistanceToSO3(R_book)            # 0.0013
MatrixLog3(R_book)               # (0, 0.4533, 0.2617), with a projection warning

# --- The book's printed answers, checked -------------------------------------
assert sin(theta) ≈ 0.5
assert round(1 - cos(theta), 3) == 0.134
assert round(R_sb, 3) == [0.866, -0.250, 0.433; 0.250, 0.967, 0.058; -0.433, 0.058, 0.900]
assert round(expc, 3) == (0, 0.453, 0.262)
assert MatrixLog3(R_sb) ≈ expc
assert R_sb' ≈ eye(3)
# BOOK SLIP: the book says R'' = R e^{−[ŵ]θ} ≠ I; it is I (R leaves ŵ fixed).
assert R_sb'' ≈ eye(3)
