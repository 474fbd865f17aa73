//! `sum`, `min` and `max` of a list or a vector of numbers (LANGUAGE.md
//! §12) as the same items written out would give them: `sum(xs)` is
//! `x₁ + x₂ + …` added one after the other, so exact items keep the sum
//! exact (§7: `sum([0.1 for k in 1:10]) == 1` as
//! `0.1 + … + 0.1 == 1`) and symbolic items sum to a formula; `min` and
//! `max` are the least or greatest item itself, with its exact form.
//! The same for numbers typed first and for a range that waited for its
//! numbers (`super::replay`).

use crate::values::exact::deref;
use std::rc::Rc;

use crate::check::rules;
use crate::check::ty::Kind;
use crate::seam::apply::Op;
use crate::seam::exactness::{CANCELLED, from_exact_form};
use crate::syntax::ast::{BinOp, CmpOp};
use crate::values::error::OpError;
use crate::values::exact::Exact;
use crate::values::ops;
use crate::values::value::Value;

/// `name(xs)` for `sum`, `min` and `max` of a list or vector of numbers
/// that may be exact or symbolic ([`sum`], [`extreme`]); None for any other
/// call, or where the builtin answers as well (what is no list or vector,
/// an empty list); Err the message of what cannot be added or ordered.
pub(crate) fn of_call(name: &str, xs: &Value) -> Option<Result<Value, String>> {
    match name {
        "sum" => sum(xs).map(|r| r.map_err(|e| e.to_string())),
        "min" | "max" => extreme(xs, name == "max"),
        _ => None,
    }
}

/// The items a fold runs over: a list's, or a vector's entries with their
/// exact forms; None for anything else (the builtin then says why).
fn items(xs: &Value) -> Option<Rc<Vec<Value>>> {
    match xs {
        Value::List(vs) => Some(Rc::clone(vs)),
        Value::Num { m, .. } if m.ncols() == 1 || m.nrows() == 1 => {
            Some(Rc::new(crate::seam::shapes::entries(xs)))
        }
        _ => None,
    }
}

/// `sum(xs)`: its items added with `+` from the first, each step typed as
/// `+` types it (rotations add to a plain matrix). Numbers add in floats
/// as the sum written out does, and keep its exact form, made when asked
/// (a list of a million numbers costs no exact work until `==` asks);
/// floats that cancelled (`sum([1e13, 0.1, -1e13])`) are made from it, as
/// the sum written out makes them. Symbolic items are added by the seam.
/// None for an empty list or what is no list or vector (the builtin
/// answers those).
fn sum(xs: &Value) -> Option<Result<Value, OpError>> {
    let items = items(xs)?;
    let mut rest = items.iter();
    let mut acc = rest.next()?.clone();
    let add_kind = |a: &Value, b: &Value| {
        rules::add_kind(&a.kind(), &b.kind()).map_err(|e| OpError::Message(e.message.clone()))
    };
    if !items.iter().all(|v| matches!(v, Value::Num { .. })) {
        for v in rest {
            let step = add_kind(&acc, v).and_then(|kind| {
                Op::Arith(BinOp::Add).apply_pair(Box::new(acc), Box::new(v.clone()), &kind)
            });
            acc = match step {
                Ok(v) => v,
                Err(e) => return Some(Err(e)),
            };
        }
        return Some(Ok(acc));
    }
    let largest = |v: &Value| match v {
        Value::Num { m, .. } => m.iter().fold(0.0_f64, |b, x| b.max(x.abs())),
        _ => 0.0,
    };
    let mut big = largest(&acc);
    for v in rest {
        let step = add_kind(&acc, v).and_then(|kind| ops::add(&acc, v, false, &kind));
        acc = match step {
            Ok(v) => v,
            Err(e) => return Some(Err(e)),
        };
        big = big.max(largest(v));
    }
    if items.len() > 1 && items.iter().all(Value::may_be_exact) {
        if let Value::Num { exact, .. } = &mut acc {
            let items = Rc::clone(&items);
            *exact = Exact::later(move || {
                let mut forms = items.iter().map(Value::exact_form);
                let first = forms.next()??;
                forms.try_fold(first, |s, f| s.add(&f?, false))
            });
        }
        let cancelled = big > 0.0
            && big.is_finite()
            && matches!(&acc, Value::Num { m, .. } if m.iter().any(|x| x.abs() <= big * CANCELLED));
        if cancelled {
            from_exact_form(&mut acc);
        }
    }
    Some(Ok(acc))
}

/// `min(xs)` (`greatest` false) or `max(xs)`: the item whose number is
/// least or greatest, itself, so that its exact form comes with it; items
/// are ordered as `<` orders them (by exact forms where they have them:
/// `max([1 + 1e-20, 1])` is 1 + 1e-20, though the floats are equal). None
/// when an item is no number (the builtin then says why); Err when two
/// items cannot be ordered.
fn extreme(xs: &Value, greatest: bool) -> Option<Result<Value, String>> {
    let items = items(xs)?;
    if !items.iter().all(|v| {
        matches!(
            v,
            Value::Num {
                kind: Kind::Scalar,
                ..
            }
        )
    }) {
        return None;
    }
    let op = if greatest { CmpOp::Gt } else { CmpOp::Lt };
    let within = within_reach(&items, greatest);
    let mut items = items.iter().zip(within).filter_map(|(v, w)| w.then_some(v));
    let mut best = items.next()?;
    for v in items {
        let beyond = match (v.as_scalar(), best.as_scalar()) {
            // (floats alone compare as floats)
            (Some(x), Some(b)) if !v.may_be_exact() && !best.may_be_exact() => {
                if greatest {
                    x > b
                } else {
                    x < b
                }
            }
            _ => match super::equality::equal(v, best, op) {
                Ok(Some(t)) => t,
                Ok(None) => return Some(Err("cannot decide the order of two items".into())),
                Err(m) => return Some(Err(m)),
            },
        };
        if beyond {
            best = v;
        }
    }
    Some(Ok(best.clone()))
}

/// How far an item's floats may be from its exact value, as
/// [`super::certify::balls`] trusts them: 1e-6 of the larger of the float
/// and its recipe's operands (`tan(2π)` is −2.4e-16 for 0, within 1e-6 of
/// 2π); 0 for a float, which is its own value.
fn reach(v: &Value) -> f64 {
    let Value::Num { m, exact, .. } = v else {
        return 0.0;
    };
    if !v.may_be_exact() {
        return 0.0;
    }
    let x = m.iter().fold(0f64, |s, x| s.max(x.abs()));
    let operands = exact
        .peek_recipe(|p| {
            deref(&p.args.refs()).iter().fold(0f64, |s, a| match a {
                Value::Num { m, .. } => m.iter().fold(s, |s, x| s.max(x.abs())),
                _ => f64::INFINITY,
            })
        })
        .unwrap_or(0.0);
    1e-6 * x.max(operands)
}

/// Which items may be the greatest (`greatest`) or least, by their floats
/// and how far each may be from its exact value ([`reach`]): an item
/// whose float is beyond another's by more than both reaches is not, and
/// is not ordered exactly (the ordering of exact items is certified
/// arithmetic, ~50 µs a pair: `max` of the 100,001 items of
/// `[sin(t) for t in 0:0.001:100]` took 4.3 s ordered pair by pair, and
/// orders a few hundred now). All of them when a float is not a number.
fn within_reach(items: &[Value], greatest: bool) -> Vec<bool> {
    let sign = if greatest { 1.0 } else { -1.0 };
    // (each item as an interval, turned so that the extreme is the top)
    let spans: Vec<(f64, f64)> = items
        .iter()
        .map(|v| {
            let x = sign * v.as_scalar().unwrap_or(f64::NAN);
            let r = reach(v);
            (x - r, x + r)
        })
        .collect();
    if spans.iter().any(|(lo, hi)| lo.is_nan() || hi.is_nan()) {
        return vec![true; items.len()];
    }
    let floor = spans.iter().fold(f64::NEG_INFINITY, |m, s| m.max(s.0));
    spans.iter().map(|s| s.1 >= floor).collect()
}
