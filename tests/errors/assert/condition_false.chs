# assert takes any bool; a scaled rotation is not in SO(3).
R = 2 * Rotz(1)
assert TestIfSO3(Rotz(1))
assert TestIfSO3(R)
