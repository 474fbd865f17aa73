//! `diff` and `subs` by a symbol that already has a number, as the
//! interpreter runs them (LANGUAGE.md §7: bound first or later, the same
//! answer; what they may read is decided below, in [`crate::calculus::held`]).
//!
//! This is interpreter, not calculus: it walks the call's AST. While `diff`
//! or `subs` evaluates its operands through [`Interp`], every `given` name
//! bound to a value (and every rate `q'` of a given function of time) is
//! read as its symbol ([`Env::hold`]); the numbers the statement reads are
//! noted in [`Env`] as the operands are evaluated; the result is then read
//! with the numbers ([`crate::calculus::substitute::now`]), and a call whose
//! operand holds numbers in place of the symbol it is by is refused here,
//! with the way out.

use super::env::{Binding, Env};
use super::interp::refine;
use super::interp::{Interp, Typed};
use super::value::Value;
use crate::builtins::Builtin;
use crate::calculus::held;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{Expr, ExprKind, Name, Span};

/// Whether a call of `name` with `args` reads its operands as symbols:
/// `diff(x, s)` and `subs(x, s, v)` with s a name.
#[inline]
pub(super) fn reads_symbols(name: &str, args: &[Expr]) -> bool {
    args.len() >= 2 && matches!(args[1].kind, ExprKind::Var(_)) && matches!(name, "diff" | "subs")
}

/// Notes in [`Env`]'s numbers read by the statement those reading `name`
/// gives ([`held::absorbed`]).
#[cold]
pub(super) fn note_read(env: &mut Env, name: Name) {
    let mut found = Vec::new();
    if let Some(b) = env.get(name)
        && !b.symbolic
    {
        held::absorbed(env, name, b.val.as_ref(), &b.absorbed, &mut found);
    }
    env.numbers_read.extend(found);
}

impl Interp<'_> {
    /// A call of `diff(x, s)` or `subs(x, s, v)`, s a name: with the given
    /// names held where some have numbers ([`Env::hold`]); refused
    /// when s is a name bound to a number that was never a symbol (`u = 2;
    /// diff(u^2, u)` would differentiate the number 4).
    #[cold]
    #[inline(never)]
    pub(super) fn symbol_call(
        &mut self,
        b: &'static Builtin,
        name: &str,
        args: &[Expr],
        span: Span,
        base: usize,
    ) -> Result<Typed, Diagnostic> {
        let held = self.env.hold();
        if let ExprKind::Var(by) = args[1].kind
            && let Some(Binding {
                val: Some(v @ Value::Num { .. }),
                ..
            }) = self.env.get(by)
        {
            let shown = crate::values::format::inline(v, 4);
            self.env.release();
            return Err(Diagnostic::error(
                ErrorKind::Domain,
                args[1].span,
                format!("{name}(…, {by}): {by} is a number ({shown}), not a symbol"),
            )
            .with_help(format!(
                "declare it with `given {by}` (its number may be bound before or after {name}), \
                 or use another name for the symbol"
            )));
        }
        let outer = std::mem::take(&mut self.env.numbers_read);
        // (the one call of builtin_call here: it is inlined where it is
        // called, and the numeric path's call site is the other)
        let out = self.builtin_call(b, name, args, span, base);
        let inner = std::mem::replace(&mut self.env.numbers_read, outer);
        if !held {
            self.env.numbers_read.extend(inner);
            return out;
        }
        self.held(name, args, span, out, inner)
    }

    /// The end of a call of `diff` or `subs` made with the given names held
    /// ([`Env::hold`]): its value `out` over the symbols read with their
    /// numbers; refused when an operand holds numbers in place of them
    /// (`inner`, the numbers its operands read).
    fn held(
        &mut self,
        name: &str,
        args: &[Expr],
        span: Span,
        out: Result<Typed, Diagnostic>,
        inner: Vec<(Name, Name)>,
    ) -> Result<Typed, Diagnostic> {
        let ExprKind::Var(by) = args[1].kind else {
            unreachable!("reads_symbols: the second argument is a name")
        };
        // (what the statement binds holds the numbers of the held names,
        // put in below, and of what the operands read)
        let held = self.env.held_names();
        self.env.release();
        for s in held {
            self.env.numbers_read.push((s, by));
        }
        let moving = inner
            .iter()
            .find(|(s, _)| held::moves_with(self.env, *s, by));
        self.env.numbers_read.extend(inner.iter().copied());
        if let Some((s, read)) = moving {
            return Err(Diagnostic::error(
                ErrorKind::Domain,
                span,
                format!(
                    "{name}(…, {by}) cannot see {s} in `{read}`: `{read}` was computed after {s} \
                     had a number, so it holds that number, and {what}",
                    what = if name == "diff" {
                        "its derivative would be taken as of a constant"
                    } else {
                        "nothing in it would be replaced"
                    }
                ),
            )
            .with_help(format!(
                "compute `{read}` before binding {s} (then {name} reads the symbol and puts the \
                 number in after), or write its expression inside {name}(…)"
            )));
        }
        let t = out?;
        let Some(v) = t.val.as_deref() else {
            return Ok(t);
        };
        let mut warnings = Vec::new();
        let now = crate::calculus::substitute::now(v, self.env, &mut warnings).map_err(|e| {
            Diagnostic::error(
                ErrorKind::Domain,
                span,
                format!("{name}(…) with the numbers bound since: {}", e.0),
            )
        })?;
        for mut w in warnings {
            w.span = span;
            self.warnings.push(w);
        }
        let now = Some(now);
        Ok(Typed::new(refine(t.ty, &now), now))
    }
}
