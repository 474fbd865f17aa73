//! The book's notation in the pest tree builder (LANGUAGE.md §4): the
//! parenthesis-free scalar functions `sin θ`, `cos 30°`; the unit alone,
//! `ans / deg`; pasted numpy and MATLAB rows `[0 -1 0; 1 0 0]`,
//! `[[ 0. -1.] [ 1.  0.]]`; and the type spellings chasles prints,
//! `given T_sa : SE(3)`. `fast` builds the same trees by hand.

use pest::iterators::Pair;

use super::ast::{Expr, ExprKind, Ident, Name, Span, UnOp};
use super::grammar::Rule;
use super::parser::Cx;
use crate::diagnostics::Diagnostic;

type Built = Result<(Expr, usize), Diagnostic>;

impl Cx {
    /// `SE(3)` → the name `SE3`, `3-vector` → `vec3`, spanning what was
    /// written.
    pub(super) fn given_type(&self, pair: &Pair<'_, Rule>) -> Ident {
        let text = pair.as_str();
        let name = match text.strip_suffix("-vector") {
            Some(n) => format!("vec{n}"),
            None => text.replace(['(', ')'], ""),
        };
        Ident {
            name: Name::new(&name),
            span: self.span(pair.as_span()),
        }
    }

    /// `deg` alone: one degree in radians, `Degrees(1)`.
    pub(super) fn deg_unit(&self, span: Span) -> (Expr, usize) {
        let one = Expr {
            kind: ExprKind::Number(1.0),
            span,
        };
        let kind = ExprKind::Degrees(Box::new(one));
        (Expr { kind, span }, 2)
    }

    /// `sin θ`, `cos 30°`: a call of the function on the atom after it.
    pub(super) fn bare_call(&self, pair: Pair<'_, Rule>) -> Built {
        let span = self.span(pair.as_span());
        let mut it = pair.into_inner();
        let (Some(func), Some(arg)) = (it.next(), it.next()) else {
            return Err(self.internal(span));
        };
        let func = Ident {
            name: func.as_str().into(),
            span: self.span(func.as_span()),
        };
        let mut parts = arg.into_inner();
        let atom = parts.next().ok_or_else(|| self.internal(span))?;
        let (mut e, mut d) = self.primary(atom)?;
        for deg in parts {
            let at = self.span(deg.as_span());
            let span = e.span.join(at);
            e = Expr {
                kind: ExprKind::Degrees(Box::new(e)),
                span,
            };
            d += 1;
        }
        let kind = ExprKind::Call {
            func,
            args: vec![e],
        };
        Ok((Expr { kind, span }, d + 1))
    }

    /// A `plain_row`: one row of numbers, or one row per `plain_list`.
    pub(super) fn plain_rows(&self, pair: Pair<'_, Rule>) -> Result<Vec<Vec<Expr>>, Diagnostic> {
        let mut rows = Vec::new();
        let mut numbers = Vec::new();
        for item in pair.into_inner() {
            match item.as_rule() {
                Rule::plain_number => numbers.push(self.plain_number(&item)?),
                Rule::plain_list => rows.push(
                    item.into_inner()
                        .map(|n| self.plain_number(&n))
                        .collect::<Result<_, _>>()?,
                ),
                _ => return Err(self.unexpected(&item)),
            }
        }
        if !numbers.is_empty() {
            rows.push(numbers);
        }
        Ok(rows)
    }

    /// `-1.`, `0.5`, `+2`: a number with its sign.
    fn plain_number(&self, pair: &Pair<'_, Rule>) -> Result<Expr, Diagnostic> {
        let span = self.span(pair.as_span());
        let text = pair.as_str();
        let (op, digits) = if let Some(rest) = text.strip_prefix('+') {
            (Some(UnOp::Pos), rest)
        } else if let Some(rest) = text.strip_prefix(['-', '−']) {
            (Some(UnOp::Neg), rest)
        } else {
            (None, text)
        };
        let value = digits.parse::<f64>().map_err(|_| self.internal(span))?;
        let start = span.end - digits.len();
        let number = Expr {
            kind: ExprKind::Number(value),
            span: Span::new(start, span.end),
        };
        Ok(match op {
            None => number,
            Some(op) => Expr {
                kind: ExprKind::Unary {
                    op,
                    operand: Box::new(number),
                },
                span,
            },
        })
    }
}
