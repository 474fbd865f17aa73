//! What a successful statement produced, for the front ends to print
//! ([`crate::output`]): its value, type and the names it bound.

use super::value::Value;
use crate::check::ty::Ty;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{Name, Span};

/// What a successful statement produced, for printing.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The whole statement, without its terminator.
    pub span: Span,
    /// The bound names (one for `x = ..`, several for `(a, b) = ..`,
    /// none for a bare expression).
    pub names: Names,
    /// The value's kind and frames.
    pub ty: Ty,
    /// The value, boxed as [`super::interp::Typed`]'s is (none when checking).
    pub val: Option<Box<Value>>,
    /// Extra text printed before the value (`derive` prints its chain).
    pub note: Option<String>,
    /// False for statements that print nothing (`given`, function definitions).
    pub prints: bool,
    /// For `(a, b) = ..`, the type of each bound part, with the frames it
    /// took from the value or from its name; empty otherwise.
    pub parts: Vec<Ty>,
    /// For a bare call of a builtin whose tuple parts have names
    /// ([`crate::builtins::parts`]), those names, to print `q = …`.
    pub labels: &'static [&'static str],
    /// For `explain EXPR`, the book's steps that compute the value, the
    /// last being the value itself (LANGUAGE.md §14); None otherwise.
    /// Boxed: every statement moves an `Outcome`, few explain.
    pub steps: Option<Box<Vec<super::explain::Shown>>>,
}

impl Outcome {
    /// The steps of `explain` (empty for any other statement).
    pub fn steps(&self) -> &[super::explain::Shown] {
        self.steps.as_deref().map_or(&[], Vec::as_slice)
    }
}

/// The names a statement bound, in order: read as a slice of names. One
/// name (the common `x = ..`) is held without a second allocation, and
/// names are the syntax tree's interned handles (no copy of the text).
#[derive(Debug, Clone)]
pub enum Names {
    /// `x = ..`, `derive T_ab`.
    One([Name; 1]),
    /// None (a bare expression) or several (`(a, b) = ..`).
    Many(Vec<Name>),
}

impl Names {
    /// The names as a slice.
    pub fn as_slice(&self) -> &[Name] {
        match self {
            Names::One(n) => n,
            Names::Many(v) => v,
        }
    }
}

impl std::ops::Deref for Names {
    type Target = [Name];
    fn deref(&self) -> &[Name] {
        self.as_slice()
    }
}

/// The warning of a statement's result `v` (at `span`) that holds NaN (an
/// undefined operation such as inf − inf) or, outside a tuple, ±inf (an
/// overflow such as `2^1e308`, or inf in the input): IEEE values are
/// printed, never silently, and a statement silenced by `;` still warns
/// (LANGUAGE.md §3). Tuples may hold inf by design (`screw_params` gives
/// h = inf for a pure translation).
#[inline]
pub fn not_finite(v: &Value, span: Span) -> Option<Diagnostic> {
    // (the common case, finite numbers, answered here without a call)
    match v {
        Value::Num { m, .. } if m.all_finite() => None,
        Value::Num { .. } | Value::Tuple(_) => not_finite_found(v, span),
        _ => None,
    }
}

/// [`not_finite`] of a value that may hold NaN or inf.
#[inline(never)]
fn not_finite_found(v: &Value, span: Span) -> Option<Diagnostic> {
    fn scan(v: &Value, top: bool, nan: &mut bool, inf: &mut bool) {
        match v {
            Value::Num { m, .. } => {
                // (the common all-finite case in one pass that vectorizes)
                if m.all_finite() {
                    return;
                }
                let xs = m.as_slice();
                *nan |= xs.iter().any(|x| x.is_nan());
                *inf |= top && xs.iter().any(|x| x.is_infinite());
            }
            Value::Tuple(vs) => vs.iter().for_each(|v| scan(v, false, nan, inf)),
            _ => {}
        }
    }
    let (mut nan, mut inf) = (false, false);
    scan(v, true, &mut nan, &mut inf);
    let message = if nan {
        "the result has NaN entries: an undefined operation (inf − inf, 0·inf, an angle of inf)"
    } else if inf {
        "the result is infinite: an overflow (the number exceeds 1.8e308) or inf in the input"
    } else {
        return None;
    };
    Some(Diagnostic::warning(ErrorKind::Domain, span, message))
}
