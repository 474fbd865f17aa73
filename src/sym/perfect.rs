//! Perfect powers of sums (issue 35; LANGUAGE.md §7): a denominator that is
//! a power of a sum prints as that power, `(1 + r[1]^2 + r[2]^2 + r[3]^2)^2`
//! in Cayley's form of a rotation (3.104), not its ten-term expansion.
//! The k-th root is taken term by term from the leading one in a
//! lexicographic order (a group order on exponent vectors, so that the
//! leading term of a product is the product of the leading terms, Laurent
//! exponents of z = e^{iθ} included), and kept only when its k-th power is
//! the sum exactly.

use super::coef::Coef;
use super::expr::{Expr, Func, Mono, Var};
use super::print::{Mode, Style, expr, power};
use num_traits::Zero;

/// The most terms of a sum whose roots are sought.
const MAX_TERMS: usize = 60;

/// The exponent vector of a monomial over `vars` (sorted).
fn exps(m: &Mono, vars: &[Var]) -> Vec<i32> {
    vars.iter()
        .map(|v| m.iter().find(|(w, _)| w == v).map_or(0, |x| x.1))
        .collect()
}

/// The leading term of `e` in the lexicographic order over `vars`.
fn lead<'a>(e: &'a Expr, vars: &[Var]) -> Option<(&'a Mono, &'a Coef)> {
    e.terms
        .iter()
        .max_by(|a, b| exps(a.0, vars).cmp(&exps(b.0, vars)))
}

/// (root, k) with rootᵏ = e, k ≥ 2 the largest such (the root's leading
/// coefficient a rational k-th root of e's): None when `e` is no such
/// power (or too long to try).
pub fn perfect_power(e: &Expr) -> Option<(Expr, u32)> {
    let n = e.terms.len();
    if !(2..=MAX_TERMS).contains(&n) {
        return None;
    }
    let mut vars: Vec<Var> = e.terms.keys().flatten().map(|(v, _)| v.clone()).collect();
    vars.sort();
    vars.dedup();
    let (top, c) = lead(e, &vars)?;
    let (num, den) = c.as_rat()?.small()?;
    let low = e
        .terms
        .keys()
        .min_by(|a, b| exps(a, &vars).cmp(&exps(b, &vars)))?;
    // k divides every exponent of the leading and the trailing monomials
    let g = top
        .iter()
        .chain(low)
        .fold(0u32, |g, (_, x)| gcd(g, x.unsigned_abs()));
    (2..=g.min(16)).rev().filter(|k| g % k == 0).find_map(|k| {
        // e = c·fᵏ: c's k-th root leads the root
        let c0 = super::coef::Rat::new(
            i128::from(num.signum()) * i128::from(iroot(num.unsigned_abs(), k)?),
            i128::from(iroot(den.unsigned_abs(), k)?),
        )?;
        if k % 2 == 0 && num < 0 {
            return None;
        }
        let c0 = Coef::rat(c0);
        let f = e.scale(&c.inv()?);
        root(&f, k, top, &vars).map(|r| (r.scale(&c0), k))
    })
}

/// The exact k-th root of n, if n is a k-th power.
fn iroot(n: u64, k: u32) -> Option<u64> {
    let guess = (n as f64).powf(1.0 / f64::from(k)).round() as u64;
    (guess.saturating_sub(1)..=guess + 1).find(|r| r.checked_pow(k) == Some(n))
}

fn gcd(mut a: u32, mut b: u32) -> u32 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// The k-th root of `e` whose leading monomial is `top`'s k-th root, term
/// by term: each next term is the leading term of the remainder over
/// k·(leading term)^(k−1).
fn root(e: &Expr, k: u32, top: &Mono, vars: &[Var]) -> Option<Expr> {
    let first: Mono = top.iter().map(|(v, x)| (v.clone(), x / k as i32)).collect();
    let mut r = Expr::zero();
    r.push(first.clone(), Coef::one());
    let below: Mono = first
        .iter()
        .map(|(v, x)| (v.clone(), -x * (k as i32 - 1)))
        .collect();
    let inv_k = Coef::int(i64::from(k)).inv()?;
    let first_exps = exps(&first, vars);
    for _ in 0..(2 * e.terms.len() + 4) {
        let rem = e.sub(&r.powi(i64::from(k))?);
        let Some((m, c)) = lead(&rem, vars) else {
            return Some(r);
        };
        let next = super::expr::mono_mul(m, &below);
        if exps(&next, vars) >= first_exps {
            return None;
        }
        r.push(next, c.mul(&inv_k));
    }
    None
}

/// The text of vᵉ (e > 0): a kept reciprocal whose sum is a perfect power
/// as that power, `(1 + r[1]^2 + r[2]^2 + r[3]^2)^2`; else `v^e`.
pub fn var_power(v: &Var, e: i32, st: Style) -> String {
    let latex = st.mode == Mode::Latex;
    if let Var::Call(call) = v
        && call.f == Func::Recip
        && let Some((r, k)) = perfect_power(&call.args[0])
    {
        let inner = expr(&r, st);
        let k = e.saturating_mul(k as i32);
        return if latex {
            format!("\\left({inner}\\right)^{{{k}}}")
        } else {
            format!("({inner})^{k}")
        };
    }
    power(&super::print::var(v, st), e, latex)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::Symbol;
    use num_traits::One;

    fn s(n: &str) -> Expr {
        Expr::symbol(Symbol::new(n))
    }

    #[test]
    fn powers_of_sums_are_found_and_others_are_not() {
        let (a, b, t) = (s("a"), s("b"), s("t"));
        let q = Expr::one().add(&a.mul(&a)).add(&b.mul(&b));
        assert_eq!(perfect_power(&q.powi(2).unwrap()), Some((q.clone(), 2)));
        assert_eq!(perfect_power(&q.powi(3).unwrap()), Some((q.clone(), 3)));
        // a fourth power is the largest: (q²)² is q⁴
        assert_eq!(perfect_power(&q.powi(4).unwrap()), Some((q.clone(), 4)));
        assert_eq!(perfect_power(&q), None);
        // one more term: no longer a square
        assert_eq!(perfect_power(&q.powi(2).unwrap().add(&a)), None);
        // a trigonometric sum: (1 + cos t)²
        let c = Expr::one().add(&Expr::cos(&t));
        assert_eq!(perfect_power(&c.powi(2).unwrap()), Some((c, 2)));
        // a leading coefficient that is a square: (2 q)²; one that is not
        let two = q.scale(&Coef::int(2));
        assert_eq!(perfect_power(&two.powi(2).unwrap()), Some((two, 2)));
        assert_eq!(
            perfect_power(&q.powi(2).unwrap().scale(&Coef::int(3))),
            None
        );
    }
}
