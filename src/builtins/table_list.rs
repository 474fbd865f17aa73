//! Builtins over lists (LANGUAGE.md §12): `len`, `sum`, `min`, `max`. They
//! also take a vector's entries, as MATLAB's do.

use std::rc::Rc;

use super::{Area, ArgError, Args, Builtin, Typing};
use crate::check::rules;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::values::ops;
use crate::values::value::Value;

/// The elements of a list, or the entries of a vector.
fn elements(a: &Args, i: usize) -> Result<Rc<Vec<Value>>, Diagnostic> {
    match a.value(i) {
        Value::List(vs) => Ok(vs.clone()),
        Value::Num { m, .. } if m.ncols() == 1 || m.nrows() == 1 => {
            Ok(Rc::new(m.iter().map(|x| Value::scalar(*x)).collect()))
        }
        Value::Tuple(vs) => Ok(Rc::new(vs.clone())),
        v => Err(a.error(
            i,
            ErrorKind::Type,
            format!("{} takes a list or a vector, not {}", a.name, v.kind().a()),
        )),
    }
}

fn listish(k: &Kind) -> bool {
    matches!(k, Kind::List(..) | Kind::Tuple(_) | Kind::Unknown) || k.is_vector()
}

fn len_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    if !listish(&args[0].kind) {
        return Err(ArgError::type_of(
            0,
            format!(
                "len takes a list, tuple or vector, not {}",
                args[0].kind.a()
            ),
        ));
    }
    Ok(Ty::scalar())
}

fn eval_len(a: &mut Args) -> Result<Value, Diagnostic> {
    Ok(Value::scalar(elements(a, 0)?.len() as f64))
}

/// `sum` of a list is its items added with `+` (LANGUAGE.md §6): the kind
/// `+` gives and the items' frames (a sum of twists in {s} is a twist in
/// {s}; of rotations a plain 3×3 matrix, as Rotz(0) + Rotz(1) is, since
/// SO(3) is not closed under addition); of a vector, a number.
fn sum_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    match &args[0].kind {
        Kind::List(k, _) => rules::add_kind(k, k)
            .map(|kind| Ty::new(kind, args[0].frames))
            .map_err(|e| ArgError::type_of(0, format!("sum of a list: {}", e.message.clone()))),
        Kind::Unknown => Ok(Ty::plain(Kind::Unknown)),
        k if k.is_vector() => Ok(Ty::scalar()),
        k => Err(ArgError::type_of(
            0,
            format!("sum takes a list or a vector, not {}", k.a()),
        )),
    }
}

fn eval_sum(a: &mut Args) -> Result<Value, Diagnostic> {
    let items = elements(a, 0)?;
    let Some(first) = items.first() else {
        return Ok(Value::scalar(0.0));
    };
    let mut acc = first.clone();
    for v in items.iter().skip(1) {
        // (each step's kind is the one `+` gives: SO(3) + SO(3) is a matrix)
        let kind = rules::add_kind(&acc.kind(), &v.kind())
            .map_err(|e| a.error(0, ErrorKind::Type, e.message.clone()))?;
        acc = ops::add(&acc, v, false, &kind)
            .map_err(|m| a.error(0, ErrorKind::Type, m.to_string()))?;
    }
    Ok(acc)
}

/// `min`/`max` of numbers.
fn extreme_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    match &args[0].kind {
        Kind::List(k, _) if matches!(**k, Kind::Scalar | Kind::Unknown) => Ok(Ty::scalar()),
        Kind::Unknown => Ok(Ty::scalar()),
        k if k.is_vector() => Ok(Ty::scalar()),
        k => Err(ArgError::type_of(
            0,
            format!(
                "min and max take numbers (a list or a vector), not {}",
                k.a()
            ),
        )),
    }
}

fn extreme(a: &mut Args, pick: fn(f64, f64) -> f64) -> Result<Value, Diagnostic> {
    let items = elements(a, 0)?;
    let mut best: Option<f64> = None;
    for v in items.iter() {
        let x = v.as_scalar().ok_or_else(|| {
            a.error(
                0,
                ErrorKind::Type,
                format!("{} takes numbers, not {}", a.name, v.kind().a()),
            )
        })?;
        best = Some(best.map_or(x, |b| pick(b, x)));
    }
    best.map(Value::scalar)
        .ok_or_else(|| a.domain(format!("{} of an empty list", a.name)))
}

fn eval_min(a: &mut Args) -> Result<Value, Diagnostic> {
    extreme(a, f64::min)
}

fn eval_max(a: &mut Args) -> Result<Value, Diagnostic> {
    extreme(a, f64::max)
}

/// The list builtins.
pub fn builtins() -> Vec<Builtin> {
    let one = |rule| Typing::Custom {
        arity: (1, 1),
        rule,
    };
    vec![
        Builtin {
            name: "len",
            aliases: &["length", "numel"],
            signature: "len(xs: list | vector) -> scalar",
            section: "§12 (docs/language.md)",
            doc: "the number of items of a list (or entries of a vector)",
            example: "len(0:pi/8:pi)",
            area: Area::Pictures,
            typing: one(len_rule),
            eval: eval_len,
        },
        Builtin {
            name: "sum",
            aliases: &[],
            signature: "sum(xs: list | vector) -> kind of + | scalar",
            section: "§12 (docs/language.md)",
            doc: "the sum of a list's items, typed as + types it (twists in {s} sum to a twist in {s}, rotations to a plain 3×3 matrix), or of a vector's entries",
            example: "sum([k^2 for k in 1:4])",
            area: Area::Pictures,
            typing: one(sum_rule),
            eval: eval_sum,
        },
        Builtin {
            name: "min",
            aliases: &[],
            signature: "min(xs: list of numbers | vector) -> scalar",
            section: "§12 (docs/language.md)",
            doc: "the least number of a list or vector",
            example: "min([cos(t) for t in 0:pi/4:pi])",
            area: Area::Pictures,
            typing: one(extreme_rule),
            eval: eval_min,
        },
        Builtin {
            name: "max",
            aliases: &[],
            signature: "max(xs: list of numbers | vector) -> scalar",
            section: "§12 (docs/language.md)",
            doc: "the greatest number of a list or vector",
            example: "max([norm((a, b)) for a in 0:2, b in 0:2])",
            area: Area::Pictures,
            typing: one(extreme_rule),
            eval: eval_max,
        },
    ]
}
