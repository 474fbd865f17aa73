//! Parsing: source text → AST with spans.
//!
//! The pipeline: `split` cuts the source into statements (newline or `;`
//! outside brackets; comments blanked; bracket errors and nesting depth
//! checked), then each statement is parsed with the pest grammar
//! `grammar/chasles.pest` and turned into an [`ast::Stmt`] by `parser`,
//! which resolves precedence with a Pratt parser and rejects trees deeper
//! than [`MAX_DEPTH`]. Ordinary statements first take `fast`, a
//! hand-written parser of the same grammar, ten times quicker, which
//! leaves every error (and a few rare forms) to pest. Syntax errors are
//! `ErrorKind::Syntax` diagnostics with friendly messages (`rules`). Spans
//! are byte offsets into the whole source.
//!
//! Contract used by the rest of the crate:
//! - [`parse_program`]: one result per statement, so one bad statement does
//!   not hide the others;
//! - [`needs_more_input`]: true while a `(`, `[`, `{` or `mech <` is open
//!   (the REPL keeps reading lines);
//! - [`ident::name_frames`]: the frame subscript of a name (`T_sb` → s, b).

pub mod ast;
mod fast;
pub mod ident;
mod mech;
mod parser;
mod rules;
mod split;

use crate::diagnostics::Diagnostic;

/// The deepest nesting accepted, both for brackets and for the expression
/// tree (`1+1+…` with more terms, or `2^2^…`, `----x` chained further, is a
/// syntax error). The checker and evaluator recurse over the tree and rely
/// on this bound.
pub const MAX_DEPTH: usize = 200;

/// Parses a script or REPL entry: one entry per statement, in order. Blank
/// and comment-only lines produce no entry.
pub fn parse_program(src: &str) -> Vec<Result<ast::Stmt, Diagnostic>> {
    let split = split::split(src);
    split
        .chunks
        .into_iter()
        .map(|chunk| match chunk.error {
            Some(error) => Err(error),
            // Most statements take the fast path; it leaves errors and rare
            // forms to pest.
            None if chunk.depth <= SHALLOW
                && let Some(stmt) = fast::parse_statement(&split.text, chunk.span) =>
            {
                Ok(stmt)
            }
            None if chunk.depth > SHALLOW || chunk.span.end - chunk.span.start > SHORT => {
                parse_on_big_stack(&split.text, chunk.span)
            }
            None => parser::parse_statement(&split.text, chunk.span),
        })
        .collect()
}

/// Statements nested deeper than this many brackets, or longer than
/// [`SHORT`] bytes (long enough for deep operator chains), are parsed on a
/// thread of their own with a large stack: building the tree costs
/// kilobytes of stack per level in debug builds, and the caller's thread
/// may have as little as 2 MB.
const SHALLOW: usize = 16;
const SHORT: usize = 256;

fn parse_on_big_stack(text: &str, span: ast::Span) -> Result<ast::Stmt, Diagnostic> {
    std::thread::scope(|scope| {
        std::thread::Builder::new()
            .name("chasles-parse".into())
            .stack_size(64 << 20)
            .spawn_scoped(scope, || parser::parse_statement(text, span))
            .ok()
            .and_then(|handle| handle.join().ok())
    })
    .unwrap_or_else(|| Err(parser::too_deep(span)))
}

/// True while a `(`, `[`, `{` or `mech <` is still open at the end of `src`
/// (the REPL should read another line). False when everything is closed
/// and also when a bracket is unbalanced the other way (an error to report).
pub fn needs_more_input(src: &str) -> bool {
    split::split(src).open_at_end
}
