//! Equality of values with symbolic sides (LANGUAGE.md §3, §7): `==` by
//! canonical forms, exactly — numbers enter with their exact forms, a
//! float coefficient (no exact form) compares as a float and is equal
//! only when every digit is — and `≈` within 1e-9 of the largest
//! coefficient. [`rounding_only`] tells a `==` that failed by rounding
//! alone, so that the answer can point to `≈`.

use super::formula::mat_of;
use super::value::Value;
use crate::sym::coef::Coef;
use crate::sym::expr::{Mono, Var};
use crate::sym::{Expr, Mat};

/// `a == b` (or `a ≈ b` when `approx`) with a formula on a side (§7),
/// decided by canonical forms: equal forms are equal; forms that differ
/// by a trigonometric polynomial (no kept call such as sqrt or atan2) are
/// different functions, since the symbols and the z = e^{iθ} are
/// algebraically independent; a difference with a kept call is undecided
/// (`Ok(None)`). `==` is exact: numbers enter with their exact forms
/// ([`mat_of`]), and a coefficient that is a float (no exact form: sin 1,
/// √(1 + √2)) compares as a float, equal only when the floats are
/// ([`rounding_only`] tells when they differ by rounding only). `≈` lets
/// each coefficient of the difference be within 1e-9 of the largest.
pub fn equal(a: &Value, b: &Value, approx: bool) -> Result<Option<bool>, String> {
    let (x, y) = sides(a, b)?;
    let mut decided = Some(true);
    for (p, q) in x.data.iter().zip(&y.data) {
        match verdict(p, q, approx, false) {
            Some(true) => continue,
            Some(false) => return Ok(Some(false)),
            None => {}
        }
        // a kept call differs: half angles made whole and quotients
        // cleared (`sym::together`), then the same test on the numerators
        let (p2, q2) = crate::sym::together::unhalved(p, q).unwrap_or((p.clone(), q.clone()));
        let (p3, q3) = match crate::sym::together::cleared(&p2, &q2) {
            Some(c) => c,
            None => (p2, q2),
        };
        match verdict(&p3, &q3, approx, true) {
            Some(true) => continue,
            Some(false) if witnessed(p, q) || exactly(&p3, &q3) => return Ok(Some(false)),
            _ if general(p, q, approx) => continue,
            _ => decided = None,
        }
    }
    Ok(decided)
}

/// True when p = q is proven with each product of symbols in an angle as
/// a symbol of its own (`sym::generalize`: a proof, never a difference).
fn general(p: &Expr, q: &Expr, approx: bool) -> bool {
    let Some((p, q)) = crate::sym::generalize::linearized(p, q) else {
        return false;
    };
    let (p, q) = crate::sym::together::unhalved(&p, &q).unwrap_or((p, q));
    let (p, q) = crate::sym::together::cleared(&p, &q).unwrap_or((p, q));
    verdict(&p, &q, approx, true) == Some(true)
}

/// True when every coefficient of both is exact (a float multiplied out
/// may differ by rounding alone).
fn exactly(p: &Expr, q: &Expr) -> bool {
    [p, q].iter().all(|e| e.terms.values().all(Coef::is_exact))
}

/// p = q decided by canonical forms: `Some(true)` when they are equal,
/// `Some(false)` when they differ by a trigonometric polynomial (no kept
/// call; a phase only with a witness point), None when a kept call
/// differs. `rewritten`: p and q are numerators of the sides, so the
/// witness is asked of the caller.
fn verdict(p: &Expr, q: &Expr, approx: bool, rewritten: bool) -> Option<bool> {
    let differing = if approx {
        approx_difference(p, q)
    } else {
        exact_difference(p, q)
    };
    if differing.is_empty() {
        // (`1e-20 b ≈ 2e-20 b` is false at b = 1e15: a term that grows with
        // a symbol must be close relative to itself too, else undecided)
        return (!approx || grows_close(p, q)).then_some(true);
    }
    if differing
        .iter()
        .any(|m| m.iter().any(|(v, _)| matches!(v, Var::Call(_))))
    {
        return None;
    }
    if differing.iter().any(|m| has_phase(m)) && (rewritten || !witnessed(p, q)) {
        return None;
    }
    Some(false)
}

/// True when a monomial holds a phase variable (`sym::phase`). A π-phase
/// u = e^{iπ/27720} is a root of unity, so its powers satisfy linear
/// relations (the cyclotomic ones: 1 + 2 cos(2π/5) − 2 cos(π/5) = 0) that
/// the canonical form does not reduce; and a phase on one side may stand
/// for a float on the other (cos(t2 + 0.6) against 0.8253 cos t2 −
/// 0.5646 sin t2, equal but for rounding). Either way a difference in such
/// terms may still be zero.
fn has_phase(m: &Mono) -> bool {
    m.iter().any(|(v, _)| match v {
        Var::Z(s) | Var::Sym(s) => s.is_phase(),
        _ => false,
    })
}

/// True when p − q is clearly nonzero at one of a few fixed points (far
/// above rounding): a witness that the sides differ. Without one, a
/// difference the canonical form cannot reduce is left undecided, never
/// answered `false`.
fn witnessed(p: &Expr, q: &Expr) -> bool {
    const POINTS: [f64; 4] = [0.3719, -1.2345, 2.0821, 0.9137];
    let d = p.sub(q);
    let mut names = Vec::new();
    d.symbols(&mut names);
    let size = scale(p, q);
    POINTS.iter().enumerate().any(|(k, x0)| {
        let at = |s: &crate::sym::Symbol| {
            let i = names.iter().position(|n| n == s)?;
            Some(x0 + 0.6180 * (i + k) as f64)
        };
        d.eval(&at).is_some_and(|v| v.abs() > 1e-8 * size)
    })
}

/// Both sides as matrices of one shape.
fn sides(a: &Value, b: &Value) -> Result<(Mat, Mat), String> {
    match (mat_of(a), mat_of(b)) {
        (Some(x), Some(y)) if (x.rows, x.cols) == (y.rows, y.cols) => Ok((x, y)),
        _ => Err(format!(
            "cannot compare {} with {}",
            a.kind().a(),
            b.kind().a()
        )),
    }
}

/// The coefficients of `p` and `q` at each monomial of either (0 where
/// one has none).
fn pairs<'a>(p: &'a Expr, q: &'a Expr) -> Vec<(&'a Mono, Coef, Coef)> {
    let mut out: Vec<(&Mono, Coef, Coef)> = Vec::new();
    for (m, c) in &p.terms {
        let d = q.terms.get(m).cloned().unwrap_or(Coef::ZERO);
        out.push((m, c.clone(), d));
    }
    for (m, d) in &q.terms {
        if !p.terms.contains_key(m) {
            out.push((m, Coef::ZERO, d.clone()));
        }
    }
    out
}

/// The monomials where `p` and `q` differ exactly: exact coefficients
/// compared exactly, a float with anything as floats.
fn exact_difference<'a>(p: &'a Expr, q: &'a Expr) -> Vec<&'a Mono> {
    pairs(p, q)
        .into_iter()
        .filter(|(_, c, d)| {
            if c.is_exact() && d.is_exact() {
                c != d
            } else {
                c.to_c64() != d.to_c64()
            }
        })
        .map(|(m, ..)| m)
        .collect()
}

/// The largest coefficient of either side (at least 1): the scale of
/// `≈`.
fn scale(p: &Expr, q: &Expr) -> f64 {
    largest(p, q).max(1.0)
}

/// The largest coefficient of either side, however small: the scale of
/// rounding (`exp(-40) t == exp(-41) t` differ by more than rounding).
fn largest(p: &Expr, q: &Expr) -> f64 {
    [p, q]
        .iter()
        .flat_map(|e| e.terms.values())
        .map(|c| {
            let (re, im) = c.to_c64();
            re.abs().max(im.abs())
        })
        .fold(0.0f64, f64::max)
}

/// True when every term of `p` and `q` with a polynomial symbol in it
/// (unbounded as the symbol grows, unlike cos and sin) differs by at most
/// 1e-9 of its own coefficient: `≈` then holds at every number, as its
/// 1e-9 · max(1, |a|, |b|) does for numbers.
fn grows_close(p: &Expr, q: &Expr) -> bool {
    pairs(p, q).into_iter().all(|(m, c, d)| {
        let grows = m
            .iter()
            .any(|(v, _)| matches!(v, Var::Sym(s) if !s.is_phase()));
        let ((a, b), (e, f)) = (c.to_c64(), d.to_c64());
        let size = a.abs().max(b.abs()).max(e.abs()).max(f.abs());
        !grows || (a - e).abs().max((b - f).abs()) <= 1e-9 * size
    })
}

/// The monomials where `p` and `q` differ by more than 1e-9 of the
/// largest coefficient (`≈`).
fn approx_difference<'a>(p: &'a Expr, q: &'a Expr) -> Vec<&'a Mono> {
    let tol = 1e-9 * scale(p, q);
    pairs(p, q)
        .into_iter()
        .filter(|(_, c, d)| {
            let ((a, b), (e, f)) = (c.to_c64(), d.to_c64());
            (a - e).abs().max((b - f).abs()) > tol
        })
        .map(|(m, ..)| m)
        .collect()
}

/// True when `a == b` is false only by rounding: every coefficient that
/// differs is a float on one side at least, within 1e-12 of itself (or
/// below 1e-15 of the largest coefficient of either matrix: noise; of the
/// largest however small, not of 1), and no kept call
/// differs (the answer then points to `≈`).
pub fn rounding_only(a: &Value, b: &Value) -> bool {
    let Ok((x, y)) = sides(a, b) else {
        return false;
    };
    let mut any = false;
    // (noise is measured against the largest coefficient of the whole
    // matrix, as rounding is for numbers: an entry made only of noise,
    // `1.2e-16 sin(a)` against 0, is rounding, issue 35)
    let whole = x
        .data
        .iter()
        .zip(&y.data)
        .map(|(p, q)| largest(p, q))
        .fold(0.0f64, f64::max);
    for (p, q) in x.data.iter().zip(&y.data) {
        let tol = 1e-12 * whole;
        for (m, c, d) in pairs(p, q) {
            let differs = if c.is_exact() && d.is_exact() {
                c != d
            } else {
                c.to_c64() != d.to_c64()
            };
            if !differs {
                continue;
            }
            // Within 1e-12 of the term itself, or noise far below the entry.
            let ((re1, im1), (re2, im2)) = (c.to_c64(), d.to_c64());
            let size = re1.abs().max(im1.abs()).max(re2.abs()).max(im2.abs());
            let gap = (re1 - re2).abs().max((im1 - im2).abs());
            let small = gap <= 1e-12 * size || gap <= 1e-3 * tol;
            let float = !c.is_exact() || !d.is_exact();
            if !small || !float || m.iter().any(|(v, _)| matches!(v, Var::Call(_))) {
                return false;
            }
            any = true;
        }
    }
    any
}
