//! The calculus on recipes (LANGUAGE.md §7: "binding numbers later makes
//! them numeric … exactly as if the numbers had been typed first"), below
//! the interpreter: a value made over `given` symbols read with the numbers
//! bound since (`substitute`, over the trees of `resolve`), the warnings of
//! such reads once per binding of their numbers (`warned`), what
//! `diff` and `subs` by a symbol that has a number may read (`held`), and
//! `diff` of a call kept over symbols once its numbers are bound (`kept`). It
//! sees the session's bindings only through [`Bindings`], which the
//! interpreter's environment ([`crate::eval::env::Env`]) implements; it
//! replays recipes with numbers through [`crate::decide`]'s replay and
//! applies operations through [`crate::seam`]. Imports nothing from
//! [`crate::eval`].

mod formula_now;
pub(crate) mod held;
mod kept;
mod kinds;
pub(crate) mod put;
pub(crate) mod resolve;
pub(crate) mod substitute;
pub(crate) mod warned;

use crate::check::ty::Kind;
use crate::syntax::name::Name;
use crate::values::value::Value;

/// A name's binding as the calculus reads it: the value bound now (a
/// `given` symbol's own symbol, or numbers bound to it since), the kind
/// the checker gave it, and how it was bound.
#[derive(Debug, Clone, Copy)]
pub struct Bound<'a> {
    /// The value, if evaluated (none when only checking).
    pub val: Option<&'a Value>,
    /// The kind the checker gave the expression bound (a twist, a wrench:
    /// more than its numbers say).
    pub kind: Kind,
    /// True for a `given` symbol (its value is the symbol itself).
    pub symbolic: bool,
    /// True for a list or tuple holding values made from symbols: reading
    /// it puts the numbers bound since into its items.
    pub derived: bool,
}

/// The session's bindings by name, as the calculus reads them (the
/// interpreter's environment: [`crate::eval::env::Env`]).
pub trait Bindings {
    /// The binding of `name` as read now: while `diff` or `subs` holds the
    /// `given` names, a held name's is its symbol's (§7).
    fn binding(&self, name: Name) -> Option<Bound<'_>>;
    /// Whether `name` was declared by `given`, or is a rate `q'`, `q''` of
    /// a given function of time.
    fn is_given(&self, name: Name) -> bool;
    /// The value `name` was declared with by `given` (its symbol), also
    /// after numbers are bound to it.
    fn declared(&self, name: Name) -> Option<&Value>;
}
