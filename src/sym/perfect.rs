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

/// (c, root, k) with c·rootᵏ = e, k ≥ 2 the largest such, c rational, the
/// root's constant term 1 where it has one (`1 + cos(t)`), else its
/// leading coefficient: None when `e` is no such power (or too long to
/// try).
pub fn perfect_power(e: &Expr) -> Option<(Coef, Expr, u32)> {
    let n = e.terms.len();
    if !(2..=MAX_TERMS).contains(&n) {
        return None;
    }
    let mut vars: Vec<Var> = e.terms.keys().flatten().map(|(v, _)| v.clone()).collect();
    vars.sort();
    vars.dedup();
    let (top, lc) = lead(e, &vars)?;
    lc.as_rat()?;
    let low = e
        .terms
        .keys()
        .min_by(|a, b| exps(a, &vars).cmp(&exps(b, &vars)))?;
    // k divides every exponent of the leading and the trailing monomials
    let g = top
        .iter()
        .chain(low)
        .fold(0u32, |g, (_, x)| gcd(g, x.unsigned_abs()));
    let f = e.scale(&lc.inv()?);
    (2..=g.min(16)).rev().filter(|k| g % k == 0).find_map(|k| {
        let r = root(&f, k, top, &vars)?;
        // (a root that is not real prints as a real form that is not its
        // value: sin(b + π/6)³ is −(1/8)(z + e^{2πi/3} z⁻¹)³, whose root
        // printed `sin(b + π/6)`, so 1/sin(b + π/6)^3 printed −8/(…)^3)
        if r.conj() != r {
            return None;
        }
        // e = lc·rᵏ = lc·c0ᵏ·(r/c0)ᵏ
        let c0 = r.terms.get(&Vec::new()).cloned().unwrap_or_else(Coef::one);
        c0.as_rat()?;
        let inv = c0.inv()?;
        let mut c = lc.clone();
        for _ in 0..k {
            c = c.mul(&c0);
        }
        Some((c, r.scale(&inv), k))
    })
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

/// The text of vᵉ (e > 0) and the constant f it leaves out (vᵉ = f·text):
/// a kept reciprocal 1/(d) prints its sum d, and where d is c·qᵏ, dᵉ as
/// `(q)^(k e)` with f = cᵉ, `(1 + r[1]^2 + r[2]^2 + r[3]^2)^2`; else `v^e`
/// with f = 1.
pub fn var_power(v: &Var, e: i32, st: Style) -> (Coef, String) {
    let latex = st.mode == Mode::Latex;
    if let Var::Call(call) = v
        && call.f == Func::Recip
        && let Some((c, r, k)) = perfect_power(&call.args[0])
    {
        let inner = expr(&r, st);
        let mut f = Coef::one();
        for _ in 0..e {
            f = f.mul(&c);
        }
        let k = e.saturating_mul(k as i32);
        let text = if latex {
            format!("\\left({inner}\\right)^{{{k}}}")
        } else {
            format!("({inner})^{k}")
        };
        return (f, text);
    }
    (Coef::one(), power(&super::print::var(v, st), e, latex))
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
        let one = Coef::one();
        assert_eq!(
            perfect_power(&q.powi(2).unwrap()),
            Some((one.clone(), q.clone(), 2))
        );
        assert_eq!(
            perfect_power(&q.powi(3).unwrap()),
            Some((one.clone(), q.clone(), 3))
        );
        // a fourth power is the largest: (q²)² is q⁴
        assert_eq!(
            perfect_power(&q.powi(4).unwrap()),
            Some((one.clone(), q.clone(), 4))
        );
        assert_eq!(perfect_power(&q), None);
        // one more term: no longer a square
        assert_eq!(perfect_power(&q.powi(2).unwrap().add(&a)), None);
        // a trigonometric sum: (1 + cos t)²
        let c = Expr::one().add(&Expr::cos(&t));
        assert_eq!(
            perfect_power(&c.powi(2).unwrap()),
            Some((one.clone(), c.clone(), 2))
        );
        // (2/3)(1 + cos t)²: its constant term 1
        let third = c
            .powi(2)
            .unwrap()
            .scale(&Coef::rat(super::super::coef::Rat::new(2, 3).unwrap()));
        assert_eq!(perfect_power(&third).map(|x| x.1), Some(c));
        // a constant taken out: 3 q² (q with its constant term 1)
        let three = q.powi(2).unwrap().scale(&Coef::int(3));
        assert_eq!(perfect_power(&three), Some((Coef::int(3), q.clone(), 2)));
        // sin(t + π/6)³: its only root term by term is not real (trial 18)
        let sixth = Coef::rat(super::super::coef::Rat::new(1, 6).unwrap());
        let u = t.add(&Expr::pi().scale(&sixth));
        assert_eq!(perfect_power(&Expr::sin(&u).powi(3).unwrap()), None);
        // a real root is kept: (1 + cos t)³
        let c = Expr::one().add(&Expr::cos(&t));
        assert_eq!(perfect_power(&c.powi(3).unwrap()), Some((one, c, 3)));
    }
}
