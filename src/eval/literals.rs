//! Numbers known from the text without evaluating it: a literal index
//! (`2`, `end + 1`, [`literal_index`]), and names bound to a number
//! written with literals (`k = 3`), known to the
//! checker without numbers, so that `chasles check` sizes `eye(k)` (the
//! 3×3 identity, in SO(3) as its numbers are) and counts `0:k` as it does
//! `eye(3)` and `0:3`: `k = 3; eye(k) * T_ab` is refused by `check` as by
//! `run`. A name bound anew (again, as a parameter, by a comprehension)
//! is no longer known: each note holds the stamp of the binding it was
//! made for ([`super::env::Binding::stamp`]).

use super::env::Env;
use super::interp::Interp;
use super::key::AsKey;
use crate::syntax::ast::{Expr, ExprKind};
use crate::syntax::name::Name;

impl Env {
    /// The number `name`'s binding was written as, when it was a literal
    /// (and the binding is still that one).
    fn literal_of(&self, name: Name) -> Option<f64> {
        let (stamp, x) = self.literals.get(&name.key())?;
        (self.get(name)?.stamp == *stamp).then_some(*x)
    }
}

impl Interp<'_> {
    /// The number `e` writes with literals and names bound so
    /// ([`literal_index`]: `2`, `-1`, `k + 1` with
    /// `k = 3`), known without evaluating it; None for anything else.
    pub(super) fn known_number(&self, e: &Expr) -> Option<f64> {
        folded_literal(e, &|n| self.env.literal_of(n))
    }

    /// Notes that `name` was just bound to `value`, if that is a number
    /// written with literals ([`Interp::known_number`]). (A note of an
    /// earlier binding of it is stale by its stamp.)
    ///
    /// Only checking reads the notes (running has the numbers), so a run
    /// makes none: no work on the statement loop's hot path (issue 40).
    #[inline]
    pub(super) fn note_literal(&mut self, name: Name, value: &Expr) {
        if self.running() {
            return;
        }
        if let Some(x) = self.known_number(value)
            && let Some(stamp) = self.env.get(name).map(|b| b.stamp)
        {
            self.env.literals.insert(name.key(), (stamp, x));
        }
    }
}

/// The number an index written as a literal stands for (`2`, `1.5`, `-1`,
/// `end + 1` once `end` is a number), known without evaluating it: numbers
/// and their sums, differences and products; None for anything else.
pub(super) fn literal_index(e: &Expr) -> Option<f64> {
    folded_literal(e, &|_| None)
}

/// [`literal_index`] where a name may stand for a number too (`name`:
/// `k + 1` after `k = 3`).
pub(super) fn folded_literal(
    e: &Expr,
    name: &dyn Fn(crate::syntax::name::Name) -> Option<f64>,
) -> Option<f64> {
    use crate::syntax::ast::BinOp;
    match &e.kind {
        ExprKind::Number(x) => Some(*x),
        ExprKind::Var(n) => name(*n),
        ExprKind::Binary { op, lhs, rhs, .. } => {
            let (a, b) = (folded_literal(lhs, name)?, folded_literal(rhs, name)?);
            match op {
                BinOp::Add => Some(a + b),
                BinOp::Sub => Some(a - b),
                BinOp::Mul => Some(a * b),
                BinOp::Div | BinOp::Pow => None,
            }
        }
        ExprKind::Unary {
            op: crate::syntax::ast::UnOp::Neg,
            operand,
        } => folded_literal(operand, name).map(|x| -x),
        ExprKind::Paren(items) if items.len() == 1 => folded_literal(&items[0], name),
        _ => None,
    }
}
