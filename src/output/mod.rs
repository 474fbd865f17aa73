//! Output: numbers and values as text for people ([`text`], [`number`]) and
//! as JSON lines ([`json`]); symbolic values through [`formula`]; the
//! steps of `explain` through [`steps`]; a statement's text with its
//! numbers written later, on a batch run's writing thread, through [`later`].

pub mod formula;
pub mod json;
pub mod later;
pub mod steps;
pub mod text;

pub use crate::values::{exact, number};
