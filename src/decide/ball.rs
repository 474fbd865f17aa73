//! Certified high-precision numbers for `==` (LANGUAGE.md §7): a real
//! number as a ball — a midpoint and a radius that the true value is
//! certainly within — at a chosen precision in bits, with the elementary
//! functions of the book (sin, cos, tan, exp, ln, sqrt, atan) bounding
//! their result rigorously (dashu-float's correctly rounded kernels, one
//! ulp of rounding, and the input's radius times the function's largest
//! slope over the ball). A ball whose radius does not exclude a pole or a
//! domain edge (`1/x` near 0, `sqrt` near 0) is refused (None), never
//! guessed. [`super::certify`] evaluates a number's recipe with these.

use dashu_float::round::mode::HalfEven;
use dashu_float::{Context, FBig, Mag, Repr, ulp_mag};
use dashu_int::IBig;

use crate::sym::coef::{Coef, Rat};
use crate::sym::expr::{Expr, Var};

/// A real number known to lie within `rad` of `mid` (binary).
pub type Ball = dashu_float::Ball<2>;

/// A ball of the exact integer `n`.
pub fn int(n: &num_bigint::BigInt) -> Ball {
    Ball::exact(Repr::new(IBig::from_le_bytes(&n.to_signed_bytes_le()), 0))
}

/// A ball of the exact fraction `r` at `prec` bits.
pub fn rat(r: &Rat, prec: usize) -> Option<Ball> {
    let (p, q) = r.parts();
    checked(int(&p).div(&int(&q), prec).ok()?)
}

/// A ball of π at `prec` bits.
pub fn pi(prec: usize) -> Ball {
    let ctx = Context::<HalfEven>::new(prec);
    rounded(ctx.pi::<2>(None), prec)
}

/// A ball of an exact number: a sum of exact real coefficients (rationals
/// and square roots of square-free integers, `sym::surd`) times powers of π. None for anything
/// else (a symbol, a kept call, a float or complex coefficient).
pub fn exact(e: &Expr, prec: usize) -> Option<Ball> {
    let mut sum = Ball::exact(Repr::zero());
    for (mono, c) in &e.terms {
        let Coef::Exact { re, im } = c else {
            return None;
        };
        if !im.is_zero() {
            return None;
        }
        let mut term = Ball::exact(Repr::zero());
        for (root, r) in re.terms() {
            let mut x = rat(r, prec)?;
            if root != 1 {
                let s = sqrt(&int(&root.into()), prec)?;
                x = x.mul(&s, prec).ok()?;
            }
            term = term.add(&x, prec).ok()?;
        }
        for (v, k) in mono {
            match v {
                Var::Pi => {
                    term = term
                        .mul(&powi(&pi(prec), i64::from(*k), prec)?, prec)
                        .ok()?
                }
                _ => return None,
            }
        }
        sum = sum.add(&term, prec).ok()?;
    }
    checked(sum)
}

/// `a + b`, `a − b`, `a b`, `a / b` (None when `b`'s ball holds 0).
pub fn add(a: &Ball, b: &Ball, prec: usize) -> Option<Ball> {
    checked(a.add(b, prec).ok()?)
}
/// `a − b`.
pub fn sub(a: &Ball, b: &Ball, prec: usize) -> Option<Ball> {
    checked(a.sub(b, prec).ok()?)
}
/// `a b`.
pub fn mul(a: &Ball, b: &Ball, prec: usize) -> Option<Ball> {
    checked(a.mul(b, prec).ok()?)
}
/// `a / b`, None when `b` may be 0.
pub fn div(a: &Ball, b: &Ball, prec: usize) -> Option<Ball> {
    if !nonzero(b) {
        return None;
    }
    checked(a.div(b, prec).ok()?)
}
/// `−a`.
pub fn neg(a: &Ball) -> Ball {
    -a.clone()
}

/// `a^k` for an integer `k` (by squaring; a negative power divides).
pub fn powi(a: &Ball, k: i64, prec: usize) -> Option<Ball> {
    let mut out = Ball::exact(Repr::one());
    let mut base = a.clone();
    let mut n = k.unsigned_abs();
    while n > 0 {
        if n & 1 == 1 {
            out = mul(&out, &base, prec)?;
        }
        n >>= 1;
        if n > 0 {
            base = mul(&base, &base, prec)?;
        }
    }
    if k < 0 {
        div(&Ball::exact(Repr::one()), &out, prec)
    } else {
        Some(out)
    }
}

/// √a: None unless the ball is exactly 0 or lies in (0, ∞) clear of 0.
pub fn sqrt(a: &Ball, prec: usize) -> Option<Ball> {
    if a.mid.significand().is_zero() {
        return a.rad.is_zero().then(|| a.clone());
    }
    if a.mid.significand().sign() == dashu_int::Sign::Negative || !nonzero(a) {
        return None;
    }
    checked(a.sqrt(prec).ok()?)
}

/// |a| (its slope is at most 1).
pub fn abs(a: &Ball) -> Ball {
    if a.mid.significand().sign() == dashu_int::Sign::Negative {
        neg(a)
    } else {
        a.clone()
    }
}

/// A function of slope at most `slope` over the ball (an upper bound):
/// the correctly rounded value at the midpoint, one ulp of rounding, and
/// the input's radius times the slope.
fn lipschitz(
    f: impl FnOnce(&Context<HalfEven>, &Repr<2>) -> dashu_float::FpResult<FBig<HalfEven, 2>>,
    a: &Ball,
    slope: Mag,
    prec: usize,
) -> Option<Ball> {
    let ctx = Context::<HalfEven>::new(prec);
    let mut out = rounded(f(&ctx, &a.mid).ok()?, prec);
    out.add_error(a.rad.mul(&slope));
    checked(out)
}

/// sin a.
pub fn sin(a: &Ball, prec: usize) -> Option<Ball> {
    lipschitz(|c, x| c.sin(x, None), a, Mag::ONE, prec)
}
/// cos a.
pub fn cos(a: &Ball, prec: usize) -> Option<Ball> {
    lipschitz(|c, x| c.cos(x, None), a, Mag::ONE, prec)
}
/// atan a.
pub fn atan(a: &Ball, prec: usize) -> Option<Ball> {
    lipschitz(|c, x| c.atan(x, None), a, Mag::ONE, prec)
}
/// tan a = sin a / cos a (None where cos may vanish).
pub fn tan(a: &Ball, prec: usize) -> Option<Ball> {
    div(&sin(a, prec)?, &cos(a, prec)?, prec)
}
/// exp a: slope e^(a + r) ≤ (|e^mid| + ulp) e^r.
pub fn exp(a: &Ball, prec: usize) -> Option<Ball> {
    let ctx = Context::<HalfEven>::new(prec);
    let mid = rounded(ctx.exp(&a.mid, None).ok()?, prec);
    let slope = mid.mag().mul(&a.rad.exp_upper());
    lipschitz(|c, x| c.exp(x, None), a, slope, prec)
}
/// ln a, for a ball clear of 0 on the positive side: slope 1/(mid − r).
pub fn ln(a: &Ball, prec: usize) -> Option<Ball> {
    if a.mid.significand().sign() == dashu_int::Sign::Negative || !nonzero(a) {
        return None;
    }
    let low = Mag::from_repr_lower(&a.mid).sub_down(&a.rad);
    if low.is_zero() {
        return None;
    }
    lipschitz(|c, x| c.ln(x, None), a, Mag::ONE.div(&low), prec)
}

/// asin a = atan(a / √(1 − a²)), for a ball inside (−1, 1) (None when
/// it may reach ±1, where the slope is infinite).
pub fn asin(a: &Ball, prec: usize) -> Option<Ball> {
    let one = Ball::exact(Repr::one());
    let c = sub(&one, &mul(a, a, prec)?, prec)?;
    if !positive(&c) {
        return None;
    }
    atan(&div(a, &sqrt(&c, prec)?, prec)?, prec)
}

/// acos a = π/2 − asin a, for a ball inside (−1, 1).
pub fn acos(a: &Ball, prec: usize) -> Option<Ball> {
    let half_pi = div(&pi(prec), &int(&2.into()), prec)?;
    sub(&half_pi, &asin(a, prec)?, prec)
}

/// atan2(y, x), the angle of (x, y) in (−π, π] (§3.2.3.3's θ): atan(y/x)
/// for x > 0, ±π/2 − atan(x/y) for y ≠ 0 of sign ±, π for y = 0 exactly
/// and x < 0; None on the branch cut (x < 0, y's ball holding 0 but not
/// only 0) and at the origin.
pub fn atan2(y: &Ball, x: &Ball, prec: usize) -> Option<Ball> {
    if positive(x) {
        return atan(&div(y, x, prec)?, prec);
    }
    if nonzero(y) {
        let half_pi = div(&pi(prec), &int(&2.into()), prec)?;
        let r = atan(&div(x, y, prec)?, prec)?;
        return if positive(y) {
            sub(&half_pi, &r, prec)
        } else {
            sub(&neg(&half_pi), &r, prec)
        };
    }
    let exact_zero = y.rad.is_zero() && y.mid.significand().is_zero();
    (exact_zero && nonzero(x)).then(|| pi(prec))
}

/// True when the ball certainly holds only positive numbers.
fn positive(a: &Ball) -> bool {
    nonzero(a) && a.mid.significand().sign() == dashu_int::Sign::Positive
}

/// True when the ball certainly excludes 0.
pub fn nonzero(a: &Ball) -> bool {
    Mag::from_repr_lower(&a.mid) > a.rad
}

/// The midpoint and the radius as floats (the radius rounded up).
pub fn floats(a: &Ball) -> (f64, f64) {
    let (v, r) = a.to_value_radius(&Context::<HalfEven>::new(64));
    let rad = r.to_f64().value();
    let rad = if rad == 0.0 { 0.0 } else { rad.next_up() };
    (v.to_f64().value(), rad)
}

/// A correctly rounded kernel's result as a ball: one ulp when inexact.
fn rounded(r: dashu_float::round::Rounded<FBig<HalfEven, 2>>, prec: usize) -> Ball {
    use dashu_float::round::Rounded;
    match r {
        Rounded::Exact(f) => Ball::exact(f.into_repr()),
        Rounded::Inexact(f, _) => {
            let mid = f.into_repr();
            let rad = ulp_mag(&mid, prec);
            Ball::with_error(mid, rad)
        }
    }
}

/// The ball, unless its radius is infinite (a pole inside it).
fn checked(b: Ball) -> Option<Ball> {
    (!b.rad.is_infinite() && !b.mid.is_infinite()).then_some(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(p: i128, q: i128) -> Ball {
        rat(&Rat::new(p, q).unwrap(), 200).unwrap()
    }

    #[test]
    fn cos_of_a_billionth_is_below_one() {
        let x = r(1, 1_000_000_000);
        let d = sub(&cos(&x, 200).unwrap(), &r(1, 1), 200).unwrap();
        assert!(nonzero(&d));
        let (m, rad) = floats(&d);
        assert!((m + 5e-19).abs() < 1e-30 && rad < 1e-50, "{m} ± {rad}");
    }

    #[test]
    fn an_identity_stays_within_its_radius() {
        let one = r(1, 1);
        let s = sin(&one, 300).unwrap();
        let c = cos(&one, 300).unwrap();
        let sum = add(&mul(&s, &s, 300).unwrap(), &mul(&c, &c, 300).unwrap(), 300).unwrap();
        let d = sub(&sum, &one, 300).unwrap();
        assert!(!nonzero(&d));
        assert!(floats(&d).1 < 1e-85);
    }

    #[test]
    fn poles_and_domains_are_refused() {
        let zero = Ball::exact(Repr::zero());
        assert!(div(&r(1, 1), &zero, 100).is_none());
        assert!(sqrt(&r(-1, 1), 100).is_none());
        assert!(ln(&zero, 100).is_none());
        let two = sqrt(&r(4, 1), 100).unwrap();
        assert_eq!(floats(&two).0, 2.0);
        let e = exp(&r(1, 1), 200).unwrap();
        assert!((floats(&e).0 - std::f64::consts::E).abs() < 1e-15);
        let l = ln(&e, 200).unwrap();
        assert!((floats(&l).0 - 1.0).abs() < 1e-15);
        let t = tan(&r(1, 1), 200).unwrap();
        assert!((floats(&t).0 - 1f64.tan()).abs() < 1e-15);
        let a = atan(&r(1, 1), 200).unwrap();
        assert!((floats(&a).0 - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        assert!((floats(&pi(200)).0 - std::f64::consts::PI).abs() < 1e-15);
    }
}
