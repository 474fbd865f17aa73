//! `a == b` over symbols that the canonical forms call true, checked at a
//! point (LANGUAGE.md §7, issue 21): a side made from a number with no
//! exact form (`cos(1e-9) cos(t)`) may owe its canonical form to a float
//! that rounds like its exact value's neighbour (cos(1e-9) is the float
//! 1). With numbers for the symbols, both sides are replayed as typed
//! first (`super::replay`) and compared by certified arithmetic
//! (`super::certify`): a point where they certainly differ proves they are
//! not the same function.

use super::certify::{Verdict, equal};
use super::value::Value;
use crate::values::exact::Exact;

/// The difference at a point of the two sides of `a == b` over symbols,
/// which the canonical forms call true, when it is certainly not 0 (the
/// sides are then different functions): a side is made from a number with no exact form
/// (`cos(1e-9) t`, whose canonical form is t), and with numbers for the symbols, replayed as
/// typed first, certified arithmetic finds the sides different. A point
/// where they differ is a proof that they are not the same function.
/// Not for axes assumed to be unit vectors (a point off the sphere proves
/// nothing).
pub(super) fn witnessed_different(a: &Value, b: &Value) -> Option<f64> {
    let floats = |v: &Value| match v {
        Value::Formula { how: Some(r), .. } => inexact_leaf(r),
        _ => false,
    };
    if !floats(a) && !floats(b) {
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
    if names.iter().any(|s| s.unit || s.is_phase()) {
        return None;
    }
    let at = |s: &crate::sym::Symbol| {
        let i = names.iter().position(|n| n == s)?;
        let mut v = Value::scalar(0.3719 + 0.1618 * i as f64);
        v.set_exact(Exact::Typed);
        Some(v)
    };
    let numbers = |v: &Value| match v {
        Value::Formula { how: Some(r), .. } => super::replay::numbers(r, &at, &mut Vec::new())
            .ok()
            .flatten(),
        // (a formula made by no replayable step, a `given` name: its
        // canonical form at the numbers, exact as typed first)
        Value::Formula { how: None, kind, m } => super::replay::canonical(kind, m, &at),
        v => Some(v.clone()),
    };
    let (x, y) = (numbers(a)?, numbers(b)?);
    match equal(&x, &y) {
        Some(Verdict::Differ(d)) => Some(d),
        _ => None,
    }
}

/// True when a leaf of recipe `r` is a number with no exact form that was
/// made from exact ones (a float whose rounding a canonical form may hide).
fn inexact_leaf(r: &std::rc::Rc<crate::values::recipe::Recipe>) -> bool {
    use crate::values::recipe::Step;
    let mut seen = std::collections::HashSet::new();
    let mut todo = vec![r];
    while let Some(r) = todo.pop() {
        if !seen.insert(std::rc::Rc::as_ptr(r)) {
            continue;
        }
        match &r.step {
            Step::Leaf(v @ Value::Num { .. }) => {
                if v.may_be_exact() && v.exact_form().is_none() {
                    return true;
                }
            }
            _ => todo.extend(r.args.iter()),
        }
    }
    false
}
