//! A comparison over symbols read while only some of them have numbers
//! (LANGUAGE.md §7: "a bool over given names is recomputed when their
//! numbers are bound, as any other value"). `a*b == 0` over free a and b
//! is false (no identity), yet with b = 0 typed first it is `a*0 == 0`,
//! true: the sides are made again from how they were made, with the
//! numbers bound so far put in, and the comparison decided again over the
//! symbols still free — or said to be undecided, never the stale verdict.

use std::collections::HashMap;
use std::rc::Rc;

use super::replay::{self, Lookup};
use super::witness::AtPoints;
use crate::seam::apply::Op;
use crate::syntax::ast::CmpOp;
use crate::values::recipe::{Recipe, Step};
use crate::values::value::Value;

/// The bool of comparison recipe `r` with the numbers `at` gives so far,
/// decided again over the symbols still free; undecided, the comparison
/// waiting for the other numbers (`crate::values::waiting`), or Err when
/// it cannot wait. None when `r` is no comparison.
pub(crate) fn compared(r: &Rc<Recipe>, at: Lookup) -> Option<Result<Value, String>> {
    let Step::Compare(op) = &r.step else {
        return None;
    };
    let mut memo = HashMap::new();
    let sides: Option<Vec<Value>> = r.args.iter().map(|a| value(a, at, &mut memo)).collect();
    let waits = match sides.as_deref() {
        Some([a, b]) => match decide(a, b, *op) {
            Some(v) => return Some(Ok(Value::Bool(v))),
            None => crate::values::waiting::make(*op, a, b),
        },
        _ => None,
    };
    Some(waits.ok_or_else(|| {
        "the comparison, with numbers for only some of its symbols, cannot be decided again: \
         it is decided once every symbol has a number"
            .to_string()
    }))
}

/// `subs` of comparison recipe `r` with the numbers `at` gives (a number
/// put for a symbol, others left free): [`compared`], but a verdict over
/// sides still holding symbols stays the comparison's formula
/// ([`crate::values::recipe::compared`]), decided again when their numbers
/// are bound. `subs(2*a == a*b, a, 1)` is false over b (2 = b is no
/// identity) and true once b = 2, as `a = 1` typed first gives; at a = 0,
/// 0 == 0 is true whatever b is (it printed false: the verdict over both
/// symbols). None when `r` is no comparison.
pub(crate) fn substituted(r: &Rc<Recipe>, at: Lookup) -> Option<Result<Value, String>> {
    let Step::Compare(op) = &r.step else {
        return None;
    };
    let mut memo = HashMap::new();
    let sides: Option<Vec<Value>> = r.args.iter().map(|a| value(a, at, &mut memo)).collect();
    if let Some([a, b]) = sides.as_deref()
        && let Some(v) = decide(a, b, *op)
    {
        return Some(Ok(crate::values::recipe::compared(v, *op, a, b)));
    }
    compared(r, at)
}

/// `a op b` over symbols as the evaluator decides it: by canonical forms,
/// and for `==` at points where a side rests on a float; None undecided.
fn decide(a: &Value, b: &Value, op: CmpOp) -> Option<bool> {
    let v = super::equality::equal(a, b, op).ok()?;
    if op != CmpOp::Eq {
        return v;
    }
    match (v, super::witness::at_points(a, b, v.is_none())) {
        (_, Some(AtPoints::Differ(_))) => Some(false),
        (_, Some(AtPoints::Identity)) => Some(true),
        (_, Some(AtPoints::Agree(_))) => None,
        (Some(false), None) if super::equality::rounding_only(a, b) => None,
        (v, None) => v,
    }
}

/// The value recipe `r` makes with the numbers bound so far (a formula
/// over the symbols still free, or numbers); None where a step cannot be
/// made again so.
pub(crate) fn made_with(r: &Rc<Recipe>, at: Lookup) -> Option<Value> {
    value(r, at, &mut HashMap::new())
}

/// [`made_with`] where what it makes is defined: a value of numbers, or a
/// formula none of whose entries is undefined at the numbers (a closed
/// form singular at a number where the expression as typed is not,
/// `exp([S] a)^-1` of a non-unit axis at a = 0, is made again so, as
/// typed first). None otherwise.
pub(crate) fn made_defined(r: &Rc<Recipe>, at: Lookup) -> Option<Value> {
    match made_with(r, at)? {
        Value::Formula { m, .. } if m.data.iter().any(|e| e.undefined().is_some()) => None,
        v @ (Value::Formula { .. } | Value::Num { .. }) => Some(v),
        _ => None,
    }
}

/// The value recipe `r` makes with the numbers bound so far: its leaves
/// with them put in, each step applied as the evaluator applies it (to
/// numbers as typed first, to formulas by their exact forms). None for a
/// step that cannot be made again so.
fn value(
    r: &Rc<Recipe>,
    at: Lookup,
    memo: &mut HashMap<*const Recipe, Option<Value>>,
) -> Option<Value> {
    let key = Rc::as_ptr(r);
    if let Some(v) = memo.get(&key) {
        return v.clone();
    }
    // (recipes are at most recipe::MAX_DEPTH deep; the stack grows on the
    // heap when it runs low, as replay's does)
    let v = stacker::maybe_grow(64 * 1024, 1024 * 1024, || step(r, at, memo));
    memo.insert(key, v.clone());
    v
}

/// One step of [`value`], its operands made first.
fn step(
    r: &Rc<Recipe>,
    at: Lookup,
    memo: &mut HashMap<*const Recipe, Option<Value>>,
) -> Option<Value> {
    let args: Option<Vec<Value>> = r.args.iter().map(|a| value(a, at, memo)).collect();
    match (&r.step, args) {
        (Step::Leaf(v), _) => Some(replay::with_numbers(v, at).unwrap_or_else(|| v.clone())),
        (Step::Op(o), Some(args)) => Op::of(o).and_then(|op| {
            let refs: Vec<&Value> = args.iter().collect();
            op.apply(&refs, &r.kind).ok()
        }),
        (Step::Part(i), Some(args)) => match args.as_slice() {
            [Value::Tuple(vs)] => vs.get(*i).cloned(),
            [Value::Num { m, .. }] if m.ncols() == 1 && *i < m.nrows() => {
                Some(Value::scalar(m[*i]))
            }
            _ => None,
        },
        (Step::Retag | Step::Closed(_), Some(mut args)) if args.len() == 1 => args.pop(),
        _ => None,
    }
}
