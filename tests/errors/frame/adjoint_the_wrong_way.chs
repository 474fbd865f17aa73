# LANGUAGE.md §6: Ad(T_sb) maps twists in {b} to {s} (3.83). A twist in {s}
# goes to {b} by the inverse: the help names Ad(inv(T_sb)) = Ad(T_bs).
T_sb = SE3(Rotz(pi/2), (1, 0, 0))
V_s = (0, 0, 1, 0, -1, 0)
V_b = Ad(T_sb) V_s            # error: V_s is in {s} already
V_b = Ad(inv(T_sb)) V_s
R_sb = T_sb.R
ω_s = (0, 0, 1)
ω_b = R_sb ω_s                # error: the inverse, R_bs
ω_b = R_sb.T ω_s
