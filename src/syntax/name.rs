//! Names in the syntax tree, interned (LANGUAGE.md §2): `T_sb`, `theta_1`,
//! `exp` as a small `Copy` handle to text kept once for the whole process,
//! so that parsing a name allocates nothing after its first appearance and
//! dropping the tree frees nothing for it. Two names are equal exactly
//! when their handles are; the text reads as a `&str` without a lookup.

use std::borrow::Borrow;
use std::collections::HashMap;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::sync::{LazyLock, Mutex};

/// A name as written (a variable, function, member or type name), interned:
/// one pointer (8 bytes, so that an identifier in the tree is no larger
/// than its span and handle).
#[derive(Clone, Copy)]
pub struct Name(&'static String);

/// Every name seen so far; each text is kept (leaked) once, so a session
/// holds one copy of each distinct name it was given.
static TABLE: LazyLock<Mutex<HashMap<&'static str, Name, foldhash::fast::FixedState>>> =
    LazyLock::new(Mutex::default);

impl Name {
    /// The handle of `text` (the same text, the same handle).
    pub fn new(text: &str) -> Name {
        // The table is only added to, so it is whole even after a panic.
        let mut table = TABLE.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(&name) = table.get(text) {
            return name;
        }
        let kept: &'static String = Box::leak(Box::new(text.to_owned()));
        let name = Name(kept);
        table.insert(kept.as_str(), name);
        name
    }

    /// The name's text.
    pub fn as_str(self) -> &'static str {
        self.0.as_str()
    }
}

/// The names a parser made recently, by their text (up to 16 bytes), so
/// that a name seen again is found without the table's lock and hash. The
/// key is the text's first and last eight bytes read as integers (a
/// shorter text zero-padded); with the length it is the whole text.
pub(crate) struct Recent {
    slots: Box<[(u64, u64, Option<Name>); RECENT]>,
}

/// Slots in [`Recent`] (a power of two).
const RECENT: usize = 256;

impl Default for Recent {
    fn default() -> Recent {
        Recent {
            slots: Box::new([(0, 0, None); RECENT]),
        }
    }
}

impl Recent {
    /// The handle of the name `src[start..end]`, as [`Name::new`] gives it.
    #[inline(always)]
    pub(crate) fn name_in(&mut self, src: &str, start: usize, end: usize) -> Name {
        let s = src.as_bytes();
        let len = end - start;
        let word = |at: usize| {
            s.get(at..)
                .and_then(|t| t.first_chunk::<8>())
                .map(|w| u64::from_le_bytes(*w))
        };
        let key = match len {
            // Eight bytes from the name's start where the text has them
            // (no call), else the name zero-padded.
            1..=7 => match word(start) {
                Some(w) => Some((w & ((1 << (8 * len)) - 1), 0)),
                None => s.get(start..end).map(|t| {
                    let mut padded = [0; 8];
                    padded[..len].copy_from_slice(t);
                    (u64::from_le_bytes(padded), 0)
                }),
            },
            8..=16 => word(start).zip(word(end - 8)),
            _ => None,
        };
        let Some((low, high)) = key else {
            return Name::new(&src[start..end]);
        };
        let mixed = (low ^ high.rotate_left(29)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        let slot = &mut self.slots[(mixed >> (64 - RECENT.trailing_zeros())) as usize];
        if slot.0 == low
            && slot.1 == high
            && let Some(name) = slot.2
            && name.len() == len
        {
            return name;
        }
        let name = Name::new(&src[start..end]);
        *slot = (low, high, Some(name));
        name
    }
}

impl PartialEq for Name {
    fn eq(&self, other: &Name) -> bool {
        // One text, one handle: comparing addresses compares the texts.
        std::ptr::eq(self.0, other.0)
    }
}

impl Eq for Name {}

impl Hash for Name {
    fn hash<H: Hasher>(&self, state: &mut H) {
        // As `str` hashes, so that `Borrow<str>` lookups agree.
        self.as_str().hash(state);
    }
}

impl PartialOrd for Name {
    fn partial_cmp(&self, other: &Name) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Name {
    fn cmp(&self, other: &Name) -> std::cmp::Ordering {
        self.as_str().cmp(other.as_str())
    }
}

impl std::ops::Deref for Name {
    type Target = str;
    fn deref(&self) -> &str {
        self.as_str()
    }
}

impl AsRef<str> for Name {
    fn as_ref(&self) -> &str {
        self.as_str()
    }
}

impl Borrow<str> for Name {
    fn borrow(&self) -> &str {
        self.as_str()
    }
}

impl fmt::Display for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl fmt::Debug for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.as_str(), f)
    }
}

impl From<&str> for Name {
    fn from(text: &str) -> Name {
        Name::new(text)
    }
}

impl From<Name> for String {
    /// The text as an owned string (quicker than `to_string`, which
    /// goes through `Display`).
    fn from(name: Name) -> String {
        name.0.clone()
    }
}

impl PartialEq<str> for Name {
    fn eq(&self, other: &str) -> bool {
        self.as_str() == other
    }
}

impl PartialEq<&str> for Name {
    fn eq(&self, other: &&str) -> bool {
        self.as_str() == *other
    }
}

impl PartialEq<String> for Name {
    fn eq(&self, other: &String) -> bool {
        self.as_str() == other
    }
}

impl PartialEq<Name> for String {
    fn eq(&self, other: &Name) -> bool {
        self == other.as_str()
    }
}

impl PartialEq<Name> for str {
    fn eq(&self, other: &Name) -> bool {
        self == other.as_str()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_text_is_the_same_name() {
        for text in ["T_sb", "x", "theta_1", "ω_s", "T_sb'", ""] {
            let n = Name::new(text);
            assert_eq!(n, Name::new(&String::from(text)));
            assert_eq!(n.as_str(), text);
            assert_eq!(n.to_string(), text);
            assert_eq!(format!("{n:?}"), format!("{text:?}"));
        }
        assert_ne!(Name::new("T_ab"), Name::new("T_ba"));
        assert!(Name::new("a") < Name::new("b"));
        let owned = String::from("exp");
        assert!(Name::new("exp") == "exp" && owned == Name::new("exp"));
    }

    #[test]
    fn recent_names_are_the_table_names() {
        let mut recent = Recent::default();
        let texts = [
            "T_ab",
            "T_ba",
            "exp",
            "x",
            "ω",
            "Ad",
            "theta_12",
            "aaaaaaaa",
            "aaaaaaaaa",
            "aaaaaaaaaa",
            "abcdefgh_ijklmnop",
            "a_very_long_name_indeed",
        ];
        let src = texts.join(" ");
        for _ in 0..3 {
            // Each name inside a longer text, and as the whole text (no
            // eight bytes to read past a short name's end).
            let mut at = 0;
            for text in texts {
                let end = at + text.len();
                assert_eq!(recent.name_in(&src, at, end), Name::new(text));
                assert_eq!(recent.name_in(text, 0, text.len()).as_str(), text);
                at = end + 1;
            }
        }
        // More names than slots: evicted names come back the same.
        let many: Vec<String> = (0..500).map(|i| format!("x_{i}")).collect();
        for text in many.iter().chain(&many) {
            assert_eq!(recent.name_in(text, 0, text.len()), Name::new(text));
        }
    }
}
