//! How a name keys the session's maps ([`super::env::Env`]'s bindings,
//! functions and claims): by the address of its interned text, one word
//! hashed, not the text.

use std::collections::HashMap;
use std::hash::{Hash, Hasher};

use crate::syntax::name::Name;

/// A map keyed by names, each hashed and compared by where its interned
/// text is ([`Name`]: one text, one address), so that a look-up hashes one
/// word, not the text (foldhash's fixed-seed hasher: a session's names are
/// not adversarial).
pub type NameMap<V> = HashMap<Key, V, foldhash::fast::FixedState>;

/// A name as a key of a [`NameMap`]: equal, and hashed alike, exactly when
/// the names are the same (`Name`'s own hash reads the text, to agree with
/// its `Borrow<str>`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub struct Key(pub Name);

impl Hash for Key {
    #[inline]
    fn hash<H: Hasher>(&self, state: &mut H) {
        state.write_usize(self.0.as_str().as_ptr() as usize);
    }
}

/// Anything that names a binding: a [`Name`] (no look-up) or a text (found
/// in, or added to, the table of names first).
pub trait AsKey {
    /// The key of the name.
    fn key(self) -> Key;
}

impl AsKey for Name {
    #[inline]
    fn key(self) -> Key {
        Key(self)
    }
}

impl AsKey for &Name {
    #[inline]
    fn key(self) -> Key {
        Key(*self)
    }
}

impl AsKey for &str {
    #[inline]
    fn key(self) -> Key {
        Key(Name::new(self))
    }
}

impl AsKey for &String {
    #[inline]
    fn key(self) -> Key {
        Key(Name::new(self))
    }
}

impl AsKey for Key {
    #[inline]
    fn key(self) -> Key {
        self
    }
}

impl AsKey for &Key {
    #[inline]
    fn key(self) -> Key {
        *self
    }
}
