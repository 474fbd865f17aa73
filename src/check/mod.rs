//! The check layer: kinds and frame tags of expressions, inferred without
//! numbers (LANGUAGE.md §5–7). [`ty`] holds the types, [`frames`] the frame
//! tags they carry, [`rules`] the frame table of §6 and its error texts,
//! [`bind`] the rule for names with frame subscripts, [`role`] what a name
//! says a vector is (a point or a free vector). The interpreter
//! ([`crate::eval`]) applies these rules in the same pass for
//! `chasles check` (no numbers) and `chasles run`.

pub mod algebra;
pub mod bind;
pub mod error;
mod frame_text;
pub mod frames;
mod free;
mod hints;
mod kind_eq;
pub mod name;
mod part_list;
pub mod parts;
mod product;
pub mod role;
pub mod rules;
pub mod ty;
