//! Decisions from a number's value (LANGUAGE.md §7; issue 21: never a
//! wrong answer): whether a square root's argument is negative, a divisor
//! zero, an arccosine's argument in [−1, 1], a tangent at a pole, which
//! side of a branch cut `atan2` is on, how two numbers are ordered. A
//! number with an exact form is decided by it, exactly; a float with
//! none, by its float. The float of an exact number may be far from it
//! (cos(3π/2)/1e-17 is −18.4 in floats and 0 in fact), so deciding by the
//! float would refuse `sqrt(√5 + cos(3π/2)/1e-17)` and accept
//! `sqrt(−√5 + cos(π/2)/1e-17)`.
//!
//! [`Decided`] is the one way a builtin or an operator reads a scalar it
//! decides on: [`Decided::order`] orders it against a bound, [`Decided::value`]
//! is the float to compute with (the float of the exact form, whose sign
//! and zero are the exact ones). Numbers as typed decide by their float
//! (a decimal and the float it reads as are on the same side of every
//! integer), so the common case costs nothing.

use std::cmp::Ordering;

use super::exact::{Exact, is_exact};
use super::value::Value;
use crate::sym::Mat;
use crate::sym::coef::{Coef, Rat};
use crate::sym::expr::{Expr, Var};

/// A scalar as decisions read it: its float, and its exact form when it
/// has one.
#[derive(Debug, Clone)]
pub struct Decided {
    float: f64,
    exact: Option<Expr>,
    /// A number as typed: exact, deciding by its float.
    typed: bool,
}

impl Decided {
    /// The scalar `v` (a number, or a formula with no symbols left); None
    /// for anything else.
    pub fn of(v: &Value) -> Option<Decided> {
        let (float, exact, typed) = match v {
            Value::Num { m, exact, .. } if m.len() == 1 => match exact {
                Exact::Float => (m[0], None, false),
                // (the float decides as the decimal would)
                Exact::Typed => (m[0], None, true),
                Exact::Later(_) | Exact::Ratio(_) | Exact::Ratios(_) => {
                    (m[0], v.exact_form().and_then(one), false)
                }
            },
            Value::Formula { m, .. } if m.rows == 1 && m.cols == 1 => {
                let e = m.get(0, 0);
                (e.as_f64()?, is_exact(m).then(|| e.clone()), false)
            }
            _ => return None,
        };
        Some(Decided {
            float,
            exact,
            typed,
        })
    }

    /// A float with no exact form.
    pub fn float(x: f64) -> Decided {
        Decided {
            float: x,
            exact: None,
            typed: false,
        }
    }

    /// True when the number is exact (typed, or with an exact form): it
    /// is in or out of a domain by its value, with no rounding to allow
    /// for.
    pub fn is_exact(&self) -> bool {
        self.typed || self.exact.is_some()
    }

    /// The float to compute with: the float nearest the exact form when
    /// there is one (exactly 0 when it is 0, and of its sign: where the
    /// terms' floats cancel, found between exact bounds), else the float
    /// (−0 read as 0).
    pub fn value(&self) -> f64 {
        match &self.exact {
            Some(e) => nearest(e).unwrap_or(self.float) + 0.0,
            None => self.float + 0.0,
        }
    }

    /// The float of an angle to take a sine, cosine or tangent of: an
    /// exact form cπ + d with c rational has c reduced modulo 2 first,
    /// exactly (`sin(3·10¹⁷π)` is sin 0, not the sine of the float of
    /// 3·10¹⁷π, which is off by more than a turn; issue 35); else
    /// [`Decided::value`].
    pub fn angle(&self) -> f64 {
        let Some(e) = &self.exact else {
            return self.value();
        };
        let turns = e.terms.iter().find_map(|(mono, c)| {
            matches!(mono.as_slice(), [(Var::Pi, 1)])
                .then(|| c.as_rat())
                .flatten()
        });
        match turns {
            Some(r) if r.rem_euclid(2) != r => {
                // e − (r − (r mod 2))π, an even multiple of π less
                let whole = r.add(&r.rem_euclid(2).neg());
                let reduced = e.sub(&Expr::constant(Coef::rat(whole)).mul(&Expr::pi()));
                nearest(&reduced).unwrap_or_else(|| self.value())
            }
            _ => self.value(),
        }
    }

    /// True when the number is a float with no exact form so large that
    /// its last place is worth a radian or more: its angle modulo 2π is
    /// unknown, and a sine or cosine of it has no significant digit.
    pub fn angle_lost(&self) -> bool {
        !self.is_exact() && self.float.is_finite() && self.float.abs() >= 2f64.powi(53)
    }

    /// The order of the number and the integer `c`: exactly when it has
    /// an exact form (None when even 50 decimal places cannot tell), else
    /// by its float (None for NaN; a decimal as typed is on the same side
    /// of an integer as its float).
    pub fn order(&self, c: f64) -> Option<Ordering> {
        match &self.exact {
            Some(e) => {
                let c = Expr::constant(Coef::rat(Rat::typed(c)?));
                Some(sign(&e.sub(&c))?.cmp(&0))
            }
            None => self.float.partial_cmp(&c),
        }
    }

    /// True when the number is 0: exactly 0 when it has an exact form,
    /// else a float 0.
    pub fn is_zero(&self) -> bool {
        self.order(0.0) == Some(Ordering::Equal)
    }

    /// Whether the number is a pole of a trigonometric function, decided
    /// exactly for an exact number: Some(true) where cos x = 0 (`Zero::Cos`,
    /// x an odd multiple of π/2) or sin x = 0 (`Zero::Sin`, x a multiple of
    /// π); an exact number Σ cₖ πᵏ with algebraic cₖ is one only when it is
    /// a rational multiple of π (π is transcendental). None for a float.
    pub fn is_pole(&self, of: Zero) -> Option<bool> {
        if self.typed {
            // (a decimal is a multiple of π only when it is 0)
            return Some(of == Zero::Sin && self.float == 0.0);
        }
        let e = self.exact.as_ref()?;
        let r = match e.terms.iter().collect::<Vec<_>>().as_slice() {
            [] => Rat::ZERO,
            [(mono, c)] if matches!(mono.as_slice(), [(Var::Pi, 1)]) => match c.as_rat() {
                Some(r) => r,
                None => return Some(false),
            },
            _ => return Some(false),
        };
        Some(match of {
            Zero::Sin => r.is_integer(),
            Zero::Cos => r.add(&Rat::new(1, 2).unwrap_or(Rat::ZERO)).is_integer(),
        })
    }
}

/// Where a trigonometric function is infinite: where the cosine is 0
/// (tan, sec) or the sine (cot, csc).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Zero {
    /// Where cos x = 0 (x an odd multiple of π/2): the poles of tan and sec.
    Cos,
    /// Where sin x = 0 (x a multiple of π): the poles of cot and csc.
    Sin,
}

/// The one entry of a 1×1 form.
fn one(m: Mat) -> Option<Expr> {
    (m.rows == 1 && m.cols == 1).then(|| m.data.into_iter().next())?
}

/// The float of an exact number (sums of square roots times powers of
/// π) and the sum of its terms' sizes; None when it has a symbol, a
/// float coefficient or is not real. The float is within a few units in
/// the last place of the sum of sizes.
fn float_and_scale(e: &Expr) -> Option<(f64, f64)> {
    let mut scale = 0.0;
    for (mono, c) in &e.terms {
        let Coef::Exact { re, im } = c else {
            return None;
        };
        if !im.is_zero() {
            return None;
        }
        let mut p = 1.0;
        for (v, k) in mono {
            if !matches!(v, Var::Pi) {
                return None;
            }
            p *= std::f64::consts::PI.powi(*k);
        }
        scale += surd_size(re) * p;
    }
    Some((e.as_f64()?, scale))
}

/// The sum of the sizes of the terms of a coefficient a + Σ cₖ√k.
fn surd_size(s: &crate::sym::coef::Surd) -> f64 {
    s.terms()
        .map(|(k, r)| r.to_f64().abs() * (k as f64).sqrt())
        .sum()
}

/// True when the float `x` of a sum of terms of total size `scale` has
/// the sum's sign and most of its digits (no cancellation to speak of).
fn trusted(x: f64, scale: f64) -> bool {
    x.abs() > 1e-9 * scale
}

/// The sign (−1, 0 or 1) of an exact number: read off its float where
/// the terms do not nearly cancel, else exactly
/// ([`crate::sym::sign::sign_with_pi`]); None when it has a symbol, a
/// float coefficient, or is within about 1e-45 of 0 without being 0.
pub fn sign(e: &Expr) -> Option<i32> {
    if e.terms.is_empty() {
        return Some(0);
    }
    if let Some(Coef::Exact { re, im }) = e.as_const() {
        return im.is_zero().then(|| re.signum() as i32);
    }
    match float_and_scale(e)? {
        (x, scale) if trusted(x, scale) => Some(if x > 0.0 { 1 } else { -1 }),
        _ => crate::sym::sign::sign_with_pi(e),
    }
}

/// The float nearest an exact number (to within a unit in the last
/// place): its float where its terms do not cancel, else found by
/// bisection between exact signs (`√2 − 1.4142135623730951` is
/// −5.1e-17, its float 0; (π − 3.6)⁴ expanded cancels 9 digits). None
/// when it has no such form.
pub fn nearest(e: &Expr) -> Option<f64> {
    if e.terms.is_empty() {
        return Some(0.0);
    }
    let (x, scale) = float_and_scale(e)?;
    // (a fraction's float is the nearest; a sum whose terms cancel by
    // less than half has every digit of its float but the last few)
    if e.as_const().is_some_and(|c| c.as_rat().is_some()) || x.abs() >= 0.5 * scale {
        return Some(x);
    }
    // v is within 8 ulp(scale) of x: bisect on the floats' order
    let above = |c: f64| -> Option<bool> {
        let c = Expr::constant(Coef::rat(Rat::typed(c)?));
        Some(crate::sym::sign::sign_with_pi(&e.sub(&c))? <= 0)
    };
    let slack = 16.0 * f64::EPSILON * scale;
    let (mut lo, mut hi) = (key(x - slack), key(x + slack));
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        match above(unkey(mid)) {
            Some(true) => hi = mid,
            Some(false) => lo = mid,
            // (within 1e-45 of it: as near as the bounds tell)
            None => return Some(unkey(mid)),
        }
    }
    Some(unkey(hi))
}

/// The floats in order as integers (−0 and 0 alike).
fn key(x: f64) -> i64 {
    let b = x.to_bits() as i64;
    if b < 0 { -(b & i64::MAX) } else { b }
}

/// The float of a [`key`].
fn unkey(k: i64) -> f64 {
    if k < 0 {
        -f64::from_bits(k.unsigned_abs())
    } else {
        f64::from_bits(k as u64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pi_times(p: i128, q: i128) -> Expr {
        Expr::pi().scale(&Coef::rat(Rat::new(p, q).expect("a fraction")))
    }

    fn exact(e: Expr) -> Decided {
        Decided {
            float: e.as_f64().unwrap_or(f64::NAN),
            exact: Some(e),
            typed: false,
        }
    }

    #[test]
    fn exact_numbers_decide_exactly() {
        // π − 3.141592653589793 > 0, though its float is 0
        let d = exact(Expr::pi().sub(&Expr::constant(Coef::rat(
            Rat::typed(std::f64::consts::PI).expect("finite"),
        ))));
        assert_eq!(d.order(0.0), Some(Ordering::Greater));
        assert!(d.value() > 0.0);
        // a float far from its exact value: the exact one decides
        let zero = Decided {
            float: -18.4,
            exact: Some(Expr::default()),
            typed: false,
        };
        assert!(zero.is_zero());
        assert_eq!(zero.value(), 0.0);
        assert_eq!(Decided::float(-0.0).value().to_bits(), 0f64.to_bits());
        assert_eq!(Decided::float(f64::NAN).order(0.0), None);
        // cancelling terms: the float nearest the number, not 0
        let r = Expr::constant(Coef::rat(
            Rat::typed(std::f64::consts::SQRT_2).expect("finite"),
        ));
        let two = Expr::constant(Coef::real(
            crate::sym::coef::Surd::sqrt_of(&Rat::int(2)).expect("√2"),
        ));
        let d = exact(two.sub(&r));
        // √2 − 1.4142135623730951 = −5.1198311275790304e-17
        let want = -5.119_831_127_579_030_4e-17;
        assert!(
            (d.value() - want).abs() <= 2.0 * f64::EPSILON * want.abs(),
            "{}",
            d.value()
        );
        let p = exact(Expr::pi().sub(&Expr::constant(Coef::rat(
            Rat::typed(std::f64::consts::PI).expect("finite"),
        ))));
        // π − 3.141592653589793 = 2.384626433832795e-16
        let want = 2.384_626_433_832_795e-16;
        assert!(
            (p.value() - want).abs() <= 2.0 * f64::EPSILON * want,
            "{}",
            p.value()
        );
    }

    #[test]
    fn poles_are_rational_multiples_of_pi() {
        assert_eq!(exact(pi_times(3, 2)).is_pole(Zero::Cos), Some(true));
        assert_eq!(exact(pi_times(-1, 2)).is_pole(Zero::Cos), Some(true));
        assert_eq!(exact(pi_times(1, 3)).is_pole(Zero::Cos), Some(false));
        assert_eq!(exact(pi_times(2, 1)).is_pole(Zero::Sin), Some(true));
        assert_eq!(exact(Expr::default()).is_pole(Zero::Sin), Some(true));
        assert_eq!(exact(Expr::int(1)).is_pole(Zero::Sin), Some(false));
        let near = pi_times(1, 2).add(&Expr::constant(Coef::rat(
            Rat::typed(1e-20).expect("finite"),
        )));
        assert_eq!(exact(near).is_pole(Zero::Cos), Some(false));
        assert_eq!(Decided::float(1.0).is_pole(Zero::Cos), None);
    }
}
