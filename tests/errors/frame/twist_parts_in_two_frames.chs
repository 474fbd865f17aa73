# LANGUAGE.md §4: naming a pair of 3-vectors as a twist, screw or wrench
# stacks them: V_s = (w_s, v_s) is the 6-vector twist (ω, v). Both parts
# must be in one frame.
w_s = (0, 0, 2)
v_s = (-2, -4, 0)
V_s = (w_s, v_s)              # the twist (0, 0, 2, -2, -4, 0) in {s}
v_b = (2.8, 4, 0)
V_s = (w_s, v_b)              # error: {s} and {b}
m_a = (0, 0, 1)
f_a = (0, 1, 0)
F_a = (m_a, f_a)              # the wrench (m, f) in {a}
