//! The symbolic engine checked against numbers (LANGUAGE.md §7, issue 21):
//! fixed regressions for the wrong answers found so far, and a
//! differential test — random expressions over the engine's operations,
//! written as chasles source, evaluated by the language and by an
//! independent numeric evaluation of the same tree.

use chasles::eval::env::Mode;
use chasles::eval::value::Value;
use chasles::session::{Session, Settings};

/// Runs `src` in a fresh session; the session and the number of errors.
fn session(src: &str) -> (Session, usize, String) {
    let mut s = Session::new(Settings::default());
    let (_, err, n) = s.run_to_strings("t.chs", src, Mode::Run, false);
    (s, n, err)
}

/// The number bound to `name`, if it is one.
fn number(s: &Session, name: &str) -> Option<f64> {
    match s.env.get(name).and_then(|b| b.val.as_ref()) {
        Some(v @ Value::Num { .. }) => v.as_scalar(),
        _ => None,
    }
}

/// The text `src` prints (failing on an error).
fn prints(src: &str) -> String {
    let mut s = Session::new(Settings::default());
    let (out, err, n) = s.run_to_strings("t.chs", src, Mode::Run, false);
    assert_eq!(n, 0, "{src}\n{err}");
    out.trim_end().to_string()
}

/// The last line `src` prints.
fn last(src: &str) -> String {
    prints(src).lines().last().unwrap_or_default().to_string()
}

// ------------------------------------------------------- fixed regressions

/// Issue 21, item 1: numbers bound later at angles outside the 15° family
/// give the number, as if typed first.
#[test]
fn numbers_bound_later_are_numbers() {
    for (angle, want) in [
        ("20 deg", 20f64.to_radians().cos()),
        ("10 deg", 10f64.to_radians().cos()),
        ("36 deg", 36f64.to_radians().cos()),
        ("0.1745", 0.1745f64.cos()),
    ] {
        let src = format!("given a : scalar\nc = cos(a)\na = {angle}\nx = c");
        let (s, n, err) = session(&src);
        assert_eq!(n, 0, "{err}");
        let x = number(&s, "x").unwrap_or_else(|| panic!("{src}: not a number"));
        assert!((x - want).abs() < 1e-14, "{src}: {x} ≠ {want}");
    }
    // a rotation is still a rotation, a plain matrix is not called one
    let out = prints("given a : scalar\nR = Rotz(a)\na = 20 deg\nR");
    assert!(out.ends_with(": SO(3)"), "{out}");
    let out = prints("given a : scalar\nM = [cos(a), 0; 0, 2]\na = 0.3\nM");
    assert!(!out.contains("SO(2)") && out.contains("0.9553"), "{out}");
    // partly bound: the other symbol stays, the number is right
    let (s, n, err) =
        session("given a, b : scalar\nc = cos(a + b)\na = 20 deg\nd = c\nb = 0.5\nx = d");
    assert_eq!(n, 0, "{err}");
    let x = number(&s, "x").expect("a number");
    assert!((x - (20f64.to_radians() + 0.5).cos()).abs() < 1e-14);
}

/// Issue 21, item 3: partial derivatives by a function of time or its
/// rate hold the other coordinates and rates fixed; by t, the chain rule.
#[test]
fn partial_derivatives_by_coordinates_and_rates() {
    let pre = "given q1(t), q2(t) : scalar\n";
    assert_eq!(last(&format!("{pre}diff(q1*q2, q1)")), "q2");
    assert_eq!(last(&format!("{pre}diff(q1', q1')")), "1");
    assert_eq!(last(&format!("{pre}diff(q1'^2 q2, q1')")), "2 q̇1 q2");
    assert_eq!(last(&format!("{pre}diff(q1*q2, t)")), "q1 q̇2 + q̇1 q2");
    assert_eq!(last(&format!("{pre}diff(sin(q1) q2', q1')")), "0");
    let lagrangian = "given q(t), m, g : scalar\nL = m q'^2/2 + m g cos(q)\n";
    assert_eq!(last(&format!("{lagrangian}diff(L, q')")), "m q̇");
    assert_eq!(last(&format!("{lagrangian}diff(L, q)")), "-g m sin(q)");
    assert_eq!(last(&format!("{lagrangian}diff(diff(L, q'), t)")), "m q̈");
    // and the bound values: ∂L/∂q̇ at m = 2, q̇ = 3
    let (s, n, err) = session(&format!(
        "{lagrangian}p = diff(L, q')\nm = 2\nq' = 3\nx = p"
    ));
    assert_eq!(n, 0, "{err}");
    assert_eq!(number(&s, "x"), Some(6.0));
}

/// Issue 21, item 4: declaring the time variable (or anything) later
/// changes nothing declared before.
#[test]
fn declaring_later_changes_nothing_before() {
    let out = last("given theta(t) : scalar\ngiven t : scalar\ndiff(sin(theta), t)");
    assert_eq!(out, "θ̇ cos(theta)");
    let out = last("given t : scalar\ngiven theta(t) : scalar\ndiff(t sin(theta), t)");
    assert_eq!(out, "sin(theta) + t θ̇ cos(theta)");
    let out = last("given theta(t) : scalar\nx = theta^2\ngiven theta : scalar\ndiff(x, t)");
    assert_eq!(out, "2 theta θ̇");
}
