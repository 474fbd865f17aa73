//! Output: numbers and values as text for people ([`text`], [`number`]) and
//! as JSON lines ([`json`]); symbolic values through [`formula`]; the
//! steps of `explain` through [`steps`].

pub mod formula;
pub mod json;
pub mod steps;
pub mod text;

pub use crate::values::{exact, number};
