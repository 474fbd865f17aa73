//! The field ℚ(e^{iρ}), ρ = π/L, of a split's angles ([`super::Lift::split`]):
//! powers of z = e^{iρ} reduced by z^L = −1 and by the minimal polynomial
//! of z, so that equal numbers written in it have one form.

use super::RHO;
use crate::decide::cyclotomic::{coef_poly, conductor_of, cyclotomic};
use crate::sym::coef::Coef;
use crate::sym::expr::{Expr, Symbol, Var};

/// `e` with each power of z = e^{iρ}, ρ = π/L, brought into [0, L) by
/// z^L = −1 (so `cos(−179ρ)` is `−cos ρ` at L = 180); powers inside kept
/// calls are left as they are.
fn wrapped(e: &Expr, l: i64) -> Expr {
    let mut out = Expr::default();
    for (mono, c) in &e.terms {
        let mut sign = false;
        let mono: crate::sym::expr::Mono = mono
            .iter()
            .filter_map(|(v, k)| match v {
                Var::Z(s) if &*s.name == RHO => {
                    let k = i64::from(*k);
                    let r = k.rem_euclid(l);
                    sign ^= ((k - r) / l) % 2 != 0;
                    (r != 0).then(|| (v.clone(), i32::try_from(r).unwrap_or(i32::MAX)))
                }
                _ => Some((v.clone(), *k)),
            })
            .collect();
        let c = if sign { c.neg() } else { c.clone() };
        // (in place: adding a one-term sum cloned the sum so far)
        out.push(mono, c);
    }
    out
}

/// `e` with the polynomial in z = e^{iρ} (ρ = π/L) of each monomial's
/// other factors reduced modulo Φ_2L, the minimal polynomial of z over ℚ:
/// `cos ρ + cos 3ρ + cos 5ρ` is then 1/2 at L = 7. Powers are first
/// brought into [0, L) by z^L = −1 ([`wrapped`]), and each coefficient
/// with a square root (or i, when i is in ℚ(z)) is first written as its
/// polynomial in z ([`coef_poly`]), so that (1 + √5)/4 and cos(π/5) meet
/// in one field at L = 5. Equal results are equal numbers; with every
/// root so written, equal numbers give equal results.
pub(super) fn reduced(e: &Expr, l: i64, z: &Var) -> Expr {
    let e = wrapped(e, l);
    let n = 2 * usize::try_from(l).unwrap_or(usize::MAX);
    if n > 720 {
        return e;
    }
    let phi = cyclotomic(n);
    let deg = phi.len() - 1;
    // (the other factors of each monomial, to their polynomial in z)
    let mut polys: std::collections::BTreeMap<crate::sym::expr::Mono, Vec<Coef>> =
        std::collections::BTreeMap::new();
    for (mono, c) in &e.terms {
        let mut k = 0usize;
        let rest: crate::sym::expr::Mono = mono
            .iter()
            .filter(|(v, p)| match v {
                Var::Z(s) if &*s.name == RHO => {
                    k = usize::try_from(*p).unwrap_or(0);
                    false
                }
                _ => true,
            })
            .cloned()
            .collect();
        let poly = polys.entry(rest).or_default();
        let written = match c {
            Coef::Exact { re, im }
                if re.rational().is_none()
                    || im.rational().is_none()
                    || (n.is_multiple_of(4) && !im.is_zero()) =>
            {
                coef_poly(c, n)
            }
            _ => None,
        };
        let written = written.unwrap_or_else(|| vec![c.clone()]);
        if poly.len() < k + written.len() {
            poly.resize(k + written.len(), Coef::int(0));
        }
        for (j, w) in written.iter().enumerate().filter(|(_, w)| !w.is_zero()) {
            poly[k + j] = poly[k + j].add(w);
        }
    }
    let mut out = Expr::default();
    for (rest, mut poly) in polys {
        for i in (deg..poly.len()).rev() {
            let c = poly[i].clone();
            if c.is_zero() {
                continue;
            }
            for (j, pj) in phi.iter().enumerate() {
                let at = i - deg + j;
                poly[at] = poly[at].add(&c.mul(&Coef::int(-pj)));
            }
        }
        for (k, c) in poly.into_iter().enumerate().take(deg) {
            if c.is_zero() {
                continue;
            }
            let mut mono = rest.clone();
            if k > 0 {
                mono.push((z.clone(), i32::try_from(k).unwrap_or(i32::MAX)));
                mono.sort_by(|a, b| a.0.cmp(&b.0));
            }
            // (in place: adding a one-term sum cloned the sum so far)
            out.push(mono, c);
        }
    }
    out
}

/// The z = e^{iρ} of the forms (`Var::Z` of ρ), as found in them.
pub(super) fn z_of<'a>(forms: impl Iterator<Item = &'a Expr>) -> Var {
    forms
        .flat_map(|e| e.terms.keys().flatten())
        .find_map(|(v, _)| match v {
            Var::Z(s) if &*s.name == RHO => Some(v.clone()),
            _ => None,
        })
        .unwrap_or_else(|| Var::Z(Symbol::new(RHO)))
}

/// The least L' ≥ L, a multiple of L, whose 2L' is a multiple of the
/// conductor of every square root among the forms' coefficients; None
/// when L already is, or L' would pass 360 (or a root is too large).
pub(super) fn widened<'a>(forms: impl Iterator<Item = &'a Expr>, l: i64) -> Option<i64> {
    let mut n = 2 * usize::try_from(l).ok()?;
    for e in forms {
        for c in e.terms.values() {
            n = num_integer::Integer::lcm(&n, &conductor_of(c)?);
        }
    }
    let wide = i64::try_from(n / 2).ok()?;
    (wide != l && wide <= 360).then_some(wide)
}
