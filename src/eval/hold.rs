//! `diff` and `subs` by a symbol that already has a number (LANGUAGE.md §7:
//! "once every symbol of a value has a number, the value is a number …
//! exactly as if the numbers had been typed first").
//!
//! `x = diff(sin(s), s); s = 1; x` is cos 1: the derivative is taken over
//! the symbol and read with its number. Typed the other way round, `s = 1;
//! diff(sin(s), s)` must be cos 1 too, not the derivative of the number
//! sin 1 (0): a student who binds the joint angles and then asks for
//! `diff(T, theta1)` wants ∂T/∂θ₁ there. So while `diff` or `subs`
//! evaluates its operands, every `given` name bound to a value (and every
//! rate `q'` of a given function of time) is read as its symbol
//! ([`Env::hold`]); the result is then read with the numbers, as a value
//! bound later is.
//!
//! A value computed *after* its symbols had numbers holds the numbers, not
//! the symbols (`s = 1; y = sin(s); diff(y, s)`): differentiating it would
//! give a plausible 0. Such a value is marked when it is bound
//! ([`super::env::Binding::from_numbers`], from [`carries_numbers`]) and a
//! `diff` or `subs` that reads it is refused, with the way out.

use super::env::{Binding, Env};
use super::interp::refine;
use super::interp::{Interp, Typed};
use super::value::{Sym, Value};
use crate::builtins::Builtin;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{Expr, ExprKind, Name, Span};

/// Whether a call of `name` with `args` reads its operands as symbols:
/// `diff(x, s)` and `subs(x, s, v)` with s a name.
#[inline]
pub(super) fn reads_symbols(name: &str, args: &[Expr]) -> bool {
    args.len() >= 2 && matches!(args[1].kind, ExprKind::Var(_)) && matches!(name, "diff" | "subs")
}

/// Notes in [`Env`]'s numbers read by the statement those reading `name`
/// gives ([`absorbed`]).
#[cold]
pub(super) fn note_read(env: &mut Env, name: Name) {
    let mut found = Vec::new();
    if let Some(b) = env.get(name)
        && !b.symbolic
    {
        absorbed(env, name, b, &mut found);
    }
    env.numbers_read.extend(found);
}

/// Adds to `out` the `given` names whose numbers reading `name` (bound to
/// `b`) gives, each with `name`: a given name or rate bound to a value,
/// the names a value computed from such numbers absorbed, the symbols now
/// bound of a value made from symbols (reading it puts their numbers in).
/// Held names ([`Env::hold`]) read as symbols and give none.
pub(super) fn absorbed(env: &Env, name: Name, b: &Binding, out: &mut Vec<(Name, Name)>) {
    let mut add = |s: Name| {
        if !out.contains(&(s, name)) {
            out.push((s, name));
        }
    };
    if env.is_given(name) {
        add(name);
    }
    b.absorbed.iter().for_each(|s| add(*s));
    if let Some(v) = &b.val {
        bound_symbols(env, v, &mut add);
    }
}

/// Calls `add` with the names of the symbols of `v` (and of how it was
/// made) that are bound to numbers now.
fn bound_symbols(env: &Env, v: &Value, add: &mut impl FnMut(Name)) {
    match v {
        Value::Formula { m, how, .. } => {
            let mut syms = Vec::new();
            m.data.iter().for_each(|e| e.symbols(&mut syms));
            if let Some(r) = how {
                crate::values::recipe::symbols(r, &mut syms);
            }
            for s in &syms {
                if super::resolve::bound(env, s).is_some() {
                    add(Name::new(&crate::values::formula::binding_name(s)));
                }
            }
        }
        Value::Sym(t) => {
            t.any(&mut |node| {
                if let Sym::Name(n) = node {
                    let n = Name::new(n);
                    if env.is_given(n) && env.get(n).is_some_and(|b| !b.symbolic) {
                        add(n);
                    }
                }
                false
            });
        }
        Value::Tuple(vs) => vs.iter().for_each(|x| bound_symbols(env, x, add)),
        Value::List(vs) => vs.iter().for_each(|x| bound_symbols(env, x, add)),
        _ => {}
    }
}

/// Whether the number of `absorbed` (a given name or rate) moves with
/// `by` (`diff(x, by)`, `subs(x, by, v)`): it is `by`, or `by` is the time
/// variable of the function of time it is (or is a rate of). Other
/// numbers are constants to a partial derivative and to a substitution:
/// putting them in first changes nothing.
fn moves_with(env: &Env, absorbed: Name, by: Name) -> bool {
    if absorbed == by {
        return true;
    }
    let base = absorbed.as_str().trim_end_matches('\'');
    let time = env
        .given(Name::new(base))
        .and_then(|b| match &b.val {
            Some(Value::Formula { m, .. }) => m.data.first().and_then(crate::sym::expr::as_symbol),
            _ => None,
        })
        .and_then(|s| s.time.clone());
    time.is_some_and(|t| *t == *by.as_str())
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
        let moving = inner.iter().find(|(s, _)| moves_with(self.env, *s, by));
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
        let now = super::substitute::now(v, self.env, &mut warnings).map_err(|e| {
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
