//! Angles that are not integer combinations of the symbols: products of
//! symbols (`cos(x y)`, SymPy's `cos(x y) − cos y = −2 sin((x y − y)/2)
//! sin((x y + y)/2)`) and irrational multiples (`sin(√6 x)`, `cos(π x)`,
//! the angles of `exp(A t)` for a 2×2 A with complex eigenvalues 1 ± √6 i,
//! §3.2.3.1). Each such term of a sine's or cosine's argument is written
//! as an integer multiple of a fresh symbol w — one w for all terms on
//! one monomial whose coefficients have rational ratios (√6 x and 2√6 x
//! are w and 2w with w = √6 x), the same on both sides of an equation —
//! so that the angles are linear and the canonical form (with
//! [`super::together::unhalved`]) decides them: sin²(√6 x) + cos²(√6 x)
//! is 1. An identity in independent w, x, y holds in particular at
//! w = √6 x, so a `true` so found is a proof; a difference is not (w = √6
//! x is a special case), and the caller answers only `true` from it.

use super::coef::{Coef, Rat};
use super::expr::{Expr, Func, Mono, Symbol, Var};
use num_traits::Zero;

/// One fresh angle: the monomial it stands on, the coefficient w has
/// there, and its symbol.
type Fresh = (Mono, Coef, Symbol);

/// True for a term of an argument that is not a plain angle: a product
/// of symbols (or of π and symbols), or a symbol with an irrational
/// coefficient. A symbol with a rational coefficient, π alone and a
/// constant are the canonical form's own.
fn odd(m: &Mono, c: &Coef) -> bool {
    let plain = m
        .iter()
        .all(|(v, k)| matches!(v, Var::Sym(_) | Var::Pi) && *k > 0);
    let degree: i32 = m.iter().map(|(_, k)| *k).sum();
    let symbols = m.iter().any(|(v, _)| matches!(v, Var::Sym(_)));
    plain && symbols && (degree >= 2 || c.as_rat().is_none())
}

/// The odd terms (monomial and coefficient) in the arguments of the sines
/// and cosines of `e`.
fn terms(e: &Expr, out: &mut Vec<(Mono, Coef)>) {
    for (v, _) in e.terms.keys().flatten() {
        let Var::Call(c) = v else { continue };
        for a in &c.args {
            if matches!(c.f, Func::Sin | Func::Cos) {
                for (m, k) in &a.terms {
                    if odd(m, k) && !out.iter().any(|(n, j)| n == m && j == k) {
                        out.push((m.clone(), k.clone()));
                    }
                }
            }
            terms(a, out);
        }
    }
}

/// c/base when it is rational.
fn ratio(c: &Coef, base: &Coef) -> Option<Rat> {
    c.mul(&base.inv()?).as_rat()
}

/// The fresh angles of the odd terms: on each monomial, one per class of
/// coefficients with rational ratios, its coefficient the first one's
/// divided by the least common denominator of the ratios (so every term
/// is an integer multiple of it).
fn fresh(found: &[(Mono, Coef)]) -> Vec<Fresh> {
    let mut classes: Vec<(Mono, Coef, Vec<Rat>)> = Vec::new();
    for (m, c) in found {
        let class = classes
            .iter_mut()
            .find_map(|(n, base, rs)| (n == m).then_some(()).and(ratio(c, base).map(|r| (rs, r))));
        match class {
            Some((rs, r)) => rs.push(r),
            None => classes.push((m.clone(), c.clone(), vec![Rat::ONE])),
        }
    }
    classes
        .into_iter()
        .enumerate()
        .filter_map(|(i, (m, base, rs))| {
            let mut den = num_bigint::BigInt::from(1);
            for r in &rs {
                let (_, d) = r.parts();
                den = num_integer::Integer::lcm(&den, &d);
            }
            let den = i128::try_from(den).ok()?;
            let w = base.mul(&Coef::rat(Rat::new(1, den)?));
            Some((m, w, Symbol::new(&format!("\u{1}angle {i}"))))
        })
        .collect()
}

/// `e` with each odd term in a sine's or cosine's argument written as an
/// integer multiple of its fresh symbol.
fn rewrite(e: &Expr, names: &[Fresh]) -> Expr {
    let mut out = Expr::zero();
    for (m, c) in &e.terms {
        let mut t = Expr::constant(c.clone());
        for (v, k) in m {
            let f = match v {
                Var::Call(call) => {
                    let args: Vec<Expr> = call
                        .args
                        .iter()
                        .map(|a| {
                            let a = rewrite(a, names);
                            if matches!(call.f, Func::Sin | Func::Cos) {
                                renamed(&a, names)
                            } else {
                                a
                            }
                        })
                        .collect();
                    super::eval::rebuild(call.f, &args)
                }
                other => Expr::var(other.clone()),
            };
            t = t.mul(&f.powi(i64::from(*k)).unwrap_or_default());
        }
        out = out.add(&t);
    }
    out
}

/// An argument with its odd terms renamed.
fn renamed(a: &Expr, names: &[Fresh]) -> Expr {
    let mut out = Expr::zero();
    for (m, c) in &a.terms {
        let multiple = names
            .iter()
            .find_map(|(n, w, s)| (n == m).then(|| ratio(c, w).map(|r| (r, s))).flatten());
        match multiple {
            Some((r, s)) => out = out.add(&Expr::symbol(s.clone()).scale(&Coef::rat(r))),
            None => {
                let mut t = Expr::zero();
                t.push(m.clone(), c.clone());
                out = out.add(&t);
            }
        }
    }
    out
}

/// p and q with every odd term inside their sines and cosines renamed to
/// a multiple of a fresh symbol (module doc); None when there is none.
pub fn linearized(p: &Expr, q: &Expr) -> Option<(Expr, Expr)> {
    let mut found = Vec::new();
    terms(p, &mut found);
    terms(q, &mut found);
    if found.is_empty() || found.len() > 8 {
        return None;
    }
    let names = fresh(&found);
    if names.is_empty() || names.len() > 4 {
        return None;
    }
    Some((rewrite(p, &names), rewrite(q, &names)))
}

/// `e` with its odd angles written as multiples of fresh symbols (module
/// doc), in canonical form there, and written back: sin²(t w) + cos²(t w)
/// is 1, which the canonical form over the product angle t w, a call it
/// cannot see into, kept (Exercise 3.19's T₂₁ printed `r2 (sin(t w2)^2 +
/// cos(t w2)^2)`). Equal to `e` (the identity holds for independent
/// fresh symbols, so at their values); None when `e` has no odd angle.
pub fn restored(e: &Expr) -> Option<Expr> {
    let mut found = Vec::new();
    terms(e, &mut found);
    if found.is_empty() || found.len() > 8 {
        return None;
    }
    let names = fresh(&found);
    if names.is_empty() || names.len() > 4 {
        return None;
    }
    let value = |s: &Symbol| {
        names.iter().find(|(_, _, n)| n == s).map(|(m, w, _)| {
            let mut x = Expr::zero();
            x.push(m.clone(), w.clone());
            x
        })
    };
    Some(rewrite(e, &names).subst(&value))
}
