//! The operation seam (issue 14), below the interpreter: every operation
//! of the language as one [`apply::Op`], with its type-and-frame rule
//! (LANGUAGE.md §6), its numeric function, its exact form over symbolic
//! scalars (chapter 3 with symbols) and its form over `given` symbols
//! (§7); how a value was made, recorded for replaying it with numbers
//! ([`crate::values::recipe`]) and, for `diff` of a scalar, the chain
//! rule's steps (§3.2.2); the exactness of each result; the shapes of
//! indexing and block matrices; ranges `a:h:b`. The interpreter
//! ([`crate::eval`]) and the proofs of `==` ([`crate::decide`]) both
//! apply operations through it; it imports neither.

pub mod apply;
mod call;
mod chain;
pub(crate) use chain::of_kept;
pub(crate) mod exactness;
mod exponential;
pub(crate) mod operation;
mod powers;
pub(crate) mod range;
pub(crate) mod shapes;
pub mod transform;
