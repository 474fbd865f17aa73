# A student's first tries at chapter 3 (issue 35): the book's transform
# written as a block over symbols, and one unknown solved for.
#
# Covers:
#   - [R, p; 0, 1] with a given rotation R and vector p is in SE(3) (3.62):
#     inv, Ad, log, .R and .p treat it as a transform; its inverse is the
#     book's [Rᵀ, -Rᵀ p; 0, 1] (3.64);
#   - [Rotz(t), (1, 2, 3); 0, 1]: a symbolic rotation beside numbers;
#   - numbers bound later give the values typed first;
#   - solve(eq, x): Exercise 2.7's f, and the real roots of a quadratic;
#   - exact numbers stay exact where their floats cancel: the difference
#     of two 21-digit integers is 1, not the floats' 0 (session 28).

given R : SO3
given p : vec3
T = [R, p; 0, 1]                              # SE(3), not a 4×4 matrix
assert inv(T) == [R^T, -R^T p; 0, 1]          # (3.64)
T.R
Ad(T)

given t : scalar
U = [Rotz(t), (1, 2, 3); 0, 1]
inv(U)
assert inv(U) * U == eye(4)

# numbers bound later: as if typed first
V = inv(T)
R = Rotz(pi/6)
p = (1, 2, 3)
V
assert V == inv([Rotz(pi/6), (1, 2, 3); 0, 1])

# Exercise 2.7: 6 (1 − n) + n f = 6 for f (note: n ≠ 0)
given n, f, x : scalar
solve(6*(1 - n) + n*f == 6, f)
solve(x^2 - 5*x + 6 == 0, x)                  # (2, 3)
(r1, r2) = solve(x^2 == 2, x)                 # ∓√2
assert r2^2 == 2

123456789012345678901 - 123456789012345678900
(10^16 + 1) - 10^16
