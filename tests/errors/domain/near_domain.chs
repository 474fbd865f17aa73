# Within rounding of the domain (1e-12), asin, acos and sqrt clamp the
# argument with a note; beyond, a domain error giving the value.
acos(1 + 2e-16)
sqrt(-2e-16)
asin(-1 - 1e-15)
acos(1.001)
sqrt(-1e-6)
asin(-1.5)
