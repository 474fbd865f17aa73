//! `subs`, `simplify` and `expand` of a tuple (or a list) over symbols
//! (`TransToRp(T)`'s R and p, `AxisAng3(v)`'s ω̂ and θ; LANGUAGE.md §7):
//! each part as if it had been given alone, so that the tuple's parts are
//! numbers once their symbols have them, as typed first. A part that is
//! already numbers is itself. Of a comparison waiting for numbers
//! (`subs(a < b, a, 1)`): the comparison of its sides so changed; of one
//! decided over free symbols, its bool.

use super::value::Value;
use crate::diagnostics::Diagnostic;
use crate::seam::apply::Op;
use crate::values::error::OpError;

/// Whether [`each_part`] may give a value for `name` called on numbers
/// only: `simplify` of a number (its simplest exact form); every other
/// path needs a tuple, a formula or a symbol.
pub(super) fn takes_numbers(name: &str) -> bool {
    name == "simplify"
}

/// `name(x, rest…)` for a tuple `x`, part by part (numbers are themselves);
/// `simplify` of a number ([`takes_numbers`]); None for any other call.
pub(super) fn each_part(
    op: Op,
    name: &str,
    vals: &[Value],
    env: &dyn crate::calculus::Bindings,
    warnings: &mut Vec<Diagnostic>,
) -> Option<Result<Value, OpError>> {
    // (a constant: the exact short number it is proven to be, §7; else
    // itself, with its exact form, so that `simplify(x) == x`'s proofs
    // still see how it was made)
    if let [v @ Value::Num { .. }] = vals
        && takes_numbers(name)
    {
        return Some(Ok(
            crate::decide::constant::simplest(v).unwrap_or_else(|| v.clone())
        ));
    }
    // (a comparison decided over free symbols, with a number put for one
    // of them: decided again, as typed first — `2 a == a^2` is false over
    // a, but at a = 0 it is true; `2 a == a b` at a = 0 is true whatever
    // b is, and at a = 1 false over b but true once b = 2)
    if let [
        Value::Formula { how: Some(r), .. },
        Value::Formula { m, .. },
        by @ Value::Num { .. },
    ] = vals
        && name == "subs"
        && let [e] = m.data.as_slice()
        && let Some(sym) = crate::sym::expr::as_symbol(e)
        && let Some(v) = crate::decide::partly::substituted(r, &|s| (*s == sym).then(|| by.clone()))
    {
        return Some(v.map_err(OpError::Message));
    }
    // (a comparison decided over free symbols is its bool)
    if let [v @ Value::Formula { .. }, ..] = vals
        && matches!(name, "subs" | "simplify" | "expand")
        && let Some(b @ Value::Bool(_)) = super::formula::constant_shown(v)
    {
        return Some(Ok(b));
    }
    if let [v @ Value::Formula { .. }, rest @ ..] = vals
        && matches!(name, "subs" | "simplify" | "expand")
        && let Some((cmp, l, r)) = waiting_sides(v)
    {
        let parts = vec![l, r];
        let mut args = vec![Value::Tuple(parts)];
        args.extend(rest.iter().cloned());
        let Some(Ok(Value::Tuple(sides))) = each_part(op, name, &args, env, warnings) else {
            return None;
        };
        let [a, b] = sides.as_slice() else {
            return None;
        };
        return Some(match crate::decide::equality::equal(a, b, cmp) {
            Ok(Some(t)) => Ok(crate::values::recipe::compared(t, cmp, a, b)),
            Ok(None) => crate::values::waiting::make(cmp, a, b).ok_or_else(|| {
                OpError::Message(format!("cannot decide `{}` without numbers", cmp.text()))
            }),
            Err(m) => Err(OpError::Message(m)),
        });
    }
    // (a list, `[f(k a) for k in 1:3]`, item by item alike)
    let (parts, rest, list): (&[Value], _, _) = match vals {
        [Value::Tuple(parts), rest @ ..] => (parts, rest, false),
        [Value::List(parts), rest @ ..] => (parts, rest, true),
        _ => return None,
    };
    // (a tuple of numbers only is itself, part by part: `subs((1, M), c,
    // 1)` with c given is (1, M), not the call kept)
    if !matches!(name, "subs" | "simplify" | "expand") {
        return None;
    }
    let mut out = Vec::with_capacity(parts.len());
    for p in parts {
        let mut refs: Vec<&Value> = vec![p];
        refs.extend(rest);
        let kind = p.kind();
        let subs = (name == "subs")
            .then(|| crate::decide::replay::subs_numbers(&refs, warnings))
            .flatten()
            // (a part kept as a call over given names: its formulas)
            .or_else(|| match refs.as_slice() {
                [Value::Sym(x), n, by] if name == "subs" => {
                    crate::calculus::put::subs_tree(x, n, by, env, warnings).map(Ok)
                }
                _ => None,
            })
            .map(|v| {
                v.map(|v| crate::calculus::substitute::retag(v, &kind))
                    .map_err(OpError::Message)
            });
        out.push(match subs.or_else(|| op.exact_or_symbolic(&refs, &kind)) {
            Some(v) => match v {
                Ok(v) => v,
                Err(e) => return Some(Err(e)),
            },
            None => p.clone(),
        });
    }
    Some(Ok(if list {
        Value::List(std::rc::Rc::new(out))
    } else {
        Value::Tuple(out)
    }))
}

/// The comparison and the two sides of a waiting bool as values (each
/// with how it was made).
fn waiting_sides(v: &Value) -> Option<(crate::syntax::ast::CmpOp, Value, Value)> {
    let (op, l, r) = crate::values::waiting::sides(v)?;
    let Value::Formula { how: Some(how), .. } = v else {
        return None;
    };
    let side = |m: crate::sym::Mat, i: usize| {
        let a = how.args.get(i)?;
        Some(Value::Formula {
            kind: a.kind,
            m,
            how: Some(a.clone()),
        })
    };
    Some((op, side(l, 0)?, side(r, 1)?))
}
