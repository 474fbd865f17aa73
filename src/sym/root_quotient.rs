//! A monomial over a square root of itself: `a/sqrt(a)` is `sqrt(a)`,
//! `a²/sqrt(a)` is `a sqrt(a)`, `a b/sqrt(a b)³` is `1/sqrt(a b)` — where
//! the root's argument is a product of symbols (coefficient 1) whose
//! powers the rest of the monomial holds. Both sides are defined for
//! the same numbers (the argument > 0), so the fold is an identity there;
//! without it `diff(a^(3/2), a)` printed `(1/2) a/sqrt(a) + sqrt(a)` and
//! `== (3/2) sqrt(a)` could not be decided.

use super::Expr;
use super::coef::Coef;
use super::expr::{Func, Mono, Var};

impl Expr {
    /// Each monomial's factors of a square root's argument moved into the
    /// root's negative odd power (see the module).
    pub(super) fn fold_root_quotients(self) -> Expr {
        let over_root = |v: &Var, e: i32| e < 0 && matches!(v, Var::Call(c) if c.f == Func::Sqrt);
        if !self.terms.keys().flatten().any(|(v, e)| over_root(v, *e)) {
            return self;
        }
        let mut out = Expr::default();
        for (mut m, c) in self.terms {
            let roots: Vec<usize> = (0..m.len())
                .filter(|i| over_root(&m[*i].0, m[*i].1))
                .collect();
            for i in roots {
                let Var::Call(call) = m[i].0.clone() else {
                    continue;
                };
                let Some(u) = plain_monomial(&call.args[0]) else {
                    continue;
                };
                while m[i].1 < 0 && holds(&m, u) {
                    for (v, k) in u {
                        if let Some(f) = m.iter_mut().find(|(w, _)| w == v) {
                            f.1 -= k;
                        }
                    }
                    m[i].1 += 2;
                }
            }
            m.retain(|(_, e)| *e != 0);
            out.push(m, c);
        }
        out
    }
}

/// The one monomial of `u` when `u` is a product of symbols' positive
/// powers with coefficient 1 (`a`, `a b²`).
fn plain_monomial(u: &Expr) -> Option<&Mono> {
    let [(m, c)] = u.terms.iter().collect::<Vec<_>>()[..] else {
        return None;
    };
    (*c == Coef::one()
        && !m.is_empty()
        && m.iter().all(|(v, k)| *k > 0 && matches!(v, Var::Sym(_))))
    .then_some(m)
}

/// Whether monomial `m` holds every factor of `u` to at least its power.
fn holds(m: &Mono, u: &Mono) -> bool {
    u.iter()
        .all(|(v, k)| m.iter().any(|(w, e)| w == v && e >= k))
}
