//! A name bound to a value, followed by a parenthesis, is a product
//! (LANGUAGE.md §4), as the book writes one: `R (1, 0, 0)`, `A (1, -3)`,
//! `n (n - 1)/2`. The grammar reads `name (…)` as a call, so the
//! evaluator turns it into the product when the name is a value and no
//! function. MATLAB's indexing `R(1, 2)` — no space, whole numbers within
//! the matrix — reads two ways: an error that shows `R[1, 2]`.

use super::interp::{Interp, Typed};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{BinOp, Expr, ExprKind, Name, Span};

impl Interp<'_> {
    /// `name (args)` with `name` bound to a value: `name * (args)`.
    pub(super) fn value_times_paren(
        &mut self,
        name: Name,
        name_span: Span,
        args: &[Expr],
        span: Span,
    ) -> Result<Typed, Diagnostic> {
        let Some(first) = args.first() else {
            return Err(Diagnostic::error(
                ErrorKind::Type,
                span,
                format!("`{name}` is a value, not a function: `{name}()` means nothing"),
            )
            .with_help(format!("write {name} alone")));
        };
        let paren_at = self.text(Span::new(name_span.end, first.span.start));
        let spaced = paren_at.starts_with(char::is_whitespace);
        if !spaced && let Some(d) = self.matlab_index(name, name_span, args, span) {
            return Err(d);
        }
        // The parenthesis: from `(` to the end of the call.
        let open = name_span.end + (paren_at.len() - paren_at.trim_start().len());
        let paren_span = Span::new(open, span.end);
        let rhs = match args {
            [one] => Expr {
                kind: one.kind.clone(),
                span: paren_span,
            },
            _ => Expr {
                kind: ExprKind::Paren(args.to_vec()),
                span: paren_span,
            },
        };
        let product = Expr {
            kind: ExprKind::Binary {
                op: BinOp::Mul,
                lhs: Box::new(Expr {
                    kind: ExprKind::Var(name),
                    span: name_span,
                }),
                rhs: Box::new(rhs),
                op_span: Span::new(name_span.end, open),
                implicit: true,
            },
            span,
        };
        self.expr(&product)
    }

    /// `R(1, 2)` on a matrix or `v(2)` on a vector, written as MATLAB
    /// indexes: an error naming `R[1, 2]` and the product.
    fn matlab_index(
        &self,
        name: Name,
        name_span: Span,
        args: &[Expr],
        span: Span,
    ) -> Option<Diagnostic> {
        let ty = self.env.get(name)?.ty;
        let (rows, cols) = ty.kind.shape()?;
        let whole = |e: &Expr, n: Option<usize>| match e.kind {
            ExprKind::Number(x) => x.fract() == 0.0 && x >= 1.0 && n.is_none_or(|n| x <= n as f64),
            _ => false,
        };
        let fits = match args {
            [i] => cols == Some(1) && rows != Some(1) && whole(i, rows),
            [i, j] => cols != Some(1) && whole(i, rows) && whole(j, cols),
            _ => false,
        };
        if !fits {
            return None;
        }
        let inside = self.text(Span::new(args[0].span.start, args[args.len() - 1].span.end));
        Some(
            Diagnostic::error(
                ErrorKind::Type,
                span,
                format!("`{name}({inside})` reads two ways: MATLAB's index, or a product"),
            )
            .with_label(name_span, format!("{name} is a value, not a function"))
            .with_help(format!(
                "index with brackets, 1-based: {name}[{inside}]; for the product write {name} ({inside}) or {name} * ({inside})"
            )),
        )
    }
}
