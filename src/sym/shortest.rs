//! Candidate forms for `simplify` (LANGUAGE.md §7: "tan and cot kept as
//! tan and cot"; SymPy's `sin(x)/(2 (1 + cos x))` = `tan(x/2)/2`,
//! `sin(x)/cos(x/2)` = `2 sin(x/2)`). Each candidate is the same value
//! written over another angle, made by exact steps only, so choosing among
//! them by printed length ([`super::together::simplest`]) never shows a
//! form that is not the value:
//!
//! - [`half_angle`]: an angle x written as 2u (a one-to-one change of
//!   variable), the quotient cancelled over u, and u written back as x/2:
//!   `sin x/(1 + cos x)` is `2 sin u cos u/(2 cos² u)` = `sin u/cos u`,
//!   which prints `tan(x/2)`.

use super::coef::{Coef, Rat};
use super::expr::{Expr, Func, Mono, Symbol, Var};
use super::trig::real_form;
use num_traits::{One, Zero};

/// The most terms an expression may have for its half-angle forms to be
/// tried (each try is a substitution and a cancel per angle).
const MAX_TERMS: usize = 24;
/// The most angles tried.
const MAX_ANGLES: usize = 3;

/// The angles of `e` (symbols with a z, and the symbols of half-angle
/// sine and cosine calls).
fn angles(e: &Expr, out: &mut Vec<Symbol>) {
    for (v, _) in e.terms.keys().flatten() {
        match v {
            Var::Z(s) if s.phase().is_none() && !out.contains(s) => out.push(s.clone()),
            Var::Call(c) if matches!(c.f, Func::Sin | Func::Cos | Func::Recip) => {
                for a in &c.args {
                    if c.f == Func::Recip {
                        angles(a, out);
                        continue;
                    }
                    let mut syms = Vec::new();
                    a.symbols(&mut syms);
                    for s in syms {
                        if !out.contains(&s) {
                            out.push(s);
                        }
                    }
                }
            }
            _ => {}
        }
    }
}

/// A symbol that no user name can be (a control character leads it).
fn fresh(s: &Symbol) -> Symbol {
    Symbol::new(&format!("\u{1}half {}", s.name))
}

/// `e` with each of its angles x in turn written as 2u, cancelled over u
/// and written back with u = x/2: one candidate per angle where that
/// changes the form; none for a large `e` or one with no quotient or half
/// angle.
pub fn half_angle(e: &Expr) -> Vec<Expr> {
    let has_half = e
        .terms
        .keys()
        .flatten()
        .any(|(v, _)| matches!(v, Var::Call(c) if matches!(c.f, Func::Sin | Func::Cos)));
    if e.terms.len() > MAX_TERMS || !(e.has_recip() || has_half) {
        return Vec::new();
    }
    let mut found = Vec::new();
    angles(e, &mut found);
    let mut out = Vec::new();
    for x in found.into_iter().take(MAX_ANGLES) {
        if x.is_timed() || x.unit {
            continue;
        }
        let u = fresh(&x);
        let two_u = Expr::symbol(u.clone()).scale(&Coef::int(2));
        let doubled = by_factors(&e.subst(&|s| (*s == x).then(|| two_u.clone())).cancel());
        let half_x = Expr::symbol(x.clone()).scale(&Coef::rat(Rat::new(1, 2).unwrap_or(Rat::ONE)));
        let back = doubled
            .subst(&|s| (*s == u).then(|| half_x.clone()))
            .cancel();
        let mut left = Vec::new();
        back.symbols(&mut left);
        if left.contains(&u) || back == *e {
            continue;
        }
        out.push(back);
    }
    out
}

/// An angle's expression from its integer combination of symbols; None
/// with a constant phase in it.
fn angle(k: &[(Symbol, i32)]) -> Option<Expr> {
    let mut a = Expr::zero();
    for (s, n) in k {
        if s.phase().is_some() {
            return None;
        }
        a = a.add(&Expr::symbol(s.clone()).scale(&Coef::int(i64::from(*n))));
    }
    Some(a)
}

/// `e` with each quotient N/D whose D is one real term c·Π fᵢ^pᵢ (sines
/// and cosines) cancelled factor by factor: N divided by each fᵢ as often
/// as it divides (`sin 2u/(4 cos² u)` is `sin u/(2 cos u)`, where the
/// whole D does not divide N). Exact division only: the same value.
pub fn by_factors(e: &Expr) -> Expr {
    use std::collections::BTreeMap;
    if !e.has_recip() {
        return e.clone();
    }
    let mut groups: BTreeMap<Mono, Expr> = BTreeMap::new();
    for (m, c) in &e.terms {
        let (den, rest): (Mono, Mono) = m
            .iter()
            .cloned()
            .partition(|(v, k)| *k > 0 && matches!(v, Var::Call(c) if c.f == Func::Recip));
        groups.entry(den).or_default().push(rest, c.clone());
    }
    let mut out = Expr::zero();
    for (den, num) in groups {
        match over_factors(&den, num) {
            Some(t) => out = out.add(&t),
            None => return e.clone(),
        }
    }
    out
}

/// num over the reciprocals `den`, each opened into its factors where it
/// has them ([`factor_list`]), those that divide num divided out, and the
/// rest kept as one reciprocal each (so that they print as the tangents
/// and cotangents they make with the numerator).
fn over_factors(den: &Mono, mut num: Expr) -> Option<Expr> {
    let mut scale = Coef::one();
    let mut below: Vec<(Expr, i64)> = Vec::new();
    let mut kept = Expr::one();
    for (v, k) in den {
        let Var::Call(call) = v else { continue };
        let Some((c, factors)) = factor_list(&call.args[0]) else {
            let mut m = Expr::zero();
            m.push(vec![(v.clone(), *k)], Coef::one());
            kept = kept.mul(&m);
            continue;
        };
        for _ in 0..*k {
            scale = scale.mul(&c);
        }
        for (f, p) in factors {
            let mut left = i64::from(p) * i64::from(*k);
            while left > 0 {
                match num.div_exact(&f) {
                    Some(q) => {
                        num = q;
                        left -= 1;
                    }
                    None => break,
                }
            }
            if left > 0 {
                below.push((f, left));
            }
        }
    }
    let mut out = num.mul(&kept);
    if let Some(r) = Expr::constant(scale).recip() {
        out = out.mul(&r);
    }
    for (f, n) in below {
        match f.recip().and_then(|r| r.powi(n)) {
            Some(r) => out = out.mul(&r),
            None => return None,
        }
    }
    Some(out)
}

/// A reciprocal's sum d as c·Π fᵢ^pᵢ with each fᵢ a sine or cosine: where
/// d is one real term ([`one_term`]), or two whose angles A, B give
/// d = c·f((A + B)/2)·g((A − B)/2) exactly (sum to product:
/// cos(2x + y) − cos y = −2 sin(x + y) sin x). None otherwise, or with a
/// constant phase in an angle.
fn factor_list(d: &Expr) -> Option<(Coef, Vec<(Expr, u32)>)> {
    let real = one_term(d);
    if real.len() == 1 {
        let ((poly, trig), c) = real.iter().next()?;
        if !poly.is_empty() {
            return None;
        }
        let fs: Option<Vec<(Expr, u32)>> = trig
            .iter()
            .map(|(a, sin, p)| {
                let x = angle(a)?;
                Some((if *sin { Expr::sin(&x) } else { Expr::cos(&x) }, *p))
            })
            .collect();
        return Some((c.clone(), fs?));
    }
    if real.len() != 2 {
        return None;
    }
    let mut angles = Vec::new();
    for (poly, trig) in real.keys() {
        match trig.as_slice() {
            [(a, _, 1)] if poly.is_empty() => angles.push(angle(a)?),
            _ => return None,
        }
    }
    let half = Coef::rat(Rat::new(1, 2)?);
    let u = angles[0].add(&angles[1]).scale(&half);
    let v = angles[0].sub(&angles[1]).scale(&half);
    for f in [Expr::sin(&u), Expr::cos(&u)] {
        for g in [Expr::sin(&v), Expr::cos(&v)] {
            if let Some(c) = d.div_exact(&f.mul(&g)).and_then(|q| q.as_const()) {
                return Some((c, vec![(f, 1), (g, 1)]));
            }
        }
    }
    None
}

/// The real form of `d` as one term where it has one: its own best form,
/// for one angle its powers of cos and sin first (`sin 2u` is
/// `2 sin u cos u`), whose factors may divide a numerator.
fn one_term(d: &Expr) -> super::trig::Real {
    use super::trig::{Power, realize};
    let best = real_form(d);
    let mut found = Vec::new();
    for (v, _) in d.terms.keys().flatten() {
        if let Var::Z(s) = v
            && !found.contains(s)
        {
            found.push(s.clone());
        }
    }
    if found.len() != 1 {
        return best;
    }
    for basis in [Power::Cos, Power::Sin] {
        let r = realize(d, std::slice::from_ref(&found), &[basis]);
        if r.len() == 1 {
            return r;
        }
    }
    best
}

/// A guard, not a proof (each candidate is made by exact steps): the
/// candidate and the canonical form agree at two points, or neither is
/// defined there.
pub fn agrees(candidate: &Expr, canonical: &Expr) -> bool {
    let mut names = Vec::new();
    canonical.symbols(&mut names);
    candidate.symbols(&mut names);
    [0.3719, -1.2345].iter().all(|x0| {
        let at = |s: &Symbol| {
            let i = names.iter().position(|n| n == s)?;
            Some(x0 + 0.6180 * i as f64)
        };
        match (candidate.eval(&at), canonical.eval(&at)) {
            (Some(a), Some(b)) => (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs())),
            (None, None) => true,
            _ => false,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::print::{Style, expr};

    fn s(n: &str) -> Expr {
        Expr::symbol(Symbol::new(n))
    }

    #[test]
    fn half_angle_and_factor_forms_are_the_value() {
        let x = s("x");
        // sin x/(1 + cos x) over x/2 is tan(x/2)
        let q = Expr::sin(&x).mul(&Expr::one().add(&Expr::cos(&x)).recip().unwrap());
        let forms = half_angle(&q);
        let texts: Vec<String> = forms.iter().map(|f| expr(f, Style::default())).collect();
        assert!(texts.contains(&"tan(x/2)".to_string()), "{texts:?}");
        assert!(forms.iter().all(|f| agrees(f, &q)));
        // sin 2x/cos² x cancelled factor by factor is 2 tan x
        let c = Expr::cos(&x);
        let r = Expr::sin(&x.scale(&Coef::int(2))).mul(&c.mul(&c).recip().unwrap());
        let f = by_factors(&r.cancel());
        assert_eq!(expr(&f, Style::default()), "2 tan(x)");
        assert!(agrees(&f, &r));
        // a guard that sees a wrong form
        assert!(!agrees(&Expr::sin(&x), &Expr::cos(&x)));
    }
}
