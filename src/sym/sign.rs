//! The sign of an exact number with π in it (LANGUAGE.md §3: exact
//! numbers are ordered exactly): Σ cₖ πᵏ with cₖ sums of square roots, bounded
//! between two fractions with π and each root known to 50 decimal
//! places. The float of such a difference loses what matters (π −
//! 3.141592653589793 is 0 in floats, 1.2e-16 in fact); the bounds keep it,
//! and say nothing (None) only when the number is within about 1e-45 of 0
//! without being 0.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use super::coef::Coef;
use super::expr::{Expr, Var};

/// π to 60 decimal places (below by less than 1e-60).
const PI_DIGITS: &str = "3141592653589793238462643383279502884197169399375105820974944";

/// Decimal places of the bounds.
const PLACES: usize = 50;

/// A closed interval [lo, hi] of fractions.
#[derive(Clone, Debug)]
struct Iv {
    lo: BigRational,
    hi: BigRational,
}

impl Iv {
    fn point(x: BigRational) -> Iv {
        Iv {
            lo: x.clone(),
            hi: x,
        }
    }
    fn add(&self, o: &Iv) -> Iv {
        Iv {
            lo: &self.lo + &o.lo,
            hi: &self.hi + &o.hi,
        }
    }
    fn mul(&self, o: &Iv) -> Iv {
        let c = [
            &self.lo * &o.lo,
            &self.lo * &o.hi,
            &self.hi * &o.lo,
            &self.hi * &o.hi,
        ];
        let lo = c.iter().min().cloned().unwrap_or_else(BigRational::zero);
        let hi = c.iter().max().cloned().unwrap_or_else(BigRational::zero);
        Iv { lo, hi }
    }
    /// 1/x for an interval of positive numbers.
    fn recip_positive(&self) -> Option<Iv> {
        (self.lo.is_positive()).then(|| Iv {
            lo: self.hi.recip(),
            hi: self.lo.recip(),
        })
    }
}

/// 10^-PLACES.
fn ulp() -> BigRational {
    BigRational::new(BigInt::one(), num_traits::pow(BigInt::from(10), PLACES))
}

/// π between two fractions.
fn pi() -> Iv {
    let digits: BigInt = PI_DIGITS[..PLACES + 1].parse().unwrap_or_default();
    let lo = BigRational::new(digits, num_traits::pow(BigInt::from(10), PLACES));
    Iv {
        hi: &lo + ulp(),
        lo,
    }
}

/// √k between two fractions (k a positive integer).
fn root(k: u128) -> Iv {
    let scale = num_traits::pow(BigInt::from(10), PLACES);
    let s = (BigInt::from(k) * &scale * &scale).sqrt();
    let lo = BigRational::new(s, scale);
    Iv {
        hi: &lo + ulp(),
        lo,
    }
}

/// The sign (−1, 0 or 1) of an expression whose every monomial is a
/// power of π (or 1) with a real exact coefficient; None when some term
/// is not of that kind, or the bounds cannot tell the sign.
pub fn sign_with_pi(e: &Expr) -> Option<i32> {
    if e.terms.is_empty() {
        return Some(0);
    }
    let pi = pi();
    let mut sum = Iv::point(BigRational::zero());
    for (mono, c) in &e.terms {
        let Coef::Exact { re, im } = c else {
            return None;
        };
        if !im.is_zero() {
            return None;
        }
        // the coefficient a + Σ cₖ√k
        let mut coef = Iv::point(BigRational::zero());
        for (k, r) in re.terms() {
            let term = Iv::point(r.to_big());
            coef = coef.add(&if k == 1 { term } else { term.mul(&root(k)) });
        }
        // times π^k
        let mut term = coef;
        for (v, k) in mono {
            if !matches!(v, Var::Pi) {
                return None;
            }
            let base = if *k < 0 {
                pi.recip_positive()?
            } else {
                pi.clone()
            };
            for _ in 0..k.unsigned_abs() {
                term = term.mul(&base);
            }
        }
        sum = sum.add(&term);
    }
    if sum.lo.is_positive() {
        Some(1)
    } else if sum.hi.is_negative() {
        Some(-1)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::coef::Rat;

    #[test]
    fn signs_near_pi() {
        let c = |x: f64| Expr::constant(Coef::rat(Rat::typed(x).expect("finite")));
        // π − 3.141592653589793 > 0 though its float is 0
        assert_eq!(
            sign_with_pi(&Expr::pi().sub(&c(std::f64::consts::PI))),
            Some(1)
        );
        let above = Expr::constant(Coef::rat(Rat::decimal(
            &"31415926535897932385".parse().expect("digits"),
            -19,
        )));
        assert_eq!(sign_with_pi(&Expr::pi().sub(&above)), Some(-1));
        assert_eq!(sign_with_pi(&Expr::default()), Some(0));
    }
}
