# twists change frame with the adjoint (3.84), wrenches with its transpose
# (Prop. 3.17): the wrong operator for either is the same kind of error
T_ab = Trans((1, 0, 0))
V_a = twist((0, 0, 1), (1, 0, 0))
F_b = wrench((0, 0, 1), (1, 0, 0))
Ad(T_ab).T * V_a
Ad(T_ab) * F_b
