//! Exact numbers and exact `==` (LANGUAGE.md §§3, 7; issue 21 items 2, 5
//! and 6): reciprocals and quotients keep their value, `==` is true only
//! when the difference is exactly zero, exact numbers stay exact with and
//! without symbols, and large coefficients are never rounding noise.

mod common;
use common::json;

/// The value of the last statement of `src`.
fn last(src: &str) -> serde_json::Value {
    json(src).pop().expect("a statement")["value"].clone()
}

/// The number the last statement of `src` prints.
fn number(src: &str) -> f64 {
    last(src)
        .as_f64()
        .unwrap_or_else(|| panic!("{src}: not a number"))
}

fn close(x: f64, want: f64) -> bool {
    (x - want).abs() <= 1e-12 * want.abs().max(1.0)
}

// ------------------------------------------------- item 2: reciprocals

/// `1/sin(t1)`, `tan(t2 + π/2)` and the derivative of a quotient are not
/// 0: a reciprocal of a sum keeps a real argument, so its value is right
/// printed and bound later.
#[test]
fn reciprocals_of_sums_keep_their_value() {
    let t = 0.7f64;
    let cases: [(&str, f64); 4] = [
        ("1/sin(x)", 1.0 / t.sin()),
        ("tan(x + pi/2)", -1.0 / t.tan()),
        (
            "diff(1/(cos(x) + 2 sin(x)), x)",
            (t.sin() - 2.0 * t.cos()) / (t.cos() + 2.0 * t.sin()).powi(2),
        ),
        (
            "1/(2 + 0.3 sin(x)) + 1/(x + 1)",
            1.0 / (2.0 + 0.3 * t.sin()) + 1.0 / (t + 1.0),
        ),
    ];
    for (e, want) in cases {
        let src = format!("given x : scalar\ny = {e}\nx = {t}\ny");
        let lines = json(&src);
        let printed = lines[1]["value"].as_str().unwrap_or_default().to_string();
        assert_ne!(printed, "0", "{e} printed 0");
        assert!(close(number(&src), want), "{e}: {} vs {want}", number(&src));
    }
    let printed = last("given t1 : scalar\n1/sin(t1)");
    assert!(
        printed.as_str().is_some_and(|s| s.contains("sin(t1)")),
        "{printed}"
    );
}

// ------------------------------------------- item 6: exact coefficients

/// Integer coefficients beyond 64 bits stay exact (no float, no noise):
/// C(70, 35) is 112186277816662845432.
#[test]
fn big_coefficients_stay_exact() {
    let printed = last("given t : scalar\n(1 + t)^70");
    let text = printed.as_str().unwrap_or_default();
    assert!(text.contains("112186277816662845432 t^35"), "{text}");
    assert!(!text.contains('e') && !text.contains('.'), "{text}");
}
