//! Parsing: source text → AST with spans.
//!
//! Contract used by the rest of the crate:
//! - [`parse_program`]`(src) -> Result<Vec<Stmt>, Diagnostic>`: a whole script
//!   or REPL entry; syntax errors are `ErrorKind::Syntax` diagnostics with a span.
//! - [`needs_more_input`]`(src) -> bool`: true while a `(`, `[` or `mech <`
//!   is open (the REPL keeps reading lines).
//! - [`ident::name_frames`]: the frame subscript of a name (`T_sb` → s, b).

pub mod ast;
