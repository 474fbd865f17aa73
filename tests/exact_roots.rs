//! Square roots of any exact rational are exact (LANGUAGE.md §7: "square
//! roots of exact numbers and what arithmetic makes of them"; issue 21):
//! √5² is 5, √8 is 2√2, √(9/4) is 3/2, 1/(√2 + √3) is √3 − √2, in numbers
//! and in symbolic coefficients alike, so `==` gives the same answer with
//! or without a symbol. A root of a root has no exact form and compares as
//! a float (`tests/exact.rs`).

mod common;
use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};
use common::json;

/// The value of the last statement of `src`.
fn last(src: &str) -> serde_json::Value {
    json(src).pop().expect("a statement")["value"].clone()
}

/// What `src` prints, with `--exact` or without, and its diagnostics.
fn text(src: &str, exact: bool) -> (String, String) {
    let mut s = Session::new(Settings {
        exact,
        ..Settings::default()
    });
    let (out, err, n) = s.run_to_strings("t.chs", src, Mode::Run, false);
    assert_eq!(n, 0, "{src}\n{err}");
    (out, err)
}

/// `a == b` answers `want`, and so does `a t == b t` with a symbol t; a
/// true answer comes with no rounding note.
fn equal(a: &str, b: &str, want: bool) {
    let plain = format!("{a} == {b}");
    let with_t = format!("given t : scalar\n({a})*t == ({b})*t");
    for src in [&plain, &with_t] {
        assert_eq!(last(src), serde_json::Value::Bool(want), "{src}");
        if want {
            let (_, err) = text(src, false);
            assert!(!err.contains("rounding"), "{src}: {err}");
        }
    }
}

#[test]
fn roots_of_any_rational_are_exact() {
    for (a, b) in [
        ("sqrt(5)^2", "5"),
        ("sqrt(5)*sqrt(5)", "5"),
        ("sqrt(7)^4", "49"),
        ("sqrt(8)", "2*sqrt(2)"),
        ("sqrt(50)", "5*sqrt(2)"),
        ("sqrt(9/4)", "3/2"),
        ("sqrt(1/3)", "sqrt(3)/3"),
        ("sqrt(1/3)", "1/sqrt(3)"),
        ("sqrt(0.05)", "sqrt(5)/10"),
        ("sqrt(10)/sqrt(2)", "sqrt(5)"),
        ("sqrt(12)*sqrt(15)", "6*sqrt(5)"),
        ("sqrt(7) + sqrt(7)", "sqrt(28)"),
        ("sqrt(2)*sqrt(3)*sqrt(5)", "sqrt(30)"),
        ("(sqrt(5) + 1)^2", "6 + 2*sqrt(5)"),
        // the golden ratio: φ² = φ + 1
        ("((1 + sqrt(5))/2)^2", "(1 + sqrt(5))/2 + 1"),
    ] {
        equal(a, b, true);
    }
    for (a, b) in [
        ("sqrt(2) + sqrt(3)", "sqrt(5)"),
        ("sqrt(5)", "2.23606797749979"),
        ("sqrt(5)^2", "5.000000000000001"),
        ("sqrt(7)", "sqrt(7.000000000001)"),
        ("sqrt(6)", "sqrt(2) + sqrt(3) - sqrt(5)"),
        ("1/sqrt(5)", "sqrt(5)/4"),
    ] {
        equal(a, b, false);
    }
}

/// Powers: negative ones, and half-integer ones of an exact rational.
#[test]
fn powers_of_roots_are_exact() {
    for (a, b) in [
        ("sqrt(5)^-3", "sqrt(5)/25"),
        ("sqrt(2)^-1", "sqrt(2)/2"),
        ("(9/4)^0.5", "3/2"),
        ("5^0.5", "sqrt(5)"),
        ("5^-0.5", "1/sqrt(5)"),
        ("5^1.5", "5*sqrt(5)"),
        ("8^0.5", "2*sqrt(2)"),
        ("(1/12)^-0.5", "2*sqrt(3)"),
        ("sqrt(5)^0", "1"),
    ] {
        equal(a, b, true);
    }
}

/// Large radicands keep every digit; a product of many distinct roots is
/// one root.
#[test]
fn large_radicands_and_many_roots() {
    for (a, b) in [
        ("sqrt(12345678910111213)^2", "12345678910111213"),
        ("sqrt(10^18 + 1)*sqrt(10^18 + 1)", "10^18 + 1"),
        ("sqrt(4*(10^18 + 9))", "2*sqrt(10^18 + 9)"),
        // 2⁶¹ − 1 is prime (found by Miller–Rabin, not by trial division)
        ("sqrt(2^61 - 1)^2", "2^61 - 1"),
        ("sqrt(3*(2^61 - 1)^2)", "(2^61 - 1)*sqrt(3)"),
        // 10⁴⁰ is beyond 128 bits, and a square
        ("sqrt(10^40)", "10^20"),
        (
            "sqrt(2)*sqrt(3)*sqrt(5)*sqrt(7)*sqrt(11)*sqrt(13)*sqrt(17)*sqrt(19)*sqrt(23)*sqrt(29)",
            "sqrt(6469693230)",
        ),
        (
            "(sqrt(2)*sqrt(3)*sqrt(5)*sqrt(7)*sqrt(11)*sqrt(13)*sqrt(17)*sqrt(19)*sqrt(23)*sqrt(29))^2",
            "6469693230",
        ),
    ] {
        equal(a, b, true);
    }
    equal("sqrt(10^18 + 1)", "10^9", false);
    // a literal of more digits than a float holds keeps them in parentheses
    for (src, want) in [
        (
            "given t : scalar\n(12345678910111213)*t == 12345678910111213*t",
            true,
        ),
        (
            "given t : scalar\n(12345678910111213)*t == 12345678910111212*t",
            false,
        ),
    ] {
        assert_eq!(last(src), serde_json::Value::Bool(want), "{src}");
    }
    // √(10¹⁸ + 1) > 10⁹ though their floats are equal
    assert_eq!(
        last("sqrt(10^18 + 1) > 10^9"),
        serde_json::Value::Bool(true)
    );
}

/// A quotient by a sum of roots is rationalised: exact, and equal to its
/// conjugate form.
#[test]
fn division_by_a_sum_of_roots() {
    for (a, b) in [
        ("1/(sqrt(2) + sqrt(3))", "sqrt(3) - sqrt(2)"),
        ("1/(sqrt(2) + sqrt(5))", "(sqrt(5) - sqrt(2))/3"),
        ("(sqrt(5) + sqrt(7))/(sqrt(5) - sqrt(7))", "-6 - sqrt(35)"),
        (
            "1/(1 + sqrt(2) + sqrt(3) + sqrt(5)) * (1 + sqrt(2) + sqrt(3) + sqrt(5))",
            "1",
        ),
        (
            "1/(sqrt(2) + sqrt(3) + sqrt(5) + sqrt(7))^2 * (sqrt(2) + sqrt(3) + sqrt(5) + sqrt(7))^2",
            "1",
        ),
    ] {
        equal(a, b, true);
    }
    equal("1/(sqrt(2) + sqrt(3))", "sqrt(3) + sqrt(2)", false);
}

/// `--exact` prints roots as the symbolic printer does (`2√2`, `1/√3`),
/// in a form that reads back; symbolic coefficients print alike, and JSON
/// carries the symbolic text and LaTeX.
#[test]
fn roots_print_exactly() {
    let (out, _) = text(
        "a = sqrt(50)\nb = sqrt(1/3)\nc = sqrt(5)^2\nd = (sqrt(5), sqrt(7)/7, -sqrt(1/5))\ne = sqrt(9/4)\nf = 1/(sqrt(2) + sqrt(3))",
        true,
    );
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        lines,
        [
            "a = 5√2",
            "b = 1/√3",
            "c = 5",
            "d = (√5, 1/√7, -1/√5)  : 3-vector",
            // (a fraction computed from integers is a fraction; a typed
            // 1.5 prints as typed)
            "e = 3/2",
            "f = (-√2 + √3)"
        ]
    );
    // what --exact prints reads back to the same number
    for (typed, printed) in [("sqrt(50)", "5√2"), ("sqrt(1/3)", "1/√3")] {
        equal(typed, printed, true);
    }
    let (out, _) = text("given t : scalar\nsqrt(5)*t\n(1 + sqrt(2))*t", false);
    assert_eq!(out, "√5 t\n(1 + √2) t\n");
    let lines = json("given t : scalar\nsqrt(20)*t");
    let v = lines.last().expect("a line");
    assert_eq!(v["value"], "2√5 t");
    assert_eq!(v["latex"], "2\\sqrt{5} t");
}
