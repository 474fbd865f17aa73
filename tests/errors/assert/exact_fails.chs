# `==` is exact: 0.1 + 0.2 is not 0.3 in floating point, but it is ≈ 0.3.
assert 0.1 + 0.2 ≈ 0.3
assert 0.1 + 0.2 == 0.3
