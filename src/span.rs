//! Places in the source text: the bottom layer every other one may use.
//!
//! A [`Span`] is a byte range; every AST node and every diagnostic carries
//! one. The line counting of the whole crate lives here too: [`line_col`]
//! for one offset, [`Anchor`] for a place whose line is already known, and
//! [`Lines`], the cursor a session moves through a script statement by
//! statement, so a long script is never rescanned from its start.

/// A half-open byte range `start..end` into the source text.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Span {
    /// Byte offset where it starts.
    pub start: usize,
    /// Byte offset just past its end.
    pub end: usize,
}

impl Span {
    /// The bytes `start..end`.
    pub fn new(start: usize, end: usize) -> Span {
        Span { start, end }
    }
    /// The smallest span covering both.
    pub fn join(self, other: Span) -> Span {
        Span {
            start: self.start.min(other.start),
            end: self.end.max(other.end),
        }
    }
}

/// A place whose line is known: `offset` lies on line `line` (1-based).
/// Line numbers after it are counted from there, so reporting an error near
/// the end of a long script does not rescan the whole script.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Anchor {
    /// A byte offset into the source.
    pub offset: usize,
    /// The 1-based line it lies on.
    pub line: usize,
}

impl Anchor {
    /// The start of the text: offset 0 on line 1.
    pub const START: Anchor = Anchor { offset: 0, line: 1 };
}

impl Default for Anchor {
    fn default() -> Anchor {
        Anchor::START
    }
}

/// The largest char boundary at or before `offset` (clamped to the text).
pub fn floor_boundary(src: &str, offset: usize) -> usize {
    let mut offset = offset.min(src.len());
    while !src.is_char_boundary(offset) {
        offset -= 1;
    }
    offset
}

/// The number of `\n` bytes in `bytes`, eight at a time: the bytes of
/// `w ^ 0x0a…0a` that are zero are the newlines, and `!((x & 0x7f…) +
/// 0x7f… | x | 0x7f…)` has the high bit of exactly those bytes set (no
/// carry crosses a byte).
fn newlines(bytes: &[u8]) -> usize {
    const ONES: u64 = 0x0101_0101_0101_0101;
    const LOW7: u64 = 0x7f7f_7f7f_7f7f_7f7f;
    let mut words = bytes.chunks_exact(8);
    let mut n = 0;
    for w in &mut words {
        let x = u64::from_le_bytes(w.try_into().unwrap_or([0; 8])) ^ (ONES * u64::from(b'\n'));
        let zero = !(((x & LOW7) + LOW7) | x | LOW7);
        // One bit per newline, summed by a multiplication into the top byte.
        n += ((zero >> 7).wrapping_mul(ONES) >> 56) as usize;
    }
    n + words.remainder().iter().filter(|&&b| b == b'\n').count()
}

/// 1-based line and column (in characters) of a byte offset.
pub fn line_col(src: &str, offset: usize) -> (usize, usize) {
    line_col_from(src, offset, Anchor::START)
}

/// [`line_col`], counting lines from `anchor` when the offset lies after it.
pub fn line_col_from(src: &str, offset: usize, anchor: Anchor) -> (usize, usize) {
    let offset = floor_boundary(src, offset);
    let anchor = if anchor.offset <= offset {
        Anchor {
            offset: floor_boundary(src, anchor.offset),
            ..anchor
        }
    } else {
        Anchor::START
    };
    let line = anchor.line + newlines(&src.as_bytes()[anchor.offset..offset]);
    let line_start = src[..offset].rfind('\n').map_or(0, |i| i + 1);
    let col = src[line_start..offset].chars().count() + 1;
    (line, col)
}

/// Line numbers of increasing offsets, counted incrementally (statements
/// come in order), so a long script costs no index of its lines.
#[derive(Debug, Clone)]
pub struct Lines<'a> {
    src: &'a [u8],
    /// The start of the line the last counted offset lies on.
    start: usize,
    line: usize,
}

impl<'a> Lines<'a> {
    /// A cursor at the start of `src`, line 1.
    pub fn new(src: &'a str) -> Lines<'a> {
        Lines {
            src: src.as_bytes(),
            start: 0,
            line: 1,
        }
    }

    /// The 1-based line of `offset` (an offset before the last one restarts
    /// the count from the top).
    pub fn line(&mut self, offset: usize) -> usize {
        let offset = offset.min(self.src.len());
        if offset < self.start {
            self.start = 0;
            self.line = 1;
        }
        let seg = &self.src[self.start..offset];
        if let Some(last) = seg.iter().rposition(|&b| b == b'\n') {
            self.line += newlines(seg);
            self.start += last + 1;
        }
        self.line
    }

    /// The last counted line, as an anchor for rendering.
    pub fn anchor(&self) -> Anchor {
        Anchor {
            offset: self.start,
            line: self.line,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_col_counts_characters() {
        assert_eq!(line_col("θ = 1", 3), (1, 3));
        assert_eq!(line_col("a\nbc", 3), (2, 2));
    }

    #[test]
    fn lines_count_forward_and_restart_backward() {
        let src = "a\nb\n\nc";
        let mut l = Lines::new(src);
        assert_eq!(l.line(0), 1);
        assert_eq!(l.line(2), 2);
        assert_eq!(l.line(5), 4);
        assert_eq!(l.anchor(), Anchor { offset: 5, line: 4 });
        assert_eq!(l.line(1), 1);
        assert_eq!(line_col_from(src, 5, Anchor { offset: 2, line: 2 }), (4, 1));
    }

    #[test]
    fn newlines_are_counted_eight_bytes_at_a_time() {
        // Newlines at every place in and across eight-byte words, next to
        // bytes one bit away from `\n` (0x0b, 0x8a, 0x0a + 0x80).
        assert_eq!(newlines(b""), 0);
        assert_eq!(newlines(b"\n"), 1);
        assert_eq!(newlines(b"\n\n\n\n\n\n\n\n"), 8);
        assert_eq!(newlines(b"\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n"), 17);
        assert_eq!(newlines(b"\x0b\x8a\x0a\x09\xff\x00\x0a\x0b|\x0a"), 3);
        assert_eq!(
            newlines("T_ab = exp([S] 0.1)\nX = log(T_ac)\nθ\n".as_bytes()),
            3
        );
        for k in 0..24 {
            let mut text = vec![b'x'; 24];
            text[k] = b'\n';
            assert_eq!(newlines(&text), 1);
            assert_eq!(newlines(&text[..k]), 0);
        }
    }
}
