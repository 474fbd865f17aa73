//! Symbols at evaluation (LANGUAGE.md §7): `theta'` names the derivative
//! θ̇ of a function of time, `diff(x, t)` takes a time variable that need
//! not have a value, and symbolic results are bounded in size and depth.

use super::interp::{Interp, Typed};
use super::value::Value;
use crate::check::ty::Ty;
use crate::diagnostics::Diagnostic;
use crate::sym::{Expr, Symbol};
use crate::syntax::ast::{Expr as Ast, ExprKind, Span};

impl Interp<'_> {
    /// `theta'`: the derivative θ̇ of a function of time `given theta(t)`
    /// (one prime per derivative), §7.
    pub(super) fn derivative_symbol(&self, name: &str) -> Option<Typed> {
        let base = name.trim_end_matches('\'');
        let dots = name.len() - base.len();
        let b = self.env.get(base).filter(|_| dots > 0)?;
        let Some(Value::Formula { m, .. }) = &b.val else {
            return None;
        };
        let mut s = m.data.first().and_then(crate::sym::expr::as_symbol)?;
        if !s.is_timed() {
            return None;
        }
        for _ in 0..dots {
            s = s.dot();
        }
        Some(Typed::new(
            Ty::scalar(),
            self.running()
                .then(|| super::formula::scalar(Expr::symbol(s))),
        ))
    }

    /// `diff(x, t)` with `t` a name with no value (and no rate `q'` of a
    /// function of time): the time variable.
    #[inline]
    pub(super) fn time_variable(&self, func: &str, i: usize, arg: &Ast) -> Option<Typed> {
        match (i, func, &arg.kind) {
            (1, "diff", ExprKind::Var(t))
                if self.env.get(t).is_none() && self.derivative_symbol(t).is_none() =>
            {
                Some(Typed::new(
                    Ty::scalar(),
                    self.running()
                        .then(|| super::formula::scalar(Expr::symbol(Symbol::new(t)))),
                ))
            }
            _ => None,
        }
    }

    /// A symbolic result beyond the size limits ([`super::symbolic::Tree::too_large`],
    /// [`crate::sym::expr::MAX_DEPTH`]) is a domain error.
    pub(super) fn within_limits(&self, t: &Typed, span: Span) -> Result<(), Diagnostic> {
        let depth = match t.val.as_deref() {
            Some(Value::Sym(s)) if s.too_large() => super::symbolic::MAX_SYM_DEPTH,
            Some(Value::Formula { m, .. })
                if m.size() > super::symbolic::MAX_SYM_NODES
                    || m.depth() > crate::sym::expr::MAX_DEPTH =>
            {
                crate::sym::expr::MAX_DEPTH
            }
            _ => return Ok(()),
        };
        Err(self
            .domain(
                span,
                format!(
                    "symbolic expression too large (more than {} terms or nested deeper than {depth})",
                    super::symbolic::MAX_SYM_NODES,
                ),
            )
            .with_help("bind numbers to the given names, or simplify step by step"))
    }
}
