# Within rounding of the domain (1e-12), asin, acos and sqrt clamp an
# argument that is a float with no exact form (exp(0) is one) with a note;
# beyond, a domain error giving the value. An exact argument (typed, or
# with an exact form) is in or out exactly: 1 + 2e-16 is outside [−1, 1].
acos(exp(0) + 2e-16)
sqrt(exp(0) - 1 - 2e-16)
asin(-exp(0) - 1e-15)
acos(1.001)
sqrt(-1e-6)
asin(-1.5)
acos(1 + 2e-16)
sqrt(-2e-16)
