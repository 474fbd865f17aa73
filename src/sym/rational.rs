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
use std::collections::BTreeMap;

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
        // every monomial of the quotient lies in the box of self's
        // exponents less d's (N(q d) = N(q) + N(d))
        let (sb, db) = (exact_bounds(self), exact_bounds(d));
        let in_box = |m: &Mono| {
            let e = |v: &Var| m.iter().find(|(w, _)| w == v).map_or(0, |(_, e)| *e);
            let b = |x: &BTreeMap<Var, (i32, i32)>, v: &Var| x.get(v).copied().unwrap_or((0, 0));
            let vars = sb.keys().chain(db.keys()).chain(m.iter().map(|(v, _)| v));
            vars.into_iter().all(|v| {
                let ((lo, hi), (dl, dh)) = (b(&sb, v), b(&db, v));
                (lo - dl..=hi - dh).contains(&e(v))
            })
        };
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
            if cmp_lex(&m, &low) == Ordering::Less || !in_box(&m) {
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
    /// ([`super::together::together`]). Terms over a square root of a
    /// sum that the sum divides fold first: `(a + 1)/sqrt(a + 1)` =
    /// `sqrt(a + 1)` ([`Expr::fold_root_sums`]).
    pub fn cancel(&self) -> Expr {
        if self.has_root_quotient() {
            return self.clone().fold_root_sums().cancel_recips();
        }
        self.cancel_recips()
    }

    /// [`Expr::cancel`] of the kept reciprocals.
    fn cancel_recips(&self) -> Expr {
        if !self.has_recip() {
            return self.clone();
        }
        let me = self.unified_recips();
        // numerators grouped by their denominator (the reciprocal factors)
        let mut groups: std::collections::BTreeMap<Mono, Expr> = Default::default();
        for (m, c) in &me.terms {
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

    /// Each kept reciprocal 1/D whose sum D is c·E^k for the sum E of
    /// another kept reciprocal written as c⁻¹ (1/E)^k: 1/cos² t (one
    /// reciprocal of (z + z⁻¹)²/4) and tan² t = sin² t (1/cos t)² then
    /// meet over 1/cos t, and 1/cos² t − tan² t cancels to 1.
    fn unified_recips(&self) -> Expr {
        let mut recips: Vec<(&Var, &Expr)> = Vec::new();
        for (v, _) in self.terms.keys().flatten() {
            if let Var::Call(c) = v
                && is_recip(v)
                && !recips.iter().any(|(w, _)| *w == v)
            {
                recips.push((v, &c.args[0]));
            }
        }
        let mut map: Vec<(&Var, &Var, i32, Coef, Coef)> = Vec::new();
        for (v, d) in &recips {
            for (w, e) in &recips {
                if v == w || d.terms.len() < e.terms.len() || e.terms.len() < 2 {
                    continue;
                }
                let (mut q, mut k) = ((*d).clone(), 0);
                while k < 8 && q.as_const().is_none() {
                    match q.div_exact(e) {
                        Some(r) => (q, k) = (r, k + 1),
                        None => break,
                    }
                }
                if let Some(c) = q.as_const().filter(|_| k > 0)
                    && let Some(ci) = c.inv()
                {
                    map.push((v, w, k, c, ci));
                    break;
                }
            }
        }
        if map.is_empty() {
            return self.clone();
        }
        let mut out = Expr::zero();
        for (m, c) in &self.terms {
            let mut t = single(Vec::new(), c.clone());
            let mut rest: Mono = Vec::new();
            for (v, e) in m {
                match map.iter().find(|(x, ..)| *x == v) {
                    // (1/D)^e = c^(−e) (1/E)^(k e)
                    Some((_, w, k, q, qi)) => {
                        let base = if *e > 0 { qi } else { q };
                        let mut f = Coef::one();
                        for _ in 0..e.unsigned_abs() {
                            f = f.mul(base);
                        }
                        t = t.mul(&single(vec![((*w).clone(), k * e)], f));
                    }
                    None => rest.push((v.clone(), *e)),
                }
            }
            out = out.add(&t.mul(&single(rest, Coef::one())));
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
        // (|p| = |−p|: Expr::abs keeps the sign whose leading coefficient is positive)
        Some(Expr::abs(&p))
    }

    /// A p with p² = self, found term by term from the leading term.
    ///
    /// A term whose square leaves the box of self's exponents (the Newton
    /// polytope of p² is twice p's) ends the search at once: a sum of
    /// squares that is not a square (‖R v‖² of a product of symbolic
    /// rotations, rpy's cos(pitch) = √(r11² + r21²)) otherwise ran on to
    /// the step limit, 2n + 8 steps, forming p² each step (cubic in all):
    /// matrix differential seed 700030 (197 terms, 403 steps, 1.4 s a
    /// try) took 258 s, seed 701867 over 5 minutes. The remainder self −
    /// p² is kept in place (adding t to p takes (2p + t)·t from it, |p|
    /// term products a step), and the search is given up (None, √ kept, a
    /// right value) when a coefficient grows far longer than self's, as
    /// in [`Expr::div_exact`], when the remainder grows far past self, or
    /// past [`MAX_ROOT_WORK`].
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
        let words = self.terms.values().map(Coef::words).max().unwrap_or(0);
        let cap = 4 * words + 16;
        let bounds = exponent_bounds(self);
        let most = 8 * self.terms.len() + 64;
        let mut work = 0usize;
        let mut r = self.sub(&p.mul(&p));
        for _ in 0..(2 * self.terms.len() + 8) {
            let Some((rm, rc)) = r.leading() else {
                // (the remainder kept in place is exact; checked once
                // against self all the same)
                return self.sub(&p.mul(&p)).is_zero().then_some(p);
            };
            if exact_zero(rc) {
                return None;
            }
            let m = mono_div(rm, &pm);
            if cmp_lex(&m, &low) == Ordering::Less || !within(&bounds, &m) {
                return None;
            }
            let c = rc.mul(&two_inv);
            work = work.saturating_add(p.terms.len() + r.terms.len());
            if c.words() > cap || work > MAX_ROOT_WORK {
                return None;
            }
            // (p + t)² − p² = (2p + t)·t
            let t = single(m.clone(), c.clone());
            let twice = single(m.clone(), c.mul(&Coef::int(2)));
            for (m, c) in p.mul(&twice).add(&t.mul(&t)).neg().terms {
                r.push(m, c);
            }
            p.push(m, c);
            if r.terms.len() > most {
                return None;
            }
        }
        self.sub(&p.mul(&p)).is_zero().then_some(p)
    }
}

/// Each variable's least and greatest exponent over the terms of `x`
/// (0 where a term lacks it): the box holding x's Newton polytope.
fn exponent_bounds(x: &Expr) -> BTreeMap<Var, (i32, i32)> {
    let mut out: BTreeMap<Var, (i32, i32)> = BTreeMap::new();
    for (v, e) in x.terms.keys().flatten() {
        let b = out.entry(v.clone()).or_insert((0, 0));
        *b = (b.0.min(*e), b.1.max(*e));
    }
    out
}

/// Each variable's least and greatest exponent over the terms of `x`,
/// a term lacking it counting 0 (exactly: a quotient's box is found by
/// subtracting these).
fn exact_bounds(x: &Expr) -> BTreeMap<Var, (i32, i32)> {
    let mut out = exponent_bounds(x);
    for (v, b) in out.iter_mut() {
        let every = x.terms.keys().all(|m| m.iter().any(|(w, _)| w == v));
        if every {
            let es = x
                .terms
                .keys()
                .filter_map(|m| m.iter().find(|(w, _)| w == v));
            *b = es.fold((i32::MAX, i32::MIN), |(lo, hi), (_, e)| {
                (lo.min(*e), hi.max(*e))
            });
        }
    }
    out
}

/// True when the square of monomial `m` lies in the box `bounds` (every
/// monomial of a root p of x does: the Newton polytope of p² is twice
/// that of p, its vertices' terms never cancelling).
fn within(bounds: &BTreeMap<Var, (i32, i32)>, m: &Mono) -> bool {
    m.iter().all(|(v, e)| {
        bounds
            .get(v)
            .is_some_and(|&(lo, hi)| (lo..=hi).contains(&e.saturating_mul(2)))
    })
}

/// The most work [`Expr::sqrt_of_square`] spends looking for a root term
/// by term: the term products of the steps and the remainder's terms
/// each step reads for its leading one (a root of some 900 terms over
/// two symbols, 0.4 s in release, is found; a dense one's square passes
/// the size limit, `MAX_SYM_NODES`, long before).
const MAX_ROOT_WORK: usize = 1_000_000;

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

    #[test]
    fn sums_of_squares_that_are_not_squares_keep_their_root() {
        // (sin a cos b + c)² + (cos a + b sin c)²: its root's second
        // term leaves the box of the exponents at once
        let (a, b, c) = (s("a"), s("b"), s("c"));
        let u = Expr::sin(&a).mul(&Expr::cos(&b)).add(&c);
        let v = Expr::cos(&a).add(&b.mul(&Expr::sin(&c)));
        let x = u.mul(&u).add(&v.mul(&v));
        assert_eq!(x.sqrt_of_square(), None);
        // a square of many terms is still found
        let p = (0..12).fold(Expr::one(), |p, k| {
            p.add(
                &Expr::sin(&a)
                    .mul(&b.powi(k).unwrap())
                    .scale(&Coef::int(k + 1)),
            )
        });
        let r = p.mul(&p).sqrt_of_square().expect("a root");
        assert!(
            r == Expr::call(Func::Abs, vec![p.clone()])
                || r == Expr::call(Func::Abs, vec![p.neg()])
        );
    }
}
