//! An [`Op`] of the seam kept by a value, and got back: a value records
//! the operation that made it as a [`values::operation::Operation`] (its
//! data owned; `values` cannot name the builtins' table) — an exact
//! number's form still to be worked out (LANGUAGE.md §3) or a step of a
//! symbolic value's recipe (§7) — and the evaluator turns it back into the
//! `Op` it was, to run it through the same seam.
//!
//! [`values::operation::Operation`]: crate::values::operation::Operation

use super::apply::Op;
use crate::values::operation::Operation;

impl<'a> Op<'a> {
    /// This operation with its data owned; a builtin keeps the name it was
    /// called by (`Ad` or `Adjoint`).
    pub fn owned(self) -> Operation {
        match self {
            Op::Neg => Operation::Neg,
            Op::Degrees => Operation::Degrees,
            Op::Arith(o) => Operation::Arith(o),
            Op::Inverse => Operation::Inverse,
            Op::Transpose => Operation::Transpose,
            Op::Member(part) => Operation::Member(part),
            Op::Index(sels) => Operation::Index(sels.into()),
            Op::Block(widths) => Operation::Block(widths.into()),
            Op::Vector => Operation::Vector,
            // (most calls name the builtin by the table's own text of the
            // name, `Env::builtin`: found by its address, no text compared)
            Op::Call(b, name) => Operation::Call(
                b.names()
                    .find(|n| std::ptr::eq(*n, name))
                    .or_else(|| b.names().find(|n| *n == name))
                    .unwrap_or(b.name),
            ),
        }
    }

    /// The operation `o` keeps, as the seam's `Op` (None: a builtin no
    /// longer in the table).
    pub fn of(o: &'a Operation) -> Option<Op<'a>> {
        Some(match o {
            Operation::Neg => Op::Neg,
            Operation::Degrees => Op::Degrees,
            Operation::Arith(op) => Op::Arith(*op),
            Operation::Inverse => Op::Inverse,
            Operation::Transpose => Op::Transpose,
            Operation::Member(part) => Op::Member(*part),
            Operation::Index(sels) => Op::Index(sels),
            Operation::Block(widths) => Op::Block(widths),
            Operation::Vector => Op::Vector,
            Operation::Call(name) => Op::Call(crate::builtins::lookup(name)?, name),
        })
    }
}
