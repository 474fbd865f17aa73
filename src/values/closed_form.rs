//! Simple closed forms of floats, for `--exact` and `:exact` (LANGUAGE.md
//! §1, §10: "numbers within 1e-12 of simple closed forms print as `1/√2`,
//! `π/6`"). A value with an exact form prints that form; a float with none
//! (`MatrixLog3(Rotz(pi/3))`, `cos(0.5235987755982988)`) prints the
//! simple form it is a rounding of, when every entry has one, after `≈ `
//! (`≈ (0, 0, π/3)`): the floats alone cannot tell π/3 from a number a
//! few units in the last place from it (22√7/21 + 3.8e-15 rounds within
//! 7 units of 22√7/21), so the form is said to be the floats' rounding,
//! not the value.
//!
//! "A rounding of" is within `ULPS` units in the last place of the form,
//! not the contract's 1e-12: a float 7e-13 from 7/3 (`7 (1/3 + 1e-13)`
//! with no exact form) is not 7/3 even to rounding; the floats of a closed
//! form worked out in double precision (a logarithm, a quaternion) are
//! within a few units of it.
//!
//! A simple form is (p/q)·√n·πᵏ: q at most `MAX_DENOMINATOR` (36 takes
//! every multiple of 5° as a fraction of π), n one of 1, 2, 3, 5, 6, 7
//! (the square roots of the book's rotations, √2/2, √3/2, and their
//! neighbours), k 0 or 1. Rationals are tried first, then roots, then
//! multiples of π, each by the smallest denominator: the first the float
//! is a rounding of is the form. A float of no such form is printed as a decimal; so
//! is a matrix with one such entry, rather than a mix of both.

use crate::sym::Mat;
use crate::sym::coef::{Coef, Rat};
use crate::sym::expr::Expr;

/// The largest denominator of a simple form.
const MAX_DENOMINATOR: i64 = 36;

/// The largest numerator: beyond it a float is a large number, not a
/// simple form.
const MAX_NUMERATOR: f64 = 1e6;

/// How many units in the last place of a simple form a float may be from
/// it and print as it (the module's doc).
const ULPS: f64 = 8.0;

/// The square roots a simple form may have.
const ROOTS: [i64; 6] = [1, 2, 3, 5, 6, 7];

/// The simple closed form of each of `xs` (an r×c matrix, row by row), or
/// None when one entry has none.
pub fn of_floats(xs: &[f64], rows: usize, cols: usize) -> Option<Mat> {
    if xs.len() != rows * cols {
        return None;
    }
    let data = xs
        .iter()
        .map(|&x| of_float(x))
        .collect::<Option<Vec<_>>>()?;
    Some(Mat { rows, cols, data })
}

/// The simple closed form `x` is a rounding of, if it has one.
pub fn of_float(x: f64) -> Option<Expr> {
    if !x.is_finite() {
        return None;
    }
    if x == 0.0 {
        return Some(Expr::default());
    }
    for pi in [false, true] {
        for n in ROOTS {
            let base = (n as f64).sqrt() * if pi { std::f64::consts::PI } else { 1.0 };
            if let Some((p, q)) = fraction_near(x / base) {
                // (a fraction that is a short decimal, 3/10, as the decimal:
                // it then prints as one, `--exact` or not)
                let r = Rat::new(p.into(), q.into())?;
                let r = match n == 1 && !pi && super::exact::is_decimal(&r) {
                    true => Rat::typed(p as f64 / q as f64)?,
                    false => r,
                };
                let mut e = Expr::constant(Coef::rat(r));
                if n > 1 {
                    e = e.mul(&Expr::sqrt(&Expr::int(n)));
                }
                if pi {
                    e = e.mul(&Expr::pi());
                }
                return Some(e);
            }
        }
    }
    None
}

/// The fraction p/q of smallest q with (p/q)·base within `ULPS` of
/// y·base, if there is one with q ≤ `MAX_DENOMINATOR` (p ≠ 0).
fn fraction_near(y: f64) -> Option<(i64, i64)> {
    (1..=MAX_DENOMINATOR).find_map(|q| {
        let p = (y * q as f64).round();
        let form = p / q as f64;
        let close = (form - y).abs() <= ULPS * f64::EPSILON * form.abs();
        (close && p != 0.0 && p.abs() <= MAX_NUMERATOR).then_some((p as i64, q))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The form as `--exact` prints it.
    fn shown(x: f64) -> Option<String> {
        let st = crate::sym::print::Style {
            mode: crate::sym::print::Mode::Text,
            digits: 4,
        };
        of_float(x).map(|e| crate::values::exact::block(&Mat::column(vec![e]), st, 0, false))
    }

    #[test]
    fn the_books_numbers_have_their_forms() {
        let r2 = std::f64::consts::FRAC_1_SQRT_2;
        let pi = std::f64::consts::PI;
        assert_eq!(shown(1.0 / 3.0).as_deref(), Some("1/3"));
        // (a short decimal is the decimal as typed, which prints as one)
        let typed = |x: f64| of_float(x).and_then(|e| e.as_const()?.as_rat());
        assert!(typed(0.30000000000000004).is_some_and(|r| r.is_typed()));
        assert!(typed(1.0 / 3.0).is_some_and(|r| !r.is_typed()));
        assert_eq!(shown(r2).as_deref(), Some("1/√2"));
        assert_eq!(shown(3f64.sqrt() / 2.0).as_deref(), Some("√3/2"));
        assert_eq!(shown(pi / 3.0).as_deref(), Some("π/3"));
        assert_eq!(shown(-pi / 6.0).as_deref(), Some("-π/6"));
        assert_eq!(shown(10.0 * pi / 180.0).as_deref(), Some("π/18"));
        assert_eq!(shown(0.0).as_deref(), Some("0"));
        // a few units in the last place of π/3 still is; 1e-13 off is not
        // (7/3 + 7e-13 is not 7/3)
        assert_eq!(shown(pi / 3.0 + 4e-16).as_deref(), Some("π/3"));
        assert_eq!(shown(pi / 3.0 + 1e-13), None);
        assert_eq!(shown(7.0 * (1.0 / 3.0 + 1e-13)), None);
        // sin 1 is no simple form, nor is 1/37
        assert_eq!(shown(1f64.sin()), None);
        assert_eq!(shown(1.0 / 37.0), None);
        assert_eq!(shown(f64::NAN), None);
    }

    #[test]
    fn a_matrix_has_a_form_only_when_every_entry_has() {
        let h = 3f64.sqrt() / 2.0;
        let m = of_floats(&[h, -0.5, 0.5, h], 2, 2).expect("Rot(30°)");
        assert_eq!(m.data.len(), 4);
        assert_eq!(of_floats(&[h, 1f64.sin()], 2, 1), None);
    }
}
