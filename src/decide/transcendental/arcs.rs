//! The arcs' normal form a + Σ cᵢ atan αᵢ ([`Form::Arc`]): atan, asin,
//! acos and atan2 of exact reals put with αᵢ in (0, 1), and sums of them
//! folded into one arc by the addition formula, so that identities between
//! arcs (`acos(0.3) == pi/2 - asin(0.3)`, Machin's formula) are equal
//! forms.

use super::Form;
use crate::sym::Expr;
use crate::sym::coef::{Coef, Rat, Surd};
use num_traits::{ToPrimitive, Zero};

/// The most atan additions [`Form::combined`] makes to put a sum of arcs
/// in one.
const MAX_ARC_STEPS: i64 = 64;

impl Form {
    /// atan α of an exact real α, in the form of [`Form::Arc`].
    pub(super) fn atan(alpha: Surd) -> Option<Form> {
        let sign = alpha.signum();
        if sign == 0.0 {
            return Some(Form::exact(Surd::ZERO));
        }
        let (beta, k) = if sign < 0.0 {
            (alpha.neg(), -1)
        } else {
            (alpha, 1)
        };
        let quarter =
            |n: i128| -> Option<Expr> { Some(Expr::pi().scale(&Coef::rat(Rat::new(n * k, 4)?))) };
        let one = Surd::rat(Rat::ONE);
        if beta == one {
            return quarter(1).map(Form::leaf);
        }
        let inside = beta.add(&one.neg()).signum() < 0.0;
        let (a, alpha, c) = if inside {
            (Expr::zero(), beta, Rat::new(k, 1)?)
        } else {
            (quarter(2)?, beta.inv()?, Rat::new(-k, 1)?)
        };
        Some(Form::Arc {
            a,
            c: vec![(alpha, c)],
        })
    }

    /// The form as a + Σ cᵢ atan αᵢ, when it is one (an exact constant is,
    /// with no terms).
    pub(super) fn as_arc(&self) -> Option<(Expr, Vec<(Surd, Rat)>)> {
        match self {
            Form::Arc { a, c } => Some((a.clone(), c.clone())),
            _ => {
                let (a, c) = self.as_log()?;
                c.is_empty().then_some((a, Vec::new()))
            }
        }
    }

    /// a + Σ cᵢ atan αᵢ, like terms collected (a constant without terms).
    pub(super) fn arc(a: Expr, terms: Vec<(Surd, Rat)>) -> Form {
        let mut c: Vec<(Surd, Rat)> = Vec::new();
        for (alpha, r) in terms {
            match c.iter_mut().find(|(b, _)| *b == alpha) {
                Some((_, s)) => *s = s.add(&r),
                None => c.push((alpha, r)),
            }
        }
        c.retain(|(_, r)| !r.is_zero());
        if c.is_empty() {
            return Form::leaf(a);
        }
        if let Some(one) = Form::combined(&a, &c) {
            return one;
        }
        c.sort_by(|(x, _), (y, _)| x.to_f64().total_cmp(&y.to_f64()));
        Form::Arc { a, c }
    }

    /// a + Σ cᵢ atan αᵢ as one arc, a' + (1/d) atan β, by the
    /// addition formula atan β + atan γ = atan((β + γ)/(1 − βγ)) (β, γ in
    /// (−1, 1), so 1 − βγ > 0 and the sum is in (−π/2, π/2)), β put back
    /// in (−1, 1) after each step as [`Form::atan`] does: atan ½ + atan ⅓
    /// = atan 1 = π/4, 4 atan(1/5) − atan(1/239) = π/4 (Machin); d is the
    /// least common denominator of the cᵢ. None past [`MAX_ARC_STEPS`]
    /// steps (d too).
    fn combined(base: &Expr, c: &[(Surd, Rat)]) -> Option<Form> {
        // (fractional cᵢ: (1/d)·Σ (d cᵢ) atan αᵢ, d the least common
        // denominator)
        let mut d = 1i64;
        for (_, r) in c {
            let den = r.parts().1.to_i64()?;
            d = d.checked_mul(den / num_integer::gcd(d, den))?;
            if d > MAX_ARC_STEPS {
                return None;
            }
        }
        let whole: Vec<i64> = c
            .iter()
            .map(|(_, r)| r.mul(&Rat::int(d)).as_int())
            .collect::<Option<_>>()?;
        let steps: i64 = whole.iter().map(|n| n.abs()).sum();
        if steps > MAX_ARC_STEPS || (c.len() == 1 && steps == 1) {
            return None;
        }
        let one = Surd::rat(Rat::ONE);
        let (mut a, mut beta) = (Expr::zero(), Surd::ZERO);
        for ((alpha, _), &n) in c.iter().zip(&whole) {
            let gamma = if n < 0 { alpha.neg() } else { alpha.clone() };
            for _ in 0..n.abs() {
                let sum = beta.add(&gamma);
                let den = one.add(&beta.mul(&gamma)?.neg());
                let next = sum.mul(&den.inv()?)?;
                match Form::atan(next)? {
                    Form::Arc { a: shift, c } => {
                        let [(b, k)] = c.as_slice() else { return None };
                        a = a.add(&shift);
                        beta = if k.is_negative() { b.neg() } else { b.clone() };
                    }
                    leaf => {
                        // (±π/4 or 0: no arc left)
                        let (shift, _) = leaf.as_log()?;
                        a = a.add(&shift);
                        beta = Surd::ZERO;
                    }
                }
            }
        }
        let by_d = Coef::rat(Rat::new(1, i128::from(d))?);
        let a = base.add(&a.scale(&by_d));
        Some(match beta.signum() {
            0.0 => Form::leaf(a),
            s => Form::Arc {
                a,
                c: vec![(
                    if s < 0.0 { beta.neg() } else { beta },
                    Rat::new(if s < 0.0 { -1 } else { 1 }, i128::from(d))?,
                )],
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// atan α in (0, 1) normal form: odd, atan α = π/2 − atan(1/α), and
    /// sums with whole or fractional coefficients folded by the addition
    /// formula into one arc.
    #[test]
    fn arcs_are_put_in_one_form() {
        let r = |n, d| Surd::rat(Rat::new(n, d).unwrap());
        let atan = |n, d| Form::atan(r(n, d)).unwrap();
        let pi_by = |n, d| Form::leaf(Expr::pi().scale(&Coef::rat(Rat::new(n, d).unwrap())));
        // atan 2 = π/2 − atan ½; atan(−3) = −π/2 + atan ⅓; atan 1 = π/4
        assert_eq!(atan(2, 1), pi_by(1, 2).add(&atan(1, 2).neg()).unwrap());
        assert_eq!(atan(-3, 1), pi_by(-1, 2).add(&atan(1, 3)).unwrap());
        assert_eq!(atan(1, 1), pi_by(1, 4));
        assert_eq!(atan(0, 1), Form::exact(Surd::ZERO));
        // Machin: 4 atan ⅕ − atan(1/239) = π/4
        let four = Form::exact(r(4, 1));
        let machin = four
            .mul(&atan(1, 5))
            .unwrap()
            .add(&atan(1, 239).neg())
            .unwrap();
        assert_eq!(machin, pi_by(1, 4));
        // (atan ½ + atan ⅓)/2 = π/8; a lone arc stays itself
        let half = Form::exact(r(1, 2));
        let sum = atan(1, 2).add(&atan(1, 3)).unwrap().mul(&half).unwrap();
        assert_eq!(sum, pi_by(1, 8));
        let third = atan(1, 2).mul(&Form::exact(r(1, 3))).unwrap();
        assert_eq!(
            third,
            Form::Arc {
                a: Expr::zero(),
                c: vec![(r(1, 2), Rat::new(1, 3).unwrap())]
            }
        );
        // unequal sums are unequal forms (nothing is proven either way)
        assert_ne!(atan(1, 2).add(&atan(1, 4)).unwrap(), pi_by(1, 4));
    }
}
