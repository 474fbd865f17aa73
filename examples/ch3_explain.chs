# Modern Robotics, chapter 3: `explain` (LANGUAGE.md §14) on every worked
# example of the chapter and the in-text computations of §3.2–§3.4 and the
# software of §3.6. Each `explain` prints the book's steps with this case's
# numbers: the equation, proposition or section, the intermediate quantity,
# and last the value itself.

# --- Example 3.1 (§3.2.3.2): Rodrigues' formula (3.51) term by term -------
w_hat = (0, 0.866, 0.5)
theta = 30 deg
explain exp([w_hat] theta)
explain Rot(w_hat, theta)        # the same by Rot(ω̂, θ) = e^{[ω̂]θ}
R_sb = Rot(w_hat, theta)
# ...and back: the log of R_sb (§3.2.3.3, case (iii)) gives ω̂ and θ again
explain MatrixLog3(R_sb)

# --- §3.6 software: MatrixLog3 and MatrixLog6 of the book's docstrings -----
explain MatrixLog3([0, 0, 1; 1, 0, 0; 0, 1, 0])
explain MatrixLog6([1, 0, 0, 0; 0, 0, -1, 0; 0, 1, 0, 3; 0, 0, 0, 1])
explain MatrixExp6((1.5708, 0, 0, 0, 2.3562, 2.3562))

# --- Example 3.2 (§3.3.1.2): the object in the gripper frame, a frame chain
T_db = [0, 0, -1, 250; 0, -1, 0, -150; -1, 0, 0, 200; 0, 0, 0, 1]
T_de = [0, 0, -1, 300; 0, -1, 0, 100; -1, 0, 0, 120; 0, 0, 0, 1]
T_ad = [0, 0, -1, 400; 0, -1, 0, 50; -1, 0, 0, 300; 0, 0, 0, 1]
T_bc = [0, -1/sqrt(2), -1/sqrt(2), 30; 0, 1/sqrt(2), -1/sqrt(2), -40; 1, 0, 0, 25; 0, 0, 0, 1]
explain inv(T_ad T_db T_bc) T_ad T_de
# the inverse by (3.64)
explain inv(T_bc)

# --- Example 3.3 (§3.3.2.1): the car's twist, V_s = [Ad_T_sb] V_b ---------
T_sb = [-1, 0, 0, 4; 0, 1, 0, 0.4; 0, 0, -1, 0; 0, 0, 0, 1]
V_b = (0, 0, -2, 2.8, 4, 0)
explain Ad(T_sb)
explain Ad(T_sb) V_b
# the screw axis of the same motion: q, ŝ, h (§3.3.2.2)
explain screw_params((0, 0, 2, -2, -4, 0))

# --- Example 3.4 (§3.3.3.2): the SE(2) logarithm -------------------------
T_sc = [cos(60 deg), -sin(60 deg), 2; sin(60 deg), cos(60 deg), 1; 0, 0, 1]
T_sb2 = SE2(30 deg, 1, 2)
explain log(displacement(T_sb2, T_sc))

# --- Example 3.5 (§3.4): the hand and the apple, F_f = [Ad_T_hf]ᵀ F_h (3.99)
T_hf = [1, 0, 0, -0.1; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1]
F_h = wrench((0, 0, 0), (0, -5, 0))
explain Ad(T_hf).T * F_h

# --- §3.3.2.2: a screw axis from q, ŝ and h ------------------------------
explain ScrewToAxis((3, 0, 0), (0, 0, 1), 2)

# --- Proposition 3.16 with a symbol: the revolute joint through q = (0, 2, 0)
given t : scalar
S = (0, 0, 1, 2, 0, 0)
explain exp([S] t)
# the joint's transform times a home configuration M: the product as written
M = [1, 0, 0, 0; 0, 1, 0, 3; 0, 0, 1, 0; 0, 0, 0, 1]
explain exp([S] (pi/2)) M
# closed forms of the inverse (3.64) and the adjoint (Def. 3.6) over a symbol
T_t = RpToTrans(Rotz(t), [1; 2; 0])
explain inv(T_t)
explain Ad(T_t)
# and its logarithm, on the branch the note names (§3.3.3.2)
explain MatrixLog6(T_t)

# --- §3.3.2: twists from Ṫ, T⁻¹Ṫ = [V_b] (3.72) and ṪT⁻¹ = [V_s] (3.73) --
given q(t) : scalar
T = RpToTrans(Rotz(q), [2 * cos(q); 2 * sin(q); 0])
explain inv(T) diff(T, t)
explain diff(T, t) inv(T)
# and diff itself, the rule at each node (§3.2.2)
explain diff(sin(q)^2 + 3 q, t)

# --- Chapter 2, Grübler's formula (2.4), in the same step format --------
explain mech < links 4; joints R R R R; planar >
