//! Collecting a sum as the book writes it (issue 35; LANGUAGE.md §7): the
//! terms that share a factor — a symbol or a trigonometric factor — print
//! as one, with every factor they share and their integer content taken
//! out, `w[1] w[2] (1 - cos(θ))` for w₁w₂ − w₁w₂ cos θ (3.52) and
//! `s (r[1]^2 + r[2]^2 + r[3]^2 + s^2)` for a characteristic polynomial.
//! Greedy: the factor shared by the most terms first (a symbol before a
//! trigonometric factor on a tie: the book keeps ω̂₁² outside (1 − cθ)),
//! again among the terms left and inside each group; a group is formed only
//! when it prints shorter than its terms. Only the printing changes: the
//! canonical form stays expanded, and the printed form reads back to it.

use std::collections::HashMap;

use super::coef::{Coef, Rat};
use super::expr::{Func, Mono, Var};
use super::fraction::term;
use super::print::{Mode, Style, join, text_width, trig_factor};
use super::trig::{Angle, Real, Trig};

/// One term being collected: its place in print order, its monomial
/// (the non-angle variables), its trigonometric factors, its coefficient.
pub(super) type Item = (usize, Mono, Vec<Trig>, Coef);

/// A factor terms may share: a variable to a positive power, or a
/// trigonometric factor (an angle and whether it is a sine) to a power.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
enum Fac {
    Var(Var),
    Trig(Angle, bool),
}

/// The terms of a real form, in print order.
pub(super) fn items(real: &Real) -> Vec<Item> {
    real.iter()
        .enumerate()
        .map(|(i, ((poly, trig), c))| (i, poly.clone(), trig.clone(), c.clone()))
        .collect()
}

/// True when collecting can differ from taking out trigonometric factors
/// alone ([`super::factor`]): a variable shared by two terms, or a common
/// integer content.
pub(super) fn worth(items: &[Item]) -> bool {
    let mut seen: HashMap<&Var, usize> = HashMap::new();
    for (_, poly, _, _) in items {
        for (v, e) in poly {
            if shareable(v, *e) {
                let n = seen.entry(v).or_insert(0);
                *n += 1;
                if *n >= 2 {
                    return true;
                }
            }
        }
    }
    items.len() >= 2 && !content(items).is_one()
}

/// A variable that can be taken out of a sum: to a positive power, and not
/// a kept quotient's sum (those print apart, [`super::fraction`]).
fn shareable(v: &Var, e: i32) -> bool {
    e > 0 && !matches!(v, Var::Call(c) if c.f == Func::Recip)
}

/// The signed terms of `items` collected, each with its place in print
/// order (that of its first term).
pub(super) fn collect(items: Vec<Item>, st: Style) -> Vec<(usize, (bool, String))> {
    if items.len() >= 2 {
        let (poly, trig, k) = common(&items);
        if !poly.is_empty() || !trig.is_empty() || !k.is_one() {
            let first = items.iter().map(|x| x.0).min().unwrap_or(0);
            return vec![(first, grouped(items, &poly, &trig, &k, st))];
        }
    }
    let mut left = items;
    let mut tried: Vec<Fac> = Vec::new();
    let mut out: Vec<(usize, (bool, String))> = Vec::new();
    while let Some(f) = most_shared(&left, &tried) {
        let (shared, rest): (Vec<Item>, Vec<Item>) = left.into_iter().partition(|x| has(x, &f));
        let flat: Vec<(bool, String)> = shared
            .iter()
            .map(|(_, poly, trig, c)| term(c, poly, trig, st))
            .collect();
        let (poly, trig, k) = common(&shared);
        let first = shared.iter().map(|x| x.0).min().unwrap_or(0);
        let g = grouped(shared.clone(), &poly, &trig, &k, st);
        if width(std::slice::from_ref(&g)) < width(&flat) {
            out.push((first, g));
            left = rest;
        } else {
            tried.push(f);
            left = shared.into_iter().chain(rest).collect();
            left.sort_by_key(|x| x.0);
        }
    }
    for (i, poly, trig, c) in left {
        out.push((i, term(&c, &poly, &trig, st)));
    }
    out.sort_by_key(|(i, _)| *i);
    out
}

/// Columns of signed terms on one line.
pub(super) fn width(ts: &[(bool, String)]) -> usize {
    text_width(&join(ts, usize::MAX, 0))
}

fn has(x: &Item, f: &Fac) -> bool {
    match f {
        Fac::Var(v) => x.1.iter().any(|(w, e)| w == v && shareable(w, *e)),
        Fac::Trig(k, sin) => x.2.iter().any(|(a, s, _)| a == k && s == sin),
    }
}

/// The factor shared by the most terms (at least two) and not yet tried:
/// a variable before a trigonometric factor on a tie, then the first in
/// print order.
fn most_shared(items: &[Item], tried: &[Fac]) -> Option<Fac> {
    let mut counts: HashMap<Fac, (usize, usize)> = HashMap::new();
    let mut order = 0;
    for (_, poly, trig, _) in items {
        let vars = poly
            .iter()
            .filter(|(v, e)| shareable(v, *e))
            .map(|(v, _)| Fac::Var(v.clone()));
        let trigs = trig.iter().map(|(k, s, _)| Fac::Trig(k.clone(), *s));
        for f in vars.chain(trigs) {
            let e = counts.entry(f).or_insert((0, order));
            e.0 += 1;
            order += 1;
        }
    }
    counts
        .into_iter()
        .filter(|(f, (n, _))| *n >= 2 && !tried.contains(f))
        .min_by_key(|(f, (n, first))| (std::cmp::Reverse(*n), matches!(f, Fac::Trig(..)), *first))
        .map(|(f, _)| f)
}

/// What every term shares: the variables (least positive power), the
/// trigonometric factors (least power), the integer content.
fn common(items: &[Item]) -> (Mono, Vec<Trig>, Coef) {
    let Some((_, p0, t0, _)) = items.first() else {
        return (Vec::new(), Vec::new(), Coef::one());
    };
    let mut poly: Mono = p0
        .iter()
        .filter(|(v, e)| shareable(v, *e))
        .cloned()
        .collect();
    let mut trig: Vec<Trig> = t0.clone();
    for (_, p, t, _) in &items[1..] {
        poly = poly
            .into_iter()
            .filter_map(|(v, e)| {
                let f = p.iter().find(|(w, _)| *w == v)?.1;
                (f > 0).then_some((v, e.min(f)))
            })
            .collect();
        trig = trig
            .into_iter()
            .filter_map(|(k, s, e)| {
                let f = t.iter().find(|(a, b, _)| *a == k && *b == s)?.2;
                Some((k, s, e.min(f)))
            })
            .collect();
    }
    (poly, trig, content(items))
}

/// The positive rational every coefficient is an integer multiple of,
/// when they are all exact rationals over one denominator (8 for
/// −8 r₂² − 8 r₃², 1/2 for (1/2) a + (1/2) b); else 1.
fn content(items: &[Item]) -> Coef {
    let mut g: i64 = 0;
    let mut den: Option<i64> = None;
    for (_, _, _, c) in items {
        let Some((n, d)) = c.as_rat().as_ref().and_then(Rat::small) else {
            return Coef::one();
        };
        if den.is_some_and(|x| x != d) {
            return Coef::one();
        }
        den = Some(d);
        g = gcd(g, n.unsigned_abs() as i64);
    }
    match (g, den) {
        (g, Some(d)) if g > 0 => Rat::new(i128::from(g), i128::from(d))
            .map(Coef::rat)
            .unwrap_or_else(Coef::one),
        _ => Coef::one(),
    }
}

fn gcd(mut a: i64, mut b: i64) -> i64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.abs()
}

/// The group `k poly (inner) trig`: the terms divided by what they share,
/// collected in turn (or with trigonometric factors taken out alone,
/// [`super::factor`], where that is shorter), their sign in front.
fn grouped(items: Vec<Item>, poly: &Mono, trig: &[Trig], k: &Coef, st: Style) -> (bool, String) {
    let inv = k.inv().unwrap_or_else(Coef::one);
    let inner: Vec<Item> = items
        .into_iter()
        .map(|(i, p, t, c)| {
            let p = p
                .into_iter()
                .filter_map(|(v, e)| {
                    let d = poly.iter().find(|(w, _)| *w == v).map_or(0, |x| x.1);
                    (e != d).then_some((v, e - d))
                })
                .collect();
            let t = t
                .into_iter()
                .filter_map(|(a, s, e)| {
                    let d = trig
                        .iter()
                        .find(|(b, r, _)| *b == a && *r == s)
                        .map_or(0, |x| x.2);
                    (e != d).then_some((a, s, e - d))
                })
                .collect();
            (i, p, t, c.mul(&inv))
        })
        .collect();
    let mut sum = inner_terms(inner, st);
    let neg = sum.first().is_some_and(|t| t.0);
    if neg {
        sum.iter_mut().for_each(|t| t.0 = !t.0);
    }
    let latex = st.mode == Mode::Latex;
    let body = join(&sum, usize::MAX, 0);
    let mut parts: Vec<String> = Vec::new();
    if !poly.is_empty() || !k.is_one() {
        let (_, front) = term(k, poly, &[], st);
        let wrap = !latex && poly.is_empty() && front.contains(['/', ' ']);
        parts.push(if wrap { format!("({front})") } else { front });
    }
    parts.push(if sum.len() == 1 {
        // (one term left: the shared factors were all it had)
        body
    } else if latex {
        format!("\\left({body}\\right)")
    } else {
        format!("({body})")
    });
    for (a, s, e) in trig {
        parts.push(trig_factor(a, if *s { "sin" } else { "cos" }, *e, st));
    }
    (neg, parts.join(" "))
}

/// A group's inner sum: collected, or with trigonometric factors taken
/// out alone where that prints shorter.
fn inner_terms(inner: Vec<Item>, st: Style) -> Vec<(bool, String)> {
    let real: Real = inner
        .iter()
        .map(|(_, p, t, c)| ((p.clone(), t.clone()), c.clone()))
        .collect();
    let by_trig = super::factor::factored(&real, st);
    if !worth(&inner) {
        return by_trig;
    }
    let collected: Vec<(bool, String)> = collect(inner, st).into_iter().map(|x| x.1).collect();
    if width(&collected) <= width(&by_trig) {
        collected
    } else {
        by_trig
    }
}
