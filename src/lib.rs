//! chasles — a calculator language for the mathematics of rigid-body motion
//! (Modern Robotics, Lynch & Park, chapters 2 and 3).
//!
//! The layers, each a module:
//! - [`syntax`]: the pest grammar (`grammar/chasles.pest`) and the AST with spans;
//! - [`check`]: kinds and frame tags, inferred without evaluating;
//! - [`eval`]: values, the session environment and evaluation;
//! - [`builtins`]: the one table of builtin functions;
//! - [`lie`]: SO(3), SE(3), SO(2), SE(2) and their algebras — plain nalgebra,
//!   no knowledge of the language, usable as a library;
//! - [`mech`]: Grübler's formula and C-space topology (chapter 2);
//! - [`diagnostics`], [`output`]: errors and values for people and for JSON;
//! - [`session`]: the pipeline parse → check → evaluate over a source text;
//! - [`cli`], [`repl`]: the front ends.
#![forbid(unsafe_code)]
// Errors carry spans, labels and help text; they are rare, so their size is not worth boxing.
#![allow(clippy::result_large_err)]

// pest_derive without its `std` feature (which adds a costly stack probe to
// every rule call; our own depth limits guard the stack) refers to `alloc`.
extern crate alloc;

pub mod builtins;
pub mod check;
pub mod cli;
pub mod diagnostics;
pub mod draw;
pub mod eval;
pub mod lie;
pub mod mech;
pub mod output;
pub mod repl;
pub mod session;
pub mod syntax;
