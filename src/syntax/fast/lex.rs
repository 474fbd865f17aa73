//! The fast path's tokens: characters, names, keywords, numbers and
//! degrees, matched exactly as the grammar's `ident`, `keyword`, `number`
//! and `degrees` rules match them.

use super::P;
use crate::syntax::ast::BinOp;

pub(super) fn is_ws(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | b'\x0C')
}

pub(super) fn xid_start(c: char) -> bool {
    if c.is_ascii() {
        c.is_ascii_alphabetic()
    } else {
        pest::unicode::XID_START(c)
    }
}

pub(super) fn xid_continue(c: char) -> bool {
    if c.is_ascii() {
        c.is_ascii_alphanumeric() || c == '_'
    } else {
        pest::unicode::XID_CONTINUE(c)
    }
}

/// How a byte continues a name (`ident_at`).
#[derive(Clone, Copy)]
enum NameByte {
    /// A letter or `'`.
    Plain,
    Digit,
    Underscore,
    /// The first byte of a non-ASCII character (or a continuation byte).
    NonAscii,
    /// Ends the name.
    Other,
}

static NAME_BYTES: [NameByte; 256] = {
    let mut table = [NameByte::Other; 256];
    let mut b = 0;
    while b < 256 {
        let c = b as u8;
        table[b] = if c.is_ascii_alphabetic() || c == b'\'' {
            NameByte::Plain
        } else if c.is_ascii_digit() {
            NameByte::Digit
        } else if c == b'_' {
            NameByte::Underscore
        } else if c >= 0x80 {
            NameByte::NonAscii
        } else {
            NameByte::Other
        };
        b += 1;
    }
    table
};

/// [`ASCII_NAME`]'s bits: the byte continues an ASCII name (a letter, a
/// digit, `_` or `'`); it is a digit.
const NAME: u8 = 1;
const DIGIT: u8 = 2;

static ASCII_NAME: [u8; 256] = {
    let mut table = [0; 256];
    let mut b = 0;
    while b < 128 {
        let c = b as u8;
        table[b] = if c.is_ascii_digit() {
            NAME | DIGIT
        } else if c.is_ascii_alphabetic() || c == b'_' || c == b'\'' {
            NAME
        } else {
            0
        };
        b += 1;
    }
    table
};

/// The grammar's `keyword` (`pi`, `π`, `deg`, `true`, `false`, `given`,
/// `derive`, `mech`) or `for`, compared byte by byte.
#[inline(always)]
fn is_keyword(word: &[u8]) -> bool {
    // Slice patterns compile to a length test and byte comparisons.
    matches!(
        word,
        [b'p', b'i']
            | [0xCF, 0x80] // π
            | [b'd', b'e', b'g']
            | [b't', b'r', b'u', b'e']
            | [b'f', b'a', b'l', b's', b'e']
            | [b'g', b'i', b'v', b'e', b'n']
            | [b'd', b'e', b'r', b'i', b'v', b'e']
            | [b'm', b'e', b'c', b'h']
            | [b'f', b'o', b'r']
    )
}

impl P<'_> {
    /// `!XID_CONTINUE` at `at`.
    pub(super) fn word_ends(&self, at: usize) -> bool {
        !self.char_at(at).is_some_and(xid_continue)
    }

    /// `word ~ !XID_CONTINUE` at `at`: the end of the word.
    #[inline(always)]
    pub(super) fn keyword_at(&self, at: usize, word: &str) -> Option<usize> {
        let word = word.as_bytes();
        // Most calls fail at the first byte.
        if self.s.get(at) != word.first() {
            return None;
        }
        let end = at + word.len();
        let text = self.s.get(at..end)?;
        let same = text.iter().zip(word).all(|(a, b)| a == b);
        (same && self.word_ends(end)).then_some(end)
    }

    /// The grammar's `ident` at `at`: `Some(Some(end))`, `Some(None)` where
    /// pest's `ident` fails, `None` to give up (a braced subscript). Notes
    /// a name with a digit or a non-ASCII character for `spacing`.
    #[inline(always)]
    pub(super) fn ident_at(&mut self, at: usize) -> Option<Option<usize>> {
        let s = self.s;
        match s.get(at) {
            Some(b) if b.is_ascii_alphabetic() => {}
            Some(b) if b.is_ascii() => return Some(None),
            Some(_) => return self.ident_from(at),
            None => return Some(None),
        }
        // An ASCII name (the common case): one table look-up a byte.
        let mut i = at + 1;
        let mut seen = 0;
        while let Some(&b) = s.get(i) {
            let class = ASCII_NAME[usize::from(b)];
            if class == 0 {
                break;
            }
            seen |= class;
            i += 1;
        }
        match s.get(i) {
            // It may go on with a non-ASCII letter.
            Some(&b) if b >= 0x80 => return self.ident_from(at),
            Some(b'{') if s[i - 1] == b'_' => return None,
            _ => {}
        }
        if seen & DIGIT != 0 {
            self.stack.passes.spacing = true;
        }
        Some((!is_keyword(&s[at..i])).then_some(i))
    }

    /// [`Self::ident_at`] for a name with a non-ASCII character.
    fn ident_from(&mut self, at: usize) -> Option<Option<usize>> {
        let s = self.s;
        match s.get(at) {
            Some(b) if b.is_ascii_alphabetic() => {}
            Some(b) if b.is_ascii() => return Some(None),
            Some(_) => match self.char_at(at) {
                Some(c) if xid_start(c) && c != 'ᵀ' => {}
                _ => return Some(None),
            },
            None => return Some(None),
        }
        let mut i = at;
        let mut odd = false;
        while let Some(&b) = s.get(i) {
            match NAME_BYTES[usize::from(b)] {
                NameByte::Plain => i += 1,
                NameByte::Digit => {
                    odd = true;
                    i += 1;
                }
                NameByte::Underscore if s.get(i + 1) == Some(&b'{') => return None,
                NameByte::Underscore => i += 1,
                NameByte::Other => break,
                NameByte::NonAscii => {
                    odd = true;
                    let Some(c) = self.char_at(i) else { break };
                    // `ᵀ` is the transpose mark and `·` the dot product,
                    // never part of a name.
                    if !xid_continue(c) || c == 'ᵀ' || c == '·' {
                        break;
                    }
                    i += c.len_utf8();
                }
            }
        }
        if odd {
            self.stack.passes.spacing = true;
        }
        // `!keyword`: a keyword not followed by XID_CONTINUE or `'`, i.e.
        // the whole run of name characters.
        Some((!is_keyword(&s[at..i])).then_some(i))
    }

    /// `number`: the end of the literal at `at`, if any.
    pub(super) fn number_at(&self, at: usize) -> Option<usize> {
        let digits = |mut i: usize| {
            while self.byte(i).is_some_and(|b| b.is_ascii_digit()) {
                i += 1;
            }
            i
        };
        let mut i = digits(at);
        if i > at {
            if self.byte(i) == Some(b'.') {
                let j = digits(i + 1);
                if j > i + 1 {
                    i = j;
                } else if self.trailing_point(i + 1) {
                    // numpy's `0.`, `1.e-3`
                    i += 1;
                }
            }
        } else if self.byte(at) == Some(b'.') {
            i = digits(at + 1);
            if i == at + 1 {
                return None;
            }
        } else {
            return None;
        }
        if matches!(self.byte(i), Some(b'e' | b'E')) {
            let mut j = i + 1;
            if matches!(self.byte(j), Some(b'+' | b'-')) {
                j += 1;
            }
            let k = digits(j);
            if k > j {
                i = k;
            }
        }
        Some(i)
    }

    /// After `2.`: `!("." | XID_START) | &(^"e" ~ ("+" | "-")? ~ ASCII_DIGIT)`.
    fn trailing_point(&self, at: usize) -> bool {
        match self.char_at(at) {
            Some('e' | 'E') => {
                let j = at + 1 + usize::from(matches!(self.byte(at + 1), Some(b'+' | b'-')));
                self.byte(j).is_some_and(|b| b.is_ascii_digit())
            }
            Some(c) => !(c == '.' || xid_start(c)),
            None => true,
        }
    }

    /// `superscript` at `at` (`²`, `⁻¹`): its end.
    pub(super) fn superscript_at(&self, at: usize) -> Option<usize> {
        const DIGITS: &str = "⁰¹²³⁴⁵⁶⁷⁸⁹";
        let rest = &self.src[at..];
        let body = rest.strip_prefix('⁻').unwrap_or(rest);
        let digits: usize = body
            .chars()
            .take_while(|&c| DIGITS.contains(c))
            .map(char::len_utf8)
            .sum();
        (digits > 0).then(|| at + (rest.len() - body.len()) + digits)
    }

    /// A sign at `at`: `+`, `-` or the book's `−`, and its width.
    pub(super) fn sign_at(&self, at: usize) -> Option<(BinOp, usize)> {
        match self.byte(at)? {
            b'+' => Some((BinOp::Add, 1)),
            b'-' => Some((BinOp::Sub, 1)),
            0xE2 if self.src[at..].starts_with('−') => Some((BinOp::Sub, '−'.len_utf8())),
            _ => None,
        }
    }

    /// `degrees` at `at`: its end.
    pub(super) fn degrees_at(&self, at: usize) -> Option<usize> {
        match self.byte(at)? {
            0xC2 if self.src[at..].starts_with('°') => Some(at + '°'.len_utf8()),
            b'd' => self.keyword_at(at, "deg"),
            _ => None,
        }
    }
}
