//! Names in the syntax tree, interned (LANGUAGE.md §2): `T_sb`, `theta_1`,
//! `exp` as a small `Copy` handle to text kept once for the whole process,
//! so that parsing a name allocates nothing after its first appearance and
//! dropping the tree frees nothing for it. Two names are equal exactly
//! when their handles are; the text reads as a `&str` without a lookup.

use std::borrow::Borrow;
use std::collections::HashSet;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::sync::{LazyLock, Mutex};

/// A name as written (a variable, function, member or type name), interned.
#[derive(Clone, Copy)]
pub struct Name(&'static str);

/// Every name seen so far; each text is kept (leaked) once, so a session
/// holds one copy of each distinct name it was given.
static TABLE: LazyLock<Mutex<HashSet<&'static str, foldhash::fast::FixedState>>> =
    LazyLock::new(Mutex::default);

impl Name {
    /// The handle of `text` (the same text, the same handle).
    pub fn new(text: &str) -> Name {
        // The table is only added to, so it is whole even after a panic.
        let mut table = TABLE.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(&kept) = table.get(text) {
            return Name(kept);
        }
        let kept: &'static str = Box::leak(text.to_owned().into_boxed_str());
        table.insert(kept);
        Name(kept)
    }

    /// The name's text.
    pub fn as_str(self) -> &'static str {
        self.0
    }
}

/// The names a parser made recently, by their text (up to 16 bytes), so
/// that a name seen again is found without the table's lock and hash: the
/// text, zero-padded, is its own key (no name contains a zero byte).
pub(crate) struct Recent {
    slots: Box<[(u128, Option<Name>); RECENT]>,
}

/// Slots in [`Recent`] (a power of two).
const RECENT: usize = 256;

impl Default for Recent {
    fn default() -> Recent {
        Recent {
            slots: Box::new([(0, None); RECENT]),
        }
    }
}

impl Recent {
    /// The handle of `text`, as [`Name::new`] gives it.
    #[inline]
    pub(crate) fn name(&mut self, text: &str) -> Name {
        let bytes = text.as_bytes();
        if bytes.is_empty() || bytes.len() > 16 {
            return Name::new(text);
        }
        let mut padded = [0u8; 16];
        padded[..bytes.len()].copy_from_slice(bytes);
        let key = u128::from_le_bytes(padded);
        let (low, high) = (key as u64, (key >> 64) as u64);
        let mixed = (low ^ high.rotate_left(32)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        let slot = &mut self.slots[(mixed >> (64 - RECENT.trailing_zeros())) as usize];
        if slot.0 == key
            && let Some(name) = slot.1
        {
            return name;
        }
        let name = Name::new(text);
        *slot = (key, Some(name));
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
        self.0.hash(state);
    }
}

impl PartialOrd for Name {
    fn partial_cmp(&self, other: &Name) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Name {
    fn cmp(&self, other: &Name) -> std::cmp::Ordering {
        self.0.cmp(other.0)
    }
}

impl std::ops::Deref for Name {
    type Target = str;
    fn deref(&self) -> &str {
        self.0
    }
}

impl AsRef<str> for Name {
    fn as_ref(&self) -> &str {
        self.0
    }
}

impl Borrow<str> for Name {
    fn borrow(&self) -> &str {
        self.0
    }
}

impl fmt::Display for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.0)
    }
}

impl fmt::Debug for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.0, f)
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
        name.0.to_owned()
    }
}

impl PartialEq<str> for Name {
    fn eq(&self, other: &str) -> bool {
        self.0 == other
    }
}

impl PartialEq<&str> for Name {
    fn eq(&self, other: &&str) -> bool {
        self.0 == *other
    }
}

impl PartialEq<String> for Name {
    fn eq(&self, other: &String) -> bool {
        self.0 == other
    }
}

impl PartialEq<Name> for String {
    fn eq(&self, other: &Name) -> bool {
        self == other.0
    }
}

impl PartialEq<Name> for str {
    fn eq(&self, other: &Name) -> bool {
        self == other.0
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
            "a_very_long_name_indeed",
            "ω",
            "Ad",
        ];
        for _ in 0..3 {
            for text in texts {
                assert_eq!(recent.name(text), Name::new(text));
                assert_eq!(recent.name(text).as_str(), text);
            }
        }
        // More names than slots: evicted names come back the same.
        let many: Vec<String> = (0..500).map(|i| format!("x_{i}")).collect();
        for text in many.iter().chain(&many) {
            assert_eq!(recent.name(text), Name::new(text));
        }
    }
}
