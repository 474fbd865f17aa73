//! Calls of user functions (`f(x, y) = expr`, LANGUAGE.md §3): the
//! arguments bound to the parameters for the body and restored after it,
//! a tuple spread over the parameters, the depth of nested calls bounded
//! ([`MAX_CALL_DEPTH`]), and an error inside the body labelled with the
//! call site as well (`f(2)` at line 5, inside `f` at line 2).

use super::interp::{Interp, MAX_CALL_DEPTH, Typed};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{Expr, Name, Span};

impl Interp<'_> {
    pub(super) fn user_call(
        &mut self,
        f: &super::value::UserFn,
        args: &[Expr],
        span: Span,
    ) -> Result<Typed, Diagnostic> {
        // `f((a, b))` with f(x, y): the tuple's parts are the arguments.
        let mut spread = None;
        if let [one] = args
            && f.params.len() >= 2
        {
            let warned = self.warnings.len();
            let t = self.expr(one)?;
            let parts = super::notation::parts(&t);
            if parts.len() == f.params.len() {
                spread = Some(parts);
            } else {
                // Evaluated again below as the one argument.
                self.warnings.truncate(warned);
            }
        }
        if spread.is_none() && args.len() != f.params.len() {
            return Err(Diagnostic::error(
                ErrorKind::Arity,
                span,
                format!(
                    "{} takes {} argument(s), got {}",
                    f.name,
                    f.params.len(),
                    args.len()
                ),
            )
            .with_help(format!("signature: {}({})", f.name, f.params.join(", "))));
        }
        if self.depth >= MAX_CALL_DEPTH {
            return Err(self.domain(
                span,
                format!("function calls nested deeper than {MAX_CALL_DEPTH} (recursion?)"),
            ));
        }
        // A user function may call itself many times over (f(n-1) + f(n-1)):
        // each call asks the budget.
        crate::budget::check().map_err(|stop| super::interp::budget_error(stop, span))?;
        let mut bound = Vec::new();
        match spread {
            Some(parts) => bound.extend(f.params.iter().cloned().zip(parts)),
            None => {
                for (p, a) in f.params.iter().zip(args) {
                    let t = self.expr(a)?;
                    bound.push((p.clone(), t));
                }
            }
        }
        let saved: Vec<(String, Option<super::env::Binding>)> = f
            .params
            .iter()
            .map(|p| (p.clone(), self.env.get_unheld(p).cloned()))
            .collect();
        // (an argument read from numbers of given symbols makes the
        // parameter hold them, super::hold)
        let absorbed: Vec<Name> = self.env.numbers_read.iter().map(|(s, _)| *s).collect();
        for (p, t) in bound {
            self.env.set(
                &p,
                super::env::Binding {
                    ty: t.ty,
                    val: t.val.map(|v| *v),
                    symbolic: false,
                    derived: false,
                    stamp: 0,
                    absorbed: absorbed.clone(),
                },
            );
        }
        self.depth += 1;
        let warned = self.warnings.len();
        let elsewhere = f.source != self.env.source;
        // An error inside the body shows the call site too: the outermost
        // call of each function (recursion labels one call, not 64).
        let result = self.expr(&f.body).map_err(|mut d| {
            if elsewhere {
                at_call(&mut d, f, span);
                return d;
            }
            if d.span.start >= span.start && d.span.end <= span.end {
                return d;
            }
            let text = format!("in this call of {}", f.name);
            d.labels.retain(|l| l.message != text);
            d.with_label(span, text)
        });
        if elsewhere {
            for w in &mut self.warnings[warned..] {
                at_call(w, f, span);
            }
        }
        self.depth -= 1;
        for (p, old) in saved {
            match old {
                Some(b) => self.env.set(&p, b),
                None => {
                    self.env.remove(&p);
                }
            }
        }
        result
    }
}

/// A diagnostic from the body of `f`, defined in another source text (an
/// earlier REPL input or notebook cell, a prelude): its spans point into
/// that text, not this one, so it is placed at the call, which is here.
fn at_call(d: &mut Diagnostic, f: &super::value::UserFn, call: Span) {
    d.span = call;
    d.labels.clear();
    d.primary_label = format!("in the body of {}, defined in an earlier input", f.name);
}
