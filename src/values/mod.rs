//! The value layer, below everything that computes: runtime [`value::Value`]s
//! whose numbers are a [`num::Num`] (a scalar, the book's 3-, 4- and
//! 6-vectors and 3×3, 4×4, 6×6 matrices in fixed-size nalgebra types, a
//! general matrix only for other shapes), symbolic expressions over
//! `given` names ([`symbolic`]), how a symbolic value was made ([`recipe`],
//! replayed with numbers once its symbols have them), the group a
//! matrix belongs to ([`convert`]), the arithmetic of the language on values
//! ([`ops`]: products, powers, inverses, members, indexing, brackets, with
//! their errors in [`error`]), and
//! numbers as text (`number`, `exact`, `format`, and the simple closed
//! forms `--exact` prints for floats, [`closed_form`]), and decisions from a
//! number's value by its exact form when it has one ([`domain`]). It imports only
//! `check`'s kinds, `syntax`'s tree (a user function's body), `lie` and
//! `mech`; `builtins` and `eval` build on it. `crate::eval::{value, ops,
//! convert, symbolic}` and `crate::output::{number, exact}` re-export these
//! modules under their former paths.

pub mod closed_form;
pub mod convert;
pub mod domain;
pub mod equality;
pub mod error;
pub mod exact;
pub mod exact_mat;
pub mod format;
pub mod formula;
pub mod limits;
pub mod linalg;
pub mod num;
pub mod number;
pub mod operation;
pub mod ops;
pub mod recipe;
pub mod symbolic;
pub mod value;
pub mod waiting;
