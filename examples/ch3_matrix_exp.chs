# Modern Robotics, chapter 3, §3.2.3.1 "Essential Results from Linear
# Differential Equations" (Eqs. 3.39–3.48, Props. 3.7 and 3.8) and the
# Cayley-Hamilton step of §3.2.3.2 that leads to Rodrigues' formula.
#
# The book has no numerical example here; the system below is chosen for
# the purpose: ẋ = A x with A = [0 1; −2 −3], x(0) = (1, 0). A = P D P^-1
# with D = diag(−1, −2), P = [1 1; −1 −2].
#
# Computes:
#   x(t) = e^{At} x(0) at t = 1 (3.47), against the closed form
#     x1(t) = 2e^−t − e^−2t, x2(t) = −2e^−t + 2e^−2t;
#   Prop. 3.7 (ii) e^{At} = P e^{Dt} P^-1, (iv) (e^A)^-1 = e^{−A},
#     (iii) e^A e^B = e^{A+B} only when AB = BA;
#   Prop. 3.8 (Cayley-Hamilton) for [ŵ]: [ŵ]^3 + [ŵ] = 0, the step to (3.51).
# Expected values (numpy):
#   e^{A} = [0.6004 0.2325; −0.4651 −0.0972],  x(1) = (0.6004, −0.4651)
#   (e^A)^-1 = e^{−A} = [−1.9525 −4.6708; 9.3415 12.0598]
#   e^{[X]} e^{[Y]} = [0.8776 0 0.4794; 0.2298 0.8776 −0.4207; −0.4207 0.4794 0.7702]
#   e^{[X]+[Y]}     = [0.8801 0.1199 0.4594; 0.1199 0.8801 −0.4594; −0.4594 0.4594 0.7602]
#   for X = (0.5, 0, 0), Y = (0, 0.5, 0), whose brackets do not commute.

A = [0, 1; -2, -3]
x0 = (1, 0)
t = 1
exp(A * t)                       # e^{At}
exp(A * t) * x0                  # x(1) = (0.6004, −0.4651)
(2 exp(-t) - exp(-2 t), -2 exp(-t) + 2 exp(-2 t))   # the closed form

# Prop. 3.7 (ii): e^{At} = P e^{Dt} P^-1
P = [1, 1; -1, -2]
D = [-1, 0; 0, -2]
P * D * inv(P)                   # = A
P * exp(D * t) * inv(P)          # = e^{At}
[exp(-t), 0; 0, exp(-2 t)]       # e^{Dt} of a diagonal D (3.46)

# Prop. 3.7 (iv): (e^A)^-1 = e^{−A}
inv(exp(A))
exp(-A)

# Prop. 3.7 (iii) needs AB = BA: rotations about different axes do not commute
X = (0.5, 0, 0)
Y = (0, 0.5, 0)
[X] * [Y] - [Y] * [X]            # not zero
exp([X]) * exp([Y])
exp([X] + [Y])                   # a different matrix
exp(A) * exp(2 * A)              # A commutes with 2A ...
exp(3 * A)                       # ... so this is the same

# Prop. 3.8 for [ŵ]: p(s) = s^3 + s, so [ŵ]^3 = −[ŵ]
w_hat = (0, sqrt(3)/2, 0.5)
[w_hat]^3 + [w_hat]              # zero

# --- The expected values, checked ---------------------------------------------
assert round(exp(A), 4) == [0.6004, 0.2325; -0.4651, -0.0972]
assert exp(A * t) * x0 ≈ (2 exp(-t) - exp(-2 t), -2 exp(-t) + 2 exp(-2 t))
assert P * D * inv(P) ≈ A
assert P * exp(D * t) * inv(P) ≈ exp(A * t)
assert inv(exp(A)) ≈ exp(-A)
assert round(exp(-A), 4) == [-1.9525, -4.6708; 9.3415, 12.0598]
assert round(exp([X]) * exp([Y]), 4) == [0.8776, 0, 0.4794; 0.2298, 0.8776, -0.4207; -0.4207, 0.4794, 0.7702]
assert round(exp([X] + [Y]), 4) == [0.8801, 0.1199, 0.4594; 0.1199, 0.8801, -0.4594; -0.4594, 0.4594, 0.7602]
assert exp(A) * exp(2 * A) ≈ exp(3 * A)
assert [w_hat]^3 + [w_hat] ≈ zeros(3, 3)
