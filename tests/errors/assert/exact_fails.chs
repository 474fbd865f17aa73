# `==` is exact: decimals as typed are exact (0.1 + 0.2 == 0.3), and so are
# square roots of exact numbers (sqrt(5)^2 == 5), but exp and log of numbers
# keep no exact form nor recipe, so exp(log(5)) is a float that misses 5 by
# rounding: ≈.
assert 0.1 + 0.2 == 0.3
assert sqrt(5)^2 == 5
assert exp(log(5)) ≈ 5
assert exp(log(5)) == 5
