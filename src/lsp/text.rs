//! An open document as the server keeps it (LANGUAGE.md §15): its text,
//! edited in place by the client's incremental changes, and the mapping
//! between the protocol's positions (a line and a column counted in UTF-16
//! code units, or in bytes where the client agreed to UTF-8) and the byte
//! offsets every [`crate::span::Span`] uses.

use lsp_types::{Position, Range, TextDocumentContentChangeEvent};

use crate::span::Span;

/// How the client counts columns: UTF-16 code units (the protocol's
/// default) or bytes (`positionEncoding: "utf-8"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Encoding {
    /// UTF-16 code units, the protocol's default.
    #[default]
    Utf16,
    /// Bytes, where the client offers `utf-8`.
    Utf8,
}

/// One open `.chs` document.
#[derive(Debug, Clone, Default)]
pub struct Document {
    /// The text as the editor holds it.
    pub text: String,
    /// The client's version of the text (diagnostics name it).
    pub version: i32,
    /// The byte offset where each line starts (line 0 at 0).
    starts: Vec<usize>,
}

impl Document {
    /// A document holding `text` at `version`.
    pub fn new(text: String, version: i32) -> Document {
        let mut d = Document {
            text,
            version,
            starts: Vec::new(),
        };
        d.index();
        d
    }

    fn index(&mut self) {
        self.starts.clear();
        self.starts.push(0);
        self.starts.extend(
            self.text
                .bytes()
                .enumerate()
                .filter(|(_, b)| *b == b'\n')
                .map(|(i, _)| i + 1),
        );
    }

    /// The number of lines (a final line without `\n` counts).
    pub fn lines(&self) -> usize {
        self.starts.len()
    }

    /// The text of line `line` (0-based), without its line break.
    pub fn line(&self, line: usize) -> &str {
        let Some(&start) = self.starts.get(line) else {
            return "";
        };
        let end = self.starts.get(line + 1).map_or(self.text.len(), |e| e - 1);
        self.text[start..end].trim_end_matches('\r')
    }

    /// The byte offset of `pos` (clamped to its line and to the text; a
    /// column inside a character lands at its start).
    pub fn offset(&self, pos: Position, enc: Encoding) -> usize {
        let line = pos.line as usize;
        let Some(&start) = self.starts.get(line) else {
            return self.text.len();
        };
        let text = self.line(line);
        let want = pos.character as usize;
        let mut units = 0;
        for (i, c) in text.char_indices() {
            units += match enc {
                Encoding::Utf16 => c.len_utf16(),
                Encoding::Utf8 => c.len_utf8(),
            };
            // (past `want` only when it falls inside `c`: its start)
            if units > want {
                return start + i;
            }
        }
        start + text.len()
    }

    /// The position of byte `offset`.
    pub fn position(&self, offset: usize, enc: Encoding) -> Position {
        let offset = crate::span::floor_boundary(&self.text, offset);
        let line = self.starts.partition_point(|&s| s <= offset) - 1;
        let before = &self.text[self.starts[line]..offset];
        let character = match enc {
            Encoding::Utf16 => before.encode_utf16().count(),
            Encoding::Utf8 => before.len(),
        };
        Position::new(line as u32, character as u32)
    }

    /// The range of a byte span.
    pub fn range(&self, span: Span, enc: Encoding) -> Range {
        Range::new(self.position(span.start, enc), self.position(span.end, enc))
    }

    /// Applies one change from `textDocument/didChange`: a range replaced,
    /// or the whole text when the change has no range.
    pub fn apply(&mut self, change: &TextDocumentContentChangeEvent, enc: Encoding) {
        match change.range {
            Some(r) => {
                let start = self.offset(r.start, enc);
                let end = self.offset(r.end, enc).max(start);
                self.text.replace_range(start..end, &change.text);
            }
            None => self.text.clone_from(&change.text),
        }
        self.index();
    }

    /// The name at byte `offset` (a binding, a builtin, a keyword, with a
    /// braced subscript as in `T_{world,cam}`, §2): its span, if the offset
    /// touches one (its end included, where the cursor stands after typing).
    pub fn word_at(&self, offset: usize) -> Option<Span> {
        let offset = crate::span::floor_boundary(&self.text, offset);
        let line_start = self.text[..offset].rfind('\n').map_or(0, |i| i + 1);
        let line_end = self.text[offset..]
            .find('\n')
            .map_or(self.text.len(), |i| offset + i);
        let line = &self.text[line_start..line_end];
        let mut chars = line.char_indices().peekable();
        while let Some((i, c)) = chars.next() {
            if !is_name_char(c) {
                continue;
            }
            let mut end = i + c.len_utf8();
            let mut last = c;
            while let Some(&(j, d)) = chars.peek() {
                if is_name_char(d) {
                    end = j + d.len_utf8();
                    last = d;
                    chars.next();
                } else if d == '{' && last == '_' {
                    // A braced subscript: through its `}` and any primes.
                    let Some(close) = line[j..].find('}') else {
                        break;
                    };
                    end = j + close + 1;
                    end += line[end..].chars().take_while(|p| *p == '\'').count();
                    while chars.peek().is_some_and(|&(k, _)| k < end) {
                        chars.next();
                    }
                    break;
                } else {
                    break;
                }
            }
            let (s, e) = (line_start + i, line_start + end);
            if s <= offset && offset <= e {
                return (!c.is_ascii_digit()).then(|| Span::new(s, e));
            }
            if s > offset {
                break;
            }
        }
        None
    }
}

/// Whether `c` may be part of a name (letters, digits, `_`, a prime).
pub fn is_name_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_' || c == '\''
}

#[cfg(test)]
mod tests {
    use super::*;

    fn change(l0: u32, c0: u32, l1: u32, c1: u32, text: &str) -> TextDocumentContentChangeEvent {
        TextDocumentContentChangeEvent {
            range: Some(Range::new(Position::new(l0, c0), Position::new(l1, c1))),
            range_length: None,
            text: text.into(),
        }
    }

    #[test]
    fn columns_count_utf16_units_or_bytes() {
        let d = Document::new("θ = 1\nR_ab = Rotz(θ)\n".into(), 1);
        // θ is one UTF-16 unit and two bytes.
        assert_eq!(d.offset(Position::new(0, 1), Encoding::Utf16), 2);
        assert_eq!(d.offset(Position::new(0, 2), Encoding::Utf8), 2);
        let at = d.text.rfind('θ').unwrap();
        assert_eq!(d.position(at, Encoding::Utf16), Position::new(1, 12));
        assert_eq!(d.position(at + 2, Encoding::Utf8), Position::new(1, 14));
        // Inside a character (𝜃 is two UTF-16 units, four bytes): its start.
        let d2 = Document::new("𝜃 + 1".into(), 1);
        assert_eq!(d2.offset(Position::new(0, 1), Encoding::Utf16), 0);
        assert_eq!(d2.offset(Position::new(0, 2), Encoding::Utf16), 4);
        assert_eq!(d2.offset(Position::new(0, 3), Encoding::Utf8), 0);
        // Past the line's end: clamped to it (θ = 1 is 6 bytes).
        assert_eq!(d.offset(Position::new(0, 99), Encoding::Utf16), 6);
        assert_eq!(d.lines(), 3);
    }

    #[test]
    fn incremental_changes_edit_in_place() {
        let mut d = Document::new("T_ab * T_cb\nx = 1\n".into(), 1);
        d.apply(&change(0, 10, 0, 11, "a"), Encoding::Utf16);
        assert_eq!(d.text, "T_ab * T_ca\nx = 1\n");
        d.apply(&change(1, 0, 1, 5, "θ = 2"), Encoding::Utf16);
        d.apply(&change(1, 1, 1, 1, "₁"), Encoding::Utf16);
        assert_eq!(d.line(1), "θ₁ = 2");
        d.apply(&change(0, 0, 2, 0, ""), Encoding::Utf16);
        assert_eq!((d.text.as_str(), d.lines()), ("", 1));
        // A change without a range replaces the whole text.
        let all = TextDocumentContentChangeEvent {
            range: None,
            range_length: None,
            text: "a\nb".into(),
        };
        d.apply(&all, Encoding::Utf8);
        assert_eq!((d.line(1), d.lines()), ("b", 2));
    }

    #[test]
    fn the_word_under_the_cursor() {
        let d = Document::new("T_sb' = exp([S] θ) M".into(), 1);
        let w = d.word_at(2).unwrap();
        assert_eq!(&d.text[w.start..w.end], "T_sb'");
        let at = d.text.find("exp").unwrap() + 3;
        let w = d.word_at(at).unwrap();
        assert_eq!(&d.text[w.start..w.end], "exp");
        assert!(d.word_at(d.text.find('=').unwrap() + 1).is_none());
        let d = Document::new("x = T_{world,cam}' * p_{cam}\n2.5".into(), 1);
        let inside = d.text.find("cam").unwrap();
        let w = d.word_at(inside).unwrap();
        assert_eq!(&d.text[w.start..w.end], "T_{world,cam}'");
        let w = d.word_at(d.text.len() - 6).unwrap();
        assert_eq!(&d.text[w.start..w.end], "p_{cam}");
        assert!(d.word_at(d.text.len() - 1).is_none(), "a number is no name");
    }
}
