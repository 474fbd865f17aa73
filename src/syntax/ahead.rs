//! Reading ahead (issue 40): the statements of a long script are read on a
//! second thread while the caller's thread checks and evaluates them, so
//! that a batch run of many statements pays for reading them on the other
//! core. The reader is [`super::statements`], unchanged: the same
//! statements, the same errors, in the same order; only where the reading
//! happens differs.
//!
//! The reader sends statements in batches over a bounded channel (so it is
//! never more than a few batches ahead, and memory stays bounded by them,
//! not by the script), and the caller hands each batch back when it is
//! done with it, so the trees are also dropped on the reader's thread and
//! the batch's storage is used again. A caller that stops early (an error,
//! an interrupt) drops its end; the reader then stops at its next batch.
//!
//! A short source (a REPL entry, a book exercise, any script of fewer than
//! a few thousand statements) is read in line, on the caller's thread,
//! statement by statement as before: the threads cost more than they save
//! there (see [`AHEAD_FROM`]).

use std::ops::ControlFlow;
use std::sync::mpsc;

use super::{ast, statements};
use crate::diagnostics::Diagnostic;
use crate::span::{Anchor, Lines};

/// One statement as read: its tree, or the syntax error that stands for it.
pub type Parsed = Result<ast::Stmt, Diagnostic>;

/// Where a statement read starts: its line, and where that line starts
/// (the line of its tree's span, or of its error's). Counted by the reader
/// as it reads, so that the caller's thread does not walk the text again.
fn at(lines: &mut Lines<'_>, parsed: &Parsed) -> Anchor {
    let start = match parsed {
        Ok(stmt) => stmt.span.start,
        Err(d) => d.span.start,
    };
    lines.line(start);
    lines.anchor()
}

/// Sources shorter than this many bytes are read in line: about 6,000 of
/// the book's statements (`T_ab = exp([S] 0.1)`), 8 ms of work. The second
/// and third threads cost about 0.6 ms on this project's 2-core virtual
/// machine (their start, their allocators' first pages, the hand-overs),
/// which the overlap repays from about 4,000 statements on
/// (`benches/book_python.py`'s script, whole process, 40 runs each:
/// 1,000 statements 3.6 ms against 3.0 ms on one thread, 4,000 even,
/// 10,000 12.3 ms against 14.5 ms).
pub const AHEAD_FROM: usize = 128 * 1024;

/// Statements per batch: enough that the channel's hand-over (a wake-up of
/// the other thread now and then) is a small part of a batch's work. The
/// first batches are smaller ([`FIRST_BATCH`], doubling up to this), so
/// that the caller starts on the first statements soon. The reader is the
/// faster thread, so it waits on a full queue and each batch taken wakes
/// it: 1,024 statements a batch, not 256, is a quarter of the wake-ups,
/// and 1–3% off the whole process at 10k and 100k statements (issue 40,
/// session 24: 60 interleaved runs each; 4,096 gained nothing more).
const BATCH: usize = 1024;

/// Statements in the first batch.
const FIRST_BATCH: usize = 16;

/// A batch ends once its statements span this many bytes of source, so
/// that the trees read ahead stay few whatever the statements' size (a
/// script of large literal matrices): at most [`QUEUE`] + 2 batches of
/// them exist at once, each this much text and one statement more.
const BATCH_BYTES: usize = 64 * 1024;

/// Full batches the reader may be ahead by.
const QUEUE: usize = 3;

/// The reader's stack: the fast parser's depth is bounded; a statement
/// nested deeper than the splitter's shallow bound is parsed on a thread of
/// its own with a larger stack (see `parse_on_big_stack`), as in line.
const READER_STACK: usize = 16 << 20;

/// Calls `each` with every statement of `src` in order, until it breaks:
/// [`super::statements`], read on a second thread when `src` is long and
/// `ahead` allows it (see the module's comment). `each` gets the statement in place; it may take
/// what it keeps (a syntax error, say), and the rest is dropped with the
/// batch. With it comes where it starts: its line and where that line
/// starts ([`Anchor`], the line of the statement's span or of its error's).
pub fn each_statement(
    src: &str,
    ahead: bool,
    mut each: impl FnMut(&mut Parsed, Anchor) -> ControlFlow<()>,
) {
    if !ahead || src.len() < AHEAD_FROM {
        return in_line(src, &mut each);
    }
    std::thread::scope(|scope| {
        let (full_to_caller, full) = mpsc::sync_channel::<Vec<(Parsed, Anchor)>>(QUEUE);
        let (used_to_reader, used) = mpsc::channel::<Vec<(Parsed, Anchor)>>();
        let reader = std::thread::Builder::new()
            .name("chasles-read".into())
            .stack_size(READER_STACK)
            .spawn_scoped(scope, move || read(src, full_to_caller, &used));
        if reader.is_err() {
            // No second thread to be had: read in line.
            return in_line(src, &mut each);
        }
        while let Ok(mut batch) = full.recv() {
            for (parsed, at) in &mut batch {
                if each(parsed, *at).is_break() {
                    return;
                }
            }
            // The reader may have finished (and dropped its end): the
            // batch is then dropped here.
            let _ = used_to_reader.send(batch);
        }
    });
}

/// [`each_statement`] on the caller's thread, one statement at a time.
fn in_line(src: &str, each: &mut impl FnMut(&mut Parsed, Anchor) -> ControlFlow<()>) {
    let mut lines = Lines::new(src);
    for mut parsed in statements(src) {
        let at = at(&mut lines, &parsed);
        if each(&mut parsed, at).is_break() {
            return;
        }
    }
}

/// The reader's loop: fills a batch (one handed back, emptied here, or a
/// new one) and sends it, until the source or the caller ends.
fn read(
    src: &str,
    full: mpsc::SyncSender<Vec<(Parsed, Anchor)>>,
    used: &mpsc::Receiver<Vec<(Parsed, Anchor)>>,
) {
    let mut statements = statements(src);
    let mut lines = Lines::new(src);
    let mut size = FIRST_BATCH;
    // Where the last batch's text ended.
    let mut read_to = 0;
    loop {
        let mut batch = match used.try_recv() {
            Ok(mut batch) => {
                batch.clear();
                batch
            }
            Err(_) => Vec::with_capacity(size),
        };
        let (from, mut ended) = (read_to, false);
        while batch.len() < size {
            let Some(parsed) = statements.next() else {
                ended = true;
                break;
            };
            read_to = match &parsed {
                Ok(stmt) => stmt.span.end,
                Err(d) => d.span.end,
            };
            let at = at(&mut lines, &parsed);
            batch.push((parsed, at));
            if read_to.saturating_sub(from) >= BATCH_BYTES {
                break;
            }
        }
        if batch.is_empty() || full.send(batch).is_err() || ended {
            break;
        }
        size = (2 * size).min(BATCH);
    }
    // The caller's loop ends when this end is dropped; the batches still
    // coming back are dropped here, off the caller's thread, until the
    // caller is done.
    drop(full);
    while let Ok(batch) = used.recv() {
        drop(batch);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Reads `src` through [`each_statement`] and through the plain
    /// iterator, each statement's tree or error as debug text with where
    /// it starts (for the plain one, counted from the top for each).
    fn both(src: &str) -> (Vec<String>, Vec<String>) {
        let mut ahead = Vec::new();
        each_statement(src, true, |p, at| {
            ahead.push(format!("{p:?} at {at:?}"));
            ControlFlow::Continue(())
        });
        let plain = statements(src)
            .map(|p| {
                let start = p.as_ref().map_or_else(|d| d.span.start, |s| s.span.start);
                let line = 1 + src[..start].matches('\n').count();
                let offset = src[..start].rfind('\n').map_or(0, |i| i + 1);
                format!("{p:?} at {:?}", Anchor { offset, line })
            })
            .collect();
        (ahead, plain)
    }

    /// A script long enough to be read ahead, with errors, silenced
    /// statements, comments, blank lines, a statement over several lines
    /// and one deeper than the fast path takes, reads the same as in line,
    /// across several batches.
    #[test]
    fn a_long_script_reads_the_same_ahead_as_in_line() {
        let lines = [
            "T_ab = exp([S] 0.1)",
            "X = log(T_ab);",
            "# a comment",
            "",
            "y = (1 +",
            "  2)",
            "z = 1 +* 2",
            "w = ((((((((((((((((((((1))))))))))))))))))))",
            "a = [1, 2; 3, 4]; b = a'",
            "s = \"text; with a semicolon\"",
        ];
        let src: String = (0..2 * AHEAD_FROM / 20)
            .map(|i| lines[i % lines.len()])
            .collect::<Vec<_>>()
            .join("\n");
        assert!(src.len() >= AHEAD_FROM);
        let (ahead, plain) = both(&src);
        assert!(plain.len() > 2 * BATCH, "{} statements", plain.len());
        assert_eq!(ahead.len(), plain.len());
        for (i, (a, p)) in ahead.iter().zip(&plain).enumerate() {
            assert_eq!(a, p, "statement {i}");
        }
        assert!(plain.iter().any(|p| p.starts_with("Err")));
    }

    /// A caller that stops early gets no statement after it stopped, and
    /// the reader ends (the call returns).
    #[test]
    fn stopping_early_ends_the_reader() {
        let src = "x = 1\n".repeat(AHEAD_FROM);
        let mut seen = 0;
        each_statement(&src, true, |p, _| {
            assert!(p.is_ok());
            seen += 1;
            if seen == 10 {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        });
        assert_eq!(seen, 10);
    }

    /// Batches hold at most [`BATCH`] statements and end once they span
    /// [`BATCH_BYTES`] of source: long statements make short batches.
    #[test]
    fn batches_are_bounded_in_statements_and_in_bytes() {
        let row = (0..500)
            .map(|i| format!("{i}.5"))
            .collect::<Vec<_>>()
            .join(", ");
        let big = format!("m = [{row}]\n");
        let src = format!(
            "{}{}{}",
            "x = 1\n".repeat(1000),
            big.repeat(200),
            "y = 2\n".repeat(1000)
        );
        let (to, full) = mpsc::sync_channel(1000);
        // No batch comes back: `read` reuses none and returns at the end.
        let (back, used) = mpsc::channel();
        drop(back);
        read(&src, to, &used);
        let batches: Vec<Vec<Parsed>> = full
            .iter()
            .map(|b: Vec<(Parsed, Anchor)>| b.into_iter().map(|(p, _)| p).collect())
            .collect();
        let sizes: Vec<usize> = batches.iter().map(Vec::len).collect();
        assert_eq!(sizes.iter().sum::<usize>(), 2200);
        assert_eq!(sizes[..5], [16, 32, 64, 128, 256], "{sizes:?}");
        for batch in &batches {
            assert!(batch.len() <= BATCH);
            let span = |p: &Parsed| p.as_ref().map(|s| s.span).expect("no error");
            let bytes = span(&batch[batch.len() - 1]).end - span(&batch[0]).start;
            assert!(bytes < BATCH_BYTES + big.len(), "{bytes} bytes");
        }
        // The big statements came in batches of a few (≈ 64 KB of them).
        let per = BATCH_BYTES.div_ceil(big.len());
        assert!(sizes.contains(&per), "{sizes:?} (expected some of {per})");
    }

    /// A short source is read in line, and reads the same.
    #[test]
    fn a_short_source_reads_the_same() {
        let (ahead, plain) = both("x = 1; y = 2\nz = x +\n");
        assert_eq!(ahead, plain);
        assert_eq!(ahead.len(), 3);
    }
}
