//! Cutting source text into statements before the grammar sees it.
//!
//! A small byte scanner (every significant character is ASCII, so UTF-8
//! text can be scanned byte by byte) that tracks open brackets and decides
//! where each statement ends: at a newline or `;` outside all brackets.
//! It also blanks what the grammar should not see, keeping byte offsets:
//! comments become spaces, and so do newlines inside `( )` and `{ }` (inside
//! `[ ]` and `mech < >` a newline separates rows or items and is kept).
//!
//! Bracket errors (unmatched, mismatched, unclosed, nested deeper than
//! [`MAX_DEPTH`]) are found here, so the recursive grammar never sees text
//! nested deep enough to exhaust the stack.

use super::MAX_DEPTH;
use super::ast::Span;
use crate::diagnostics::{Diagnostic, ErrorKind};

/// One statement: its trimmed span, or the bracket error found in it.
#[derive(Debug)]
pub(crate) struct Chunk {
    pub span: Span,
    /// Boxed: rare, and a chunk is handed out per statement.
    pub error: Option<Diagnostic>,
    /// The deepest bracket nesting in the statement.
    pub depth: usize,
}

/// The result of [`split`].
#[cfg(test)]
#[derive(Debug)]
pub(crate) struct Split {
    /// The source with comments and continuation newlines replaced by
    /// spaces; same length and offsets as the source.
    pub text: String,
    pub chunks: Vec<Chunk>,
    /// A bracket (or `mech <`) is still open at the end of the source and no
    /// bracket error was found.
    pub open_at_end: bool,
}

/// How many times an unclosed bracket is recovered from by restarting after
/// its line; beyond this the rest of the source stays one statement (keeps
/// the scan linear on pathological input).
const MAX_RECOVERIES: usize = 32;

/// Splits `src` into statements.
#[cfg(test)]
pub(crate) fn split(src: &str) -> Split {
    let mut splitter = Splitter::new(src);
    let chunks: Vec<Chunk> = splitter.by_ref().collect();
    let open_at_end = splitter.open_at_end;
    let text = String::from_utf8(splitter.view().to_vec()).unwrap_or_else(|_| src.to_string());
    Split {
        text,
        chunks,
        open_at_end,
    }
}

/// The scanner of [`split`] as an iterator: yields one statement at a time,
/// so a long script is processed in memory bounded by its size plus one
/// statement (not one chunk per statement up front).
pub(crate) struct Splitter<'a> {
    src: &'a str,
    bytes: &'a [u8],
    /// No byte at or after this offset has been blanked: there `buf` and
    /// the source agree.
    blanked_to: usize,
    /// The blanked text; `buf[chunk.span]` is final once a chunk is yielded.
    /// Empty until something is blanked (the source is read instead).
    buf: Vec<u8>,
    /// See [`Split::open_at_end`] (valid once the iterator is exhausted).
    pub open_at_end: bool,
    any_error: bool,
    recoveries: usize,
    start: usize,
    i: usize,
    /// Open brackets: the byte (`(`, `[`, `{`, or `<` for `mech <`) and offset.
    stack: Vec<(u8, usize)>,
    error: Option<Diagnostic>,
    /// The deepest nesting in the current statement.
    depth: usize,
    done: bool,
}

impl<'a> Splitter<'a> {
    pub(crate) fn new(src: &'a str) -> Splitter<'a> {
        Splitter {
            src,
            bytes: src.as_bytes(),
            blanked_to: 0,
            buf: Vec::new(),
            open_at_end: false,
            any_error: false,
            recoveries: 0,
            start: 0,
            i: 0,
            stack: Vec::new(),
            error: None,
            depth: 0,
            done: false,
        }
    }

    /// The blanked text of a yielded chunk.
    pub(crate) fn text(&self, span: Span) -> &str {
        if span.start >= self.blanked_to
            && let Some(text) = self.src.get(span.start..span.end)
        {
            // Nothing blanked: the source itself, already known UTF-8.
            return text;
        }
        self.view()
            .get(span.start..span.end)
            .and_then(|b| std::str::from_utf8(b).ok())
            .unwrap_or("")
    }

    /// Where the next statement starts, when nothing is open, pending or
    /// blanked there: the place [`super::fast::parse_statement_in`] may
    /// read the next statement from, in the splitter's stead.
    pub(crate) fn clean_start(&self) -> Option<usize> {
        (!self.done
            && self.i == self.start
            && self.stack.is_empty()
            && self.error.is_none()
            && self.start >= self.blanked_to)
            .then_some(self.start)
    }

    /// Goes on after a statement read from the source up to `end`: the
    /// offset of its terminating newline or `;`, or the source's length.
    pub(crate) fn skip_to(&mut self, end: usize) {
        if end >= self.bytes.len() {
            self.done = true;
        } else {
            self.start = end + 1;
            self.i = end + 1;
        }
        self.depth = 0;
    }

    /// The text as blanked so far.
    fn view(&self) -> &[u8] {
        if self.buf.is_empty() {
            self.bytes
        } else {
            &self.buf
        }
    }

    /// The blanked text, to blank more of it (copied from the source the
    /// first time).
    fn blanked(&mut self) -> &mut [u8] {
        if self.buf.is_empty() {
            self.buf = self.bytes.to_vec();
        }
        &mut self.buf
    }

    /// The statement `buf[start..end]` (nested `depth` deep), trimmed;
    /// None for a blank one.
    fn chunk(&self, start: usize, end: usize, error: Option<Diagnostic>) -> Option<Chunk> {
        make_chunk(self.view(), (start, end, self.depth), error)
    }
}

impl Iterator for Splitter<'_> {
    type Item = Chunk;

    fn next(&mut self) -> Option<Chunk> {
        let bytes = self.bytes;
        let n = bytes.len();
        loop {
            if self.done {
                return None;
            }
            // Skip the bytes that neither end a statement nor open or
            // close anything.
            let mut i = self.i;
            // Four bytes a round while they last, then one by one.
            while let Some(w) = bytes.get(i..i + 4) {
                if significant(w[0]) {
                    break;
                } else if significant(w[1]) {
                    i += 1;
                    break;
                } else if significant(w[2]) {
                    i += 2;
                    break;
                } else if significant(w[3]) {
                    i += 3;
                    break;
                }
                i += 4;
            }
            while i < n && !significant(bytes[i]) {
                i += 1;
            }
            self.i = i;
            if i >= n {
                if self.stack.is_empty() {
                    self.done = true;
                    let error = self.error.take();
                    return self.chunk(self.start, n, error);
                }
                // Something is still open at the end of the input.
                if self.error.is_none() && !self.any_error {
                    self.open_at_end = true;
                }
                // Report the outermost: the statement is cut at its line.
                let &(open, at) = self.stack.first().unwrap_or(&(b'(', self.start));
                let err = self.error.take().unwrap_or_else(|| unclosed(open, at));
                self.any_error = true;
                // Recover: end this statement at the end of the line of the
                // outermost open bracket and scan the rest afresh.
                let outer = self.stack.first().map_or(self.start, |&(_, at)| at);
                let line_end = bytes[outer..].iter().position(|&b| b == b'\n');
                match line_end {
                    Some(off) if self.recoveries < MAX_RECOVERIES => {
                        self.recoveries += 1;
                        let nl = outer + off;
                        let chunk = self.chunk(self.start, nl, Some(err));
                        self.depth = 0;
                        // Undo the blanking done under the wrong assumption.
                        if !self.buf.is_empty() {
                            self.buf[nl..].copy_from_slice(&bytes[nl..]);
                        }
                        self.stack.clear();
                        self.start = nl + 1;
                        self.i = nl + 1;
                        if chunk.is_some() {
                            return chunk;
                        }
                        continue;
                    }
                    _ => {
                        self.done = true;
                        return self.chunk(self.start, n, Some(err));
                    }
                }
            }

            let b = bytes[i];
            match b {
                // A string, "a; b # c.svg": its text is neither comment,
                // separator nor bracket. Unclosed, it runs to the line's end.
                b'"' => {
                    let len = bytes[i + 1..].iter().position(|&c| c == b'"' || c == b'\n');
                    let close = len.map_or(n, |k| i + 1 + k);
                    self.i = if bytes.get(close) == Some(&b'"') {
                        close + 1
                    } else {
                        close
                    };
                    continue;
                }
                b'#' => {
                    let end = bytes[i..]
                        .iter()
                        .position(|&c| c == b'\n')
                        .map_or(n, |k| i + k);
                    self.blanked()[i..end].fill(b' ');
                    self.i = end;
                    self.blanked_to = self.blanked_to.max(self.i);
                    continue;
                }
                b'\n' | b';' => match self.stack.last() {
                    None => {
                        self.any_error |= self.error.is_some();
                        let error = self.error.take();
                        let chunk = self.chunk(self.start, i, error);
                        self.start = i + 1;
                        self.depth = 0;
                        self.i = i + 1;
                        if chunk.is_some() {
                            return chunk;
                        }
                        continue;
                    }
                    Some((b'(' | b'{', _)) if b == b'\n' => {
                        self.blanked()[i] = b' ';
                        self.blanked_to = self.blanked_to.max(i + 1);
                    }
                    Some(_) => {}
                },
                b'(' | b'[' | b'{' => {
                    open(&mut self.stack, &mut self.error, b, i);
                    self.depth = self.depth.max(self.stack.len());
                }
                b'<' if follows_mech(&self.view()[self.start..i]) => {
                    open(&mut self.stack, &mut self.error, b, i);
                    self.depth = self.depth.max(self.stack.len());
                }
                b'>' => {
                    if let Some((b'<', _)) = self.stack.last() {
                        self.stack.pop();
                    }
                }
                b')' | b']' | b'}' => {
                    let error = &mut self.error;
                    match self.stack.last() {
                        Some(&(o, _)) if closer_of(o) == b => {}
                        Some(&(o, at)) => {
                            if error.is_none() {
                                *error = Some(
                                    Diagnostic::error(
                                        ErrorKind::Syntax,
                                        Span::new(i, i + 1),
                                        format!("mismatched '{}'", b as char),
                                    )
                                    .with_primary_label(format!(
                                        "expected '{}'",
                                        closer_of(o) as char
                                    ))
                                    .with_label(
                                        Span::new(at, at + 1),
                                        format!("'{}' opened here", opener_name(o)),
                                    ),
                                );
                            }
                        }
                        None => {
                            if error.is_none() {
                                *error = Some(
                                    Diagnostic::error(
                                        ErrorKind::Syntax,
                                        Span::new(i, i + 1),
                                        format!("unmatched '{}'", b as char),
                                    )
                                    .with_primary_label(
                                        format!("no '{}' is open here", opener_of(b) as char),
                                    ),
                                );
                            }
                        }
                    }
                    self.stack.pop();
                }
                _ => {}
            }
            self.i = i + 1;
        }
    }
}

/// The bytes [`Splitter::next`] acts on: quotes, comments, statement ends
/// and brackets (`<` and `>` for `mech < >`).
fn significant(b: u8) -> bool {
    SIGNIFICANT[usize::from(b)]
}

static SIGNIFICANT: [bool; 256] = {
    let mut table = [false; 256];
    let bytes = *b"\"#\n;()[]{}<>";
    let mut k = 0;
    while k < bytes.len() {
        table[bytes[k] as usize] = true;
        k += 1;
    }
    table
};

fn open(stack: &mut Vec<(u8, usize)>, error: &mut Option<Diagnostic>, b: u8, at: usize) {
    stack.push((b, at));
    if stack.len() > MAX_DEPTH && error.is_none() {
        *error = Some(
            Diagnostic::error(
                ErrorKind::Syntax,
                Span::new(at, at + 1),
                format!("expression nested too deeply (limit {MAX_DEPTH})"),
            )
            .with_help("split it into several statements with intermediate names"),
        );
    }
}

fn unclosed(open: u8, at: usize) -> Diagnostic {
    Diagnostic::error(
        ErrorKind::Syntax,
        Span::new(at, at + 1),
        format!("unclosed '{}' opened here", opener_name(open)),
    )
    .with_help(format!("close it with '{}'", closer_of(open) as char))
}

fn closer_of(open: u8) -> u8 {
    match open {
        b'(' => b')',
        b'[' => b']',
        b'{' => b'}',
        _ => b'>',
    }
}

fn opener_of(close: u8) -> u8 {
    match close {
        b')' => b'(',
        b']' => b'[',
        b'}' => b'{',
        _ => b'<',
    }
}

fn opener_name(open: u8) -> &'static str {
    match open {
        b'(' => "(",
        b'[' => "[",
        b'{' => "{",
        _ => "mech <",
    }
}

/// Whether the text before a `<` ends with the keyword `mech`.
fn follows_mech(before: &[u8]) -> bool {
    let mut end = before.len();
    while end > 0 && matches!(before[end - 1], b' ' | b'\t' | b'\r' | b'\n') {
        end -= 1;
    }
    let Some(word_start) = end.checked_sub(4) else {
        return false;
    };
    if &before[word_start..end] != b"mech" {
        return false;
    }
    // `mech` must be a whole word, not the end of `my_mech`.
    word_start == 0 || {
        let p = before[word_start - 1];
        !(p.is_ascii_alphanumeric() || p == b'_' || p == b'\'' || p >= 0x80)
    }
}

/// The statement `buf[start..end]` (nested `depth` deep), trimmed; None
/// for a blank one.
fn make_chunk(
    buf: &[u8],
    (mut start, mut end, depth): (usize, usize, usize),
    error: Option<Diagnostic>,
) -> Option<Chunk> {
    let blank = |b: u8| matches!(b, b' ' | b'\t' | b'\r' | b'\n' | b'\x0C');
    while start < end && blank(buf[start]) {
        start += 1;
    }
    while end > start && blank(buf[end - 1]) {
        end -= 1;
    }
    if start == end && error.is_none() {
        return None;
    }
    Some(Chunk {
        span: Span::new(start, end),
        error,
        depth,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(src: &str) -> Vec<String> {
        let s = split(src);
        s.chunks
            .iter()
            .map(|c| s.text[c.span.start..c.span.end].to_string())
            .collect()
    }

    #[test]
    fn splits_on_newlines_and_semicolons() {
        assert_eq!(
            texts("a = 1; b = 2\n\n c = 3 # hi\n"),
            ["a = 1", "b = 2", "c = 3"]
        );
    }

    #[test]
    fn brackets_keep_rows_and_parens_continue() {
        assert_eq!(
            texts("M = [1, 2\n 3, 4]\nf(1,\n 2)"),
            ["M = [1, 2\n 3, 4]", "f(1,  2)"]
        );
        assert_eq!(
            texts("mech < links 4; joints 4R; planar >; x"),
            ["mech < links 4; joints 4R; planar >", "x"]
        );
    }

    #[test]
    fn comments_are_blanked() {
        assert_eq!(
            texts("[1, 2 # first (row\n 3, 4]"),
            ["[1, 2             \n 3, 4]"]
        );
    }

    #[test]
    fn unclosed_recovers_after_its_line() {
        let s = split("x = f(1\ny = 2\n");
        assert_eq!(s.chunks.len(), 2);
        assert!(s.chunks[0].error.is_some());
        assert!(s.chunks[1].error.is_none());
        // For the REPL the `(` is still open: keep reading.
        assert!(s.open_at_end);
        assert!(split("[1, 2\n").open_at_end);
        assert!(!split("x)\n[1, 2\n").open_at_end);
    }
}
