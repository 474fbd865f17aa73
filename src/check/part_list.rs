//! The name of a tuple's list of part types ([`super::ty::Ty::parts`]):
//! a number into the process's interned table ([`super::parts`]), so that
//! [`super::ty::Ty`] stays `Copy` and small (it moves through every node
//! of every statement: a slice reference in it cost the 100k-statement
//! script ~80 instructions a statement, issue 40). Apart from the table,
//! which holds types, so that the type can name it without a cycle.

/// A tuple's part types, by their number in the interned table
/// ([`Parts::get`] reads them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Parts(pub(super) std::num::NonZeroU32);
