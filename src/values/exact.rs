//! Closed forms for the REPL's `:exact` mode (LANGUAGE.md §10): a number
//! within 1e-12 of a simple closed form prints as that form — `1/2`,
//! `1/√2`, `√3/2`, `2√2`, `π/6`, `-π/2`, `2π/3` — instead of decimals.
//!
//! The forms tried, in order: a fraction p/q, p/q·√k for k = 2, 3, 5, 6,
//! and p/q·π, each with a denominator q ≤ 12 and a small numerator.
//! Integers are left to the ordinary printer.

/// How close a value must be to a closed form.
pub const TOLERANCE: f64 = 1e-12;

/// Largest denominator tried.
const MAX_DEN: i64 = 12;

/// Largest numerator (in absolute value) tried.
const MAX_NUM: i64 = 144;

/// Square roots tried (square-free, so each form is unique).
const ROOTS: [i64; 4] = [2, 3, 5, 6];

/// The closed form of `x`, if it is within [`TOLERANCE`] of one and not
/// an integer (integers print as themselves anyway).
pub fn closed_form(x: f64) -> Option<String> {
    if !x.is_finite() || (x - x.round()).abs() <= TOLERANCE {
        return None;
    }
    if let Some((p, q)) = fraction(x) {
        return Some(ratio(p, q));
    }
    for k in ROOTS {
        if let Some((p, q)) = fraction(x / (k as f64).sqrt()) {
            return Some(times(p, q, &format!("√{k}"), Some(k)));
        }
    }
    fraction(x / std::f64::consts::PI).map(|(p, q)| times(p, q, "π", None))
}

/// The smallest denominator q ≤ 12 with x ≈ p/q (so p/q is in lowest terms).
fn fraction(x: f64) -> Option<(i64, i64)> {
    if !x.is_finite() || x.abs() > MAX_NUM as f64 {
        return None;
    }
    (1..=MAX_DEN).find_map(|q| {
        let p = (x * q as f64).round();
        let close = (x - p / q as f64).abs() <= TOLERANCE;
        (close && p != 0.0 && p.abs() <= MAX_NUM as f64).then_some((p as i64, q))
    })
}

/// `p/q` with the sign in front.
fn ratio(p: i64, q: i64) -> String {
    if q == 1 {
        p.to_string()
    } else {
        format!("{p}/{q}")
    }
}

/// p/q times a symbol: `π/6`, `-2π/3`, `√3/2`, `3√2`; `1/√k` for √k/k.
fn times(p: i64, q: i64, symbol: &str, root: Option<i64>) -> String {
    let sign = if p < 0 { "-" } else { "" };
    let p = p.abs();
    if root == Some(q) && p == 1 {
        return format!("{sign}1/{symbol}");
    }
    let coef = if p == 1 { String::new() } else { p.to_string() };
    if q == 1 {
        format!("{sign}{coef}{symbol}")
    } else {
        format!("{sign}{coef}{symbol}/{q}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn book_forms() {
        let cases = [
            (1.0 / 2f64.sqrt(), "1/√2"),
            (-1.0 / 2f64.sqrt(), "-1/√2"),
            (3f64.sqrt() / 2.0, "√3/2"),
            (PI / 6.0, "π/6"),
            (-PI / 2.0, "-π/2"),
            (2.0 * PI / 3.0, "2π/3"),
            (PI, "π"),
            (2f64.sqrt(), "√2"),
            (2.0 * 2f64.sqrt(), "2√2"),
            (1.0 / 3f64.sqrt(), "1/√3"),
            (0.5, "1/2"),
            (-0.25, "-1/4"),
            (2.0 / 3.0, "2/3"),
        ];
        for (x, want) in cases {
            assert_eq!(closed_form(x).as_deref(), Some(want), "{x}");
        }
    }

    #[test]
    fn leaves_others_alone() {
        for x in [
            0.0,
            1.0,
            -3.0,
            0.123456789,
            1.0 / 2f64.sqrt() + 1e-9,
            f64::NAN,
            f64::INFINITY,
            1e300,
        ] {
            assert_eq!(closed_form(x), None, "{x}");
        }
    }
}
