//! Rewrites of a parsed statement into the tree the rest of the crate reads
//! (LANGUAGE.md §4), shared by both parsers:
//!
//! - the exponent `T` always transposes: `R^T`, `R^{T}` become `R.T`, even
//!   when a name `T` is bound, and `R^T (p)` (eq. 3.64's `-R^T p`) is
//!   `R.T (p)`, a product, not `R^(T(p))`;
//! - nested brackets as numpy writes them, `[[0, -1, 0], [1, 0, 0]]`, are
//!   rows: a bracket whose every element is a bracketed row of two or more
//!   entries (and which has two or more of them) is the matrix of those
//!   rows. `[[w], p; 0, 1]` (the book's `[ω]`) and a lone `[[1, 2, 3]]`
//!   (the bracket of a vector) are not rewritten.

use super::ast::{Expr, ExprKind, Ident, IndexArg, Stmt, StmtKind};

/// Applies the rewrites to every expression of `stmt`.
pub fn stmt(stmt: &mut Stmt) {
    match &mut stmt.kind {
        StmtKind::Expr(e) => expr(e),
        StmtKind::Assign { value, .. } | StmtKind::Destructure { value, .. } => expr(value),
        StmtKind::FnDef { body, .. } | StmtKind::Assert(body) | StmtKind::Explain(body) => {
            expr(body)
        }
        StmtKind::Given { .. } | StmtKind::Derive { .. } => {}
    }
}

fn expr(e: &mut Expr) {
    match &mut e.kind {
        ExprKind::Number(_) | ExprKind::Bool(_) | ExprKind::Var(_) | ExprKind::Mech(_) => {}
        ExprKind::Binary { lhs, rhs, .. } | ExprKind::Compare { lhs, rhs, .. } => {
            expr(lhs);
            expr(rhs);
        }
        ExprKind::Unary { operand: x, .. }
        | ExprKind::Degrees(x)
        | ExprKind::Member { base: x, .. } => expr(x),
        ExprKind::Call { args, .. } | ExprKind::Paren(args) => args.iter_mut().for_each(expr),
        ExprKind::Index { base, args } => {
            expr(base);
            for a in args {
                if let IndexArg::Expr(x) = a {
                    expr(x);
                }
            }
        }
        ExprKind::Brackets(rows) => {
            rows.iter_mut().flatten().for_each(expr);
            if let Some(flat) = numpy_rows(rows) {
                *rows = flat;
            }
        }
        ExprKind::Str(_) => {}
        ExprKind::Range { start, step, end } => {
            expr(start);
            step.iter_mut().for_each(|h| expr(h));
            expr(end);
        }
        ExprKind::Comprehension { body, vars } => {
            expr(body);
            vars.iter_mut().for_each(|(_, over)| expr(over));
        }
    }
    transpose(e);
}

/// `X^T` → `X.T`; `X^T (p)` → `X.T (p)`.
fn transpose(e: &mut Expr) {
    let ExprKind::Binary {
        op: super::ast::BinOp::Pow,
        rhs,
        implicit: false,
        ..
    } = &e.kind
    else {
        return;
    };
    if let ExprKind::Call { func, .. } = &rhs.kind
        && func.name == "T"
        && func.span.start == rhs.span.start
    {
        transpose_times(e);
        return;
    }
    if !matches!(&rhs.kind, ExprKind::Var(t) if t == "T") {
        return;
    }
    let member = Ident {
        name: "T".into(),
        span: rhs.span,
    };
    let kind = std::mem::replace(&mut e.kind, ExprKind::Bool(false));
    if let ExprKind::Binary { lhs, .. } = kind {
        e.kind = ExprKind::Member { base: lhs, member };
    }
}

/// The rows of `[[a, b], [c, d]]`, if every element is a one-row bracket
/// of two or more entries and there are at least two of them.
fn numpy_rows(rows: &[Vec<Expr>]) -> Option<Vec<Vec<Expr>>> {
    let n = rows.iter().map(Vec::len).sum::<usize>();
    // Checked before anything is allocated: most brackets are not rows.
    if n < 2 || !rows.iter().flatten().all(|el| row_of(el).is_some()) {
        return None;
    }
    Some(rows.iter().flatten().filter_map(row_of).cloned().collect())
}

/// The one row of a bracket `[a, b, …]` of two or more entries.
fn row_of(el: &Expr) -> Option<&Vec<Expr>> {
    match &el.kind {
        ExprKind::Brackets(inner) if inner.len() == 1 && inner[0].len() >= 2 => Some(&inner[0]),
        _ => None,
    }
}

/// `X^T (p)`, read as `X^(T(p))` by the grammar → `X.T (p)`: the `T` of
/// an exponent is never a function.
fn transpose_times(e: &mut Expr) {
    let kind = std::mem::replace(&mut e.kind, ExprKind::Bool(false));
    let ExprKind::Binary { lhs, rhs, .. } = kind else {
        e.kind = kind;
        return;
    };
    let Expr {
        kind: rhs_kind,
        span: rhs_span,
    } = *rhs;
    let ExprKind::Call { func, mut args } = rhs_kind else {
        return;
    };
    let base_span = lhs.span.join(func.span);
    let base = Expr {
        kind: ExprKind::Member {
            base: lhs,
            member: func.clone(),
        },
        span: base_span,
    };
    // The parenthesis after `T`: one argument is itself, several a vector.
    let paren_span = super::ast::Span::new(func.span.end, rhs_span.end);
    let arg = if args.len() == 1 {
        let mut a = args.remove(0);
        a.span = paren_span;
        a
    } else {
        Expr {
            kind: ExprKind::Paren(args),
            span: paren_span,
        }
    };
    let op_span = super::ast::Span::new(func.span.end, func.span.end);
    e.kind = ExprKind::Binary {
        op: super::ast::BinOp::Mul,
        lhs: Box::new(base),
        rhs: Box::new(arg),
        op_span,
        implicit: true,
    };
}
