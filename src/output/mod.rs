//! Output: numbers and values as text for people ([`text`], [`number`]) and
//! as JSON lines ([`json`]).

pub mod exact;
pub mod json;
pub mod number;
pub mod text;
