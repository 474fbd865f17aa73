# The group identities of chapter 3 proven over symbols, and an angle
# solved for (issue 35, session 18).
#
# Covers:
#   - (T U)⁻¹ = U⁻¹ T⁻¹ (3.63-3.64) and Ad_{TU} = Ad_T Ad_U (Definition
#     3.20) for block transforms [R, p; 0, 1] with given rotations, and a
#     wrong version left undecided (never `true`);
#   - what a given kind says: Rᵀ = R⁻¹ (Prop. 3.3), R [w] Rᵀ = [R w] (3.30),
#     rotations keep inner products, Wᵀ = -W in so(3);
#   - a power of an exponential kept in a name, (e^X)ⁿ = e^{nX} (3.51);
#   - a block of symbolic blocks has the size of its blocks;
#   - solve for an angle: a cos x + b sin x = c, and Exercise 3.7(b)'s
#     rotation that takes one vector to another.

given R1, R2 : SO3
given p1, p2, w, u, v : vec3
given W : so3
T = [R1, p1; 0, 1];
U = [R2, p2; 0, 1];
inv(T U) == inv(U) inv(T)
Ad(T U) == Ad(T) Ad(U)
inv(T U) == inv(T) inv(U)

inv(R1) == R1^T
R1 [w] R1^T == [R1 * w]
dot(R1 u, R1 v) == dot(u, v)
W^T == -W
det(R1)

given x
X = [(1, 2, 3)] x;
E = exp(X);
E^2 == exp(2 X)
E^-1 == exp(-X)

[1, 0; 0, R1]

solve(sin(x) == 1/2, x)
solve(cos(x) + sin(x) == 1, x)
given th
th_b = solve(Rot((2, 2, 1)/3, th) (1, 0, 1) == (0, 1, 1), th)
th_b == -pi/2
