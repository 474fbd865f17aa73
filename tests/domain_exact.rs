//! Domain decisions by exact forms (LANGUAGE.md §7; issue 21: never a
//! wrong answer): whether a builtin's argument is in its domain, a
//! divisor zero, an angle a pole, which side of a branch cut — decided by
//! the number's exact form when it has one, by its float otherwise. The
//! float of an exact number may be far from it: cos(3π/2) is −1.8e-16 in
//! floats, so cos(3π/2)/1e-17 is −18.4 there and 0 in fact. Found by
//! `tests/exact_differential.rs` (matrix seed 310521: `sqrt(sqrt(5) +
//! cos(3*pi/2)/1e-17)` was refused as the square root of −16.1).

mod common;

use common::{error, outputs, printed};

/// The number `src`'s last statement prints.
fn value(src: &str) -> f64 {
    let v = common::last_numbers(src);
    assert_eq!(v.len(), 1, "{src}: {v:?}");
    v[0]
}

fn close(x: f64, want: f64) -> bool {
    (x - want).abs() <= 1e-14 * want.abs().max(1.0)
}

/// sqrt, asin, acos: in or out of the domain by the exact form, and the
/// value computed from it (no note: nothing was rounded into the domain).
#[test]
fn roots_and_inverse_sines_decide_by_the_exact_form() {
    // the float of the argument is −16.4: √√3 all the same
    let src = "sqrt(sqrt(3) + cos(3*pi/2)/1e-17)";
    assert!(close(value(src), 3f64.powf(0.25)), "{}", value(src));
    let (_, err) = outputs(src);
    assert!(err.is_empty(), "{err}");
    // the case found: 5^(1/4), the float of the argument being −16.1
    let src = "sqrt(sqrt(5) + cos(3*pi/2)/1e-17)";
    assert!(close(value(src), 5f64.powf(0.25)), "{}", value(src));
    let e = error("sqrt(-sqrt(5) + cos(pi/2)/1e-17)");
    assert!(e.contains("sqrt(-2.23606797749979)"), "{e}");
    // the float of the argument is +3.9: not real all the same
    let e = error("sqrt(-sqrt(3) + cos(pi/2)/1e-17)");
    assert!(e.contains("not real"), "{e}");
    // exactly 1 and −1, whatever the floats (1.0000000000000002)
    assert_eq!(value("acos(sqrt(2)*sqrt(2)/2)"), 0.0);
    assert_eq!(value("acos((sqrt(3)^2)/3)"), 0.0);
    assert!(close(
        value("asin(-(sqrt(3)^2)/3)"),
        -std::f64::consts::FRAC_PI_2
    ));
    assert!(close(value("acos(1 + cos(pi/2)*1e5)"), 0.0));
    // exactly 0: the root is 0, not the root of the float's 1.2e-16
    assert_eq!(value("sqrt(sin(pi))"), 0.0);
    let (out, err) = outputs("sqrt(sin(2*pi))");
    assert_eq!((out.as_str(), err.as_str()), ("0\n", ""));
    // a number as typed is exact, but a few units in the last place
    // outside is a computed float typed back: the edge, with a note
    // (issue 36; this was a domain error)
    for (src, want) in [
        ("acos(1 + 2e-16)", 0.0),
        ("acos(1.0000000000000002)", 0.0),
        ("asin(-1.0000000000000002)", -std::f64::consts::FRAC_PI_2),
        ("sqrt(-2e-16)", 0.0),
        ("sqrt(-1e-17)", 0.0),
    ] {
        assert_eq!(value(src), want, "{src}");
        let (_, err) = outputs(src);
        assert!(err.contains("a rounding error; taken as"), "{src}: {err}");
    }
    // beyond a few units, the domain error as before
    let e = error("acos(1.000000000000001)");
    assert!(e.contains("must be in [−1, 1]"), "{e}");
    let e = error("sqrt(-1e-15)");
    assert!(e.contains("not real"), "{e}");
    // a float with no exact form within rounding is clamped, with a note
    let (out, err) = outputs("acos(exp(0) + 2e-16)");
    assert_eq!(out, "0\n");
    assert!(err.contains("a rounding error; taken as 1"), "{err}");
}

/// Division by a number whose exact form is 0 is by zero, whatever its
/// float (1/cos(π/2) printed 1.6331e16, 1/(sin(π) 10²⁰) printed 0.0001);
/// also the inverse, a negative power and a matrix divided.
#[test]
fn division_by_an_exact_zero_is_refused() {
    for src in [
        "1/cos(pi/2)",
        "1/(sin(pi) * 1e20)",
        "x = cos(pi/2)\n1/x",
        "[1, 2; 3, 4]/cos(pi/2)",
        "(sin(pi)*1e20)^-1",
        "0^-1",
        "acos(cos(pi/2)/cos(pi/2))",
    ] {
        let e = error(src);
        assert!(e.contains("division by zero"), "{src}: {e}");
    }
    let e = error("inv(sin(pi)*1e20)");
    assert!(e.contains("inverse of zero"), "{e}");
    // a divisor near 0 but not 0 divides, by the float nearest it (its
    // float is 0: √2 − 1.4142135623730951 is −5.1198311275790304e-17)
    let q = value("1/(sqrt(2) - 1.4142135623730951)");
    assert!(close(q * -5.119_831_127_579_030_4e-17, 1.0), "{q}");
}

/// log of a number whose exact form is 0 or negative is refused; powers
/// and sizes read exact exponents and sides exactly.
#[test]
fn logs_powers_and_sizes_decide_by_the_exact_form() {
    let e = error("log(cos(pi/2))");
    assert!(e.contains("log of 0"), "{e}");
    assert_eq!(value("log(sqrt(2)^2/2)"), 0.0);
    // sin(2π)^0.5 is 0 (its float −2.4e-16 has no real root)
    assert_eq!(value("sin(2*pi)^0.5"), 0.0);
    // (−8)^(√2²) is 64: the exponent is 2, not 2.0000000000000004
    assert_eq!(value("(-8)^(sqrt(2)^2)"), 64.0);
    assert_eq!(printed("zeros(sqrt(2)^2, 1)"), "(0, 0)  : 2-vector\n");
    assert_eq!(printed("NearZero(sin(pi)*1e10)"), "true\n");
}

/// Poles of tan, cot, sec and csc are decided exactly: an odd multiple of
/// π/2 (a multiple of π) however large, and nothing else.
#[test]
fn poles_are_decided_exactly() {
    for (src, what) in [
        ("tan(pi/2 + 10^16*pi)", "tangent is infinite"),
        ("sec(-pi/2)", "secant is infinite"),
        ("cot(2*pi)", "cotangent is infinite"),
        ("csc(3*pi)", "cosecant is infinite"),
        ("cot(0)", "cotangent is infinite"),
    ] {
        let e = error(src);
        assert!(e.contains(what), "{src}: {e}");
    }
    // near a pole but not at it, where the float cannot tell: refused,
    // saying so (not "cos x is 0")
    let e = error("tan(pi/2 + 1e-20)");
    assert!(e.contains("within rounding of a pole"), "{e}");
    assert!(close(value("tan(pi/4)"), 1.0));
}

/// atan2 on its cut (y = 0, x < 0) is π, by the exact zero: the float of
/// sin(2π) is −2.4e-16, which gave −π; and −0 is 0 (the range is (−π, π]).
#[test]
fn atan2_reads_the_sign_of_an_exact_zero() {
    let pi = std::f64::consts::PI;
    assert_eq!(value("atan2(sin(2*pi), -1)"), pi);
    assert_eq!(value("atan2(-0, -1)"), pi);
    assert_eq!(value("atan2(sin(-pi), -sqrt(2))"), pi);
    assert!(close(value("atan2(-1, -1)"), -3.0 * pi / 4.0));
}

/// The float computed from an exact form is the float nearest it, also
/// where its terms cancel: 1/(a²) of a = √(4056/5) + √(5046/6) is
/// (p − q√k)/r with large p, q, and (π − 3.6)⁴ expanded cancels nine
/// digits; the floats of those forms were 2e-13 and 2e-12 off (found by
/// `tests/exact_differential.rs` in release, seeds 5067705 and 5098294).
#[test]
fn values_from_exact_forms_are_the_nearest_floats() {
    let x = value("(-1) / ((sqrt(4056/5) + sqrt(5046/6))^(-2))");
    assert!((x + 3_304.131_233_435_581).abs() <= 4e-12, "{x}");
    let y = value("(1e-18 + (pi - 18/5)^4)^2");
    assert!((y - 0.001_949_900_954_856_011_1).abs() <= 1e-18, "{y}");
}
