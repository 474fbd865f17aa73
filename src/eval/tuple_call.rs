//! `subs`, `simplify` and `expand` of a tuple over symbols
//! (`TransToRp(T)`'s R and p, `AxisAng3(v)`'s ω̂ and θ; LANGUAGE.md §7):
//! each part as if it had been given alone, so that the tuple's parts are
//! numbers once their symbols have them, as typed first. A part that is
//! already numbers is itself.

use super::apply::Op;
use super::value::Value;
use crate::diagnostics::Diagnostic;
use crate::values::error::OpError;

/// `name(x, rest…)` for a tuple `x` with a symbolic part, part by part;
/// None for any other call.
pub(super) fn each_part(
    op: Op,
    name: &str,
    vals: &[Value],
    warnings: &mut Vec<Diagnostic>,
) -> Option<Result<Value, OpError>> {
    let [Value::Tuple(parts), rest @ ..] = vals else {
        return None;
    };
    if !matches!(name, "subs" | "simplify" | "expand")
        || !parts
            .iter()
            .any(|p| matches!(p, Value::Sym(_) | Value::Formula { .. }))
    {
        return None;
    }
    let mut out = Vec::with_capacity(parts.len());
    for p in parts {
        let mut refs: Vec<&Value> = vec![p];
        refs.extend(rest);
        let kind = p.kind();
        let subs = (name == "subs")
            .then(|| super::replay::subs_numbers(&refs, warnings))
            .flatten()
            .map(|v| {
                v.map(|v| super::substitute::retag(v, &kind))
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
    Some(Ok(Value::Tuple(out)))
}
