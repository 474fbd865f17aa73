# Modern Robotics, chapter 3, §3.3.1.2, Example 3.2 (Figure 3.15):
# a robot arm on a mobile base picks up an object seen by a ceiling camera.
#
# Frames: {a} fixed, {b} the wheeled platform, {c} the end-effector,
# {d} the camera, {e} the object. Given T_db, T_de (camera), T_bc (arm joint
# angles) and T_ad (known in advance), find the object in the hand frame:
#   T_ab T_bc T_ce = T_ad T_de,  T_ab = T_ad T_db
#   T_ce = (T_ad T_db T_bc)^-1 T_ad T_de
#
# Book's printed answers:
#   T_ad T_de          = [1 0 0 280; 0 1 0 -50; 0 0 1 0; 0 0 0 1]
#   T_ad T_db T_bc     = [0 -1/√2 -1/√2 230; 0 1/√2 -1/√2 160; 1 0 0 75; 0 0 0 1]
#   (T_ad T_db T_bc)^-1 = [0 0 1 -75; -1/√2 1/√2 0 70/√2; -1/√2 -1/√2 0 390/√2; 0 0 0 1]
#   T_ce = [0 0 1 -75; -1/√2 1/√2 0 -260/√2; -1/√2 -1/√2 0 130/√2; 0 0 0 1]
#
# BOOK SLIP: the last entry of T_ce, (T_ce)_34, is 160/√2 = 113.1371, not
#   130/√2 = 91.92. Row 3 of (T_ad T_db T_bc)^-1 is (−1/√2, −1/√2, 0, 390/√2);
#   times the column (280, −50, 0, 1) of T_ad T_de it gives
#   (−280 + 50 + 390)/√2 = 160/√2. Checked with numpy, and by the other chain
#   T_ce = T_bc^-1 T_db^-1 T_de, which gives the same 160/√2. All other entries
#   (−75, −260/√2 = −183.8478, and the intermediate products) are right.
# The seed's text of T_bc lost its first row in extraction ("0 \\ -1/√2 …");
#   from the product the book prints, the first row is (0, −1/√2, −1/√2, 30).

T_db = [ 0,  0, -1,  250
         0, -1,  0, -150
        -1,  0,  0,  200
         0,  0,  0,    1]
T_de = [ 0,  0, -1,  300
         0, -1,  0,  100
        -1,  0,  0,  120
         0,  0,  0,    1]
T_ad = [ 0,  0, -1,  400
         0, -1,  0,   50
        -1,  0,  0,  300
         0,  0,  0,    1]
T_bc = [ 0, -1/sqrt(2), -1/sqrt(2),  30
         0,  1/sqrt(2), -1/sqrt(2), -40
         1,  0,          0,          25
         0,  0,          0,           1]

T_ae = T_ad * T_de               # [1 0 0 280; 0 1 0 -50; 0 0 1 0; 0 0 0 1]
T_ab = T_ad * T_db               # [1 0 0 200; 0 1 0 200; 0 0 1 50; 0 0 0 1]
T_ac = T_ad * T_db * T_bc        # [0 -0.7071 -0.7071 230; 0 0.7071 -0.7071 160; 1 0 0 75; 0 0 0 1]
T_ca = inv(T_ac)                 # [0 0 1 -75; -0.7071 0.7071 0 49.4975; -0.7071 -0.7071 0 275.7716; ...]
sqrt(2) * T_ca[2, 4]             # 70  (the book's 70/√2)
sqrt(2) * T_ca[3, 4]             # 390 (the book's 390/√2)

T_ce = inv(T_ad * T_db * T_bc) * T_ad * T_de   # the book's formula
sqrt(2) * T_ce[2, 4]             # -260 (the book's −260/√2)
sqrt(2) * T_ce[3, 4]             # 160  (the book prints 130/√2: a slip)

# The same T_ce by a shorter chain that never goes through {a}:
inv(T_bc) * inv(T_db) * T_de

# --- The book's printed answers, checked -------------------------------------
assert T_ae ≈ [1, 0, 0, 280; 0, 1, 0, -50; 0, 0, 1, 0; 0, 0, 0, 1]
assert T_ac ≈ [0, -1/sqrt(2), -1/sqrt(2), 230; 0, 1/sqrt(2), -1/sqrt(2), 160; 1, 0, 0, 75; 0, 0, 0, 1]
assert T_ca ≈ [0, 0, 1, -75; -1/sqrt(2), 1/sqrt(2), 0, 70/sqrt(2); -1/sqrt(2), -1/sqrt(2), 0, 390/sqrt(2); 0, 0, 0, 1]
# BOOK SLIP: the book prints 130/√2 for the last entry of T_ce; it is 160/√2.
assert T_ce ≈ [0, 0, 1, -75; -1/sqrt(2), 1/sqrt(2), 0, -260/sqrt(2); -1/sqrt(2), -1/sqrt(2), 0, 160/sqrt(2); 0, 0, 0, 1]
assert inv(T_bc) * inv(T_db) * T_de ≈ T_ce
