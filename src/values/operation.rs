//! The operations of the evaluator's seam (`seam::apply::Op`: every
//! operator and builtin call, "children, then apply") with their data
//! owned, so that a value can keep how it was made: an exact number's
//! form still to be worked out ([`super::exact::Pending`], LANGUAGE.md §3)
//! and a symbolic value's recipe, replayed once its symbols have numbers
//! ([`super::recipe::Step::Op`], §7). One list, so that the two records
//! and the seam cannot drift apart; `seam::apply` turns an `Op` into an
//! [`Operation`] and back.

use super::ops::Sel;
use super::symbolic::Part;
use crate::syntax::ast::BinOp;

/// An operation of the evaluator's seam with its data owned (`Op`
/// borrows its selectors, widths and the name a builtin was called by).
#[derive(Debug, Clone)]
pub enum Operation {
    /// `-x`.
    Neg,
    /// `x deg`, `x°`: an angle in degrees, as radians.
    Degrees,
    /// `a + b`, `a - b`, `a b`, `a / b`, `a ^ b`.
    Arith(BinOp),
    /// `X^-1` of symbols that become numbers (`inv`, `^-1`).
    Inverse,
    /// `x.T`, the transpose.
    Transpose,
    /// `T.R`, `T.p`, `V.w`, `V.v`, `F.m`, `F.f`: a part of a value.
    Member(Part),
    /// `x[i]`, `M[i, j]`, `M[:, j]` (1-based).
    Index(Box<[Sel]>),
    /// `[x]` (the bracket of 3.30, 3.70) and `[a, b; c, d]`: the number of
    /// entries of each row.
    Block(Box<[usize]>),
    /// `(a, b, c)`: a column vector of scalars.
    Vector,
    /// A builtin, by the name it was called with (`Ad` or `Adjoint`).
    Call(&'static str),
}
