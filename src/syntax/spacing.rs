//! The readings the grammar cannot tell apart, refused once the tree is
//! built (both parsers' trees go through here), each with an error that
//! shows both readings (LANGUAGE.md §4):
//!
//! - inside `[ ]`, MATLAB reads `[1 -x]` and `[2 pi]` as two entries, and
//!   chasles as 1 − x and 2π: an element whose `+`/`-` has space before it
//!   and none after, and a one-element row with a product written with a
//!   space, are errors. Plain numbers (`[1 -2]`, `[0 -1 0]`) are read as
//!   printed by the grammar and never reach this check;
//! - `2 3`: two numbers side by side;
//! - `R [1, 2]`: an index or a product? (`R[1, 2]` indexes; `sin(θ) [w]`
//!   multiplies by the book's bracket);
//! - the parenthesis-free `sin θ^2`, `sin 2θ` and `sin θ/2`;
//! - numbered two-frame names that do not split, `T_123` (§2).

use super::ast::{BinOp, Expr, ExprKind, Ident, IndexArg, Span, Stmt, StmtKind};
use super::ident::name_error;
use crate::diagnostics::{Diagnostic, ErrorKind};

type Checked = Result<(), Diagnostic>;

/// The first unclear reading in `stmt`, as an error. `src` is the whole
/// source the statement's spans point into.
pub fn check(stmt: &Stmt, src: &str) -> Checked {
    let c = Check { src };
    match &stmt.kind {
        StmtKind::Expr(e) => c.expr(e),
        StmtKind::Assign { target, value } => {
            c.name(target)?;
            c.expr(value)
        }
        StmtKind::Destructure { targets, value } => {
            targets.iter().try_for_each(|t| c.name(t))?;
            c.expr(value)
        }
        StmtKind::FnDef { params, body, .. } => {
            params.iter().try_for_each(|t| c.name(t))?;
            c.expr(body)
        }
        StmtKind::Given { names, .. } => names.iter().try_for_each(|t| c.name(t)),
        StmtKind::Derive { target } => c.name(target),
        StmtKind::Assert(cond) | StmtKind::Explain(cond) => c.expr(cond),
    }
}

struct Check<'a> {
    src: &'a str,
}

impl Check<'_> {
    fn text(&self, s: Span) -> &str {
        self.src.get(s.start..s.end).unwrap_or("").trim()
    }

    fn name(&self, id: &Ident) -> Checked {
        self.name_at(&id.name, id.span)
    }

    fn name_at(&self, name: &str, span: Span) -> Checked {
        match name_error(name) {
            None => Ok(()),
            Some(message) => {
                let (base, sub) = name.rsplit_once('_').unwrap_or((name, ""));
                let splits: Vec<String> = sub
                    .char_indices()
                    .skip(1)
                    .map(|(i, _)| format!("{base}_{{{},{}}}", &sub[..i], &sub[i..]))
                    .collect();
                Err(
                    Diagnostic::error(ErrorKind::Syntax, span, message).with_help(format!(
                        "name the two frames with braces: {}",
                        splits.join(" or ")
                    )),
                )
            }
        }
    }

    /// Walks `e` outside any bracket row.
    fn expr(&self, e: &Expr) -> Checked {
        match &e.kind {
            ExprKind::Number(_) | ExprKind::Bool(_) | ExprKind::Mech(_) => Ok(()),
            ExprKind::Var(name) => self.name_at(name, e.span),
            ExprKind::Binary { lhs, rhs, .. } => {
                self.expr(lhs)?;
                self.node(e)?;
                self.expr(rhs)
            }
            ExprKind::Unary { operand: x, .. }
            | ExprKind::Degrees(x)
            | ExprKind::Member { base: x, .. } => self.expr(x),
            ExprKind::Compare { lhs, rhs, .. } => {
                self.expr(lhs)?;
                self.expr(rhs)
            }
            ExprKind::Call { args, .. } | ExprKind::Paren(args) => {
                args.iter().try_for_each(|a| self.expr(a))
            }
            ExprKind::Index { base, args } => {
                self.expr(base)?;
                args.iter().try_for_each(|a| match a {
                    IndexArg::Expr(x) => self.expr(x),
                    IndexArg::All(_) => Ok(()),
                })
            }
            ExprKind::Brackets(rows) => rows.iter().try_for_each(|row| {
                let single = row.len() == 1;
                row.iter().try_for_each(|x| self.row(x, single))
            }),
            ExprKind::Str(_) => Ok(()),
            ExprKind::Range { start, step, end } => {
                self.expr(start)?;
                step.iter().try_for_each(|h| self.expr(h))?;
                self.expr(end)
            }
            ExprKind::Comprehension { body, vars } => {
                self.expr(body)?;
                vars.iter().try_for_each(|(n, over)| {
                    self.name(n)?;
                    self.expr(over)
                })
            }
        }
    }

    /// Walks an element of a bracket row: the chain at its top is what
    /// MATLAB splits at spaces (sums in any row; in a one-element row also
    /// products written with a space).
    fn row(&self, e: &Expr, single: bool) -> Checked {
        let ExprKind::Binary {
            op,
            lhs,
            rhs,
            op_span,
            implicit,
        } = &e.kind
        else {
            return self.expr(e);
        };
        let sum = matches!(op, BinOp::Add | BinOp::Sub) && !implicit;
        if self.grouped(e) || *op == BinOp::Pow || !(sum || single) {
            return self.expr(e);
        }
        // The leftmost unclear pair is reported first.
        self.row(lhs, single)?;
        if sum && self.looks_like_a_sign(*op_span) {
            return Err(self.ambiguous_sign(lhs, *op_span, rhs));
        }
        if *implicit && single && rhs.span.start > lhs.span.end {
            return Err(self.ambiguous_product(lhs, rhs));
        }
        self.node(e)?;
        self.row(rhs, single)
    }

    /// A parenthesized group: its span reaches beyond its operands.
    fn grouped(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Binary { lhs, .. } => e.span.start < lhs.span.start,
            ExprKind::Unary { .. } => self.src[e.span.start..].starts_with('('),
            _ => false,
        }
    }

    /// The operand a binary chain ends with (`x` in `2 * x`).
    fn last_operand<'e>(&self, e: &'e Expr) -> &'e Expr {
        match &e.kind {
            ExprKind::Binary { rhs, .. } if !self.grouped(e) => self.last_operand(rhs),
            ExprKind::Unary { operand, .. } if !self.grouped(e) => self.last_operand(operand),
            _ => e,
        }
    }

    /// The operand a binary chain starts with (`3` in `3^2`).
    fn first_operand<'e>(&self, e: &'e Expr) -> &'e Expr {
        match &e.kind {
            ExprKind::Binary { lhs, .. } if !self.grouped(e) => self.first_operand(lhs),
            _ => e,
        }
    }

    /// `sin θ`, written without parentheses.
    fn bare_call<'e>(&self, e: &'e Expr) -> Option<&'e Expr> {
        match &e.kind {
            // `√2` binds to its atom alone: `√3/2`, `√2 x` read one way.
            ExprKind::Call { args, .. }
                if args.len() == 1
                    && !self.text(e.span).ends_with(')')
                    && !self.text(e.span).starts_with('√') =>
            {
                Some(&args[0])
            }
            _ => None,
        }
    }

    /// The checks of one binary node.
    fn node(&self, e: &Expr) -> Checked {
        let ExprKind::Binary {
            op,
            lhs,
            rhs,
            op_span,
            implicit,
        } = &e.kind
        else {
            return Ok(());
        };
        // Only juxtaposition, `^` and `/` can read two ways; a sum or a
        // written `*` is clear.
        if !(*implicit || matches!(op, BinOp::Pow | BinOp::Div)) {
            return Ok(());
        }
        let last = self.last_operand(lhs);
        let bare = self.bare_call(last);
        if !*implicit && bare.is_none() {
            return Ok(());
        }
        let first = self.first_operand(rhs);
        // A juxtaposition reads two ways only after a number, after `sin 2`
        // or before a bracket.
        if *implicit
            && !(matches!(last.kind, ExprKind::Number(_) | ExprKind::Degrees(_))
                || bare.is_some_and(|a| matches!(a.kind, ExprKind::Number(_)))
                || matches!(first.kind, ExprKind::Brackets(_)))
        {
            return Ok(());
        }
        let (l, r) = (self.text(last.span), self.text(first.span));
        match op {
            BinOp::Mul if *implicit => {
                if matches!(last.kind, ExprKind::Number(_) | ExprKind::Degrees(_))
                    && r.starts_with(|c: char| c.is_ascii_digit() || c == '.')
                {
                    return Err(Diagnostic::error(
                        ErrorKind::Syntax,
                        first.span,
                        format!("missing operator between `{l}` and `{r}`"),
                    )
                    .with_help("separate elements with `,` ([1, 2, 3]) or multiply with `*`"));
                }
                if let Some(arg) = bare
                    && matches!(arg.kind, ExprKind::Number(_))
                {
                    let (name, a) = split_bare(l);
                    let both = self.text(Span::new(arg.span.start, first.span.end));
                    let what = self.text(Span::new(last.span.start, first.span.end));
                    return Err(two_readings(
                        first.span,
                        what,
                        &format!("{name}({both})"),
                        &format!("({name} {a}) {r} for the product"),
                    ));
                }
                if let ExprKind::Brackets(rows) = &first.kind
                    && matches!(
                        last.kind,
                        ExprKind::Var(_)
                            | ExprKind::Call { .. }
                            | ExprKind::Index { .. }
                            | ExprKind::Member { .. }
                    )
                    && first.span.start > last.span.end
                    && index_like(rows)
                {
                    return Err(two_readings(
                        first.span,
                        &format!("{l} {r}"),
                        &format!("{l}{r} to index"),
                        &format!("{l} * {r} to multiply"),
                    ));
                }
                Ok(())
            }
            BinOp::Pow if bare.is_some() && self.last_operand(lhs).span == lhs.span => {
                // `^2`, or a superscript `²`.
                let p = match self.text(*op_span) {
                    "^" => format!("^{}", self.text(rhs.span)),
                    sup => sup.to_string(),
                };
                let (name, a) = split_bare(l);
                Err(two_readings(
                    *op_span,
                    &format!("{l}{p}"),
                    &format!("({l}){p}"),
                    &format!("{name}({a}{p})"),
                ))
            }
            BinOp::Div
                if bare.is_some() && !self.src[..op_span.start].ends_with(char::is_whitespace) =>
            {
                let d = self.text(rhs.span);
                let (name, a) = split_bare(l);
                Err(two_readings(
                    *op_span,
                    &format!("{l}/{d}"),
                    &format!("{name}({a}/{d})"),
                    &format!("({l})/{d}"),
                ))
            }
            _ => Ok(()),
        }
    }

    /// Space (or a tab) just before the operator and none just after: `1 -2`.
    fn looks_like_a_sign(&self, op: Span) -> bool {
        let before = self.src[..op.start].chars().next_back();
        let after = self.src[op.end..].chars().next();
        matches!(before, Some(c) if c == ' ' || c == '\t')
            && matches!(after, Some(c) if !c.is_whitespace())
    }

    fn ambiguous_sign(&self, lhs: &Expr, op: Span, rhs: &Expr) -> Diagnostic {
        let (a, sign, b) = (
            self.text(lhs.span),
            &self.src[op.start..op.end],
            self.text(rhs.span),
        );
        Diagnostic::error(
            ErrorKind::Syntax,
            op,
            format!("`{a} {sign}{b}` inside brackets is ambiguous (MATLAB reads two entries)"),
        )
        .with_help(format!(
            "write `{a}, {sign}{b}` for two entries or `{a} {sign} {b}` for the {}",
            if sign == "+" { "sum" } else { "difference" }
        ))
    }

    fn ambiguous_product(&self, lhs: &Expr, rhs: &Expr) -> Diagnostic {
        let (a, b) = (self.text(lhs.span), self.text(rhs.span));
        Diagnostic::error(
            ErrorKind::Syntax,
            Span::new(lhs.span.end, rhs.span.start),
            format!("`{a} {b}` inside brackets is ambiguous (MATLAB reads two entries)"),
        )
        .with_help(format!(
            "write `{a}, {b}` for two entries or `{a} * {b}` for the product"
        ))
    }
}

/// `sin θ` → ("sin", "θ").
fn split_bare(text: &str) -> (&str, &str) {
    match text.split_once(char::is_whitespace) {
        Some((f, a)) => (f, a.trim()),
        None => (text, ""),
    }
}

/// Brackets that could be an index (one or two subscripts: `[1, 2]`,
/// `[2]`), not the book's bracket of one vector (`[w]`) nor a vector of
/// three or more entries (`[1, 0, 0]`, only a product).
fn index_like(rows: &[Vec<Expr>]) -> bool {
    match rows {
        [row] if row.len() == 1 => matches!(row[0].kind, ExprKind::Number(_)),
        [row] => row.len() == 2,
        _ => false,
    }
}

fn two_readings(at: Span, what: &str, one: &str, other: &str) -> Diagnostic {
    Diagnostic::error(ErrorKind::Syntax, at, format!("`{what}` reads two ways"))
        .with_help(format!("write {one}, or {other}"))
}
