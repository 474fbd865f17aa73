//! `solve` for an angle (issue 35, trial 18's t35; Exercise 3.7(b)): x
//! inside a sine and cosine, a cos kx + b sin kx = c (tan x = c among
//! them). Every root is checked here by an independent computation (the
//! equation evaluated in f64 at the printed number), the exact ones also
//! by an exact `==`, and the list is checked complete against a count of
//! the roots in (−π, π] made by hand.

mod common;
use common::{error, json, numbers};
use std::f64::consts::PI;

/// The roots `solve(eq, x)` prints, and its note.
fn roots(eq: &str) -> (Vec<f64>, String) {
    let j = json(&format!("given x\nsolve({eq}, x)"));
    let last = j.last().expect("a line");
    let note = last["warnings"][0]["message"]
        .as_str()
        .unwrap_or_default()
        .to_string();
    (numbers(&last["value"]), note)
}

/// `eq` has exactly `count` roots, each with f(root) = 0 to 1e-12, in
/// (−π, π], increasing, and the note on the general solution.
fn check(eq: &str, f: fn(f64) -> f64, count: usize, period: &str) -> Vec<f64> {
    let (rs, note) = roots(eq);
    assert_eq!(rs.len(), count, "{eq}: {rs:?}");
    for r in &rs {
        assert!(f(*r).abs() < 1e-12, "{eq}: f({r}) = {}", f(*r));
        assert!(*r > -PI && *r <= PI + 1e-15, "{eq}: {r} outside (−π, π]");
    }
    assert!(rs.windows(2).all(|w| w[0] < w[1]), "{eq}: {rs:?}");
    assert_eq!(
        note,
        format!("the roots in (−π, π]; every x = root + {period} (n an integer) solves it too")
    );
    rs
}

/// The brief's examples: sin x = 1/2, cos x = 0, tan x = 1, exactly.
#[test]
fn the_book_angles_are_exact() {
    let r = check("sin(x) == 1/2", |x| x.sin() - 0.5, 2, "2πn");
    assert!((r[0] - PI / 6.0).abs() < 1e-15 && (r[1] - 5.0 * PI / 6.0).abs() < 1e-15);
    check("cos(x) == 0", f64::cos, 2, "2πn");
    let r = check("tan(x) == 1", |x| x.tan() - 1.0, 2, "2πn");
    assert!((r[0] + 3.0 * PI / 4.0).abs() < 1e-15 && (r[1] - PI / 4.0).abs() < 1e-15);
    // exact: the roots are the book's angles, not floats near them
    let j = json(
        "given x\n(p, q) = solve(sin(x) == 1/2, x)\n(p == pi/6, q == 5*pi/6)\n\
         (u, v) = solve(tan(x) == 1, x)\n(u == -3*pi/4, v == pi/4)\n\
         (c, d) = solve(cos(x) == 0, x)\n(c == -pi/2, d == pi/2)\n\
         solve(cos(x) == -1, x) == pi\nsolve(cos(x) + sin(x) == sqrt(2), x) == pi/4",
    );
    for i in [1, 3, 5] {
        assert_eq!(j[i]["value"], serde_json::json!([true, true]), "{:?}", j[i]);
    }
    assert_eq!(j[6]["value"], true, "{:?}", j[6]);
    assert_eq!(j[7]["value"], true, "{:?}", j[7]);
}

/// Roots with no closed form are their numbers; a sum of sine and cosine,
/// a multiple angle, tan² and 1/cos all solve, each root checked here.
#[test]
fn every_root_checks_in_an_independent_evaluation() {
    check("sin(x) == 1/3", |x| x.sin() - 1.0 / 3.0, 2, "2πn");
    check("sin(x) == -1/3", |x| x.sin() + 1.0 / 3.0, 2, "2πn");
    check("cos(x) == 0.3", |x| x.cos() - 0.3, 2, "2πn");
    check(
        "3*cos(x) + 4*sin(x) == 2",
        |x| 3.0 * x.cos() + 4.0 * x.sin() - 2.0,
        2,
        "2πn",
    );
    check(
        "cos(x) + sin(x) == 1",
        |x| x.cos() + x.sin() - 1.0,
        2,
        "2πn",
    );
    check("sin(x) == pi/4", |x| x.sin() - PI / 4.0, 2, "2πn");
    check("tan(x) == 2", |x| x.tan() - 2.0, 2, "2πn");
    check("tan(x) == -sqrt(3)", |x| x.tan() + 3f64.sqrt(), 2, "2πn");
    check("tan(x) == 0", f64::tan, 2, "2πn");
    check("1/cos(x) == 2", |x| 1.0 / x.cos() - 2.0, 2, "2πn");
    check("sin(2*x) == 1/2", |x| (2.0 * x).sin() - 0.5, 4, "πn");
    check(
        "sin(x)*cos(x) == 1/4",
        |x| x.sin() * x.cos() - 0.25,
        4,
        "πn",
    );
    check("tan(x)^2 == 3", |x| x.tan().powi(2) - 3.0, 4, "πn");
    check("sin(3*x) == 1", |x| (3.0 * x).sin() - 1.0, 3, "2πn/3");
    // the period in lowest terms: 2πn/4 is πn/2
    check("sin(4*x) == 1/2", |x| (4.0 * x).sin() - 0.5, 8, "πn/2");
    // a touching root is one root: c = √(a² + b²)
    let r = check("cos(x) == 1", |x| x.cos() - 1.0, 1, "2πn");
    assert_eq!(r, vec![0.0]);
    // π itself, never −π
    let r = check("sin(x) == 0", f64::sin, 2, "2πn");
    assert!(r[0] == 0.0 && (r[1] - PI).abs() < 1e-15, "{r:?}");
}

/// Beyond reach, a refusal naming why (never a wrong root).
#[test]
fn refusals_name_why() {
    let cases = [
        ("sin(x) == 2", "no real x solves it: |c| > √(a² + b²)"),
        ("cos(x) + sin(x) == 2", "a² + b² = 2"),
        ("a*sin(x) == 1", "not exact numbers"),
        (
            "sin(x) == x",
            "occurs both alone and inside a sine or cosine",
        ),
        ("sin(x)^2 + sin(x) == 0", "more than one multiple of x"),
        ("sin(x^2) == 0", "inside sin(…)"),
        ("sin(40*x) == 0", "up to 12 x"),
    ];
    for (eq, why) in cases {
        let e = error(&format!("given x, a\nsolve({eq}, x)"));
        assert!(e.contains(why), "{eq}: {e}");
        assert!(e.contains("cannot solve for x"), "{eq}: {e}");
    }
}

/// Exercise 3.7(b): v₂ = e^{[ω̂]θ} v₁ with ω̂ = (2/3, 2/3, 1/3), v₁ = (1, 0,
/// 1), v₂ = (0, 1, 1), θ in [−π, π]: each entry alone has two roots, and
/// the vector equation keeps the one they share, θ = −π/2 (checked here
/// by Rodrigues' formula in f64, and exactly by `==`).
#[test]
fn a_vector_equation_keeps_the_roots_of_every_entry() {
    let src = "given θ\nw = (2/3, 2/3, 1/3)\nv1 = (1, 0, 1)\nv2 = (0, 1, 1)\n\
               t = solve(Rot(w, θ) v1 == v2, θ)\nt == -pi/2\nsolve(exp([w] θ) v1 - v2, θ)\n\
               solve((Rot(w, θ) v1)[1] == 0, θ)";
    let j = json(src);
    let n = j.len();
    let t = j[n - 4]["value"].as_f64().unwrap();
    assert_eq!(j[n - 3]["value"], true, "{:?}", j[n - 3]);
    assert_eq!(j[n - 2]["value"].as_f64(), Some(t));
    // entry 1 alone has a second root, which the vector equation drops
    assert_eq!(numbers(&j[n - 1]["value"]).len(), 2);
    // independent: Rodrigues' formula v cos θ + (ω × v) sin θ + ω (ω·v)(1 − cos θ)
    let (w, v1, v2) = (
        [2.0 / 3.0, 2.0 / 3.0, 1.0 / 3.0],
        [1.0, 0.0, 1.0],
        [0.0, 1.0, 1.0],
    );
    let cross = [
        w[1] * v1[2] - w[2] * v1[1],
        w[2] * v1[0] - w[0] * v1[2],
        w[0] * v1[1] - w[1] * v1[0],
    ];
    let dot: f64 = (0..3).map(|i| w[i] * v1[i]).sum();
    for i in 0..3 {
        let rv = v1[i] * t.cos() + cross[i] * t.sin() + w[i] * dot * (1.0 - t.cos());
        assert!((rv - v2[i]).abs() < 1e-12, "entry {i}: {rv}");
    }
    // no common root: refused naming why
    let e = error("given θ\nw = (2/3, 2/3, 1/3)\nsolve(Rot(w, θ) (1, 0, 1) == (0, 0, 1), θ)");
    assert!(e.contains("no real θ solves every entry"), "{e}");
    let e = error("given x\nsolve((1, 2, 3) == x, x)");
    assert!(e.contains("these sides are 3x1 and 1x1"), "{e}");
}

/// A root of the canonical form where the equation as typed is undefined
/// is no root: `(x − 1)²/(x − 1)` is `x − 1` once cancelled, but at 1 it
/// is a division by zero (as `subs` says there); solve gave 1.
#[test]
fn a_root_the_quotient_cancelled_is_not_a_root() {
    for eq in [
        "(x - 1)^2/(x - 1) == 0",
        "x^2/x == 0",
        "sin(x)^2/sin(x) == 0",
    ] {
        let e = error(&format!("given x\nsolve({eq}, x)"));
        assert!(
            e.contains("no root is in the domain of the equation as typed"),
            "{eq}: {e}"
        );
    }
    let (rs, note) = roots("(x - 1)^2*(x + 2)/(x - 1) == 0");
    assert_eq!(rs, vec![-2.0]);
    assert!(note.contains("not a root: x = 1"), "{note}");
    // a cancelled factor that is not a root changes nothing
    let (rs, note) = roots("(x^2 - 1)/(x - 1) == 0");
    assert_eq!((rs, note.as_str()), (vec![-1.0], ""));
}

/// An equation whose sides are one canonical form once a factor is
/// cancelled holds where the sides are defined as typed, not everywhere:
/// `x/x == 1` is undefined at x = 0 (subs says division by zero there),
/// and solve said it "holds for every x". Each excluded point is checked
/// by the same substitution as typed; a step whose domain is not known
/// here (a square root, a sine in a divisor) says "where both sides are
/// defined", and an equation with no division still holds for every x.
#[test]
fn an_identity_holds_only_where_the_sides_are_defined() {
    let cases = [
        (
            "x/x == 1",
            "holds for every x ≠ 0: at x = 0 a side is undefined",
        ),
        (
            "x^2/x == x",
            "holds for every x ≠ 0: at x = 0 a side is undefined",
        ),
        (
            "(x^2 - 1)/(x - 1) == x + 1",
            "holds for every x ≠ 1: at x = 1",
        ),
        ("1/x == 1/x", "holds for every x ≠ 0"),
        ("x^-1 * x == 1", "holds for every x ≠ 0"),
        ("(x, x/x) == (x, 1)", "holds for every x ≠ 0"),
        ("(x - a)/(x - a) == 1", "holds for every x ≠ a"),
        (
            "x/x + (x - 2)/(x - 2) == 2",
            "holds for every x except x = 0 (division by zero) and x = 2 (division by zero)",
        ),
        (
            "1/(x^2 - 2) == 1/(x^2 - 2)",
            "except x = -√2 (division by zero) and x = √2 (division by zero)",
        ),
        (
            "sin(x)/sin(x) == 1",
            "holds for every x where both sides are defined as typed",
        ),
        (
            "sqrt(x)^2 == x",
            "holds for every x where both sides are defined as typed",
        ),
        (
            "x/x + sqrt(x)^2 == 1 + x",
            "where both sides are defined as typed (not at x = 0 (division by zero))",
        ),
        (
            "x + 1 == x + 1",
            "holds for every x: both sides are the same",
        ),
        ("a/a == 1", "holds for every x: both sides are the same"),
        (
            "Rotz(x) Rotz(x)^T == eye(3)",
            "holds for every x: both sides are the same",
        ),
    ];
    for (eq, want) in cases {
        let e = error(&format!("given x, a\nsolve({eq}, x)"));
        assert!(e.contains(want), "{eq}: {e}");
        if !want.contains("every x:") {
            assert!(!e.contains("every x:"), "{eq}: {e}");
        }
    }
    // the point excluded is excluded by subs too, and x/x is 1 elsewhere
    let e = error("given x\nsubs(x/x, x, 0)");
    assert!(e.contains("division by zero"), "{e}");
    let j = json("given x\nsubs(x/x, x, 3)\nsimplify(x/x)");
    assert_eq!(j[0]["value"], 1.0);
    assert_eq!(j[1]["value"], 1.0);
}

/// A divisor with no real zero excludes no x: `1/(x^2 + 1) == 1/(x^2 +
/// 1)` said it holds "for every x where both sides are defined as typed",
/// though x² + 1 > 0 for every real x; now "for every x". Even powers of
/// one sign with a constant (x⁴ + 1, 2x² + 3), or a quadratic of negative
/// discriminant (x² + 2x + 5), are never 0; a divisor with real zeros, or
/// whose sign is not known (another symbol in it), is as before.
#[test]
fn a_divisor_with_no_real_zero_excludes_no_x() {
    let cases = [
        (
            "1/(x^2 + 1) == 1/(x^2 + 1)",
            "holds for every x: both sides are the same",
        ),
        (
            "(x^2 + 1)/(x^2 + 1) == 1",
            "holds for every x: both sides are the same",
        ),
        (
            "x/(x^4 + 1) == x/(x^4 + 1)",
            "holds for every x: both sides are the same",
        ),
        (
            "1/(x^2 + 2*x + 5) == 1/(x^2 + 2*x + 5)",
            "holds for every x: both sides are the same",
        ),
        (
            "1/(x^2 + 1)^2 == 1/(x^2 + 1)^2",
            "holds for every x: both sides are the same",
        ),
        (
            "1/(x^2 + 2*x + 1) == 1/(x^2 + 2*x + 1)",
            "holds for every x ≠ -1",
        ),
        (
            "1/(x^2 - 1) == 1/(x^2 - 1)",
            "except x = -1 (division by zero) and x = 1 (division by zero)",
        ),
        (
            "1/(x^2 + a) == 1/(x^2 + a)",
            "holds for every x where both sides are defined as typed",
        ),
        (
            "x/x == 1",
            "holds for every x ≠ 0: at x = 0 a side is undefined",
        ),
    ];
    for (eq, want) in cases {
        let e = error(&format!("given x, a\nsolve({eq}, x)"));
        assert!(e.contains(want), "{eq}: {e}");
    }
}
