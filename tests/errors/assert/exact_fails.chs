# `==` is exact: decimals as typed are exact (0.1 + 0.2 == 0.3), square
# roots of exact numbers are exact (sqrt(5)^2 == 5), and exp and log of
# numbers keep how they were made (exp(log(5)) == 5 is proven). The matrix
# exponential of numbers is a float with no recipe: the length of its
# first column misses 1 by rounding, so it is ≈ 1 but not == 1.
assert 0.1 + 0.2 == 0.3
assert sqrt(5)^2 == 5
assert exp(log(5)) == 5
x = exp([(0.1, 0.2, 0.3)])
y = x[1,1]^2 + x[2,1]^2 + x[3,1]^2
assert y ≈ 1
assert y == 1
