# Modern Robotics, chapter 3, §3.4 "Wrenches" (Eqs. 3.97–3.102,
# Proposition 3.17), worked on the hand-and-apple example.
#
# SOURCE NOTE: the hand/apple example is Example 3.28 of the published
#   edition (Cambridge University Press, 2017), §3.4, Figure 3.21. The seed
#   text of the book used by this project is an earlier preprint whose §3.4
#   has no numerical example, so the data below are the published edition's
#   (verified here by hand and with numpy), not the seed's.
#
# A robot hand holds an apple; a six-axis force-torque sensor sits between
# the hand and the robot's last link, with frame {f}. {h} is at the hand's
# center of mass, {a} at the apple's. Hand 0.5 kg, apple 0.1 kg, g = 10 m/s²,
# L1 = 10 cm ({h} is L1 ahead of {f} along x̂_f), L2 = 15 cm ({a} another L2).
# Gravity on the hand in {h}: f_h = (0, −5, 0) N; on the apple in {a}
# (ẑ_a points down): f_a = (0, 0, 1) N.
#
# Computes:
#   F_f = [Ad_T_hf]^T F_h + [Ad_T_af]^T F_a   (Prop. 3.17, Eq. 3.101)
#   the apple's share again from m = r × f (3.97), directly in {f};
#   F_h back from F_f with Eq. (3.102): F_h = [Ad_T_fh]^T F_f;
#   power is frame-independent (3.98): V_h^T F_h = V_f^T F_f, for the wrist
#   turning about ẑ_f at 1 rad/s.
#
# Book's printed answers (published edition, Example 3.28):
#   F_h = (0, 0, 0, 0, −5, 0),  F_a = (0, 0, 0, 0, 0, 1)
#   T_hf = [1 0 0 −0.1; 0 1 0 0; 0 0 1 0; 0 0 0 1]
#   T_af = [1 0 0 −0.25; 0 0 1 0; 0 −1 0 0; 0 0 0 1]
#   F_f = (0, 0, −0.75, 0, −6, 0)
# The hand and apple shares are (0, 0, −0.5, 0, −5, 0) and (0, 0, −0.25, 0, −1, 0).
# The power lines are this script's own check (not in the book):
#   V_h = (0, 0, 1, 0, 0.1, 0); power −0.5 W (hand), −0.25 W (apple), −0.75 W total.
#
# A wrench changes frame with the TRANSPOSED adjoint of the opposite
# transform: Ad(T_hf).T * F_h is F_f. Writing Ad(T_fh) * F_h (as for a twist)
# is a frame error in chasles, whose help cites Prop. 3.17.

T_hf = [1, 0, 0, -0.1
        0, 1, 0,  0
        0, 0, 1,  0
        0, 0, 0,  1]
T_af = [1,  0, 0, -0.25
        0,  0, 1,  0
        0, -1, 0,  0
        0,  0, 0,  1]
F_h = wrench((0, 0, 0), (0, -5, 0))   # the hand's weight, at its center of mass
F_a = wrench((0, 0, 0), (0, 0, 1))    # the apple's weight, at its center of mass

# --- The wrench felt at the sensor ------------------------------------------
Ad(T_hf).T * F_h                 # (0, 0, −0.5, 0, −5, 0)
Ad(T_af).T * F_a                 # (0, 0, −0.25, 0, −1, 0)
F_f = Ad(T_hf).T * F_h + Ad(T_af).T * F_a   # (0, 0, −0.75, 0, −6, 0)

# The apple's share from first principles: m = r × f, all in {f}
T_fa = inv(T_af)
r_f = T_fa.p                     # the apple's center in {f}: (0.25, 0, 0)
f_f = T_fa.R * F_a.f             # its weight in {f}: (0, −1, 0)
wrench(cross(r_f, f_f), f_f)     # (0, 0, −0.25, 0, −1, 0), as above

# Eq. (3.102): back from {f} to {h}
Ad(inv(T_hf)).T * (Ad(T_hf).T * F_h)   # = F_h

# --- Power does not depend on the frame (3.98) -------------------------------
V_f = twist((0, 0, 1), (0, 0, 0))     # the wrist turns about ẑ_f at 1 rad/s
V_h = Ad(T_hf) * V_f             # (0, 0, 1, 0, 0.1, 0)
V_a = Ad(T_af) * V_f
dot(V_h, F_h)                    # −0.5 W: power of gravity on the hand
dot(V_a, F_a)                    # −0.25 W: on the apple
dot(V_f, F_f)                    # −0.75 W: the sum, computed in {f}
V_f.T * F_f                      # −0.75 W again, as the book writes it: V_fᵀ F_f

# --- The book's printed answers, checked -------------------------------------
assert Ad(T_hf).T * F_h ≈ (0, 0, -0.5, 0, -5, 0)
assert Ad(T_af).T * F_a ≈ (0, 0, -0.25, 0, -1, 0)
assert F_f ≈ (0, 0, -0.75, 0, -6, 0)
assert wrench(cross(r_f, f_f), f_f) ≈ Ad(T_af).T * F_a
assert V_h ≈ (0, 0, 1, 0, 0.1, 0)
assert dot(V_h, F_h) ≈ -0.5
assert dot(V_a, F_a) ≈ -0.25
assert dot(V_f, F_f) ≈ dot(V_h, F_h) + dot(V_a, F_a)                   # (3.98)
