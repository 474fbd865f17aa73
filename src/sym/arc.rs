//! Inverse trigonometric functions at exact numbers whose angle is a
//! rational multiple of π with a closed form (LANGUAGE.md §7, issue 21):
//! `atan(1)` is π/4, `asin(1/2)` π/6, `acos(-1/2)` 2π/3, `atan2(1, -1)`
//! 3π/4, `atan(2 - sqrt(3))` π/12. The angle is guessed from the float
//! and then proven: its sine and cosine, exact numbers of the canonical
//! form, must satisfy the defining equation exactly, and the angle must
//! lie in the function's range (asin, atan: [−π/2, π/2]; acos: [0, π];
//! atan2: (−π, π] with the signs of its arguments). A guess that is not
//! proven leaves the number a float, as before.

use super::coef::{Coef, Rat, Surd};
use super::expr::{Expr, Func};

/// The largest denominator of the angle's multiple of π that is guessed
/// (the book's angles are multiples of π/12; π/5, π/8 have no exact
/// cosine in the canonical form and are left as floats).
const MAX_DEN: i128 = 24;

/// The exact real number an expression is, if it is one.
fn real(e: &Expr) -> Option<Surd> {
    match e.as_const()? {
        Coef::Exact { re, im } if im.is_zero() => Some(re),
        _ => None,
    }
}

/// (cos rπ, sin rπ) as exact real numbers, when the canonical form has
/// them.
fn cos_sin(r: &Rat) -> Option<(Surd, Surd)> {
    let angle = Expr::pi().scale(&Coef::rat(r.clone()));
    Some((real(&Expr::cos(&angle))?, real(&Expr::sin(&angle))?))
}

/// rπ as an expression.
fn angle(r: Rat) -> Expr {
    Expr::pi().scale(&Coef::rat(r))
}

/// f(x) for f asin, acos or atan at an exact x, as rπ when proven; None
/// otherwise (the caller keeps the float).
pub fn inverse(f: Func, x: &Expr) -> Option<Expr> {
    let x = real(x)?;
    let value = match f {
        Func::Asin => x.to_f64().asin(),
        Func::Acos => x.to_f64().acos(),
        Func::Atan => x.to_f64().atan(),
        _ => return None,
    };
    let r = guess(value)?;
    let (c, s) = cos_sin(&r)?;
    let half = Rat::new(1, 2)?;
    let within = |lo: &Rat, hi: &Rat| !lt(&r, lo) && !lt(hi, &r);
    let proven = match f {
        Func::Asin => s == x && within(&half.neg(), &half),
        Func::Acos => c == x && within(&Rat::ZERO, &Rat::ONE),
        // tan rπ = x: sin rπ = x cos rπ, cos rπ > 0
        _ => s == x.mul(&c)? && c.signum() > 0.0,
    };
    proven.then(|| angle(r))
}

/// atan2(y, x) at exact y, x, not both 0, as rπ when proven: sin rπ·x =
/// cos rπ·y, with cos rπ of x's sign and sin rπ of y's, r in (−1, 1].
pub fn atan2(y: &Expr, x: &Expr) -> Option<Expr> {
    let (y, x) = (real(y)?, real(x)?);
    if x.is_zero() && y.is_zero() {
        return None;
    }
    // (y = 0 exactly: 0 or π, never −π, whatever the sign of a float 0)
    let r = if y.is_zero() {
        if x.signum() < 0.0 {
            Rat::ONE
        } else {
            Rat::ZERO
        }
    } else {
        guess(y.to_f64().atan2(x.to_f64()))?
    };
    if !lt(&Rat::int(-1), &r) || lt(&Rat::ONE, &r) {
        return None;
    }
    let (c, s) = cos_sin(&r)?;
    let proven = s.mul(&x)? == c.mul(&y)? && c.signum() == x.signum() && s.signum() == y.signum();
    proven.then(|| angle(r))
}

/// The multiple r of π nearest `value`, with a denominator at most
/// [`MAX_DEN`].
fn guess(value: f64) -> Option<Rat> {
    if !value.is_finite() {
        return None;
    }
    let t = value / std::f64::consts::PI;
    if t.abs() < 1e-300 {
        return Some(Rat::ZERO);
    }
    Rat::approximate(t, MAX_DEN)
}

/// a < b.
fn lt(a: &Rat, b: &Rat) -> bool {
    let d = b.add(&a.neg());
    !d.is_zero() && !d.is_negative()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn num(n: i64, d: i64) -> Expr {
        Expr::constant(Coef::rat(Rat::new(n.into(), d.into()).unwrap()))
    }
    fn pi_times(n: i64, d: i64) -> Option<Expr> {
        Some(angle(Rat::new(n.into(), d.into()).unwrap()))
    }

    #[test]
    fn the_book_angles_are_exact() {
        assert_eq!(inverse(Func::Atan, &num(1, 1)), pi_times(1, 4));
        assert_eq!(inverse(Func::Asin, &num(1, 2)), pi_times(1, 6));
        assert_eq!(inverse(Func::Acos, &num(-1, 2)), pi_times(2, 3));
        assert_eq!(inverse(Func::Acos, &num(-1, 1)), pi_times(1, 1));
        assert_eq!(inverse(Func::Asin, &num(-1, 1)), pi_times(-1, 2));
        assert_eq!(inverse(Func::Atan, &num(0, 1)), pi_times(0, 1));
        assert_eq!(atan2(&num(1, 1), &num(-1, 1)), pi_times(3, 4));
        assert_eq!(atan2(&num(0, 1), &num(-2, 1)), pi_times(1, 1));
        assert_eq!(atan2(&num(-1, 1), &num(0, 1)), pi_times(-1, 2));
        let root3 = Expr::sqrt(&num(3, 1));
        assert_eq!(inverse(Func::Atan, &root3), pi_times(1, 3));
        assert_eq!(inverse(Func::Atan, &num(2, 1).sub(&root3)), pi_times(1, 12));
    }

    #[test]
    fn other_numbers_are_not_guessed() {
        // atan(0.9999999999999999) is not π/4, however close
        assert_eq!(inverse(Func::Atan, &num(9_999_999, 10_000_000)), None);
        assert_eq!(inverse(Func::Asin, &num(1, 3)), None);
        assert_eq!(atan2(&num(0, 1), &num(0, 1)), None);
        assert_eq!(atan2(&num(1, 1), &num(2, 1)), None);
    }
}
