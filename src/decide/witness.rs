//! `a == b` over symbols when a side rests on a number with no exact form
//! (LANGUAGE.md §7, issue 21: never a wrong answer). The canonical forms
//! ([`crate::values::equality`]) hold such a number as a float
//! coefficient, and a float can round either way: `cos(1e-9) t` prints as
//! `t` though it is not t, and `(cos(π/7) + cos(3π/7) + cos(5π/7)) t` is
//! not the float `0.5 t` though it is t/2. So a verdict that rests on a
//! float is not read off the floats: both sides are replayed as typed
//! first, with numbers for the symbols (`super::replay`), at as many
//! points as the difference can have terms, and compared there by
//! certified arithmetic (`super::certify`):
//!
//! - a point where the sides certainly differ proves they are different
//!   functions (`false`);
//! - the difference of the two canonical forms is a sum c₁m₁(x) + … +
//!   cₖmₖ(x) over the monomials mᵢ of the sides (products of symbols, of
//!   e^{iθ} and of kept calls; what is constant, π and phases, goes with
//!   the coefficient), whose cᵢ the floats only estimate. Proven zero at k
//!   points where the k monomials' values form a nonsingular matrix, every
//!   cᵢ is 0: the sides are the same function (`true`);
//! - sides that agree at every point far past rounding, with no proof,
//!   are undecided, and the answer says so.
//!
//! Before the points, the sides' recipes are lifted (`super::lift`): the
//! numbers in them made functions of new symbols that stand for them, the
//! given symbols kept; equal lifted forms are an identity, so the sides
//! are equal for every value of the symbols, proven with no point.
//!
//! The premise is that a float sum which cancelled to within rounding left
//! no monomial out of both sides (`sym::coef` drops such noise); a
//! difference hiding there is still caught when a point shows it.

use std::collections::BTreeSet;

use super::certify::{Verdict, equal};
use crate::sym::expr::{Mono, Var};
use crate::sym::{Expr, Symbol};
use crate::values::exact::Exact;
use crate::values::formula::mat_of;
use crate::values::value::Value;

/// What the sides of `a == b` are, found at points by certified
/// arithmetic.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum AtPoints {
    /// Certainly different at a point, by this much: not the same function.
    Differ(f64),
    /// Proven equal at enough points: the same function.
    Identity,
    /// Within each other's balls at some point to this many digits, with
    /// no proof either way.
    Agree(u32),
}

/// The most points tried: sides whose difference may have more terms are
/// left to the canonical forms (a point may still show a difference).
const MAX_POINTS: usize = 32;

/// The verdict of `a == b` over symbols by certified arithmetic at points,
/// when a side rests on a number with no exact form made from exact ones
/// (`cos(1e-9) t`, `cos(pi/7) t`); None when neither does, when a side
/// cannot be replayed with numbers, or for axes assumed to be unit
/// vectors (a point off the sphere proves nothing). `open`: the canonical
/// forms could not tell (a phase stands for a number with no exact form,
/// `cos(t + 0.1)` against `cos(t + 0.1000001)`), so the points are asked
/// whether or not a side rests on such a float.
pub(crate) fn at_points(a: &Value, b: &Value, open: bool) -> Option<AtPoints> {
    if !open && !rests_on_float(a) && !rests_on_float(b) {
        return None;
    }
    let mut names = Vec::new();
    for v in [a, b] {
        match v {
            Value::Formula { how: Some(r), .. } => crate::values::recipe::symbols(r, &mut names),
            Value::Formula { how: None, m, .. } => {
                m.data.iter().for_each(|e| e.symbols(&mut names))
            }
            _ => {}
        }
    }
    names.retain(|s| !s.is_phase());
    let mut seen = std::collections::HashSet::new();
    names.retain(|s| seen.insert(s.clone()));
    if names.is_empty() || names.iter().any(|s| s.unit) {
        return None;
    }
    // (first the lifted forms, `super::lift`: an identity in the symbols
    // and in what stands for the numbers holds at every point)
    match super::lift::verdict(a, b) {
        Some(Ok(())) => return Some(AtPoints::Identity),
        Some(Err(d)) => {
            let d = super::ball::exact(&d, 128).map_or(0.0, |d| super::ball::floats(&d).0);
            return Some(AtPoints::Differ(d));
        }
        None => {}
    }
    // The monomials (as functions of the symbols) each entry's difference
    // may hold: how many points prove it zero.
    let (x, y) = (mat_of(a)?, mat_of(b)?);
    if (x.rows, x.cols) != (y.rows, y.cols) {
        return None;
    }
    let supports: Vec<Vec<Mono>> = x
        .data
        .iter()
        .zip(&y.data)
        .map(|(p, q)| support(p, q))
        .collect();
    let wanted = supports.iter().map(Vec::len).max().unwrap_or(0).max(1);
    let points = wanted.min(MAX_POINTS);
    let mut agree: Option<u32> = None;
    for k in 0..points {
        let at = |s: &Symbol| {
            let i = names.iter().position(|n| n == s)?;
            let mut v = Value::scalar(point(i, k));
            v.set_exact(Exact::Typed);
            Some(v)
        };
        let (p, q) = (numbers(a, &at)?, numbers(b, &at)?);
        match equal(&p, &q)? {
            Verdict::Differ(d) => return Some(AtPoints::Differ(d)),
            Verdict::Agree(n) => agree = Some(agree.map_or(n, |m| m.min(n))),
            Verdict::Equal => {}
        }
    }
    if let Some(n) = agree {
        return Some(AtPoints::Agree(n));
    }
    if wanted > MAX_POINTS {
        return None;
    }
    let at = |s: &Symbol| {
        let i = names.iter().position(|n| n == s)?;
        Some(i)
    };
    supports
        .iter()
        .all(|m| independent(m, points, &at))
        .then_some(AtPoints::Identity)
}

/// The number of symbol `i` at point `k`: a decimal of four digits in
/// [0.1, 2.6), exact as typed, drawn by a fixed hash of (i, k) so that the
/// points lie on no line or low curve (points on a line would make the
/// monomials' matrix singular), and positive (lengths and square roots
/// stay in their domains).
fn point(i: usize, k: usize) -> f64 {
    let mut h = (i as u64) << 32 ^ (k as u64) ^ 0x9e37_79b9_7f4a_7c15;
    // (splitmix64's finaliser)
    h = (h ^ (h >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h = (h ^ (h >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^= h >> 31;
    (1000 + h % 25000) as f64 / 10000.0
}

/// The value of a side with numbers for its symbols, replayed as typed
/// first (a number is itself).
fn numbers(v: &Value, at: super::replay::Lookup) -> Option<Value> {
    match v {
        Value::Formula { how: Some(r), .. } => super::replay::numbers(r, at, &mut Vec::new())
            .ok()
            .flatten(),
        // (a formula made by no replayable step, a `given` name: its
        // canonical form at the numbers, exact as typed first)
        Value::Formula { how: None, kind, m } => super::replay::canonical(kind, m, at),
        v => Some(v.clone()),
    }
}

/// The monomials of p and q as functions of the symbols: each with its
/// constant factors (π, phases, calls of no symbol) left out, distinct.
fn support(p: &Expr, q: &Expr) -> Vec<Mono> {
    let mut out = BTreeSet::new();
    for m in p.terms.keys().chain(q.terms.keys()) {
        let f: Mono = m
            .iter()
            .filter(|(v, _)| match v {
                Var::Pi => false,
                Var::Sym(s) | Var::Z(s) => !s.is_phase(),
                Var::Call(c) => {
                    let mut names = Vec::new();
                    c.args.iter().for_each(|e| e.symbols(&mut names));
                    names.iter().any(|s| !s.is_phase())
                }
            })
            .cloned()
            .collect();
        out.insert(f);
    }
    out.into_iter().collect()
}

/// True when the monomials' values at the first `points` points form a
/// matrix of full column rank (each monomial a column), well above
/// rounding: a sum of them that is zero at every point has every
/// coefficient 0.
fn independent(monos: &[Mono], points: usize, index: &dyn Fn(&Symbol) -> Option<usize>) -> bool {
    if monos.is_empty() {
        // (both entries 0: nothing to prove)
        return true;
    }
    if monos.len() > points {
        return false;
    }
    let mut m = nalgebra::DMatrix::<nalgebra::Complex<f64>>::zeros(points, monos.len());
    for (j, mono) in monos.iter().enumerate() {
        let e = Expr {
            terms: [(mono.clone(), crate::sym::coef::Coef::one())]
                .into_iter()
                .collect(),
        };
        for k in 0..points {
            let at = |s: &Symbol| index(s).map(|i| point(i, k));
            let Some((re, im)) = e.eval_c(&at) else {
                return false;
            };
            if !(re.is_finite() && im.is_finite()) {
                return false;
            }
            m[(k, j)] = nalgebra::Complex::new(re, im);
        }
    }
    let sv = m.svd(false, false).singular_values;
    let (lo, hi) = sv.iter().fold((f64::INFINITY, 0f64), |(lo, hi), s| {
        (lo.min(*s), hi.max(*s))
    });
    hi > 0.0 && lo > 1e-8 * hi
}

/// True when a side of `a == b` rests on a number with no exact form
/// made from exact ones: a `false` read off its float may be rounding (the
/// caller then cannot decide where [`at_points`] did not).
pub(crate) fn on_float(a: &Value, b: &Value) -> bool {
    // (a float with no recipe on a side compares as a float, §7)
    (rests_on_float(a) || rests_on_float(b)) && !plain_float(a) && !plain_float(b)
}

/// True when a side is, or was made from, a float with no recipe (a
/// matrix exponential of numbers).
fn plain_float(v: &Value) -> bool {
    match v {
        Value::Formula { how: Some(r), .. } => leaf_where(r, &|v| !v.may_be_exact()),
        v @ Value::Num { .. } => !v.may_be_exact(),
        _ => false,
    }
}

/// True when a side rests on a number with no exact form made from exact
/// ones: a leaf of its recipe is one, or it is one.
fn rests_on_float(v: &Value) -> bool {
    match v {
        Value::Formula { how: Some(r), .. } => inexact_leaf(r),
        v @ Value::Num { .. } => v.may_be_exact() && v.exact_form().is_none(),
        _ => false,
    }
}

/// True when a leaf of recipe `r` is a number with no exact form that was
/// made from exact ones (a float whose rounding a canonical form may hide).
fn inexact_leaf(r: &std::rc::Rc<crate::values::recipe::Recipe>) -> bool {
    leaf_where(r, &|v| v.may_be_exact() && v.exact_form().is_none())
}

/// True when a numeric leaf of recipe `r` is `what`.
fn leaf_where(
    r: &std::rc::Rc<crate::values::recipe::Recipe>,
    what: &dyn Fn(&Value) -> bool,
) -> bool {
    use crate::values::recipe::Step;
    let mut seen = std::collections::HashSet::new();
    let mut todo = vec![r];
    while let Some(r) = todo.pop() {
        if !seen.insert(std::rc::Rc::as_ptr(r)) {
            continue;
        }
        match &r.step {
            Step::Leaf(v @ Value::Num { .. }) => {
                if what(v) {
                    return true;
                }
            }
            _ => todo.extend(r.args.iter()),
        }
    }
    false
}
