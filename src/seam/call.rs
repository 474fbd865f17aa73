//! A builtin applied to numbers through its table row (the numeric path
//! of [`super::apply::Op::Call`]): where the call stands, for its
//! messages and warnings, and the call itself, which gives back the
//! arguments it only read (the recipe of an exact form keeps them).

use crate::builtins::{Args, Builtin, Spans};
use crate::check::ty::Ty;
use crate::diagnostics::Diagnostic;
use crate::syntax::ast::Span;
use crate::values::ops::OpError;
use crate::values::value::Value;

/// Where a builtin call stands, for its messages: the arguments' spans
/// and source texts, the call's span, and the statement's warnings.
pub struct Site<'w> {
    /// Where each argument stands.
    pub spans: Spans,
    /// The whole call.
    pub call_span: Span,
    /// Each argument's static type and source text; empty where unknown.
    pub typed: Vec<(Ty, String)>,
    /// The statement's warnings, added to.
    pub warnings: &'w mut Vec<Diagnostic>,
    /// The θ = π decision of a logarithm by certified arithmetic
    /// (`crate::decide::turn`, given by the caller; None: by the floats).
    pub certified_turn: Option<fn(&Value) -> Option<crate::lie::so3::HalfTurn>>,
    /// Entries by certified arithmetic (`crate::decide::turn::entries`).
    pub certified_entries: Option<fn(&Value) -> Option<crate::values::exact_mat::Entries>>,
}

/// A builtin applied to numbers by its table row's function, with its
/// notes ([`super::apply::Op::Call`]'s numeric function; the evaluator gives the call's
/// [`Site`], the substitution of numbers into symbols none).
pub fn call(b: &Builtin, vals: Vec<Value>, site: Site) -> Result<Value, Diagnostic> {
    call_keeping(b, vals, site).map(|(v, _)| v)
}

/// [`call`], giving back the arguments as they were (a builtin only reads
/// them): the recipe of the result's exact form keeps them, with no copy
/// ([`super::apply::Op::exact_of_owned`]).
#[inline(always)]
pub fn call_keeping(
    b: &Builtin,
    vals: Vec<Value>,
    site: Site,
) -> Result<(Value, Vec<Value>), Diagnostic> {
    let mut args = Args {
        name: b.name,
        signature: b.signature,
        vals,
        spans: site.spans,
        call_span: site.call_span,
        warnings: site.warnings,
        typed: site.typed,
        certified_turn: site.certified_turn,
        certified_entries: site.certified_entries,
    };
    let v = (b.eval)(&mut args)?;
    crate::builtins::notes::after_call(&mut args, &v);
    Ok((v, args.vals))
}

/// [`call`] where the call stands nowhere (symbols re-evaluated): errors
/// as their message, warnings dropped.
pub fn call_nowhere(b: &Builtin, vals: Vec<Value>) -> Result<Value, OpError> {
    let mut warnings = Vec::new();
    let site = Site {
        spans: Spans::default(),
        call_span: Span::default(),
        typed: Vec::new(),
        warnings: &mut warnings,
        certified_turn: None,
        certified_entries: None,
    };
    call(b, vals, site).map_err(|d| OpError::Message(d.into_message()))
}
