# Modern Robotics, chapter 3, §3.3.2.1, Example 3.3 (Figure 3.17):
# the twist of a car with a single front wheel, driving in the plane.
#
# ẑ_b points into the page, ẑ_s out of it. The car turns about the point r
# at w = 2 rad/s about an axis out of the page:
#   r_s = (2, −1, 0), r_b = (2, −1.4, 0), ω_s = (0, 0, 2), ω_b = (0, 0, −2),
#   T_sb = [−1 0 0 4; 0 1 0 0.4; 0 0 −1 0; 0 0 0 1].
#
# Computes v_s = ω_s × (−r_s) = r_s × ω_s and v_b = r_b × ω_b, the twists
# V_s and V_b, and confirms them with V_s = [Ad_T_sb] V_b as the book asks
# ("To confirm these results, try calculating V_s = [Ad_T_sb] V_b"), and
# V_b = [Ad_T_bs] V_s. Also checks the data: r_s = T_sb r_b, ω_s = R_sb ω_b.
#
# Book's printed answers:
#   v_s = (−2, −4, 0),  v_b = (2.8, 4, 0)
#   V_s = (0, 0, 2, −2, −4, 0),  V_b = (0, 0, −2, 2.8, 4, 0)
# (All consistent; no slip found.)

T_sb = [-1, 0,  0, 4
         0, 1,  0, 0.4
         0, 0, -1, 0
         0, 0,  0, 1]
r_s = (2, -1, 0)
r_b = (2, -1.4, 0)
w_s = (0, 0, 2)
w_b = (0, 0, -2)

# the data agree with T_sb
T_sb * r_b                       # = r_s (r is a point)
T_sb.R * w_b                     # = w_s (w is a free vector: rotate only)

# linear velocities of the body points at the frame origins
v_s = cross(w_s, -r_s)           # (−2, −4, 0)
cross(r_s, w_s)                  # the same
v_b = cross(r_b, w_b)            # (2.8, 4, 0)

V_s = twist(w_s, v_s)            # (0, 0, 2, −2, −4, 0)
V_b = twist(w_b, v_b)            # (0, 0, −2, 2.8, 4, 0)

# the book's check
Ad(T_sb)
Ad(T_sb) * V_b                   # = V_s
Ad(inv(T_sb)) * V_s              # = V_b

# --- The book's printed answers, checked -------------------------------------
assert v_s == (-2, -4, 0)
assert v_b ≈ (2.8, 4, 0)
assert V_s ≈ (0, 0, 2, -2, -4, 0)
assert V_b ≈ (0, 0, -2, 2.8, 4, 0)
assert Ad(T_sb) * V_b ≈ V_s
assert Ad(inv(T_sb)) * V_s ≈ V_b
