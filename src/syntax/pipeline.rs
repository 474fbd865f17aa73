//! Long scripts parsed on a second thread while the first checks and
//! evaluates: the statements of [`super::statements`], in order, handed
//! over in batches.
//!
//! Parsing is a function of the text alone (no statement's meaning changes
//! how a later one parses), so it can run ahead of evaluation. On a
//! machine with two cores a 100,000-statement script then takes about the
//! time of its slower half instead of the sum of both. Short texts (every
//! REPL entry, every example of the book) are parsed inline: a thread is
//! not worth its start-up there.

use std::ops::ControlFlow;
use std::sync::mpsc;

use super::ast::Stmt;
use crate::diagnostics::Diagnostic;

/// Texts at least this long are parsed on a second thread (about 3,000
/// statements of the book's kind).
pub const PIPELINE_BYTES: usize = 64 * 1024;

/// Statements handed over at once: enough to make the channel's cost per
/// statement negligible, few enough that evaluation starts at once.
const BATCH: usize = 256;

/// Batches parsed ahead of evaluation at most (bounds the memory a long
/// script's trees take when evaluation is the slower half).
const AHEAD: usize = 16;

/// Calls `each` on every statement of `src` in order (or its syntax error),
/// until `each` breaks. Long texts are parsed on a second thread; the
/// result is the same as iterating [`super::statements`].
pub fn for_each_statement(
    src: &str,
    mut each: impl FnMut(Result<Stmt, Diagnostic>) -> ControlFlow<()>,
) {
    if src.len() < PIPELINE_BYTES {
        for parsed in super::statements(src) {
            if each(parsed).is_break() {
                return;
            }
        }
        return;
    }
    std::thread::scope(|scope| {
        let (tx, rx) = mpsc::sync_channel::<Vec<Result<Stmt, Diagnostic>>>(AHEAD);
        let parser = std::thread::Builder::new()
            .name("chasles-parse".into())
            .stack_size(64 << 20)
            .spawn_scoped(scope, move || {
                let mut batch = Vec::with_capacity(BATCH);
                for parsed in super::statements(src) {
                    batch.push(parsed);
                    if batch.len() == BATCH {
                        let full = std::mem::replace(&mut batch, Vec::with_capacity(BATCH));
                        // A closed channel: evaluation stopped; stop too.
                        if tx.send(full).is_err() {
                            return;
                        }
                    }
                }
                if !batch.is_empty() {
                    let _ = tx.send(batch);
                }
            });
        if parser.is_err() {
            // No thread to be had: parse inline.
            for parsed in super::statements(src) {
                if each(parsed).is_break() {
                    return;
                }
            }
            return;
        }
        for batch in rx {
            for parsed in batch {
                if each(parsed).is_break() {
                    // Dropping the receiver ends the parser at its next batch.
                    return;
                }
            }
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    fn long_script(n: usize) -> String {
        let lines = [
            "T_ab = exp([S] 0.1)",
            "x = (1, 2,\n 3)",
            "y = 2 +",
            "z = 2 pi",
        ];
        let mut s = String::from("S = (0, 0, 1, 0, 2, 0)\n");
        for i in 0..n {
            s.push_str(lines[i % lines.len()]);
            s.push('\n');
        }
        s
    }

    /// The pipelined statements are those of `statements`, in order,
    /// errors included.
    #[test]
    fn the_same_statements_in_the_same_order() {
        let src = long_script(20_000);
        assert!(src.len() >= PIPELINE_BYTES);
        let inline: Vec<_> = crate::syntax::statements(&src).collect();
        let mut piped = Vec::new();
        for_each_statement(&src, |s| {
            piped.push(s);
            ControlFlow::Continue(())
        });
        assert_eq!(piped.len(), inline.len());
        for (a, b) in piped.iter().zip(&inline) {
            match (a, b) {
                (Ok(x), Ok(y)) => assert_eq!(x, y),
                (Err(x), Err(y)) => assert_eq!((x.span, &x.message), (y.span, &y.message)),
                _ => panic!("pipelined and inline statements differ"),
            }
        }
        assert!(
            inline.iter().any(|s| s.is_err()),
            "the script has errors to compare"
        );
    }

    /// Breaking stops at that statement (the parser thread ends too).
    #[test]
    fn a_break_stops_at_once() {
        let src = long_script(20_000);
        assert!(crate::syntax::statements(&src).count() > 10_000);
        let mut seen = 0;
        for_each_statement(&src, |_| {
            seen += 1;
            if seen == 1000 {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        });
        assert_eq!(seen, 1000);
    }
}
