# LANGUAGE.md §4: a transform moves points (3.65); a free vector — an
# angular velocity ω (typed w), a linear velocity v, a force f, a moment m,
# an axis ω̂, ŝ — only rotates. The trial's input gave (1, 5, −2), the
# translation added to an angular velocity; the answer is R_sb ω_b = (1, 3, −2).
T_sb = SE3(Rotx(-pi/2), (0, 2, 0))
ω_b = (1, 2, 3)
ω_s = T_sb ω_b                # error: use T_sb.R (R_sb)
ω_s = T_sb.R ω_b              # (1, 3, -2)
f_b = (0, 0, 1)
T_sb * f_b                    # a force: error
V_b = (0, 0, 1, 1, 0, 0)
T_sb * V_b                    # a twist: error naming Ad(T_sb)
given u_b : free              # a name whose letters do not say it
u_b = (1, 0, 0)
T_sb * u_b                    # error
p_b = (1, 2, 3)
T_sb * p_b                    # a point: (1, 5, -2)
