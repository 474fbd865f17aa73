//! Output: numbers and values as text for people ([`text`], [`number`]) and
//! as JSON lines ([`json`]); symbolic values through [`formula`].

pub mod formula;
pub mod json;
pub mod text;

pub use crate::values::{exact, number};
