//! List comprehensions (LANGUAGE.md §12): `[body for a in r1, b in r2]`
//! from a bracket whose first row is followed by a `comp_tail`.

use pest::iterators::Pair;

use super::ast::{Expr, ExprKind, Span};
use super::grammar::Rule;
use super::parser::{Built, Cx, check_depth};
use crate::diagnostics::{Diagnostic, ErrorKind};

impl Cx {
    /// `[body for a in r1, b in r2]`: one expression before `for`.
    pub(super) fn comprehension(
        &self,
        mut rows: Vec<Vec<Expr>>,
        tail: Pair<'_, Rule>,
        depth: usize,
        span: Span,
    ) -> Built {
        let body = match (rows.len(), rows.first().map(Vec::len)) {
            (1, Some(1)) => rows.pop().and_then(|mut r| r.pop()),
            _ => None,
        };
        let Some(body) = body else {
            return Err(Diagnostic::error(
                ErrorKind::Syntax,
                self.span(tail.as_span()),
                "a list comprehension takes one expression before `for`",
            )
            .with_help("write [expr for k in 0:4], or a tuple: [(a, b) for k in 0:4]"));
        };
        let mut vars = Vec::new();
        let mut depth = depth;
        for var in tail.into_inner() {
            if var.as_rule() != Rule::comp_var {
                continue;
            }
            let mut it = var.into_inner();
            let name = self.ident(it.next().ok_or_else(|| self.internal(span))?)?;
            let over = it
                .find(|p| p.as_rule() == Rule::expr)
                .ok_or_else(|| self.internal(span))?;
            let (over, d) = self.expr(over)?;
            depth = depth.max(d);
            vars.push((name, over));
        }
        check_depth(depth + 1, span)?;
        let kind = ExprKind::Comprehension {
            body: Box::new(body),
            vars,
        };
        Ok((Expr { kind, span }, depth + 1))
    }
}
