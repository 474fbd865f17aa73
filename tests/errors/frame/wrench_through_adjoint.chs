# wrenches transform with the transpose of the adjoint (Prop. 3.17)
T_ab = Trans((1, 0, 0))
F_b = wrench((0, 0, 1), (1, 0, 0))
Ad(T_ab) * F_b
