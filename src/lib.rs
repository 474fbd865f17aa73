//! chasles — a calculator language for the mathematics of rigid-body motion
//! (Modern Robotics, Lynch & Park, chapters 2 and 3).
//!
//! The layers, each a module importing only the layers below it (checked
//! by `layers.py`; `lie` and `mech` import nothing from the language):
//!
//! ```text
//! cli           the binary's dispatcher (flags, subcommands): the one
//!               module above the front ends, starting one of them
//! repl, kernel, front ends (the terminal; the Jupyter kernel; the
//! lsp           language server); none imports another
//! frontend      what the front ends share: `:` commands, help text, the
//!               statement runner that records each statement's writes,
//!               completion
//! grade         a run's asserts as test cases: JUnit XML, Gradescope (§14)
//! session       parse → check → evaluate over a source text; reading scripts
//! effects       the one gate for files a statement asks to write (`save`,
//!               printed pictures, `:save`): written, refused or confined
//!               by the front end; evaluation itself never writes
//! output        outcomes as text blocks and JSON lines
//! draw          pictures: marks, projection, SVG and PNG (§12)
//! eval          the environment and the interpreter (`diff` and `subs`
//!               run with the given names held), derive
//! calculus      the calculus on recipes: values made over `given`
//!               symbols read with the numbers bound since, their
//!               warnings once per binding, what `diff`/`subs` may read;
//!               the bindings through a trait the environment implements
//! decide        the proofs of `==`, `≈` and `<` (exact forms, certified
//!               balls, lifts, witnesses at points) and the replay of how
//!               a value was made with numbers (§7)
//! seam          the one operation seam (`seam::apply::Op`: rule, numbers,
//!               exact and symbolic forms of each operation), recipes and
//!               the chain rule on them, exactness, ranges
//! builtins      the one table of builtin functions (help and completion
//!               use it); rows compute through `lie::group`'s types
//! values        runtime values (`values::num::Num`: fixed-size shapes),
//!               symbols, the language's arithmetic (its errors:
//!               `values::error::OpError`), numbers as text
//! check         kinds and frame tags (interned frame names), inferred
//!               without evaluating: the frame algebra
//! syntax        the pest grammar (`grammar/chasles.pest`), the fast parser
//!               that agrees with it, and the AST (names interned:
//!               `syntax::name::Name`)
//! diagnostics   errors and warnings as data, and their rendering
//! span, budget  byte spans and line numbers; the evaluation budget
//!               (interrupt, deadline, numbers held) every loop asks
//! lie, mech,    SO(3), SE(3), SO(2), SE(2) (free functions and the group
//! sym           types of `lie::group`); Grübler and C-space (chapter 2);
//!               symbolic scalars in canonical form — none of them knows
//!               the language
//! ```
//!
//! Each layer imports only layers below it in this list (`draw` imports
//! `values` and `check`; `session` drives `draw`). Each stage has one error
//! type: `syntax` and everything from `eval` up report a
//! `diagnostics::Diagnostic`; `check` a `check::error::RuleError`,
//! `builtins` an `ArgError`, `values` an `OpError`, `mech` a `MechError`,
//! each turned into a `Diagnostic` in one place.
//!
//! - [`syntax`]: the pest grammar and the AST with spans;
//! - [`check`]: kinds and frame tags, inferred without evaluating;
//! - [`values`]: values, symbolic expressions, arithmetic on values, and
//!   numbers on one line (`eval::value`, `eval::ops`, `output::number` are
//!   re-exports of its modules);
//! - [`eval`]: the session environment and evaluation;
//! - [`calculus`]: numbers bound later put into values made over symbols
//!   (§7), read through [`calculus::Bindings`];
//! - [`decide`]: deciding `==`, `≈` and `<`, and replaying recipes with
//!   numbers;
//! - [`seam`]: the operation seam every evaluation goes through;
//! - [`builtins`]: the one table of builtin functions;
//! - [`lie`]: SO(3), SE(3), SO(2), SE(2) and their algebras — plain nalgebra,
//!   no knowledge of the language, usable as a library;
//! - [`mech`]: Grübler's formula and C-space topology (chapter 2);
//! - [`sym`]: symbolic scalars in canonical form and the book's closed
//!   forms over them (chapter 3 with symbols), no knowledge of the language;
//! - [`span`], [`diagnostics`], [`output`]: places in the source, errors,
//!   and values for people and for JSON;
//! - [`budget`]: the one evaluation budget (Ctrl-C, `--timeout`,
//!   `--max-memory`, the preview's few milliseconds) that every long loop
//!   asks whether to go on;
//! - [`session`]: the pipeline parse → check → evaluate over a source text;
//! - [`effects`]: the gate every file write goes through;
//! - [`frontend`]: the `:` commands, help and completion every front end
//!   shares;
//! - [`grade`]: every assert of a run as a test case, written as JUnit XML
//!   or Gradescope's `results.json`;
//! - [`cli`], [`repl`], [`kernel`], [`lsp`]: the dispatcher and the front
//!   ends.
#![forbid(unsafe_code)]
#![warn(missing_docs)]
// Errors carry spans, labels and help text; they are rare, so their size is not worth boxing.
#![allow(clippy::result_large_err)]

// pest_derive without its `std` feature (which adds a costly stack probe to
// every rule call; our own depth limits guard the stack) refers to `alloc`.
extern crate alloc;

pub mod budget;
pub mod builtins;
pub mod calculus;
pub mod check;
pub mod cli;
pub mod decide;
pub mod diagnostics;
pub mod draw;
pub mod effects;
pub mod eval;
pub mod frontend;
pub mod grade;
pub mod kernel;
pub mod lie;
pub mod lsp;
pub mod mech;
pub mod output;
pub mod repl;
pub mod seam;
pub mod session;
pub mod span;
pub mod sym;
pub mod syntax;
pub mod values;
