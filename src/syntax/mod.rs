//! Parsing: source text → AST with spans.
//!
//! The pipeline: `split` cuts the source into statements (newline or `;`
//! outside brackets; comments blanked; bracket errors and nesting depth
//! checked), then each statement is parsed with the pest grammar
//! `grammar/chasles.pest` and turned into an [`ast::Stmt`] by `parser`,
//! which resolves precedence with a Pratt parser and rejects trees deeper
//! than [`MAX_DEPTH`]. Ordinary statements first take `fast`, a
//! hand-written parser of the same grammar, ten times quicker, which
//! leaves every error (and a few rare forms) to pest. Most statements do
//! not even pass through the splitter's scan: where it stands at the start
//! of a statement, `fast::parse_statement_in` reads the statement straight
//! from the source up to its newline or `;` and the splitter only skips it;
//! anything the splitter would change or refuse (a newline inside `( )`, a
//! string, a bracket error) sends the statement the long way. Names in the
//! tree are interned ([`name::Name`]). `spacing` then
//! refuses what reads two ways (`[1 -x]`, `[2 pi]`, `R [1, 2]`, `sin θ^2`,
//! `T_123`) with both readings, and `rewrite` turns the book's notation into
//! the plain tree (numpy's nested rows, `R^T` = `R.T`); a statement the fast
//! path read without anything these passes act on skips them. Syntax errors are
//! `ErrorKind::Syntax` diagnostics with friendly messages (`rules`). Spans
//! are byte offsets into the whole source.
//!
//! Contract used by the rest of the crate:
//! - [`parse_program`]: one result per statement, so one bad statement does
//!   not hide the others;
//! - [`needs_more_input`]: true while a `(`, `[`, `{` or `mech <` is open
//!   (the REPL keeps reading lines);
//! - [`ident::name_frames`]: the frame subscript of a name (`T_sb` → s, b).

mod ahead;
pub mod ast;
mod book;
mod comprehension;
mod fast;
mod grammar;
pub mod ident;
mod mech;
pub mod name;
mod parser;
mod ranges;
mod rewrite;
mod rules;
mod signs;
mod spacing;
mod split;

pub use ahead::{AHEAD_FROM, Parsed, each_statement};

use crate::diagnostics::{Diagnostic, ErrorKind};

/// The deepest nesting accepted, both for brackets and for the expression
/// tree (`1+1+…` with more terms, or `2^2^…`, `----x` chained further, is a
/// syntax error). The checker and evaluator recurse over the tree and rely
/// on this bound.
pub const MAX_DEPTH: usize = 200;

/// Parses a script or REPL entry: one entry per statement, in order. Blank
/// and comment-only lines produce no entry.
pub fn parse_program(src: &str) -> Vec<Result<ast::Stmt, Diagnostic>> {
    statements(src).collect()
}

/// [`parse_program`] one statement at a time: each statement is split off
/// and parsed only when asked for, so a long script needs memory for its
/// text and one statement, not for every statement's tree at once.
pub fn statements(src: &str) -> impl Iterator<Item = Result<ast::Stmt, Diagnostic>> + '_ {
    statements_read(src, true)
}

/// [`statements`] with every statement split off by the splitter first
/// (`fused` false), as the fused reading must agree with.
#[cfg(test)]
pub(crate) fn statements_split(
    src: &str,
) -> impl Iterator<Item = Result<ast::Stmt, Diagnostic>> + '_ {
    statements_read(src, false)
}

fn statements_read(
    src: &str,
    fused: bool,
) -> impl Iterator<Item = Result<ast::Stmt, Diagnostic>> + '_ {
    let mut splitter = split::Splitter::new(src);
    let mut stack = fast::Stack::default();
    std::iter::from_fn(move || {
        // Most statements are read by the fast parser straight from the
        // source, the splitter only skipping them; it scans the rest.
        if fused
            && let Some(from) = splitter.clean_start()
            && let Some(mut stmt) = fast::parse_statement_in(src, from, &mut stack)
        {
            splitter.skip_to(stack.end);
            stmt.silent = src.as_bytes().get(stack.end) == Some(&b';');
            // Most statements need neither pass (checked without a call).
            if stack.passes.spacing || stack.passes.rewrite {
                return Some(after_parsing(&mut stmt, stack.passes, src).map(|()| stmt));
            }
            return Some(Ok(stmt));
        }
        let chunk = splitter.next()?;
        let text = splitter.text(chunk.span);
        // Most statements take the fast path; it leaves errors and rare
        // forms to pest.
        if chunk.error.is_none()
            && text.len() <= MAX_STATEMENT_BYTES
            && chunk.depth <= FAST_DEPTH
            && let Some(mut stmt) = fast::parse_statement_with(text, chunk.span, &mut stack)
        {
            stmt.silent = silenced(src, stmt.span.end);
            return Some(after_parsing(&mut stmt, stack.passes, src).map(|()| stmt));
        }
        let parsed = match chunk.error {
            Some(error) => Err(error),
            None if text.len() > MAX_STATEMENT_BYTES => Err(too_long(chunk.span, text.len())),
            None if chunk.depth > SHALLOW => parse_on_big_stack(text, chunk.span),
            None => parser::parse_chunk(text, chunk.span),
        };
        Some(parsed.and_then(|mut stmt| {
            stmt.silent = silenced(src, stmt.span.end);
            after_parsing(&mut stmt, fast::Passes::ALL, src).map(|()| stmt)
        }))
    })
}

/// Whether the statement ending at `end` in `src` is ended by `;` (only
/// blanks between): it is silent (LANGUAGE.md §3). The splitter ends a
/// statement at a `;` outside brackets, so the first byte after its text
/// that is not a blank is its terminator; a comment's `;` is behind a `#`.
pub fn silenced(src: &str, end: usize) -> bool {
    src.as_bytes()
        .get(end..)
        .and_then(|rest| rest.iter().find(|&&b| !matches!(b, b' ' | b'\t' | b'\r')))
        == Some(&b';')
}

/// The passes after parsing: `spacing` refuses what reads two ways,
/// `rewrite` turns the book's notation into the plain tree.
fn after_parsing(stmt: &mut ast::Stmt, passes: fast::Passes, src: &str) -> Result<(), Diagnostic> {
    if passes.spacing {
        spacing::check(stmt, src)?;
    }
    if passes.rewrite {
        rewrite::stmt(stmt);
    }
    Ok(())
}

/// The longest statement accepted (bytes). The grammar needs memory
/// proportional to the statement (about a hundred bytes per byte of
/// text), so a runaway line is refused rather than parsed.
pub const MAX_STATEMENT_BYTES: usize = 1 << 20;

fn too_long(span: ast::Span, len: usize) -> Diagnostic {
    let at = ast::Span::new(span.start, span.start + 1);
    Diagnostic::error(
        ErrorKind::Syntax,
        at,
        format!("statement too long ({len} bytes; the limit is {MAX_STATEMENT_BYTES})"),
    )
    .with_help("split it into several statements with intermediate names")
}

/// Statements nested deeper than this many brackets are parsed on a thread
/// of their own with a large stack: building the tree costs several
/// kilobytes of stack per bracket level in debug builds, and the caller's
/// thread may have as little as 2 MB.
const SHALLOW: usize = 48;

/// The fast path ([`fast`]) takes statements nested at most this deep.
const FAST_DEPTH: usize = 16;

fn parse_on_big_stack(chunk: &str, span: ast::Span) -> Result<ast::Stmt, Diagnostic> {
    std::thread::scope(|scope| {
        std::thread::Builder::new()
            .name("chasles-parse".into())
            .stack_size(64 << 20)
            .spawn_scoped(scope, || parser::parse_chunk(chunk, span))
            .ok()
            .and_then(|handle| handle.join().ok())
    })
    .unwrap_or_else(|| Err(rules::too_deep(span)))
}

/// True while a `(`, `[`, `{` or `mech <` is still open at the end of `src`
/// (the REPL should read another line). False when everything is closed
/// and also when a bracket is unbalanced the other way (an error to report).
pub fn needs_more_input(src: &str) -> bool {
    let mut splitter = split::Splitter::new(src);
    splitter.by_ref().for_each(drop);
    splitter.open_at_end
}
