//! Angles that are not linear in the symbols (`cos(x y)`, SymPy's
//! `cos(x y) − cos y = −2 sin((x y − y)/2) sin((x y + y)/2)`): each
//! product of symbols inside a sine or cosine is given a fresh symbol w of
//! its own, the same on both sides of an equation, so that the angles are
//! linear and the canonical form (with [`super::together::unhalved`])
//! decides them. An identity in independent w, x, y holds in particular at
//! w = x y, so a `true` so found is a proof; a difference is not (w = x y
//! is a special case), and the caller answers only `true` from it.

use super::expr::{Expr, Func, Mono, Symbol, Var};
use num_traits::Zero;

/// The products of symbols (monomials of degree ≥ 2, no calls) in the
/// arguments of the sines and cosines of `e`.
fn products(e: &Expr, out: &mut Vec<Mono>) {
    for (v, _) in e.terms.keys().flatten() {
        let Var::Call(c) = v else { continue };
        for a in &c.args {
            if matches!(c.f, Func::Sin | Func::Cos) {
                for m in a.terms.keys() {
                    let degree: i32 = m.iter().map(|(_, k)| *k).sum();
                    let plain = m.iter().all(|(v, k)| matches!(v, Var::Sym(_)) && *k > 0);
                    if plain && degree >= 2 && !out.contains(m) {
                        out.push(m.clone());
                    }
                }
            }
            products(a, out);
        }
    }
}

/// `e` with each product of `names` in a sine's or cosine's argument
/// written as its fresh symbol.
fn rewrite(e: &Expr, names: &[(Mono, Symbol)]) -> Expr {
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

/// An argument with its products of symbols renamed.
fn renamed(a: &Expr, names: &[(Mono, Symbol)]) -> Expr {
    let mut out = Expr::zero();
    for (m, c) in &a.terms {
        let mut t = Expr::zero();
        match names.iter().find(|(n, _)| n == m) {
            Some((_, s)) => t = t.add(&Expr::symbol(s.clone())),
            None => t.push(m.clone(), super::coef::Coef::one()),
        }
        out = out.add(&t.scale(c));
    }
    out
}

/// p and q with every product of symbols inside their sines and cosines
/// renamed to a fresh symbol (module doc); None when there is none.
pub fn linearized(p: &Expr, q: &Expr) -> Option<(Expr, Expr)> {
    let mut found = Vec::new();
    products(p, &mut found);
    products(q, &mut found);
    if found.is_empty() || found.len() > 4 {
        return None;
    }
    let names: Vec<(Mono, Symbol)> = found
        .into_iter()
        .enumerate()
        .map(|(i, m)| (m, Symbol::new(&format!("\u{1}product {i}"))))
        .collect();
    Some((rewrite(p, &names), rewrite(q, &names)))
}
