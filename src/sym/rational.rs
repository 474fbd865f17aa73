//! Quotients and roots of canonical expressions (LANGUAGE.md §7): exact
//! division of one expression by another (so that common factors cancel,
//! `(a² − b²)/(a − b)` = a + b, `sin 2t / cos t` = 2 sin t), the cancellation
//! of a kept reciprocal `1/(d)` against a numerator that d divides, and the
//! square root of a perfect square, √(p²) = |p|. Every step is exact: where
//! a division or a root is not exact the expression is left as it is.
//!
//! Division is by leading terms under the lexicographic order of exponents
//! (over the sorted variables), which is compatible with products of
//! Laurent monomials: the leading term of a product is the product of the
//! leading terms, so an exact quotient is found term by term.

use std::cmp::Ordering;

use super::coef::{Coef, Surd};
use super::expr::{Expr, Func, Mono, Var, mono_mul};
use num_traits::Zero;

/// Lexicographic comparison of two monomials' exponent vectors.
fn cmp_lex(a: &Mono, b: &Mono) -> Ordering {
    let (mut i, mut j) = (0, 0);
    loop {
        match (a.get(i), b.get(j)) {
            (None, None) => return Ordering::Equal,
            (Some((_, e)), None) => return e.cmp(&0),
            (None, Some((_, f))) => return 0.cmp(f),
            (Some((v, e)), Some((w, f))) => match v.cmp(w) {
                Ordering::Less => return e.cmp(&0),
                Ordering::Greater => return 0.cmp(f),
                Ordering::Equal => match e.cmp(f) {
                    Ordering::Equal => {
                        i += 1;
                        j += 1;
                    }
                    o => return o,
                },
            },
        }
    }
}

/// a / b for monomials.
fn mono_div(a: &Mono, b: &Mono) -> Mono {
    let inv: Mono = b
        .iter()
        .map(|(v, e)| (v.clone(), e.saturating_neg()))
        .collect();
    mono_mul(a, &inv)
}

fn single(m: Mono, c: Coef) -> Expr {
    let mut e = Expr::zero();
    e.push(m, c);
    e
}

impl Expr {
    /// The leading term (largest monomial in the lexicographic order).
    fn leading(&self) -> Option<(&Mono, &Coef)> {
        self.terms.iter().max_by(|a, b| cmp_lex(a.0, b.0))
    }
    /// The trailing term (smallest monomial).
    fn trailing(&self) -> Option<(&Mono, &Coef)> {
        self.terms.iter().min_by(|a, b| cmp_lex(a.0, b.0))
    }

    /// The exact quotient self / d, when d divides self (as Laurent
    /// polynomials in the symbols, the z's and the kept calls); None when
    /// it does not, or when d is 0.
    pub fn div_exact(&self, d: &Expr) -> Option<Expr> {
        if d.is_zero() {
            return None;
        }
        if self.is_zero() {
            return Some(Expr::zero());
        }
        if d.terms.len() == 1 {
            return Some(self.mul(&d.recip()?));
        }
        let (dm, dc) = d.leading()?;
        let dinv = dc.inv()?;
        // every monomial of the quotient lies between these two
        let low = mono_div(self.trailing()?.0, d.trailing()?.0);
        let limit = 4 * (self.terms.len() + d.terms.len()) + 64;
        // a quotient's coefficients far longer than those divided: no
        // exact quotient in sight, and each step would cost more (the
        // remainder of a 25th power of a sum over cos u + 0.905 grew by
        // 1.81 a step, to thousands of digits: 10 s, sym differential
        // seed 900623); given up as not dividing, which keeps the
        // reciprocal, a right value
        let words = |e: &Expr| e.terms.values().map(Coef::words).max().unwrap_or(0);
        let cap = 4 * words(self).max(words(d)) + 16;
        let mut r = self.clone();
        let mut q = Expr::zero();
        for _ in 0..limit {
            let Some((rm, rc)) = r.leading() else {
                return Some(q);
            };
            if exact_zero(rc) {
                return None;
            }
            let m = mono_div(rm, dm);
            if cmp_lex(&m, &low) == Ordering::Less {
                return None;
            }
            let c = rc.mul(&dinv);
            if c.words() > cap {
                return None;
            }
            // (in place: a copy of r and q each step was quadratic)
            for (m, c) in single(m.clone(), c.clone()).mul(d).neg().terms {
                r.push(m, c);
            }
            q.push(m, c);
            if r.terms.len() > 8 * (self.terms.len() + d.terms.len()) + 64 {
                return None;
            }
        }
        r.is_zero().then_some(q)
    }

    /// True when some monomial holds a kept reciprocal.
    pub fn has_recip(&self) -> bool {
        self.terms
            .keys()
            .flatten()
            .any(|(v, e)| is_recip(v) && *e > 0)
    }

    /// Kept reciprocals cancelled where their sum divides the numerator
    /// that they multiply: `(a + b) · 1/(a + b)` = 1, `2 sin t · 1/(2 cos t)`
    /// stays (a tangent), `sin 2t · 1/(cos t)` = 2 sin t; terms over
    /// reciprocals of sums are put over one denominator first
    /// ([`super::together::together`]).
    pub fn cancel(&self) -> Expr {
        if !self.has_recip() {
            return self.clone();
        }
        // numerators grouped by their denominator (the reciprocal factors)
        let mut groups: std::collections::BTreeMap<Mono, Expr> = Default::default();
        for (m, c) in &self.terms {
            let (den, rest): (Mono, Mono) =
                m.iter().cloned().partition(|(v, e)| is_recip(v) && *e > 0);
            groups.entry(den).or_default().push(rest, c.clone());
        }
        // terms over reciprocals of sums: over one denominator
        let groups = super::together::together(groups);
        let mut out = Expr::zero();
        for (den, mut num) in groups {
            let mut left: Mono = Vec::new();
            for (v, e) in den {
                let Var::Call(call) = &v else { continue };
                let d = &call.args[0];
                let mut k = e;
                while k > 0 {
                    match num.div_exact(d) {
                        Some(q) => {
                            num = q;
                            k -= 1;
                        }
                        None => break,
                    }
                }
                if k > 0 {
                    left.push((v.clone(), k));
                }
            }
            out = out.add(&num.mul(&single(left, Coef::one())));
        }
        out
    }

    /// √x where x is the square of an expression p: |p| (an `abs` call
    /// unless p is a positive constant); None when x is not a perfect
    /// square found exactly.
    pub fn sqrt_of_square(&self) -> Option<Expr> {
        let p = self.square_root_poly()?;
        if p.conj() != p {
            return None;
        }
        if let Some(c) = p.as_const() {
            let (re, im) = c.to_c64();
            if im != 0.0 {
                return None;
            }
            return Some(Expr::constant(if re < 0.0 { c.neg() } else { c }));
        }
        // |p| = |−p|: the sign that makes the leading coefficient positive
        let (_, lead) = p.terms.iter().next()?;
        let p = match lead.as_real() {
            Some(s) if s.signum() < 0.0 => p.neg(),
            _ => p,
        };
        Some(Expr::call(Func::Abs, vec![p]))
    }

    /// A p with p² = self, found term by term from the leading term.
    fn square_root_poly(&self) -> Option<Expr> {
        let (lm, lc) = self.leading()?;
        if lm.iter().any(|(_, e)| e % 2 != 0) {
            return None;
        }
        let root_m: Mono = lm.iter().map(|(v, e)| (v.clone(), e / 2)).collect();
        let root_c = coef_sqrt(lc)?;
        let mut p = single(root_m, root_c.clone());
        let (pm, pc) = (p.terms.keys().next()?.clone(), root_c.clone());
        let two_inv = pc.mul(&Coef::int(2)).inv()?;
        let low = {
            let (tm, _) = self.trailing()?;
            if tm.iter().any(|(_, e)| e % 2 != 0) {
                return None;
            }
            tm.iter().map(|(v, e)| (v.clone(), e / 2)).collect::<Mono>()
        };
        // (given up, as div_exact is, once a coefficient of the root grows
        // past 4 times the longest of x's plus 16 words, or the squares
        // formed pass MAX_SQUARING term products: no exact root is found
        // then, and √x is kept — the norm of a vector of large entries
        // with decimal coefficients spent minutes here, matrix seed 821232)
        let words = |e: &Expr| e.terms.values().map(Coef::words).max().unwrap_or(0);
        let cap = 4 * words(self) + 16;
        let mut work = 0usize;
        for _ in 0..(2 * self.terms.len() + 8) {
            // (a term product of coefficients w words long costs about w²)
            let w = 1 + words(&p);
            work = work.saturating_add(
                p.terms
                    .len()
                    .saturating_mul(p.terms.len())
                    .saturating_mul(w * w),
            );
            if work > MAX_SQUARING {
                return None;
            }
            let r = self.sub(&p.mul(&p));
            let Some((rm, rc)) = r.leading() else {
                return Some(p);
            };
            if exact_zero(rc) || rc.words() > cap {
                return None;
            }
            let m = mono_div(rm, &pm);
            if cmp_lex(&m, &low) == Ordering::Less {
                return None;
            }
            p = p.add(&single(m, rc.mul(&two_inv)));
        }
        self.sub(&p.mul(&p)).is_zero().then_some(p)
    }
}

/// The most term products [`Expr::sqrt_of_square`] forms squaring its
/// candidate roots before it gives up, each weighted by the square of its
/// coefficients' length in words (a few milliseconds).
const MAX_SQUARING: usize = 1_000_000;

/// A float coefficient that should have cancelled: division is not exact.
fn exact_zero(c: &Coef) -> bool {
    matches!(c, Coef::Approx { re, im } if re.abs() + im.abs() < 1e-12)
}

fn is_recip(v: &Var) -> bool {
    matches!(v, Var::Call(c) if c.f == Func::Recip)
}

/// √c for a rational c (times i when c is negative: the root of sin²t
/// has coefficients ±i/2), exact ([`Surd::sqrt_of`]); None for 0 or a
/// root with no exact form.
fn coef_sqrt(c: &Coef) -> Option<Coef> {
    let r = c.as_rat()?;
    if r.is_zero() {
        return None;
    }
    let root = Coef::real(Surd::sqrt_of(&if r.is_negative() {
        r.neg()
    } else {
        r.clone()
    })?);
    Some(if r.is_negative() {
        root.mul(&Coef::i())
    } else {
        root
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::expr::Symbol;
    use num_traits::One;

    fn s(n: &str) -> Expr {
        Expr::symbol(Symbol::new(n))
    }

    #[test]
    fn exact_division_cancels_common_factors() {
        let (a, b) = (s("a"), s("b"));
        let num = a.mul(&a).sub(&b.mul(&b));
        assert_eq!(num.div_exact(&a.sub(&b)), Some(a.add(&b)));
        assert_eq!(a.add(&Expr::one()).div_exact(&a.sub(&b)), None);
        let t = s("t");
        let two = Expr::sin(&t.scale(&Coef::int(2)));
        assert_eq!(
            two.div_exact(&Expr::cos(&t)),
            Some(Expr::sin(&t).scale(&Coef::int(2)))
        );
        assert_eq!(Expr::sin(&t).div_exact(&Expr::cos(&t)), None);
    }

    #[test]
    fn reciprocals_cancel_against_their_multiples() {
        let (a, b) = (s("a"), s("b"));
        let x = a.add(&b).mul(&a.add(&b).recip().unwrap()).cancel();
        assert_eq!(x, Expr::one());
    }

    #[test]
    fn roots_of_squares_are_absolute_values() {
        let t = s("t");
        let c = Expr::cos(&t);
        let r = c.mul(&c).sqrt_of_square().unwrap();
        assert_eq!(r, Expr::call(Func::Abs, vec![c.clone()]));
        let x = s("x");
        let sq = x.mul(&x).scale(&Coef::int(4));
        assert_eq!(
            sq.sqrt_of_square(),
            Some(Expr::call(Func::Abs, vec![x.scale(&Coef::int(2))]))
        );
        assert_eq!(x.sqrt_of_square(), None);
        assert_eq!(x.mul(&x).add(&Expr::one()).sqrt_of_square(), None);
    }
}
