//! Evaluation: values, the session environment, and the interpreter that
//! walks each statement once, checking kinds and frames by
//! [`crate::check`]'s rules and computing values through [`crate::lie`].

mod compound;
pub mod convert;
mod derive;
pub mod env;
mod expr;
pub mod interp;
pub mod list;
pub mod ops;
mod substitute;
pub mod symbolic;
pub mod value;
