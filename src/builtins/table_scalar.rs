//! Scalar functions: the trigonometric functions and their inverses with
//! their domains (arcsine and arccosine on [−1, 1], §3.2.3.3's angles),
//! `atan2`, `sqrt` and `abs`; `tan`, `cot`, `sec` and `csc` refuse their
//! poles (angle units are in `table_units`). Each checks
//! its domain — by the argument's exact form when it has one
//! ([`crate::values::domain`]) — and names the cause of a refusal
//! (`sqrt(-1)`, `acos(2)`).

use std::cmp::Ordering;

use super::{Area, Args, Builtin, FrameRule, Param, Typing};
use crate::check::ty::Kind;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::values::domain::Zero;
use crate::values::value::Value;

/// The return kind of every scalar function.
pub(super) fn scalar() -> Kind {
    Kind::Scalar
}

/// A scalar function, infinite where `pole` says (tan, sec where cos x
/// = 0; cot, csc where sin x = 0). The pole is decided by the exact form
/// of x when it has one ([`Decided::is_pole`]: `tan(π/2 + 10¹⁶π)` is at
/// a pole whatever its float); a float within rounding of a pole is
/// refused too, its value there being rounding noise.
fn unary(
    a: &mut Args,
    f: fn(f64) -> f64,
    pole: Option<Zero>,
    why: &str,
) -> Result<Value, Diagnostic> {
    let d = a.decided(0)?;
    let trig = matches!(a.name, "sin" | "cos" | "tan" | "cot" | "sec" | "csc");
    let x = match trig {
        // (an exact multiple of π reduced exactly, issue 35)
        true => d.angle(),
        false => d.value(),
    };
    if trig && d.angle_lost() {
        a.warnings.push(Diagnostic::warning(
            ErrorKind::Domain,
            a.call_span,
            format!(
                "{}({}): the argument is a float with no exact form, and at this size its last digit is worth {} radians, so its angle modulo 2π is unknown and the result has no significant digit",
                a.name,
                crate::values::number::fmt_num(x, 4),
                crate::values::number::fmt_num(ulp(x), 4)
            ),
        )
        .with_help("give the angle exactly (`3*10^17*pi`), or reduce it modulo 2π before it grows"));
    }
    let Some(zero) = pole else {
        return Ok(Value::scalar(f(x)));
    };
    let near = match zero {
        Zero::Cos => x.cos(),
        Zero::Sin => x.sin(),
    };
    match d.is_pole(zero) {
        Some(true) => {}
        None if near.abs() <= POLE => {}
        Some(false) if near.abs() <= POLE => {
            let which = if zero == Zero::Cos { "cos" } else { "sin" };
            return Err(a.error(
                0,
                ErrorKind::Domain,
                format!(
                    "{}({x}): x is within rounding of a pole ({which} x is {near:.1e} in floats), \
                     so a float of the value would be rounding noise",
                    a.name
                ),
            ));
        }
        _ => return Ok(Value::scalar(f(x))),
    }
    Err(a.error(0, ErrorKind::Domain, format!("{}({x}): {why}", a.name)))
}

/// The gap between `x` and the next float away from 0.
fn ulp(x: f64) -> f64 {
    let x = x.abs();
    f64::from_bits(x.to_bits() + 1) - x
}

/// Below this, cos x (or sin x) is a computed zero: x is a pole (π/2 in
/// floats has cos = 6.1e-17), and a value of 1e16 would be rounding noise.
const POLE: f64 = 1e-15;

/// How far outside its domain an argument may be and still count as
/// rounding (`acos(1 + 2e-16)`, `sqrt(-2e-16)`): clamped to the domain,
/// with a note.
pub const ROUNDING: f64 = 1e-12;

/// How far outside its domain an exact argument (a number as typed) may be
/// and still be rounded to the edge, with a note: four units in the last
/// place of 1 (8.9e-16), so that a float printed at full precision and
/// typed back (`acos(1.0000000000000002)`, `sqrt(-1e-17)`) is the edge it
/// was computed as; `acos(1.000000000000001)` stays a domain error.
pub const ULPS: f64 = 4.0 * f64::EPSILON;

/// A scalar function on `[lo, hi]`. An exact argument (typed, or with an
/// exact form) is in or out by its value, exactly (`sqrt(√5 +
/// cos(3π/2)/1e-17)` is √√5: the float of the argument, −16.1, is not the
/// number; `sqrt(-1e-6)` is not real), except that within [`ULPS`] of the
/// edge it is taken as the edge with a note (`sqrt(-2e-16)` is 0, a
/// rounding typed back); a float with no exact form within
/// [`ROUNDING`] of the interval is clamped into it with a note (rounding
/// may have put it outside); farther is a domain error giving the value.
fn near_domain(
    a: &mut Args,
    f: fn(f64) -> f64,
    lo: f64,
    hi: f64,
    why: &str,
) -> Result<Value, Diagnostic> {
    let d = a.decided(0)?;
    let x = d.value();
    let below = |c: f64| {
        if c.is_finite() {
            d.order(c)
        } else {
            Some(Ordering::Less)
        }
    };
    let inside = match (d.order(lo), below(hi)) {
        (Some(l), Some(h)) if d.is_exact() => Some(l.is_ge() && h.is_le()),
        _ => None,
    };
    let c = match inside {
        // (the float of an exact number inside may be a rounding outside)
        Some(true) => return Ok(Value::scalar(f(x.clamp(lo, hi)))),
        // an exact number a few units in the last place outside (by its
        // exact value) is a computed float typed back
        // (`acos(1.0000000000000002)`, `sqrt(-1e-17)`): rounded to the
        // edge it is outside of, with the note below
        Some(false)
            if d.order(lo - ULPS).is_some_and(Ordering::is_ge)
                && d.order(lo).is_some_and(Ordering::is_lt) =>
        {
            lo
        }
        Some(false)
            if below(hi + ULPS).is_some_and(Ordering::is_le)
                && below(hi).is_some_and(Ordering::is_gt) =>
        {
            hi
        }
        Some(false) => {
            return Err(a.error(0, ErrorKind::Domain, format!("{}({x}): {why}", a.name)));
        }
        None if (lo..=hi).contains(&x) => return Ok(Value::scalar(f(x))),
        None if x >= lo - ROUNDING && x <= hi + ROUNDING => x.clamp(lo, hi),
        None => {
            return Err(a.error(0, ErrorKind::Domain, format!("{}({x}): {why}", a.name)));
        }
    };
    let num = |v: f64| crate::values::number::fmt_num(v, 4);
    let interval = if hi.is_finite() {
        format!("[{}, {}]", num(lo), num(hi))
    } else {
        format!("[{}, ∞)", num(lo))
    };
    let by = match (x - c).abs() {
        // (an exact number outside whose float is the edge)
        0.0 => "less than a unit in the last place".to_string(),
        d => format!("{d:.1e}"),
    };
    a.warnings.push(Diagnostic::note(
        ErrorKind::Domain,
        a.call_span,
        format!(
            "{}({x}): the argument is outside {interval} by {by}, a rounding error; taken as {}",
            a.name,
            num(c)
        ),
    ));
    Ok(Value::scalar(f(c)))
}

macro_rules! scalar_fn {
    ($name:literal, $doc:literal, $f:expr, $pole:expr, $why:literal) => {
        Builtin {
            name: $name,
            aliases: &[],
            signature: concat!($name, "(x: scalar) -> scalar"),
            section: "—",
            doc: $doc,
            example: concat!($name, "(0.5)"),
            area: Area::Scalars,
            typing: Typing::Fixed {
                params: &[Param::Scalar],
                ret: scalar,
                frames: FrameRule::None,
            },
            eval: |a| unary(a, $f, $pole, $why),
        }
    };
}

/// A scalar function on an interval, clamping rounding errors.
macro_rules! clamped_fn {
    ($name:literal, $doc:literal, $f:expr, ($lo:expr, $hi:expr), $why:literal) => {
        Builtin {
            eval: |a| near_domain(a, $f, $lo, $hi, $why),
            ..scalar_fn!($name, $doc, $f, None, $why)
        }
    };
}

/// The scalar functions, in help order (after `table_math`'s).
pub(super) fn builtins() -> Vec<Builtin> {
    use Area::*;
    use Param::*;
    vec![
        Builtin {
            name: "atan2",
            aliases: &[],
            signature: "atan2(y: scalar, x: scalar) -> scalar",
            section: "§3.2.3.3",
            doc: "the angle of (x, y), in (−π, π]",
            example: "atan2(1, 1)",
            area: Scalars,
            typing: Typing::Fixed {
                params: &[Scalar, Scalar],
                ret: scalar,
                frames: FrameRule::None,
            },
            // (the sides of the cut at y = 0, x < 0 by the exact forms:
            // atan2(sin(2π), −1) is π, not −π)
            eval: |a| {
                Ok(Value::scalar(
                    a.decided(0)?.value().atan2(a.decided(1)?.value()),
                ))
            },
        },
        scalar_fn!("sin", "sine (radians)", f64::sin, None, ""),
        scalar_fn!("cos", "cosine (radians)", f64::cos, None, ""),
        scalar_fn!(
            "tan",
            "tangent (radians), sin x / cos x",
            f64::tan,
            Some(Zero::Cos),
            "cos x is 0 there, so the tangent is infinite"
        ),
        scalar_fn!(
            "cot",
            "cotangent (radians), cos x / sin x",
            |x| x.cos() / x.sin(),
            Some(Zero::Sin),
            "sin x is 0 there, so the cotangent is infinite"
        ),
        scalar_fn!(
            "sec",
            "secant (radians), 1 / cos x",
            |x| 1.0 / x.cos(),
            Some(Zero::Cos),
            "cos x is 0 there, so the secant is infinite"
        ),
        scalar_fn!(
            "csc",
            "cosecant (radians), 1 / sin x",
            |x| 1.0 / x.sin(),
            Some(Zero::Sin),
            "sin x is 0 there, so the cosecant is infinite"
        ),
        clamped_fn!(
            "asin",
            "arcsine, in [−π/2, π/2]",
            f64::asin,
            (-1.0, 1.0),
            "the argument must be in [−1, 1]"
        ),
        clamped_fn!(
            "acos",
            "arccosine, in [0, π]",
            f64::acos,
            (-1.0, 1.0),
            "the argument must be in [−1, 1]"
        ),
        scalar_fn!("atan", "arctangent", f64::atan, None, ""),
        clamped_fn!(
            "sqrt",
            "square root (also written √2, √(x + 1))",
            f64::sqrt,
            (0.0, f64::INFINITY),
            "the square root of a negative number is not real"
        ),
        scalar_fn!("abs", "absolute value", f64::abs, None, ""),
    ]
}
