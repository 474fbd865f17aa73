//! A spacing check the grammar cannot express: inside `[ ]`, MATLAB reads
//! `[1 -2]` as two entries, and chasles (which separates entries with `,`,
//! LANGUAGE.md §4) as the difference 1 − 2. The two readings differ
//! silently, so an element whose `+`/`-` has space before it and none after
//! (`1 -2`, `x +y`) is a syntax error that names both fixes. `1 - 2`,
//! `1-2` and `1, -2` are all fine.

use super::ast::{BinOp, Expr, ExprKind, IndexArg, Span, Stmt, StmtKind};
use crate::diagnostics::{Diagnostic, ErrorKind};

/// The first ambiguous `a -b` inside brackets in `stmt`, as an error.
/// `src` is the whole source the statement's spans point into.
pub fn check(stmt: &Stmt, src: &str) -> Result<(), Diagnostic> {
    match &stmt.kind {
        StmtKind::Expr(e) => expr(e, src, false),
        StmtKind::Assign { value, .. } | StmtKind::Destructure { value, .. } => {
            expr(value, src, false)
        }
        StmtKind::FnDef { body, .. } => expr(body, src, false),
        StmtKind::Given { .. } | StmtKind::Derive { .. } => Ok(()),
    }
}

/// Walks `e`; `in_row` is true for an element of a bracket row, where the
/// chain of `+`/`-` at its top is what MATLAB would split.
fn expr(e: &Expr, src: &str, in_row: bool) -> Result<(), Diagnostic> {
    match &e.kind {
        ExprKind::Number(_)
        | ExprKind::Bool(_)
        | ExprKind::Var(_)
        | ExprKind::Str(_)
        | ExprKind::Mech(_) => Ok(()),
        ExprKind::Binary {
            op,
            lhs,
            rhs,
            op_span,
            implicit,
        } => {
            let sum = matches!(op, BinOp::Add | BinOp::Sub) && !implicit;
            // Only the top chain of sums is split by MATLAB: `[2*(1 -2)]`
            // and `[x * -1]` are not ambiguous. The leftmost `a -b` of a
            // chain is reported first.
            expr(lhs, src, in_row && sum)?;
            if in_row && sum && looks_like_a_sign(src, *op_span) {
                return Err(ambiguous(src, lhs, *op_span, rhs));
            }
            expr(rhs, src, false)
        }
        ExprKind::Unary { operand, .. } => expr(operand, src, false),
        ExprKind::Degrees(inner) => expr(inner, src, false),
        ExprKind::Call { args, .. } | ExprKind::Paren(args) => {
            args.iter().try_for_each(|a| expr(a, src, false))
        }
        ExprKind::Member { base, .. } => expr(base, src, false),
        ExprKind::Index { base, args } => {
            expr(base, src, false)?;
            args.iter().try_for_each(|a| match a {
                IndexArg::Expr(x) => expr(x, src, false),
                IndexArg::All(_) => Ok(()),
            })
        }
        ExprKind::Brackets(rows) => rows.iter().flatten().try_for_each(|x| expr(x, src, true)),
        ExprKind::Range { start, step, end } => {
            expr(start, src, false)?;
            step.iter().try_for_each(|s| expr(s, src, false))?;
            expr(end, src, false)
        }
        ExprKind::Comprehension { body, vars } => {
            expr(body, src, false)?;
            vars.iter().try_for_each(|(_, r)| expr(r, src, false))
        }
    }
}

/// Space (or a tab) just before the operator and none just after: `1 -2`.
fn looks_like_a_sign(src: &str, op: Span) -> bool {
    let before = src[..op.start].chars().next_back();
    let after = src[op.end..].chars().next();
    matches!(before, Some(c) if c == ' ' || c == '\t')
        && matches!(after, Some(c) if !c.is_whitespace())
}

fn ambiguous(src: &str, lhs: &Expr, op: Span, rhs: &Expr) -> Diagnostic {
    let (a, sign, b) = (
        src[lhs.span.start..lhs.span.end].trim(),
        &src[op.start..op.end],
        src[rhs.span.start..rhs.span.end].trim(),
    );
    Diagnostic::error(
        ErrorKind::Syntax,
        op,
        format!("`{a} {sign}{b}` inside brackets is ambiguous (MATLAB reads two entries)"),
    )
    .with_help(format!(
        "write `{a}, {sign}{b}` for two entries or `{a} {sign} {b}` for the {}",
        if sign == "-" { "difference" } else { "sum" }
    ))
}
