//! `solve(eq, x)` (LANGUAGE.md §8): one unknown of a linear or polynomial
//! equation, as Exercise 2.7 asks (`6 (1 − n) + n f = 6` for f). The
//! equation's two sides minus each other, a polynomial in x with
//! coefficients free of x, is solved in closed form up to degree 2; any
//! other equation is refused, naming why.

use super::Expr;
use super::coef::Coef;
use super::expr::{Symbol, Var};
use std::collections::BTreeMap;

/// The solution of one unknown.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// The real roots, in increasing order (one for a linear equation).
    pub roots: Vec<Expr>,
    /// The coefficient that must not be 0 for the root of a linear
    /// equation with a symbolic coefficient (`n f = 6 n` gives f = 6 for
    /// n ≠ 0); None when it is a nonzero number.
    pub unless_zero: Option<Expr>,
    /// For an angle inside a sine and cosine of k x
    /// ([`super::solve_angle`]): k, the roots being those in (−π, π] and
    /// the general solution adding 2πn/k. None for a polynomial.
    pub period_of: Option<i32>,
}

/// The coefficients of `e` as a polynomial in `x`, by power; Err naming
/// why it is not one (x inside a function, or in a denominator).
pub fn coefficients(e: &Expr, x: &Symbol) -> Result<BTreeMap<i32, Expr>, String> {
    let out = by_power(
        e,
        x,
        |v| matches!(v, Var::Sym(s) if s == x),
        |v| match v {
            Var::Z(s) if s == x => Some(format!("{} is inside a sine or cosine", x.name)),
            Var::Call(call) => Some(format!("{} is inside {}(…)", x.name, call.f.name())),
            _ => None,
        },
    )?;
    if out.keys().any(|p| *p < 0) {
        return Err(format!("{} is in a denominator", x.name));
    }
    Ok(out)
}

/// The terms of `e` grouped by the power of the one factor `of` picks out
/// (x itself for a polynomial, z = e^{ix} for an angle), every other factor
/// kept in that power's coefficient; the zero coefficients dropped. A
/// factor that mentions `x` otherwise is refused with `refuse`'s message
/// (a call is asked only when its arguments mention x).
pub(super) fn by_power(
    e: &Expr,
    x: &Symbol,
    of: impl Fn(&Var) -> bool,
    refuse: impl Fn(&Var) -> Option<String>,
) -> Result<BTreeMap<i32, Expr>, String> {
    let mut out: BTreeMap<i32, Expr> = BTreeMap::new();
    for (m, c) in &e.terms {
        let mut power = 0;
        let mut rest = Vec::with_capacity(m.len());
        for (v, k) in m {
            let mentioned = match v {
                Var::Call(call) => call.args.iter().any(|a| mentions(a, x)),
                _ => true,
            };
            if of(v) {
                power = *k;
            } else if let Some(why) = mentioned.then(|| refuse(v)).flatten() {
                return Err(why);
            } else {
                rest.push((v.clone(), *k));
            }
        }
        out.entry(power).or_default().push(rest, c.clone());
    }
    out.retain(|_, c| !c.terms.is_empty());
    Ok(out)
}

/// Whether `x` occurs in `e`.
pub(super) fn mentions(e: &Expr, x: &Symbol) -> bool {
    let mut found = Vec::new();
    e.symbols(&mut found);
    found.contains(x)
}

/// The real roots of `e = 0` for `x` (see the module): Err naming why
/// there is no answer to give.
pub fn solve(e: &Expr, x: &Symbol) -> Result<Solution, String> {
    if super::solve_angle::is_angular(e, x) {
        let (roots, k) = super::solve_angle::solve_angle(e, x)?;
        return Ok(Solution {
            roots,
            unless_zero: None,
            period_of: Some(k),
        });
    }
    let cs = coefficients(e, x)?;
    let c = |k: i32| cs.get(&k).cloned().unwrap_or_default();
    let degree = cs.keys().next_back().copied().unwrap_or(0);
    match degree {
        0 if cs.is_empty() => Err(format!(
            "the equation holds for every {}: both sides are the same",
            x.name
        )),
        0 => Err(format!(
            "{} does not occur in the equation (its sides differ by {})",
            x.name,
            super::print::expr(&c(0), Default::default())
        )),
        1 => {
            let (a, b) = (c(1), c(0));
            let root = b
                .neg()
                .div(&a)
                .map(|r| r.cancel())
                .ok_or_else(|| format!("cannot divide by the coefficient of {}", x.name))?;
            let unless_zero = a.as_const().is_none().then_some(a);
            Ok(Solution {
                roots: vec![root],
                unless_zero,
                period_of: None,
            })
        }
        2 => quadratic(&c(2), &c(1), &c(0), x),
        d => Err(format!(
            "the equation has degree {d} in {}: solve finds the roots of degree 1 and 2",
            x.name
        )),
    }
}

/// Whether `e`, a polynomial in `x` whose coefficients are exact real
/// numbers, is never 0 at a real x, so that a division by it is defined
/// for every real x: only even powers of x, with coefficients of one sign
/// and a constant term not 0 (x² + 1, 2x⁴ + x² + 3: each term ≥ 0 and
/// the constant > 0), or a quadratic a x² + b x + c whose discriminant
/// b² − 4ac is < 0 (x² + 2x + 5). The signs are exact
/// ([`super::sign::sign_with_pi`]); false whenever they are not known (a
/// coefficient with another symbol in it, x inside a function).
pub fn never_zero(e: &Expr, x: &Symbol) -> bool {
    let Ok(cs) = coefficients(e, x) else {
        return false;
    };
    let sign = |c: &Expr| super::sign::sign_with_pi(c).filter(|s| *s != 0);
    let Some(constant) = cs.get(&0).and_then(sign) else {
        return false;
    };
    if cs
        .iter()
        .all(|(k, c)| k % 2 == 0 && sign(c) == Some(constant))
    {
        return true;
    }
    match (cs.keys().next_back(), cs.get(&2), cs.get(&1)) {
        (Some(2), Some(a), Some(b)) => {
            let disc = b.mul(b).sub(&a.mul(&cs[&0]).scale(&Coef::int(4)));
            sign(&disc) == Some(-1)
        }
        _ => false,
    }
}

/// The real roots of every `es[i] = 0` at once (the entries of a vector
/// or matrix equation, Exercise 3.7(b)'s v₂ = e^{[ω̂]θ} v₁): the roots of
/// the first entry [`solve`] solves, kept where every other entry is 0 at
/// them (exactly, or to 1e-12 of its size at the root's number; between
/// that and 1e-9 is doubt, and refused). Roots must be numbers.
pub fn solve_entries(es: &[Expr], x: &Symbol) -> Result<Solution, String> {
    let live: Vec<(usize, &Expr)> = es
        .iter()
        .enumerate()
        .filter(|(_, e)| !e.terms.is_empty())
        .collect();
    let [(_, first), ..] = live.as_slice() else {
        return Err(format!(
            "the equation holds for every {}: both sides are the same",
            x.name
        ));
    };
    if live.len() == 1 {
        return solve(first, x);
    }
    // an entry with no condition on its coefficient first, then the one
    // with the fewest inexact roots, then the fewest roots (any one has
    // every common root; the exact ones print the book's angles)
    let inexact = |s: &Solution| {
        s.roots
            .iter()
            .filter(|r| r.as_const().is_some_and(|c| !c.is_exact()))
            .count()
    };
    let Some((i, mut s)) = live
        .iter()
        .filter_map(|(i, e)| solve(e, x).ok().map(|s| (*i, s)))
        .min_by_key(|(_, s)| (s.unless_zero.is_some(), inexact(s), s.roots.len()))
    else {
        let m = solve(first, x).err().unwrap_or_default();
        return Err(format!("no entry can be solved for {}: {m}", x.name));
    };
    let mut kept = Vec::with_capacity(s.roots.len());
    for r in &s.roots {
        let Some(v) = r.eval(&|_| None) else {
            return Err(format!(
                "the root {} = {} of entry {} has symbols: solve one entry at a time",
                x.name,
                super::print::expr(r, Default::default()),
                i + 1
            ));
        };
        let mut all = true;
        for (j, e) in &live {
            if *j == i {
                continue;
            }
            match zero_at(e, x, r, v) {
                Some(true) => {}
                Some(false) => all = false,
                None => {
                    return Err(format!(
                        "cannot decide whether entry {} is 0 at {} = {v}",
                        j + 1,
                        x.name
                    ));
                }
            }
        }
        if all {
            kept.push(r.clone());
        }
    }
    if kept.is_empty() {
        return Err(format!(
            "no real {} solves every entry: the roots of entry {} leave another entry ≠ 0",
            x.name,
            i + 1
        ));
    }
    s.roots = kept;
    // (the entries may differ in period; all of them have 2π)
    s.period_of = s.period_of.map(|_| 1);
    Ok(s)
}

/// Whether `e` is 0 at x = r (of number v): exactly, or to 1e-12 of its
/// size; false beyond 1e-9 of it; None between (doubt).
fn zero_at(e: &Expr, x: &Symbol, r: &Expr, v: f64) -> Option<bool> {
    if e.subst(&|s| (s == x).then(|| r.clone())).terms.is_empty() {
        return Some(true);
    }
    let scale: f64 = e
        .terms
        .values()
        .map(|c| {
            let (re, im) = c.to_c64();
            re.hypot(im)
        })
        .sum::<f64>()
        .max(1.0);
    let (re, im) = e.eval_c(&|s| (s == x).then_some(v))?;
    let size = re.hypot(im) / scale;
    if size <= 1e-12 {
        Some(true)
    } else if size > 1e-9 {
        Some(false)
    } else {
        None
    }
}

/// The real roots of a x² + b x + c = 0 with exact numbers a ≠ 0, b, c:
/// (−b ± √(b² − 4ac)) / 2a, in increasing order.
fn quadratic(a: &Expr, b: &Expr, c: &Expr, x: &Symbol) -> Result<Solution, String> {
    let exact = |e: &Expr| {
        e.terms.is_empty()
            || e.as_const()
                .is_some_and(|k| k.as_real().is_some() && k.is_exact())
    };
    if !(exact(a) && exact(b) && exact(c)) {
        return Err(format!(
            "a quadratic in {} with symbolic or inexact coefficients: solve finds its roots when they are exact numbers",
            x.name
        ));
    }
    let disc = b.mul(b).sub(&a.mul(c).scale(&Coef::int(4)));
    let d = disc.as_f64().unwrap_or(0.0);
    if d < 0.0 {
        return Err(format!(
            "no real {} solves it: the discriminant b² − 4ac is {} < 0",
            x.name,
            super::print::expr(&disc, Default::default())
        ));
    }
    let two_a = a.scale(&Coef::int(2));
    let root = |s: &Expr| {
        b.neg()
            .add(s)
            .div(&two_a)
            .map(|r| r.cancel())
            .ok_or_else(|| "cannot divide by 2a".to_string())
    };
    let mut roots = if disc.terms.is_empty() {
        vec![root(&Expr::default())?]
    } else {
        let s = Expr::sqrt(&disc);
        vec![root(&s.neg())?, root(&s)?]
    };
    roots.sort_by(|p, q| {
        let (p, q) = (p.as_f64().unwrap_or(0.0), q.as_f64().unwrap_or(0.0));
        p.total_cmp(&q)
    });
    Ok(Solution {
        roots,
        unless_zero: None,
        period_of: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn x() -> Symbol {
        Symbol::new("x")
    }

    fn sx() -> Expr {
        Expr::symbol(x())
    }

    #[test]
    fn linear_with_a_symbolic_coefficient() {
        // Exercise 2.7: 6 (1 − n) + n f − 6 = 0 for f is 6, for n ≠ 0.
        let n = Expr::symbol(Symbol::new("n"));
        let f = Symbol::new("f");
        let e = Expr::int(6)
            .mul(&Expr::int(1).sub(&n))
            .add(&n.mul(&Expr::symbol(f.clone())))
            .sub(&Expr::int(6));
        let s = solve(&e, &f).unwrap();
        assert_eq!(s.roots, vec![Expr::int(6)]);
        assert_eq!(s.unless_zero, Some(n));
    }

    #[test]
    fn a_polynomial_never_zero_is_told_by_exact_signs() {
        let x2 = sx().mul(&sx());
        let no = |e: &Expr| never_zero(e, &x());
        // x² + 1, −x² − 1, x⁴ + x² + 3, x² + 2x + 5 (b² − 4ac = −16)
        assert!(no(&x2.add(&Expr::int(1))));
        assert!(no(&x2.add(&Expr::int(1)).neg()));
        assert!(no(&x2.mul(&x2).add(&x2).add(&Expr::int(3))));
        assert!(no(&x2.add(&sx().scale(&Coef::int(2))).add(&Expr::int(5))));
        // x² − 1, x², x² + 2x + 1, x³ + 1, x² + n: zeros, or not known
        assert!(!no(&x2.sub(&Expr::int(1))));
        assert!(!no(&x2));
        assert!(!no(&x2.add(&sx().scale(&Coef::int(2))).add(&Expr::int(1))));
        assert!(!no(&x2.mul(&sx()).add(&Expr::int(1))));
        assert!(!no(&x2.add(&Expr::symbol(Symbol::new("n")))));
    }

    #[test]
    fn quadratic_roots_are_exact_and_ordered() {
        // x² − 2 = 0: ∓√2
        let e = sx().mul(&sx()).sub(&Expr::int(2));
        let s = solve(&e, &x()).unwrap();
        let r: Vec<f64> = s.roots.iter().map(|r| r.as_f64().unwrap()).collect();
        assert!((r[0] + 2f64.sqrt()).abs() < 1e-15 && (r[1] - 2f64.sqrt()).abs() < 1e-15);
        // x² − 5x + 6 = 0: 2, 3
        let e = sx()
            .mul(&sx())
            .sub(&sx().scale(&Coef::int(5)))
            .add(&Expr::int(6));
        assert_eq!(
            solve(&e, &x()).unwrap().roots,
            vec![Expr::int(2), Expr::int(3)]
        );
        // (x − 1)² = 0: one root
        let e = sx().sub(&Expr::int(1)).powi(2).unwrap();
        assert_eq!(solve(&e, &x()).unwrap().roots, vec![Expr::int(1)]);
    }

    #[test]
    fn refusals_name_why() {
        let e = sx().mul(&sx()).add(&Expr::int(1));
        assert!(solve(&e, &x()).unwrap_err().contains("no real x"));
        let e = sx().powi(3).unwrap().sub(&Expr::int(1));
        assert!(solve(&e, &x()).unwrap_err().contains("degree 3"));
        let e = Expr::sin(&sx()).sub(&sx());
        let err = solve(&e, &x()).unwrap_err();
        assert!(err.contains("inside"), "{err}");
        assert!(
            solve(&Expr::default(), &x())
                .unwrap_err()
                .contains("every x")
        );
        assert!(
            solve(&Expr::int(3), &x())
                .unwrap_err()
                .contains("does not occur")
        );
    }
}
