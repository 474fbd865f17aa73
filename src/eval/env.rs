//! The session state: bindings with their static type (kind and frames)
//! and, when running, their value; user functions; settings.

use std::collections::HashMap;
use std::rc::Rc;

use super::value::{UserFn, Value};
use crate::check::bind::Claim;
use crate::check::ty::Ty;
use crate::syntax::name::Name;

/// A map keyed by names, with a hash fast on short keys (foldhash's
/// fixed-seed hasher: a session's names are not adversarial).
pub type NameMap<V> = HashMap<String, V, foldhash::fast::FixedState>;

/// What to do with a frame mismatch (`--frames strict|warn|off`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FrameMode {
    /// An error (the default).
    #[default]
    Strict,
    /// A warning; the result is untagged.
    Warn,
    /// Ignored; the result is untagged.
    Off,
}

impl FrameMode {
    pub fn parse(s: &str) -> Option<FrameMode> {
        match s {
            "strict" => Some(FrameMode::Strict),
            "warn" => Some(FrameMode::Warn),
            "off" => Some(FrameMode::Off),
            _ => None,
        }
    }
    pub fn as_str(self) -> &'static str {
        match self {
            FrameMode::Strict => "strict",
            FrameMode::Warn => "warn",
            FrameMode::Off => "off",
        }
    }
}

/// Check only (no numbers) or check and evaluate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// `chasles check`: types and frames only.
    Check,
    /// `chasles run`, `-e`, the REPL: types, frames and values.
    Run,
}

/// A name's binding: its static type and (when running) its value.
#[derive(Debug, Clone)]
pub struct Binding {
    pub ty: Ty,
    pub val: Option<Value>,
    /// True for `given` symbols.
    pub symbolic: bool,
}

/// All bindings of a session. Statements only insert after they succeed,
/// so an error never leaves a partial change behind.
#[derive(Debug, Clone, Default)]
pub struct Env {
    pub vars: NameMap<Binding>,
    pub fns: NameMap<Rc<UserFn>>,
    /// What each name bound so far says about its value (the frames of its
    /// subscript, its book letter), read once per name; keyed by where the
    /// name's interned text is ([`Name`]: one text, one address), so a
    /// look-up hashes two words, not the text.
    claims: HashMap<(usize, usize), Claim, foldhash::fast::FixedState>,
    /// The types of the arguments of the builtin calls being checked, as a
    /// stack: each call pushes its own and pops them when it returns. Kept
    /// here so that its storage outlives one statement's interpreter.
    pub(super) arg_tys: Vec<Ty>,
}

impl Env {
    #[inline]
    pub fn get(&self, name: &str) -> Option<&Binding> {
        self.vars.get(name)
    }
    #[inline]
    pub fn set(&mut self, name: &str, b: Binding) {
        // Rebinding a name (the common case in a long script) keeps its key.
        match self.vars.get_mut(name) {
            Some(old) => *old = b,
            None => {
                self.vars.insert(name.to_string(), b);
            }
        }
    }
    /// Binds `name` to a copy of a checked value (not a `given` symbol),
    /// reusing the old binding's storage when the name is bound already.
    #[inline]
    pub fn set_value(&mut self, name: &str, ty: &Ty, val: Option<&Value>) {
        match self.vars.get_mut(name) {
            Some(old) => {
                old.ty = *ty;
                match (&mut old.val, val) {
                    (Some(o), Some(v)) => o.clone_from(v),
                    // Checking: no value before, none now.
                    (None, None) => {}
                    (o, v) => *o = v.cloned(),
                }
                old.symbolic = false;
            }
            None => {
                let b = Binding {
                    ty: *ty,
                    val: val.cloned(),
                    symbolic: false,
                };
                self.vars.insert(name.to_string(), b);
            }
        }
    }
    /// What `name` says about a value bound to it ([`Claim::of`]), read
    /// from the name the first time only.
    #[inline]
    pub fn claim(&mut self, name: Name) -> Claim {
        let text = name.as_str();
        let key = (text.as_ptr() as usize, text.len());
        if let Some(c) = self.claims.get(&key) {
            return *c;
        }
        let c = Claim::of(text);
        self.claims.insert(key, c);
        c
    }
    /// Names in sorted order (for `:vars` and derive's deterministic search).
    pub fn names(&self) -> Vec<&String> {
        let mut v: Vec<&String> = self.vars.keys().collect();
        v.sort();
        v
    }
}
