# Within rounding of the domain (1e-12), asin, acos and sqrt clamp an
# argument that is a float with no exact form (exp(0) is one) with a note;
# beyond, a domain error giving the value. An exact argument (typed, or
# with an exact form) is in or out exactly, except within four units in the
# last place of the edge (a computed float typed back): 1 + 2e-16 is taken
# as 1 with a note, 1 + 2e-15 is outside [−1, 1].
acos(exp(0) + 2e-16)
sqrt(exp(0) - 1 - 2e-16)
asin(-exp(0) - 1e-15)
acos(1.001)
sqrt(-1e-6)
asin(-1.5)
acos(1 + 2e-16)
sqrt(-2e-16)
acos(1 + 2e-15)
sqrt(-1e-15)
