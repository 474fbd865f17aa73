//! Frame names, interned (LANGUAGE.md §6): the letters of a frame {a},
//! {world}, {b1} as a small `Copy` handle, so that a frame tag is copied and
//! compared as integers. The text is kept once for the whole process and
//! looked up only to print. One-character ASCII names (the book's {s}, {b},
//! {0}) are their own handle and never touch the table.

use std::collections::HashMap;
use std::fmt;
use std::sync::{LazyLock, Mutex};

/// The name of a frame ({s}, {b}, {world}) without its primes, interned.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Name(u32);

/// Handles below this are one ASCII character (the character's code).
const ASCII: u32 = 128;

/// Every one-character ASCII string, for printing those handles.
static ASCII_TEXT: [u8; ASCII as usize] = {
    let mut t = [0u8; ASCII as usize];
    let mut i = 0;
    while i < ASCII as usize {
        t[i] = i as u8;
        i += 1;
    }
    t
};

/// [`ASCII_TEXT`] as text, to slice one character from.
static ASCII_STR: &str = match std::str::from_utf8(&ASCII_TEXT) {
    Ok(s) => s,
    Err(_) => "",
};

/// The text of every longer name, by handle − [`ASCII`], and the way back.
#[derive(Default)]
struct Table {
    text: Vec<&'static str>,
    ids: HashMap<&'static str, u32, foldhash::fast::FixedState>,
}

static TABLE: LazyLock<Mutex<Table>> = LazyLock::new(Mutex::default);

fn table() -> std::sync::MutexGuard<'static, Table> {
    // The table is only appended to, so it is whole even after a panic.
    TABLE.lock().unwrap_or_else(|e| e.into_inner())
}

impl Name {
    /// The handle of the frame name `text` (the same text, the same handle).
    pub fn new(text: &str) -> Name {
        if let [c] = text.as_bytes()
            && u32::from(*c) < ASCII
        {
            return Name(u32::from(*c));
        }
        let mut t = table();
        if let Some(&id) = t.ids.get(text) {
            return Name(id);
        }
        let id = ASCII + u32::try_from(t.text.len()).expect("fewer than 2³² frame names");
        // Names live as long as the process: a session names few frames.
        let text: &'static str = Box::leak(text.to_owned().into_boxed_str());
        t.text.push(text);
        t.ids.insert(text, id);
        Name(id)
    }

    /// The name's text: `b` of {b}, `world` of {world}.
    pub fn as_str(self) -> &'static str {
        if self.0 < ASCII {
            let i = self.0 as usize;
            // (one ASCII byte is a whole character: no scan)
            return ASCII_STR.get(i..=i).unwrap_or("");
        }
        table().text[(self.0 - ASCII) as usize]
    }
}

impl fmt::Display for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl fmt::Debug for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}", self.as_str())
    }
}

impl From<&str> for Name {
    fn from(text: &str) -> Name {
        Name::new(text)
    }
}

impl From<String> for Name {
    fn from(text: String) -> Name {
        Name::new(&text)
    }
}

impl PartialEq<str> for Name {
    fn eq(&self, other: &str) -> bool {
        self.as_str() == other
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_text_is_the_same_name() {
        for text in ["b", "world", "b1", "0", "ω", "cam"] {
            let n = Name::new(text);
            assert_eq!(n, Name::new(text));
            assert_eq!(n.as_str(), text);
            assert_eq!(n.to_string(), text);
        }
        assert_ne!(Name::new("a"), Name::new("b"));
        assert_ne!(Name::new("world"), Name::new("cam"));
        assert_eq!(format!("{:?}", Name::new("s")), "\"s\"");
    }
}
