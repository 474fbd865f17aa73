//! Common trigonometric factors taken out when printing (issue 21: no more
//! sin/cos calls than SymPy's `simplify`): terms that share a factor print
//! as one, `(sin(t1) sin(t5) + cos(t1) cos(t5) cos(t2 + t3 + t4)) cos(t6)`
//! for sin(t1) sin(t5) cos(t6) + cos(t1) cos(t5) cos(t2 + t3 + t4) cos(t6).
//! Greedy: the factor shared by the most terms first, then again among
//! the terms left, and again inside each group (a tilted 6-joint chain's
//! entries print nested, `((…) cos(t3) + …) cos(t2)`: 1,296 sin/cos calls
//! fall to 598). A sum of more than 12 terms with multiple angles
//! (`(sin a + cos b)^30`) is an expansion and stays a sum of short lines.
//! Only the printing changes; the canonical form stays expanded, and the
//! printed form reads back to it.

use super::coef::Coef;
use super::expr::Mono;
use super::fraction::term;
use super::print::{Mode, Style, join, trig_factor};
use super::trig::{Real, Trig};

/// The most terms an expression may have for its factors to be taken out
/// (past the expression limit: every printed expression).
const MAX_TERMS: usize = 100_000;
/// The most terms of a sum with multiple angles (`cos(3 b)`) whose factors
/// are taken out.
const LONG: usize = 12;

/// One term being grouped: its place in print order, its monomial, its
/// trigonometric factors left, its coefficient.
type Item<'a> = (usize, &'a Mono, Vec<Trig>, &'a Coef);

/// The signed terms of a real form, common factors taken out (again
/// inside each group: `((a + b) cos(t2) + c) cos(t1)`).
pub fn factored(real: &Real, st: Style) -> Vec<(bool, String)> {
    // a long sum with multiple angles is an expansion (`(sin a + cos b)^30`,
    // `cos(3 b)`): it stays a sum of short lines
    let multiple = || {
        real.keys()
            .flat_map(|(_, trig)| trig)
            .any(|(k, _, _)| k.iter().any(|(s, e)| e.abs() >= 2 && !s.is_phase()))
    };
    if real.len() > MAX_TERMS || (real.len() > LONG && multiple()) {
        return real
            .iter()
            .map(|((poly, trig), c)| term(c, poly, trig, st))
            .collect();
    }
    let items: Vec<Item> = real
        .iter()
        .enumerate()
        .map(|(i, ((poly, trig), c))| (i, poly, trig.clone(), c))
        .collect();
    group(items, st).into_iter().map(|(_, t)| t).collect()
}

/// The terms grouped by their most shared factor, each group's inner sum
/// grouped in turn; in the order of each group's first term.
fn group(items: Vec<Item>, st: Style) -> Vec<(usize, (bool, String))> {
    let mut left = items;
    let mut out: Vec<(usize, (bool, String))> = Vec::new();
    while let Some(f) = most_shared(&left) {
        let (shared, rest): (Vec<_>, Vec<_>) =
            left.into_iter().partition(|(_, _, t, _)| t.contains(&f));
        left = rest;
        let first = shared.iter().map(|x| x.0).min().unwrap_or(0);
        let inner: Vec<Item> = shared
            .into_iter()
            .map(|(i, poly, trig, c)| (i, poly, trig.into_iter().filter(|x| *x != f).collect(), c))
            .collect();
        let mut inner: Vec<(bool, String)> = group(inner, st).into_iter().map(|(_, t)| t).collect();
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
    for (i, poly, trig, c) in left {
        out.push((i, term(c, poly, &trig, st)));
    }
    out.sort_by_key(|(i, _)| *i);
    out
}

/// The trigonometric factor shared by the most terms (at least two; the
/// first in print order on a tie): one count per factor, so that a long
/// sum is factored in time linear in its terms per factor taken out.
fn most_shared(terms: &[Item]) -> Option<Trig> {
    let mut counts: std::collections::HashMap<&Trig, (usize, usize)> = Default::default();
    let mut order = 0;
    for (_, _, trig, _) in terms {
        for f in trig {
            let e = counts.entry(f).or_insert((0, order));
            e.0 += 1;
            order += 1;
        }
    }
    counts
        .into_iter()
        .filter(|(_, (n, _))| *n >= 2)
        .min_by_key(|(_, (n, first))| (std::cmp::Reverse(*n), *first))
        .map(|(f, _)| f.clone())
}

#[cfg(test)]
mod tests {
    use crate::sym::expr::{Expr, Symbol};
    use crate::sym::print::{Style, expr, join};

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
        // L + (1 - L) cos t: the term without cos t stays outside (the
        // printed shape is the book's, cos(t) + L (1 - cos(t)): sym::shape)
        let (l, t) = (s("L"), s("t"));
        let g = l.sub(&l.mul(&Expr::cos(&t))).add(&Expr::cos(&t));
        let alone = super::factored(&crate::sym::trig::real_form(&g), Style::default());
        assert_eq!(join(&alone, usize::MAX, 0), "(1 - L) cos(t) + L");
        assert_eq!(expr(&g, Style::default()), "cos(t) + L (1 - cos(t))");
    }
}
