# Closed forms of chapter 3's exponentials over a symbol (issue 35): the
# matrix exponential of a linear system (§3.2.1, eq. 3.41-3.48), the book's
# exercises on x' = A x, and the block transform's algebra (3.62-3.64).
#
# Covers:
#   - exp(A t) of an exact 2×2 with real distinct, repeated and complex
#     eigenvalues (Exercises 33 and 34 of the seed), checked by its own
#     differential equation d/dt e^{At} = A e^{At} and by e^{A·0} = I;
#   - products of exponentials folded, exp(X)^n as exp(n X);
#   - [R, p; 0, 1]: inv, TransInv, products, .R, and R Rᵀ = I (Prop. 3.3);
#   - a value that relied on a unit axis says so when numbers break it.

given t, x1, x2

# Exercise 34: x' = A x with A = [0, 1; -2, -3]
A = [0, 1; -2, -3]
E = exp(A t)
diff(E, t) == A E
subs(E, t, 0) == eye(2)

# Exercise 33: the solution x(t) = e^{At} x0, and complex eigenvalues 2 ± i
exp([-2, 1; 0, -1] t) (x1, x2)
exp([2, -1; 1, 2] t)
exp([1, 1; 0, 1] t)

exp(t) exp(-t)
given x
exp([(0, 0, 1)] x)^4 == exp([(0, 0, 1)] 4 x)

# The transform as a block (3.62) and its inverse (3.64)
given R : SO3
given p : vec3
T = [R, p; 0, 1]
TransInv(T)
inv(T) T
T.R
R R^T
inv(Ad(T)) == Ad(inv(T))

# An assumption stated, then broken by numbers bound later (§7)
given u : vec3
Ru = exp([u] x)
d = dot(u, u) == 1
u = (1, 1, 0)
d
