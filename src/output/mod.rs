//! Output: numbers and values as text for people ([`text`], [`number`]) and
//! as JSON lines ([`json`]); symbolic values through [`formula`].

pub mod exact;
pub mod formula;
pub mod json;
pub mod number;
pub mod text;
