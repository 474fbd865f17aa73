# Symbolic axes and the logs of symbolic transforms (issue 21; §3.2.3 and
# §3.3.3). `given w : vec3` is the book's unit axis ω̂: exp([w] t) is
# Rodrigues' formula (3.51) in w's components w[1], w[2], w[3], printed as
# (3.52) with ω̂₃² written as 1 − ω̂₁² − ω̂₂² (the canonical form on the unit
# sphere, so that `==` decides). `given S : screw` gives Proposition 3.16.
# A note says once that the axis was assumed to be a unit vector; a note
# names the branch of each log. Each `assert` stops the script if it fails.

given w : vec3
given S : screw
given t, a, b, t1, t2 : scalar

# --- Rodrigues' formula with a symbolic axis (3.51, 3.52) -------------------------
R = exp([w] t)                   # the diagonal: cos t + (1 − cos t) w[i]²
Rot(w, t)                        # the same rotation
exp([w] (t1 + t2))               # one angle t1 + t2
assert R R^T == I
assert det(R) == 1
assert R * w == w                # the axis is fixed
assert exp([w] a) exp([w] b) == exp([w] (a + b))
assert Rot(w, t) == R
assert R.T == exp([w] (-t))
assert trace(R) == 1 + 2 cos(t)  # (3.54)

# --- no unit relation where no axis was assumed ---------------------------------
given p : vec3
dot(p, p)                        # p is no exponential's axis: not 1
assert dot(R * p, R * p) == dot(p, p)

# --- the screw exponential with a symbolic screw axis (Proposition 3.16) --------
T = exp([S] t)
assert exp([S] a) exp([S] b) == exp([S] (a + b))
assert T.R * S.w == S.w
assert T.R == exp([S.w] t)

# --- the closed form at numbers ------------------------------------------------
X = subs(subs(subs(subs(R, w[1], 0), w[2], 0.6), w[3], 0.8), t, 0.3)
assert X ~= exp([(0, 0.6, 0.8)] 0.3)   # Example 3.1's axis, rounded

# --- logs of symbolic transforms (§3.3.3.2) --------------------------------------
S1 = (0, 0, 1, 0, -2, 0.5)
log(exp([S1] t))                 # [S1] t, for t in (−π, π)
assert log(exp([S1] t)) == [S1] t
assert MatrixLog6(exp([S1] t)) == S1 t
log([Rotz(t), (1, 2, 3); 0, 0, 0, 1])   # v θ = θ G⁻¹(θ) p, with cot(θ/2) (3.94)
log([eye(3), (t, 2, 3); 0, 0, 0, 1])    # R = I: [0, p; 0, 0], no branch
log(exp([w] t))                  # [w] t, for t in (−π, π)
assert log(exp([w] t)) == [w] t
assert log(exp([S] t)) == [S] t

# --- bound later: the operations as typed, with the numbers -----------------------
w = (0, 0, 2)                    # not a unit vector: exp([w] t) = Rotz(2 t)
t = 0.3
R                                # R says it relied on ‖w‖ = 1 (§7)
assert R ~= Rotz(0.6)

# --- numbers that leave a closed form's branch (§7) ------------------------------
given u : scalar
L = log(Rotz(u))                 # [ẑ] u, for u in (−π, π)
u = 4
L                                # the principal log [ẑ] (4 − 2π), and a warning
assert L == log(Rotz(4))
