//! Control characters shown escaped (LANGUAGE.md §1): a script, a file
//! name or an argument must not be able to move the cursor, change colours
//! or ring the bell of the terminal that reads chasles' messages. NUL is
//! `\0`, ESC `\x1b`, other C0 and C1 controls and DEL `\xNN` or `\u{NN}`;
//! newlines stay newlines only where a caller keeps them (`keep_newline`).

use std::borrow::Cow;

/// Whether `c` would act on a terminal rather than print.
fn is_control(c: char) -> bool {
    c.is_control()
        || matches!(c, '\u{2028}' | '\u{2029}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
}

/// One control character, escaped.
fn push_escaped(out: &mut String, c: char) {
    match c {
        '\0' => out.push_str("\\0"),
        '\t' => out.push_str("\\t"),
        '\n' => out.push_str("\\n"),
        '\r' => out.push_str("\\r"),
        c if (c as u32) < 0x100 => out.push_str(&format!("\\x{:02x}", c as u32)),
        c => out.push_str(&format!("\\u{{{:x}}}", c as u32)),
    }
}

/// `s` with every control character escaped (newlines and tabs too: for
/// one-line texts such as file names and messages).
pub fn controls(s: &str) -> Cow<'_, str> {
    escape(s, false)
}

/// `s` with control characters escaped, keeping newlines and tabs (for
/// text of several lines such as a rendered diagnostic).
pub fn controls_keep_lines(s: &str) -> Cow<'_, str> {
    escape(s, true)
}

fn escape(s: &str, keep_lines: bool) -> Cow<'_, str> {
    let kept = |c: char| keep_lines && matches!(c, '\n' | '\t');
    if !s.chars().any(|c| is_control(c) && !kept(c)) {
        return Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        if is_control(c) && !kept(c) {
            push_escaped(&mut out, c);
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

/// Bytes that may not be UTF-8 (a command-line argument, a file name), as
/// text: valid UTF-8 as it is with controls escaped, other bytes as `\xNN`.
pub fn bytes(b: &[u8]) -> String {
    let mut out = String::new();
    for chunk in b.utf8_chunks() {
        out.push_str(&controls(chunk.valid()));
        for x in chunk.invalid() {
            out.push_str(&format!("\\x{x:02x}"));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn controls_are_escaped_and_plain_text_borrowed() {
        assert!(matches!(controls("T_ab ≠ T_ba"), Cow::Borrowed(_)));
        assert_eq!(controls("a\0b\x1b[31mc\x07"), "a\\0b\\x1b[31mc\\x07");
        assert_eq!(controls("x\ny"), "x\\ny");
        assert_eq!(controls_keep_lines("x\ny\r"), "x\ny\\r");
        assert_eq!(controls("\u{9b}2J"), "\\x9b2J");
        assert_eq!(controls("\u{202e}abc"), "\\u{202e}abc");
        assert_eq!(bytes(b"bad\xff.chs"), "bad\\xff.chs");
        assert_eq!(bytes(b"\x1b]0;x\x07"), "\\x1b]0;x\\x07");
    }
}
