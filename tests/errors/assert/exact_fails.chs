# `==` is exact: decimals as typed are exact (0.1 + 0.2 == 0.3), but √5 has
# no exact form here, so sqrt(5)^2 is a float that misses 5 by rounding: ≈.
assert 0.1 + 0.2 == 0.3
assert sqrt(5)^2 ≈ 5
assert sqrt(5)^2 == 5
