//! Evaluation: values, the session environment, and the interpreter that
//! walks each statement once, checking kinds and frames by
//! [`crate::check`]'s rules and computing values through [`crate::lie`].

pub mod apply;
mod ball;
mod balls;
mod certify;
mod chain;
mod compare;
mod compound;
mod cyclotomic;
mod decide;
mod derive;
pub mod env;
mod exactness;
mod expr;
pub mod graph;
mod hold;
pub mod interp;
mod lift;
pub mod list;
mod lower;
mod naming;
mod notation;
mod operation;
mod order;
mod outcome;
mod paren_product;
mod replay;
mod resolve;
mod shapes;
mod slice;
mod slips;
mod substitute;
mod symbols;
mod transcendental;
mod tuple_call;
mod turn;
mod user_fn;
mod warned;
mod witness;

pub use crate::values::{convert, formula, ops, symbolic, value};
