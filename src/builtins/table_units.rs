//! Angle units and conversions (LANGUAGE.md §8): `deg2rad` and `rad2deg`
//! on numbers, vectors and matrices, entry by entry; and `round`, to
//! compare a result with the digits the book prints. The units themselves
//! are words of the language: `30 deg` and `30°` are postfix (the grammar),
//! `pi/6 rad` multiplies by `rad` = 1 (the evaluator's constants).

use std::f64::consts::PI;

use super::{Area, ArgError, Args, Builtin, Typing};
use crate::check::rules::scaled_kind;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::values::value::Value;

/// A number, vector or matrix in, the same shape out (a group element
/// scaled is no longer one); frames are kept.
fn entrywise_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    let k = &args[0].kind;
    if k.shape().is_none() {
        return Err(ArgError::type_of(
            0,
            format!("angles are numbers, vectors or matrices, not {}", k.a()),
        ));
    }
    let kind = match k {
        Kind::Twist | Kind::Screw | Kind::Wrench => Kind::Vector(Some(6)),
        other => scaled_kind(other),
    };
    Ok(Ty::new(kind, args[0].frames))
}

/// Every entry of argument 0 times `factor`.
fn scale(a: &mut Args, factor: f64) -> Result<Value, Diagnostic> {
    let m = a.mat(0)?.map(|x| x * factor);
    let kind = match a.value(0).kind() {
        Kind::Twist | Kind::Screw | Kind::Wrench => Kind::Vector(Some(6)),
        k => scaled_kind(&k),
    };
    if m.iter().any(|x| x.is_nan()) {
        return Err(a.error(0, ErrorKind::Domain, "an entry is NaN"));
    }
    Ok(Value::Num {
        kind,
        m,
        exact: Default::default(),
    })
}

/// round(x, n): numbers, vectors, matrices; n a whole number of decimals.
fn round_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    let t = entrywise_rule(&args[..1])?;
    if args.len() == 2 && !args[1].kind.maybe_scalar() {
        return Err(ArgError::type_of(1, "the number of decimals is a number"));
    }
    Ok(t)
}

/// Every entry rounded to `n` decimals (half away from zero): `n = 3`
/// gives the book's printed digits, so `round(R, 3) == [0.866, …]` holds
/// exactly (k/10ⁿ is the double nearest the decimal the book prints).
fn eval_round(a: &mut Args) -> Result<Value, Diagnostic> {
    let n = if a.len() == 2 { a.int(1, 0, 15)? } else { 0 };
    let scale = 10f64.powi(n as i32);
    let m = a.mat(0)?.map(|x| (x * scale).round() / scale);
    let kind = match a.value(0).kind() {
        Kind::Twist | Kind::Screw | Kind::Wrench => Kind::Vector(Some(6)),
        k => scaled_kind(&k),
    };
    Ok(Value::Num {
        kind,
        m,
        exact: Default::default(),
    })
}

pub(super) fn builtins() -> Vec<Builtin> {
    vec![
        Builtin {
            name: "round",
            aliases: &[],
            signature: "round(x: scalar | vector | matrix, n: scalar = 0) -> same shape",
            section: "—",
            doc: "every entry rounded to n decimals, to compare with the book's printed digits",
            example: "round(Rotz(30 deg), 3)",
            area: Area::Scalars,
            typing: Typing::Custom {
                arity: (1, 2),
                rule: round_rule,
            },
            eval: eval_round,
        },
        Builtin {
            name: "deg2rad",
            aliases: &["radians"],
            signature: "deg2rad(x: scalar | vector | matrix) -> same shape",
            section: "—",
            doc: "degrees to radians, entry by entry (the same as `x deg`)",
            example: "deg2rad((30, 45, 90))",
            area: Area::Scalars,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: entrywise_rule,
            },
            eval: |a| scale(a, PI / 180.0),
        },
        Builtin {
            name: "rad2deg",
            aliases: &["degrees"],
            signature: "rad2deg(x: scalar | vector | matrix) -> same shape",
            section: "—",
            doc: "radians to degrees, entry by entry",
            example: "rad2deg((pi/6, pi/4, pi/2))",
            area: Area::Scalars,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: entrywise_rule,
            },
            eval: |a| scale(a, 180.0 / PI),
        },
    ]
}
