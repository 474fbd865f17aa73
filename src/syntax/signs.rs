//! The book's signs as operators (issue 22): `√2`, `√(x + 1)` are
//! `sqrt` of the atom after the sign; `a · b` is `dot(a, b)` and `a × b`
//! `cross(a, b)`, at the precedence of `*`. Also the check of a
//! juxtaposition in the pest tree (`M[1; 2]`).

use pest::iterators::Pair;

use super::ast::{Expr, ExprKind, Ident, Span};
use super::grammar::Rule;
use super::parser::{Built, Cx, check_depth};
use crate::diagnostics::{Diagnostic, ErrorKind};

impl Cx {
    /// `l · r` → `dot(l, r)`, `l × r` → `cross(l, r)`, the function named
    /// at the sign; `None` for any other operator.
    pub(super) fn product_call(
        &self,
        op: Rule,
        l: Expr,
        r: Expr,
        op_span: Span,
    ) -> Result<Expr, (Expr, Expr)> {
        let name = match op {
            Rule::dot_op => "dot",
            Rule::cross_op => "cross",
            _ => return Err((l, r)),
        };
        let span = l.span.join(r.span);
        let func = Ident {
            name: name.into(),
            span: op_span,
        };
        let kind = ExprKind::Call {
            func,
            args: vec![l, r],
        };
        Ok(Expr { kind, span })
    }

    /// `√x`: `sqrt(x)`, the function named at the sign.
    pub(super) fn root(&self, pair: Pair<'_, Rule>, span: Span) -> Built {
        let sign = Span::new(span.start, span.start + '√'.len_utf8());
        let arg = pair
            .into_inner()
            .next()
            .ok_or_else(|| self.internal(span))?;
        let (arg, d) = self.primary(arg)?;
        check_depth(d + 1, span)?;
        let func = Ident {
            name: "sqrt".into(),
            span: sign,
        };
        let kind = ExprKind::Call {
            func,
            args: vec![arg],
        };
        Ok((Expr { kind, span }, d + 1))
    }

    /// `left right` with nothing between. Legal everywhere the book writes
    /// a product (`2 pi`, `A t`, `T_sb T_bc`); `spacing.rs` refuses the
    /// readings that are not plain once the tree is built. Here only a
    /// bracket right after a name that is not a valid index (`M[1; 2]`).
    pub(super) fn check_juxtaposition(
        &self,
        left: &Pair<'_, Rule>,
        right: &Pair<'_, Rule>,
    ) -> Result<(), Diagnostic> {
        let last = left.clone().into_inner().last().map(|p| p.as_rule());
        let first = right.clone().into_inner().next().map(|p| p.as_rule());
        let indexable = matches!(
            last,
            Some(Rule::ident | Rule::call | Rule::index | Rule::member)
        );
        if indexable
            && first == Some(Rule::brackets)
            && left.as_span().end() == right.as_span().start()
        {
            return Err(Diagnostic::error(
                ErrorKind::Syntax,
                self.span(right.as_span()),
                "an index takes one or two subscripts separated by `,`",
            )
            .with_help("write M[i], M[i, j], M[i, :] or M[:, j]"));
        }
        Ok(())
    }
}
