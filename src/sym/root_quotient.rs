//! A monomial over a square root of itself: `a/sqrt(a)` is `sqrt(a)`,
//! `a²/sqrt(a)` is `a sqrt(a)`, `a b/sqrt(a b)³` is `1/sqrt(a b)` — where
//! the root's argument is a product of symbols (coefficient 1) whose
//! powers the rest of the monomial holds (and `sqrt(a)/a` is
//! `1/sqrt(a)`, where it divides by them). Both sides are defined for
//! the same numbers (the argument > 0), so the fold is an identity there;
//! without it `diff(a^(3/2), a)` printed `(1/2) a/sqrt(a) + sqrt(a)` and
//! `== (3/2) sqrt(a)` could not be decided. Terms over the root of a
//! sum fold together when their numerators add up to a multiple of it
//! (`(a + 1)/sqrt(a + 1)` is `sqrt(1 + a)`: [`Expr::fold_root_sums`]).

use super::Expr;
use super::coef::Coef;
use super::expr::{Func, Mono, Var};

impl Expr {
    /// √x · √x = x: a square root's even powers become powers of x; and
    /// |x|·|x| = x² for a real x (symbols and calls are real): an absolute
    /// value's even powers become powers of x.
    pub(super) fn fold_roots(self) -> Expr {
        let is_root = |v: &Var, e: i32| {
            e.abs() >= 2
                && matches!(v, Var::Call(c) if c.f == Func::Sqrt
                    || (c.f == Func::Abs && c.args[0].conj() == c.args[0]))
        };
        if !self.terms.keys().flatten().any(|(v, e)| is_root(v, *e)) {
            return self;
        }
        let mut out = Expr::default();
        for (m, c) in self.terms {
            let mut rest: Mono = Vec::new();
            let mut t = Expr::constant(c);
            for (v, e) in m {
                match &v {
                    Var::Call(call) if is_root(&v, e) => {
                        // (√x^e = x^(e/2) √x^(e % 2); |x|^e = x^(e − e % 2) |x|^(e % 2))
                        let half = if call.f == Func::Abs {
                            e - e % 2
                        } else {
                            e / 2
                        };
                        let inner = call.args[0].powi(i64::from(half)).unwrap_or_default();
                        t = t.mul(&inner);
                        if e % 2 != 0 {
                            rest.push((v.clone(), e % 2));
                        }
                    }
                    _ => rest.push((v, e)),
                }
            }
            let mut r = Expr::default();
            r.push(rest, Coef::one());
            out = out.add(&t.mul(&r));
        }
        out
    }
    /// Each monomial's factors of a square root's argument moved into the
    /// root's negative odd power (see the module); and out of a positive
    /// one over them: `sqrt(a)/a` is `1/sqrt(a)` (both defined for a > 0
    /// alone, so an identity everywhere).
    pub(super) fn fold_root_quotients(self) -> Expr {
        let over_root = |v: &Var, e: i32| e != 0 && matches!(v, Var::Call(c) if c.f == Func::Sqrt);
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
                while m[i].1 > 0 && owes(&m, u) {
                    for (v, k) in u {
                        if let Some(f) = m.iter_mut().find(|(w, _)| w == v) {
                            f.1 += k;
                        }
                    }
                    m[i].1 -= 2;
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

/// Whether monomial `m` divides by every factor of `u` to at least its
/// power.
fn owes(m: &Mono, u: &Mono) -> bool {
    u.iter()
        .all(|(v, k)| m.iter().any(|(w, e)| w == v && *e <= -k))
}

/// Whether `v` is a square root of a sum (`sqrt(1 + a)`).
fn root_of_sum(v: &Var) -> bool {
    matches!(v, Var::Call(c) if c.f == Func::Sqrt && c.args[0].terms.len() > 1)
}

impl Expr {
    /// Whether some term divides by a square root of a sum
    /// (`a/sqrt(1 + a)`): [`Expr::fold_root_sums`] has work to do.
    pub fn has_root_quotient(&self) -> bool {
        self.terms
            .keys()
            .flatten()
            .any(|(v, e)| *e < 0 && root_of_sum(v))
    }

    /// The terms over one negative power of the square root √u of a sum
    /// whose numerators add up to a multiple of u, folded as the module
    /// folds a monomial's: u·q/√u^k = q/√u^(k−2), since √u·√u = u for the
    /// principal root. `(a + 1)/sqrt(a + 1)` printed `a/sqrt(1 + a) +
    /// 1/sqrt(1 + a)`; it is `sqrt(1 + a)`. Domain: the left side is
    /// defined where u > 0 (a negative power of √u), and there both sides
    /// are the same number; at u = 0 the right side may be defined where
    /// the left is not, the cancellation `x/x` = 1 also makes (`solve`
    /// reads the domain from the expression as typed,
    /// `crate::decide::domain`). Numerators that do not add up to a
    /// multiple of u (`(a + 2)/sqrt(a + 1)`) are left as they are.
    pub fn fold_root_sums(self) -> Expr {
        if !self.has_root_quotient() {
            return self;
        }
        let mut out = Expr::default();
        // (each root and power, with the sum of the numerators over it)
        let mut groups: Vec<((Var, i32), Expr)> = Vec::new();
        for (mut m, c) in self.terms {
            let Some(i) = m.iter().position(|(v, e)| *e < 0 && root_of_sum(v)) else {
                out.push(m, c);
                continue;
            };
            let root = m.remove(i);
            match groups.iter_mut().find(|(r, _)| *r == root) {
                Some((_, num)) => num.push(m, c),
                None => {
                    let mut num = Expr::default();
                    num.push(m, c);
                    groups.push((root, num));
                }
            }
        }
        for ((v, mut e), mut num) in groups {
            let Var::Call(call) = &v else {
                continue;
            };
            while e < 0 {
                match num.div_exact(&call.args[0]) {
                    Some(q) => {
                        num = q;
                        e += 2;
                    }
                    None => break,
                }
            }
            let mut power = Expr::default();
            power.push(if e == 0 { Vec::new() } else { vec![(v, e)] }, Coef::one());
            out = out.add(&num.mul(&power));
        }
        out
    }
}
