# Modern Robotics, chapter 3: the frame algebra of the chapter with symbols
# instead of numbers (LANGUAGE.md §3 `given`, §6 `derive`, §7 symbols).
# Check it without any numbers with:  chasles check ch3_symbolic_chain.chs
#
# Covers:
#   - Example 3.2 (§3.3.1.2): from T_ab T_bc T_ce = T_ad T_de and
#     T_ab = T_ad T_db, the book's T_ce = (T_ad T_db T_bc)^-1 T_ad T_de;
#     `derive T_ce` finds a chain from {c} to {e} by itself;
#   - subscript cancellation for rotations and transforms (§3.2.1.2, §3.3.1.2):
#     R_ab R_bc = R_ac, T_ab p_b = p_a, T_de = T_ed^-1;
#   - fixed-frame vs body-frame displacement (3.66): exp([S_s]θ) T_sb, T_sb exp([S_b]θ);
#   - twists and wrenches (Prop. 3.15, Prop. 3.17): V_s = [Ad_T_sb] V_b,
#     F_b = [Ad_T_ab]^T F_a, and the power V^T F (3.98);
#   - then the numbers of Example 3.2 are bound to the same names, and the
#     book's formula evaluates to T_ce; so does T_ce as `derive` bound it
#     over the symbols (binding numbers later makes them numeric, §7).
#
# Expected results (frames are the point here):
#   T_ad T_db                → T_ab-like, SE(3) {a}←{b}
#   inv(T_ad T_db T_bc) T_ad T_de → SE(3) {c}←{e}, simplifying to
#                              inv(T_bc) inv(T_db) T_de (T_ad^-1 T_ad cancels)
#   derive T_ce              → the chain T_ce = inv(T_bc) * inv(T_db) * T_de
#   inv(T_ab) * T_ab         → I
#   T_ab * T_bc * T_cd       → T_ab T_bc T_cd : SE(3) {a}←{d}
#   Ad(T_sb) * V_b           → twist {s};  Ad(T_ab).T * F_a → wrench {b}
# With the numbers of Example 3.2, T_ce = [0 0 1 -75; -0.7071 0.7071 0 -183.8478;
#   -0.7071 -0.7071 0 113.1371; 0 0 0 1] (the book's last entry, 130/√2, is a
#   slip for 160/√2 = 113.1371: see ch3_ex3_2_camera.chs).

# --- Example 3.2 without numbers --------------------------------------------------
given T_ad, T_db, T_bc, T_de : SE3
T_ad * T_db                                  # T_ab: {a}←{b}
T_ad * T_db * T_bc                           # T_ac: {a}←{c}
T_ad * T_de                                  # T_ae: {a}←{e}
inv(T_ad * T_db * T_bc) * T_ad * T_de        # the book's T_ce: {c}←{e}
derive T_ce                                  # chasles finds a chain itself
derive T_cc                                  # the empty chain: I of {c} to itself

# --- Subscript cancellation ---------------------------------------------------------
given R_ab, R_bc : SO3
given p_b : vec3
R_ab * R_bc                                  # {a}←{c}
R_ab * p_b                                   # p_a
R_bc.T                                       # R_cb = R_bc^T
given T_ab, T_cd : SE3
inv(T_ab) * T_ab                             # I
T_ab * T_bc * T_cd                           # T_ab T_bc T_cd : {a}←{d}
T_ab * p_b                                   # p_a (a point)

# --- Displacing a frame in {s} or in {b} ------------------------------------------
given T_sb : SE3
given S_s, S_b : screw
given theta : scalar
exp([S_s] theta) * T_sb                      # fixed frame: {s}←{b moved}
T_sb * exp([S_b] theta)                      # body frame:  {s}←{b moved}

# --- Twists and wrenches --------------------------------------------------------
given V_b : twist
given F_a : wrench
V_s = Ad(T_sb) * V_b                         # {s}
Ad(inv(T_sb)) * V_s                          # back to {b}
F_b = Ad(T_ab).T * F_a                       # Prop. 3.17: {b}
Ad(inv(T_ab)).T * F_b                        # back to {a}
dot(V_b, F_b)                                # power, in {b}
F_s = Ad(inv(T_sb)).T * F_b                  # the wrench in {s}
V_s.T * F_s                                  # the power in {s}: V_b.T F_b, the same (3.98)

# --- Example 3.2 with its numbers -----------------------------------------------
T_db = [0, 0, -1, 250; 0, -1, 0, -150; -1, 0, 0, 200; 0, 0, 0, 1]
T_de = [0, 0, -1, 300; 0, -1, 0, 100; -1, 0, 0, 120; 0, 0, 0, 1]
T_ad = [0, 0, -1, 400; 0, -1, 0, 50; -1, 0, 0, 300; 0, 0, 0, 1]
T_bc = [0, -1/sqrt(2), -1/sqrt(2), 30; 0, 1/sqrt(2), -1/sqrt(2), -40; 1, 0, 0, 25; 0, 0, 0, 1]
inv(T_ad * T_db * T_bc) * T_ad * T_de        # T_ce, now numeric
T_ce                                         # bound by derive over symbols; the numbers count now

# --- A matrix written over a symbol (§3.2.1.2: Rot(ẑ, φ)) ------------------------
given phi : scalar
Rot_phi = [cos(phi), -sin(phi), 0; sin(phi), cos(phi), 0; 0, 0, 1]
phi = 30 deg
Rot_phi                                      # now Rotz(30°): [0.866 -0.5 0; 0.5 0.866 0; 0 0 1], SO(3)

# --- The expected values, checked ---------------------------------------------
# BOOK SLIP: the book prints 130/√2 for the last entry of T_ce; it is 160/√2.
assert T_ce ≈ [0, 0, 1, -75; -1/sqrt(2), 1/sqrt(2), 0, -260/sqrt(2); -1/sqrt(2), -1/sqrt(2), 0, 160/sqrt(2); 0, 0, 0, 1]
assert inv(T_ad * T_db * T_bc) * T_ad * T_de ≈ T_ce
assert Rot_phi ≈ Rotz(30 deg)
