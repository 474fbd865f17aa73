//! Common trigonometric factors taken out when printing (issue 21: no more
//! sin/cos calls than SymPy's `simplify`): terms that share a factor print
//! as one, `(sin(t1) sin(t5) + cos(t1) cos(t5) cos(t2 + t3 + t4)) cos(t6)`
//! for sin(t1) sin(t5) cos(t6) + cos(t1) cos(t5) cos(t2 + t3 + t4) cos(t6).
//! Greedy and one level deep: the factor shared by the most terms first,
//! then again among the terms left; a sum of more than `MAX_TERMS` (12) terms
//! is left as it is. Only the printing changes; the canonical form stays
//! expanded.

use super::coef::Coef;
use super::expr::Mono;
use super::fraction::term;
use super::print::{Mode, Style, join, trig_factor};
use super::trig::{Real, Trig};

/// The most terms an expression may have for its factors to be taken out:
/// a long expansion (`(sin a + cos b)^30`) stays a sum of short lines.
const MAX_TERMS: usize = 12;

/// The signed terms of a real form, common factors taken out.
pub fn factored(real: &Real, st: Style) -> Vec<(bool, String)> {
    if real.len() > MAX_TERMS {
        return real
            .iter()
            .map(|((poly, trig), c)| term(c, poly, trig, st))
            .collect();
    }
    let mut left: Vec<(&Mono, &[Trig], &Coef)> = real
        .iter()
        .map(|((poly, trig), c)| (poly, trig.as_slice(), c))
        .collect();
    // (position of the first term, the text) of each printed term
    let mut out: Vec<(usize, (bool, String))> = Vec::new();
    let order: Vec<*const Coef> = left.iter().map(|(_, _, c)| *c as *const Coef).collect();
    let at = |c: &Coef| order.iter().position(|p| std::ptr::eq(*p, c)).unwrap_or(0);
    while let Some(f) = most_shared(&left) {
        let (shared, rest): (Vec<_>, Vec<_>) =
            left.into_iter().partition(|(_, t, _)| t.contains(&f));
        left = rest;
        let first = at(shared[0].2);
        let mut inner: Vec<(bool, String)> = shared
            .iter()
            .map(|(poly, trig, c)| {
                let without: Vec<Trig> = trig.iter().filter(|x| **x != f).cloned().collect();
                term(c, poly, &without, st)
            })
            .collect();
        let neg = inner[0].0;
        if neg {
            inner.iter_mut().for_each(|t| t.0 = !t.0);
        }
        let sum = join(&inner, usize::MAX, 0);
        let name = if f.1 { "sin" } else { "cos" };
        let factor = trig_factor(&f.0, name, f.2, st);
        let text = if st.mode == Mode::Latex {
            format!("\\left({sum}\\right) {factor}")
        } else {
            format!("({sum}) {factor}")
        };
        out.push((first, (neg, text)));
    }
    for (poly, trig, c) in left {
        out.push((at(c), term(c, poly, trig, st)));
    }
    out.sort_by_key(|(i, _)| *i);
    out.into_iter().map(|(_, t)| t).collect()
}

/// The trigonometric factor shared by the most terms (at least two; the
/// first in print order on a tie).
fn most_shared(terms: &[(&Mono, &[Trig], &Coef)]) -> Option<Trig> {
    let mut best: Option<(usize, &Trig)> = None;
    for (_, trig, _) in terms {
        for f in *trig {
            let n = terms.iter().filter(|(_, t, _)| t.contains(f)).count();
            if n >= 2 && best.is_none_or(|(m, _)| n > m) {
                best = Some((n, f));
            }
        }
    }
    best.map(|(_, f)| f.clone())
}

#[cfg(test)]
mod tests {
    use crate::sym::expr::{Expr, Symbol};
    use crate::sym::print::{Style, expr};

    fn s(n: &str) -> Expr {
        Expr::symbol(Symbol::new(n))
    }

    #[test]
    fn shared_factors_come_out_with_their_sign() {
        let (a, b, c) = (s("a"), s("b"), s("c"));
        let (ca, sa, cb, sc) = (Expr::cos(&a), Expr::sin(&a), Expr::cos(&b), Expr::sin(&c));
        // −cos a cos b − 2 sin a cos b + sin c: cos b shared, the group negative
        let e = ca
            .mul(&cb)
            .neg()
            .sub(&sa.mul(&cb).add(&sa.mul(&cb)))
            .add(&sc);
        assert_eq!(
            expr(&e, Style::default()),
            "-(cos(a) + 2 sin(a)) cos(b) + sin(c)"
        );
        // nothing shared: as before
        let f = ca.add(&sc);
        assert_eq!(expr(&f, Style::default()), "cos(a) + sin(c)");
        // L + (1 - L) cos t: the term without cos t stays outside
        let (l, t) = (s("L"), s("t"));
        let g = l.sub(&l.mul(&Expr::cos(&t))).add(&Expr::cos(&t));
        assert_eq!(expr(&g, Style::default()), "(1 - L) cos(t) + L");
    }
}
