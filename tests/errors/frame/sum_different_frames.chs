# adding twists in different frames
V_a = twist((0, 0, 1), (1, 0, 0))
V_b = twist((0, 0, 1), (0, 1, 0))
V_a + V_b
