//! The kinds of a product's factors checked again once some have become
//! numbers (LANGUAGE.md §7: as if the numbers had been typed first): a
//! product over given names whose sizes the checker could not know
//! (`eye(k) T_ab` over a given k, an "n×4 matrix") is refused where the
//! numbers bound since make it one the product's rule refuses.

use super::Bindings;
use crate::check::ty::Ty;
use crate::seam::apply::{Hints, Op};
use crate::syntax::ast::BinOp;
use crate::syntax::name::Name;
use crate::values::value::{Sym, Value};

/// Why `a b` is refused, as typed first, when one factor has become
/// numbers and the other is a given name (whose kind is declared): the
/// product's rule on their kinds (`[3×3 numbers] T_ab`, made as `eye(k)
/// T_ab` over a given k, is "cannot multiply an SO(3) by an SE(3)" at
/// k = 3). None when the rule takes them, or a factor is neither.
pub(super) fn unmultiplied(env: &dyn Bindings, a: &Sym, b: &Sym) -> Option<String> {
    let numbers = |s: &Sym| match s {
        Sym::Const(v, _) if matches!(**v, Value::Num { .. }) => Some(v.kind()),
        _ => None,
    };
    let kind = |s: &Sym| match s {
        Sym::Name(n) => env.binding(Name::new(n)).map(|b| b.kind),
        s => numbers(s),
    };
    numbers(a).or_else(|| numbers(b))?;
    let tys = [Ty::plain(kind(a)?), Ty::plain(kind(b)?)];
    Op::Arith(BinOp::Mul)
        .rule(&tys, Hints::default())
        .err()
        .map(|e| e.into_message())
}
