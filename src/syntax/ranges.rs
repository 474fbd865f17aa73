//! Ranges and strings (LANGUAGE.md §12) as trees: `a:b` and `a:s:b` from
//! the loosest infix operator `range_op`, and the text of `"name.svg"`.

use super::ast::{Expr, ExprKind, Span};
use crate::diagnostics::{Diagnostic, ErrorKind};

/// `l:r`, or `a:s:b` when `l` is the unparenthesized range `a:s`.
pub(super) fn range(l: Expr, r: Expr, op_span: Span) -> Result<Expr, Diagnostic> {
    let span = l.span.join(r.span);
    // `(0:2):4` keeps its parentheses: its left side is then not a range.
    let bare = |start: &Expr| start.span.start == l.span.start;
    let kind = match l.kind {
        ExprKind::Range {
            ref start,
            step: Some(_),
            ..
        } if bare(start) => {
            return Err(Diagnostic::error(
                ErrorKind::Syntax,
                op_span,
                "a range has at most two colons: start:end or start:step:end",
            )
            .with_help("write 0:4 or 0:pi/8:pi"));
        }
        ExprKind::Range {
            start,
            step: None,
            end,
        } if start.span.start == span.start => ExprKind::Range {
            start,
            step: Some(end),
            end: Box::new(r),
        },
        _ => ExprKind::Range {
            start: Box::new(l),
            step: None,
            end: Box::new(r),
        },
    };
    Ok(Expr { kind, span })
}

/// The text of a string literal, without its quotes.
pub(super) fn string(quoted: &str) -> String {
    let inner = quoted.strip_prefix('"').unwrap_or(quoted);
    inner.strip_suffix('"').unwrap_or(inner).to_string()
}
