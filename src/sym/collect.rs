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

/// The most terms of a sum whose symbols shared by some of its terms are
/// taken out (`partial` in [`collect`]).
pub(super) const LONG: usize = 12;

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

/// A sum as it prints: terms, and groups of terms with what they share
/// taken out. Decided once on the plain text ([`measure`]), so that the
/// text, the shorthand and LaTeX print one shape.
#[derive(Debug, Clone)]
pub(super) enum Node {
    Term(Item),
    /// `k poly (inner) trig`, in the place of its first term.
    Group {
        first: usize,
        k: Coef,
        poly: Mono,
        trig: Vec<Trig>,
        inner: Inner,
    },
    /// `(a-sum) (b-sum)`: a sum over the symbols times a sum over the
    /// angles ([`super::bilinear`]), in the place of its first term.
    Product {
        first: usize,
        left: Vec<Node>,
        right: Vec<Node>,
    },
}

/// A group's inner sum: collected, or with trigonometric factors taken
/// out alone ([`super::factor`]).
#[derive(Debug, Clone)]
pub(super) enum Inner {
    Nodes(Vec<Node>),
    ByTrig(Real),
}

impl Node {
    pub(super) fn first(&self) -> usize {
        match self {
            Node::Term(x) => x.0,
            Node::Group { first, .. } | Node::Product { first, .. } => *first,
        }
    }
}

/// The plain text every shape is decided on.
pub(super) const PLAIN: Style = Style {
    mode: Mode::Text,
    digits: 4,
};

/// What a printed sum costs: its factors (each variable power,
/// trigonometric factor and coefficient other than 1 — a group's shared
/// factors once), then its columns. The book's shape has the fewest
/// factors: `w[1] w[2] (1 - cos(θ))` has 4 where its expansion has 5.
pub(super) fn measure(ts: &[(bool, String)]) -> (usize, usize) {
    let text = join(ts, usize::MAX, 0);
    let mut atoms = 0;
    let mut word = false;
    let mut call_depth = 0usize;
    let mut prev = ' ';
    for ch in text.chars() {
        if call_depth > 0 {
            match ch {
                '(' => call_depth += 1,
                ')' => call_depth -= 1,
                _ => {}
            }
        } else if ch == '(' && (prev.is_alphanumeric() || prev == '/') {
            // a call's argument (`cos(t1 + t2)`, `1/(…)`) is part of its word
            call_depth = 1;
        } else if matches!(ch, ' ' | '(' | ')') {
            word = false;
        } else if !word && !matches!(ch, '+' | '-') {
            word = true;
            atoms += 1;
        }
        prev = ch;
    }
    (atoms, text_width(&text))
}

/// The terms of `items` collected: the shape, each node in the place of
/// its first term; symbols shared by some of the terms (not all) taken out
/// only where `partial` (the whole sum has at most [`LONG`] terms).
pub(super) fn collect(items: Vec<Item>, partial: bool) -> Vec<Node> {
    if items.len() >= 2 {
        let (poly, trig, k) = common(&items);
        if !poly.is_empty() || !trig.is_empty() || !k.is_one() {
            let g = grouped(items.clone(), poly.clone(), trig.clone(), k, partial);
            if pays(&items, &g, &poly, &trig) {
                return vec![g];
            }
        }
    }
    // in a long sum, an expansion ((a + b + c)^3), symbols shared by some
    // of the terms stay in them, as the trigonometric grouping keeps a long
    // sum with multiple angles a sum of short lines ([`super::factor`])
    let long = !partial;
    let mut left = items;
    let mut tried: Vec<Fac> = Vec::new();
    let mut out: Vec<Node> = Vec::new();
    while let Some(f) = most_shared(&left, &tried) {
        if long && matches!(f, Fac::Var(_)) {
            tried.push(f);
            continue;
        }
        let (shared, rest): (Vec<Item>, Vec<Item>) = left.into_iter().partition(|x| has(x, &f));
        let (poly, trig, k) = common(&shared);
        let g = grouped(shared.clone(), poly.clone(), trig.clone(), k, partial);
        if pays(&shared, &g, &poly, &trig) {
            out.push(g);
            left = rest;
        } else {
            tried.push(f);
            left = shared.into_iter().chain(rest).collect();
            left.sort_by_key(|x| x.0);
        }
    }
    out.extend(left.into_iter().map(Node::Term));
    out.sort_by_key(Node::first);
    out
}

/// True when the group `g` of `items` (sharing `poly` and `trig`) prints
/// fewer factors than its terms; or as many where it is m + m·x = m (1 + x)
/// with m gone from x: `x^2 (1 + y)`, `L1 (1 - sin(t2))`, `2 (1 - cos(t))`
/// — not Horner's nesting `t (1/5 + t)` of a polynomial.
fn pays(items: &[Item], g: &Node, poly: &Mono, trig: &[Trig]) -> bool {
    let flat: Vec<(bool, String)> = items
        .iter()
        .map(|(_, p, t, c)| term(c, p, t, PLAIN))
        .collect();
    let (after, before) = (measure(&[render(g, PLAIN)]), measure(&flat));
    if after.0 != before.0 {
        return after.0 < before.0;
    }
    let alone = items.iter().any(|x| {
        let vars: Mono =
            x.1.iter()
                .filter(|(v, e)| shareable(v, *e))
                .cloned()
                .collect();
        vars == *poly && x.2 == trig
    });
    let gone = items.iter().all(|x| {
        poly.iter()
            .all(|(v, e)| x.1.iter().find(|(w, _)| w == v).map(|y| y.1) == Some(*e))
            && trig.iter().all(|(a, s, e)| {
                x.2.iter().find(|(b, r, _)| b == a && r == s).map(|y| y.2) == Some(*e)
            })
    });
    alone && gone
}

/// The signed terms of a shape in the style `st`.
pub(super) fn render_all(nodes: &[Node], st: Style) -> Vec<(bool, String)> {
    nodes.iter().map(|n| render(n, st)).collect()
}

fn render_inner(inner: &Inner, st: Style) -> Vec<(bool, String)> {
    match inner {
        Inner::Nodes(nodes) => render_all(nodes, st),
        Inner::ByTrig(real) => super::factor::factored(real, st),
    }
}

/// One node's sign and text: a group's sign is its inner sum's first.
fn render(node: &Node, st: Style) -> (bool, String) {
    let (k, poly, trig, inner) = match node {
        Node::Term((_, poly, trig, c)) => return term(c, poly, trig, st),
        Node::Product { left, right, .. } => return product(left, right, st),
        Node::Group {
            k,
            poly,
            trig,
            inner,
            ..
        } => (k, poly, trig, inner),
    };
    let mut sum = render_inner(inner, st);
    let neg = positive(&mut sum);
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

/// Turns a sum in parentheses to start positive, with its constant first
/// where it has one (`(1 - cos(t))`, not `(cos(t) - 1)` nor `-(…)`), else
/// its first positive term first (`2 r[2] r[3] - r[1] (…)`), else all
/// turned: true when the sum was turned (its sign goes in front).
fn positive(sum: &mut [(bool, String)]) -> bool {
    let constant = |t: &(bool, String)| {
        t.1.chars()
            .all(|c| c.is_ascii_digit() || matches!(c, '/' | '.' | '√'))
    };
    let (turn, front) = match sum.iter().position(constant) {
        Some(j) => (sum[j].0, Some(j)),
        None => match sum.iter().position(|t| !t.0) {
            Some(j) => (false, Some(j)),
            None => (true, None),
        },
    };
    if turn {
        sum.iter_mut().for_each(|t| t.0 = !t.0);
    }
    if let Some(j) = front {
        sum[..=j].rotate_right(1);
    }
    turn
}

/// `(a) (b)`, each side's sign in front, a side of one term without
/// parentheses, a side that is 1 left out; under a negative sign, the
/// symbol side turned where it has a negative term, else the angle side
/// (`S[1] (…) (t - sin(t))`, not `-S[1] (…) (sin(t) - t)`).
fn product(left: &[Node], right: &[Node], st: Style) -> (bool, String) {
    let mut a = render_all(left, st);
    let mut b = render_all(right, st);
    let mut neg = positive(&mut a) != positive(&mut b);
    // under a negative sign, a side that has a negative term turns, its
    // positive terms first: (S[3] S[4] - S[1] S[6]) (1 - cos(t)), not
    // -(S[1] S[6] - S[3] S[4]) (…); (t1 + t2 - sin(t1 + t2))
    for side in [&mut a, &mut b] {
        if neg && side.iter().any(|t| t.0) {
            side.iter_mut().for_each(|t| t.0 = !t.0);
            side.sort_by_key(|t| t.0);
            neg = false;
        }
    }
    let latex = st.mode == Mode::Latex;
    let side = |ts: &[(bool, String)]| -> Option<String> {
        let body = join(ts, usize::MAX, 0);
        match ts.len() {
            1 if body == "1" => None,
            1 => Some(body),
            _ if latex => Some(format!("\\left({body}\\right)")),
            _ => Some(format!("({body})")),
        }
    };
    let parts: Vec<String> = [side(&a), side(&b)].into_iter().flatten().collect();
    if parts.is_empty() {
        return (neg, "1".into());
    }
    (neg, parts.join(" "))
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
/// collected in turn (or with trigonometric factors taken out alone where
/// that costs less).
fn grouped(items: Vec<Item>, poly: Mono, trig: Vec<Trig>, k: Coef, partial: bool) -> Node {
    let first = items.iter().map(|x| x.0).min().unwrap_or(0);
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
    Node::Group {
        first,
        k,
        poly,
        trig,
        inner: inner_shape(inner, partial),
    }
}

/// A group's inner sum: collected, or with trigonometric factors taken
/// out alone where that costs less.
fn inner_shape(inner: Vec<Item>, partial: bool) -> Inner {
    let real: Real = inner
        .iter()
        .map(|(_, p, t, c)| ((p.clone(), t.clone()), c.clone()))
        .collect();
    if !worth(&inner) {
        return Inner::ByTrig(real);
    }
    let by_trig = super::factor::factored(&real, PLAIN);
    let nodes = collect(inner, partial);
    if measure(&render_all(&nodes, PLAIN)) <= measure(&by_trig) {
        Inner::Nodes(nodes)
    } else {
        Inner::ByTrig(real)
    }
}
