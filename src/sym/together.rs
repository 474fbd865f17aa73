//! Quotients over a common denominator (LANGUAGE.md §7, "quotients
//! (`1/(a + b sin t)`, common factors cancelled)"; "`a == b` … answers
//! `true` or `false`"). A kept reciprocal 1/(d) is a call, so two forms of
//! one rational function (`1 + tan² t` and `1/cos² t`, the derivative of
//! `(a + sin t)/(b + cos t)` term by term and as one quotient) are
//! different canonical forms. Here:
//!
//! - [`together`]: the terms over reciprocals of *sums* (`b + cos t`, not
//!   a single term such as `cos t`, which prints as the tangent, secant or
//!   cosecant it makes) are put over one denominator, so that a quotient of
//!   sums prints as one quotient and its common factors cancel;
//! - [`cleared`]: both sides of an equation multiplied by every kept
//!   denominator of either, so that equal rational functions have equal
//!   numerators (the denominators are nonzero functions, so the numerators
//!   are equal exactly when the sides are);
//! - [`unhalved`]: both sides with each angle θ that enters a sine or
//!   cosine as a fraction (θ/2) scaled by the common denominator of its
//!   fractions (θ ↦ 2θ: one-to-one, so equal functions stay equal and
//!   different ones different), so half angles become whole ones, whose
//!   trigonometric polynomials are canonical.

use std::collections::BTreeMap;
use std::sync::Arc;

use super::coef::{Coef, Rat};
use super::expr::{Call, Expr, Func, Mono, Symbol, Var};
use num_traits::{One, Zero};

/// The most terms the products of [`together`] and [`cleared`] may form:
/// beyond it the form is left as it is (an undecided `==` is honest, a
/// second of work is not).
pub const MAX_TERMS: usize = 4000;

fn recip_of(v: &Var) -> Option<&Arc<Call>> {
    match v {
        Var::Call(c) if c.f == Func::Recip => Some(c),
        _ => None,
    }
}

/// True when the reciprocal 1/(d) is of a sum (more than one real term):
/// `1/(b + cos t)`, not `1/cos t`.
pub fn of_sum(c: &Call) -> bool {
    let d = &c.args[0];
    d.terms.len() > 64 || super::trig::real_form(d).len() > 1
}

/// d^n, None past [`MAX_TERMS`] terms.
fn bounded_pow(d: &Expr, n: i32) -> Option<Expr> {
    let mut out = Expr::one();
    for _ in 0..n {
        if out.terms.len().saturating_mul(d.terms.len()) > MAX_TERMS {
            return None;
        }
        out = out.mul(d);
    }
    Some(out)
}

/// Groups of numerators by their denominators (the reciprocal factors of
/// positive power), with the groups whose denominators hold reciprocals of
/// sums put over one denominator (for each part of single-term
/// reciprocals, which stays as it is: `tan t + 1/(1 + a)` keeps the
/// tangent). A merge that would pass [`MAX_TERMS`] is not made.
pub fn together(groups: BTreeMap<Mono, Expr>) -> BTreeMap<Mono, Expr> {
    // by the single-term part of the denominator: (sum part, numerator)
    let mut by_rest: BTreeMap<Mono, Vec<(Mono, Expr)>> = BTreeMap::new();
    for (den, num) in groups {
        let (sums, rest): (Mono, Mono) = den
            .into_iter()
            .partition(|(v, _)| recip_of(v).is_some_and(|c| of_sum(c)));
        by_rest.entry(rest).or_default().push((sums, num));
    }
    let mut out: BTreeMap<Mono, Expr> = BTreeMap::new();
    let mut put = |den: Mono, num: Expr| {
        let e = out.entry(den).or_default();
        *e = e.add(&num);
    };
    for (rest, parts) in by_rest {
        let with_sums: Vec<&(Mono, Expr)> = parts.iter().filter(|(s, _)| !s.is_empty()).collect();
        let merged = (with_sums.len() > 1).then(|| merge(&with_sums)).flatten();
        for (sums, num) in &parts {
            if merged.is_some() && !sums.is_empty() {
                continue;
            }
            put(super::expr::mono_mul(&rest, sums), num.clone());
        }
        if let Some((sums, num)) = merged {
            put(super::expr::mono_mul(&rest, &sums), num);
        }
    }
    out
}

/// The numerators over the least common power of each sum's reciprocal.
fn merge(parts: &[&(Mono, Expr)]) -> Option<(Mono, Expr)> {
    let mut top: Mono = Vec::new();
    for (sums, _) in parts {
        for (v, e) in sums {
            match top.iter_mut().find(|(w, _)| w == v) {
                Some((_, k)) => *k = (*k).max(*e),
                None => top.push((v.clone(), *e)),
            }
        }
    }
    top.sort_by(|a, b| a.0.cmp(&b.0));
    let mut num = Expr::zero();
    for (sums, n) in parts {
        let mut t = n.clone();
        for (v, e) in &top {
            let have = sums.iter().find(|(w, _)| w == v).map_or(0, |(_, k)| *k);
            let d = &recip_of(v)?.args[0];
            let f = bounded_pow(d, e - have)?;
            if t.terms.len().saturating_mul(f.terms.len()) > MAX_TERMS {
                return None;
            }
            t = t.mul(&f);
        }
        num = num.add(&t);
        if num.terms.len() > MAX_TERMS {
            return None;
        }
    }
    Some((top, num))
}

/// The highest power of each kept reciprocal in `e` (0 where only
/// negative powers occur), added to `top`.
fn powers(e: &Expr, top: &mut Vec<(Var, i32)>) {
    for (v, k) in e.terms.keys().flatten() {
        if recip_of(v).is_none() {
            continue;
        }
        match top.iter_mut().find(|(w, _)| w == v) {
            Some((_, h)) => *h = (*h).max(*k),
            None => top.push((v.clone(), (*k).max(0))),
        }
    }
}

/// `e` times Π dᵢ^{topᵢ}: each term's 1/dᵢ^k becomes dᵢ^{topᵢ − k}.
fn times(e: &Expr, top: &[(Var, i32)]) -> Option<Expr> {
    let mut cache: Vec<(Var, i32, Expr)> = Vec::new();
    let mut out = Expr::zero();
    for (m, c) in &e.terms {
        let mut rest: Mono = Vec::new();
        let mut t = Expr::constant(c.clone());
        let mut seen: Vec<&Var> = Vec::new();
        for (v, k) in m {
            match top.iter().find(|(w, _)| w == v) {
                Some((_, h)) => {
                    seen.push(v);
                    t = t.mul(&power(&mut cache, v, h - k)?);
                }
                None => rest.push((v.clone(), *k)),
            }
        }
        for (v, h) in top {
            if !seen.contains(&v) {
                t = t.mul(&power(&mut cache, v, *h)?);
            }
        }
        let mut r = Expr::zero();
        r.push(rest, Coef::one());
        out = out.add(&t.mul(&r));
        if out.terms.len() > MAX_TERMS {
            return None;
        }
    }
    Some(out)
}

fn power(cache: &mut Vec<(Var, i32, Expr)>, v: &Var, n: i32) -> Option<Expr> {
    if let Some((_, _, e)) = cache.iter().find(|(w, k, _)| w == v && *k == n) {
        return Some(e.clone());
    }
    let e = bounded_pow(&recip_of(v)?.args[0], n)?;
    cache.push((v.clone(), n, e.clone()));
    Some(e)
}

/// p and q times every kept denominator of either (to its highest power),
/// repeated while reciprocals remain at the top (a denominator may hold
/// one), at most four times: None when neither has one, or past
/// [`MAX_TERMS`].
pub fn cleared(p: &Expr, q: &Expr) -> Option<(Expr, Expr)> {
    let (mut p, mut q) = (p.clone(), q.clone());
    let mut any = false;
    for _ in 0..4 {
        let mut top = Vec::new();
        powers(&p, &mut top);
        powers(&q, &mut top);
        if top.is_empty() {
            break;
        }
        any = true;
        p = times(&p, &top)?;
        q = times(&q, &top)?;
    }
    any.then_some((p, q))
}

/// The symbols that enter a sine, cosine, tangent or a reciprocal's
/// argument with a fractional coefficient, with the least common
/// denominator of their fractions.
fn fractions(e: &Expr, out: &mut Vec<(Symbol, i64)>) {
    for (v, _) in e.terms.keys().flatten() {
        let Var::Call(c) = v else { continue };
        for a in &c.args {
            if matches!(c.f, Func::Sin | Func::Cos | Func::Tan) {
                for (m, k) in &a.terms {
                    let (Some(r), [(Var::Sym(s), 1)]) = (k.as_rat(), m.as_slice()) else {
                        continue;
                    };
                    let Some((_, den)) = r.small() else { continue };
                    if den == 1 {
                        continue;
                    }
                    match out.iter_mut().find(|(t, _)| t == s) {
                        Some((_, n)) => *n = lcm(*n, den),
                        None => out.push((s.clone(), den)),
                    }
                }
            }
            fractions(a, out);
        }
    }
}

fn lcm(a: i64, b: i64) -> i64 {
    let (mut x, mut y) = (a, b);
    while y != 0 {
        (x, y) = (y, x % y);
    }
    (a / x).saturating_mul(b)
}

/// p and q with each angle that enters a sine or cosine as a fraction
/// (θ/2, θ/3) scaled by the common denominator of its fractions (θ ↦ 2θ),
/// the same on both sides; None when there is none.
pub fn unhalved(p: &Expr, q: &Expr) -> Option<(Expr, Expr)> {
    let mut found = Vec::new();
    fractions(p, &mut found);
    fractions(q, &mut found);
    found.retain(|(_, n)| *n <= 12);
    if found.is_empty() {
        return None;
    }
    let by = |s: &Symbol| {
        let (_, n) = found.iter().find(|(t, _)| t == s)?;
        Some(Expr::symbol(s.clone()).scale(&Coef::rat(Rat::int(*n))))
    };
    Some((p.subst(&by), q.subst(&by)))
}

/// `e` = n/d split at its kept reciprocals: n, and d's reciprocals with
/// their highest powers; None when `e` has none, when n still holds one
/// (one nested in another), or past [`MAX_TERMS`].
fn split(e: &Expr) -> Option<(Expr, Vec<(Var, i32)>)> {
    let mut top = Vec::new();
    powers(e, &mut top);
    top.retain(|(_, h)| *h > 0);
    if top.is_empty() {
        return None;
    }
    let num = times(e, &top)?;
    (!num.has_recip()).then_some((num, top))
}

/// `e` over one denominator: every term times each kept reciprocal's sum
/// to its highest power, that product of reciprocals written once, common
/// factors cancelled (`1 + tan² t` is `1/cos² t`, `1/cos² t − 1` is
/// `tan² t`); None when `e` has no reciprocal, one nested in another, or
/// past [`MAX_TERMS`].
pub fn over_one(e: &Expr) -> Option<Expr> {
    let (num, top) = split(e)?;
    let mut den = Expr::zero();
    let mut mono = top;
    mono.sort_by(|a, b| a.0.cmp(&b.0));
    den.push(mono, Coef::one());
    Some(num.mul(&den).cancel())
}

/// 1/(c·m) for one term: each exponent negated, and a kept reciprocal
/// turned over is its sum again (1/(1/(1 + sin t)) is 1 + sin t, not the
/// reciprocal to the power −1, a second form of the same value).
pub fn turned_term(m: &Mono, c: &Coef) -> Option<Expr> {
    let (sums, m): (Mono, Mono) = m
        .iter()
        .map(|(v, e)| (v.clone(), e.saturating_neg()))
        .partition(|(v, e)| *e < 0 && recip_of(v).is_some());
    let mut out = Expr::zero();
    out.push(m, c.inv()?);
    for (v, e) in sums {
        out = out.mul(&recip_of(&v)?.args[0].powi(i64::from(e.saturating_neg()))?);
    }
    Some(out.fold_exps().fold_phases())
}

/// 1/e for a sum `e` over kept reciprocals: e = n/d with d the product of
/// its reciprocals' sums to their highest powers, so 1/e = d/n, cancelled;
/// None when `n` still holds a reciprocal (one nested in another), or
/// past [`MAX_TERMS`].
pub fn turned_over(e: &Expr) -> Option<Expr> {
    let (num, top) = split(e).filter(|(num, _)| !num.is_zero())?;
    let mut den = Expr::one();
    for (v, h) in &top {
        den = den.mul(&bounded_pow(&recip_of(v)?.args[0], *h)?);
        if den.terms.len() > MAX_TERMS {
            return None;
        }
    }
    Some(den.mul(&num.recip()?).cancel())
}

/// What `simplify` prints (LANGUAGE.md §7): the shortest in print of the
/// canonical form with quotients cancelled ([`Expr::cancel`]), the same
/// over one denominator ([`over_one`]), cancelled factor by factor
/// ([`super::shortest::by_factors`]), its half-angle forms
/// ([`super::shortest::half_angle`]) and the same made simplest over
/// fresh symbols for its irrational angles and its angles that are
/// products of symbols
/// ([`super::generalize::refolded`]); equal values every one, the
/// canonical form on a tie.
pub fn simplest(e: &Expr) -> Expr {
    let cancelled = e.cancel();
    let factored = cancelled
        .has_recip()
        .then(|| super::shortest::by_factors(&cancelled));
    let others: Vec<Expr> = over_one(e)
        .into_iter()
        .chain(factored)
        .chain(super::shortest::half_angle(&cancelled))
        .chain(super::generalize::refolded(&cancelled, &simplest))
        .filter(|c| *c != cancelled)
        .collect();
    if others.is_empty() {
        return cancelled;
    }
    let len = |x: &Expr| {
        super::print::expr(x, super::print::Style::default())
            .chars()
            .count()
    };
    let mut best_len = len(&cancelled);
    let mut best = cancelled;
    for c in others {
        let n = len(&c);
        if n < best_len && super::shortest::agrees(&c, &best) {
            (best, best_len) = (c, n);
        }
    }
    best
}
