# `==` is exact: decimals as typed are exact (0.1 + 0.2 == 0.3), and so are
# square roots of exact numbers (sqrt(5)^2 == 5), but a root of a root has
# no exact form here, so sqrt(1 + sqrt(2))^2 is a float that misses
# 1 + √2 by rounding: ≈.
assert 0.1 + 0.2 == 0.3
assert sqrt(5)^2 == 5
assert sqrt(1 + sqrt(2))^2 ≈ 1 + sqrt(2)
assert sqrt(1 + sqrt(2))^2 == 1 + sqrt(2)
