//! Help for the words of the language that are not functions (LANGUAGE.md
//! §11: every keyword, unit and command has help): keywords (`given`,
//! `derive`, `mech`, `assert`, `explain`), units (`deg`, `°`, `rad`), constants (`pi`,
//! `e`, `inf`, `I`, `true`), `ans`, and the operators a student asks about
//! (`==`, `≈`, `^T`, `^-1`).

/// (the names one entry answers to, its text), in help order.
pub const KEYWORDS: &[(&[&str], &str)] = &[
    (
        &["given"],
        "given NAME, ... : TYPE    symbols with a type and frames but no numbers (§7)
  given T_ab, T_bc : SE3    → T_ab * T_bc checks frames and prints T_ab T_bc : SE(3) {a}←{c}
  given theta : scalar      a symbolic angle; given theta(t) : scalar a function of time
  given u_b : free          u_b holds a free vector (only rotates; T * u_b is an error),
                            given c : point a point; they stay so when bound to numbers
  types: scalar vec3 vec6 SO3 SE3 SO2 SE2 so3 se3 twist screw wrench
         (also spelled SO(3), SE(3), so(3), se(3)); binding numbers later makes them numeric",
    ),
    (
        &["derive"],
        "derive T_ce    find a chain of known transforms from {c} to {e} (using inverses),
  print the chain it used (T_ce = inv(T_bc) * inv(T_db) * T_de) and bind its value;
  no chain: an error listing the frames reachable from each end",
    ),
    (
        &["mech", "mechanism"],
        "mech < links N; joints ...; planar|spatial|spherical >    a mechanism (chapter 2)
  mech < links 4; joints 4R; planar >       Grübler's formula (2.4), step by step
  mech < legs 6 UPS; spatial >              a parallel mechanism
  dof(m) gives the number; :help mechanisms lists the joints",
    ),
    (
        &["assert"],
        "assert COND    stop the script (exit 1, an `assert` error) when COND is false,
  showing both sides: assert T_ce ≈ T_ce_book, assert det(R) == 1;
  passing asserts print nothing; `chasles check` checks the sides' kinds and frames",
    ),
    (
        &["explain", "steps"],
        "explain EXPR    the book's steps for the value of EXPR, with this case's numbers (§14):
  each step names its equation, proposition or section and the quantity it gives;
  the last step is the value itself. --json adds \"steps\": [{ref, name, text, value}];
  --latex and notebooks render them as LaTeX. It covers:
  log(R), MatrixLog3   §3.2.3.3: tr R (3.54), the case (R = I; tr R = −1 with (3.58)/(3.59)/(3.60);
                       general), θ, ω̂ (3.61), [ω̂]θ; near θ = 0 or π the formula used instead and why
  log(T), MatrixLog6   §3.3.3.2: the case (R = I: pure translation), G⁻¹(θ) (3.94), v (3.93)
  exp, MatrixExp3/6    Rodrigues (3.51) term by term; Prop. 3.16: G(θ) (3.88), p (3.89), (3.90)
  inv, TransInv        (3.64);  Ad(T): [p]R (Def. 3.6);  Ad(T_ab).T * F_a: (3.99)
  ScrewToAxis, screw, screw_params    q, ŝ, h (§3.3.2.2)
  euler_zyx, euler_zxz, rpy, quat, cayley    the branch and gimbal lock
  T_ad T_db T_bc ...   a frame chain: which subscript cancels in each product, in order
  mech < ... >, dof    Grübler's formula (2.4) with N, J, Σfᵢ, m
  exp([S] θ)           with a symbol θ: q, ŝ, h of the axis and the closed forms (Prop. 3.16)
  The REPL's preview shows the value only.",
    ),
    (
        &["for", "in", "range", "ranges", "list", "lists", ":"],
        "0:4   0:pi/8:pi    ranges as in MATLAB, the end included (within rounding)
  [k^2 for k in 0:4]                    a list; [f(a, b) for a in r1, b in r2] a grid, a outermost
  xs[2]   (a, b, c) = xs   len sum min max    index from 1, destructure (§12)
  a function reaches the items only through a comprehension: [f(x) for x in xs]",
    ),
    (
        &["==", "equal"],
        "a == b    true when a and b are exactly equal (same shape, every entry);
  symbolic sides are compared without numbers. For rounded values use a ≈ b",
    ),
    (
        &["≈", "~=", "approx"],
        "a ≈ b (typed a ~= b)    true when every entry agrees within 1e-9 relative
  (1e-9 · max(1, largest entry)): the way to check a result against the book",
    ),
    (
        &["deg", "°", "degrees"],
        "x deg, x°    degrees to radians (angles are radians): Rotz(30 deg), cos 45°
  the unit binds to the number before it: 30 deg = 30 · π/180; deg2rad(x) on vectors",
    ),
    (
        &["rad", "radians"],
        "x rad    radians, the unit angles already have: pi/6 rad = pi/6
  rad2deg(x) converts radians to degrees (also on vectors and matrices)",
    ),
    (
        &["pi", "π"],
        "pi, π    3.14159…; 2 pi and pi/2 as the book writes them",
    ),
    (
        &["e"],
        "e    2.71828… (when no variable e is bound); exp(x) is e^x",
    ),
    (
        &["inf", "Inf", "∞"],
        "inf    infinity, e.g. the pitch of a pure translation: screw(q, s, inf)",
    ),
    (
        &["I", "identity"],
        "I    the identity of the size its context needs: I + W, T - I; eye(n) when no context gives the size",
    ),
    (
        &["true", "false"],
        "true, false    the two bools; comparisons (==, ≈) give them",
    ),
    (
        &["ans"],
        "ans    the value of the last expression statement (not of an assignment):
  Rotz(pi/2) * (1, 0, 0) then ans[2]",
    ),
    (
        &["^T", "T", "ᵀ"],
        "X^T, X.T, Xᵀ    the transpose; for R_ab it is R_ba (Prop. 3.1), frames swapped",
    ),
    (
        &["^-1", "inverse"],
        "X^-1, X^{-1}, inv(X)    the inverse; R^-1 = R^T (Prop. 3.1), T^-1 by (3.64) (Prop. 3.10)",
    ),
    (
        &["[w]", "bracket", "[]"],
        "[x]    the book's bracket: [w] ∈ so(3) for a 3-vector (3.30), [V] ∈ se(3) for a 6-vector (3.72)",
    ),
];

/// The help text for `word`, if it is a keyword, unit, constant or operator.
pub fn keyword(word: &str) -> Option<&'static str> {
    KEYWORDS
        .iter()
        .find(|(names, _)| names.contains(&word))
        .map(|(_, text)| *text)
}

/// Every word that has keyword help, for completion.
pub fn words() -> impl Iterator<Item = &'static str> {
    KEYWORDS.iter().flat_map(|(names, _)| names.iter().copied())
}
