//! Evaluation: values, the session environment, and the interpreter that
//! walks each statement once, checking kinds and frames by
//! [`crate::check`]'s rules and computing values through [`crate::lie`].

mod binding;
mod call;
mod compare;
mod compound;
mod derive;
pub mod env;
pub mod explain;
mod expr;
mod given_equal;
pub mod graph;
mod hold;
pub mod interp;
mod key;
pub mod list;
mod literals;
mod lower;
mod naming;
mod notation;
pub mod outcome;
mod paren_product;
mod relied;
mod slice;
mod slips;
mod solve;
mod symbols;
mod tuple_call;
mod user_fn;

pub use crate::values::{convert, formula, ops, symbolic, value};

/// A binding read with the numbers bound since (the calculus on recipes).
use crate::calculus::substitute;

/// The operation seam, now [`crate::seam::apply`] (kept here for the
/// paths `eval::apply` already written).
pub use crate::seam::apply;
