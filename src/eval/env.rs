//! The session state: bindings with their static type (kind and frames)
//! and, when running, their value; user functions; settings.

use std::rc::Rc;
use std::sync::LazyLock;

use super::value::{UserFn, Value};
use crate::builtins::{self, Builtin};
use crate::check::bind::Claim;
use crate::check::ty::Ty;
use crate::diagnostics::{Diagnostic, Severity};
use crate::syntax::name::Name;

pub use super::key::{AsKey, Key, NameMap};

/// `ans`, the name an expression statement binds its value to.
pub static ANS: LazyLock<Name> = LazyLock::new(|| Name::new("ans"));

/// `I`, the identity, unless the session binds the name.
pub static IDENTITY: LazyLock<Name> = LazyLock::new(|| Name::new("I"));

/// `e`, Euler's number, unless the session binds the name.
pub static EULER: LazyLock<Name> = LazyLock::new(|| Name::new("e"));

/// `exp`, the builtin the book's `[S] θ` juxtaposition calls (3.51, 3.88).
pub static EXP: LazyLock<Name> = LazyLock::new(|| Name::new("exp"));

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
    /// The mode `--frames` names (`strict`, `warn`, `off`), or None.
    pub fn parse(s: &str) -> Option<FrameMode> {
        match s {
            "strict" => Some(FrameMode::Strict),
            "warn" => Some(FrameMode::Warn),
            "off" => Some(FrameMode::Off),
            _ => None,
        }
    }
    /// The mode's name as `--frames` takes it.
    pub fn as_str(self) -> &'static str {
        match self {
            FrameMode::Strict => "strict",
            FrameMode::Warn => "warn",
            FrameMode::Off => "off",
        }
    }
    /// The policy for a refused operation: a frame mismatch (`frame`) is
    /// an error when strict, a warning when `warn`, nothing when `off`; any
    /// other refusal is an error. Ok when evaluation goes on (with the
    /// operands' frames dropped).
    pub fn refusal(
        self,
        frame: bool,
        mut d: Diagnostic,
        warnings: &mut Vec<Diagnostic>,
    ) -> Result<(), Diagnostic> {
        match (frame, self) {
            (false, _) | (true, FrameMode::Strict) => Err(d),
            (true, FrameMode::Warn) => {
                d.severity = Severity::Warning;
                warnings.push(d);
                Ok(())
            }
            (true, FrameMode::Off) => Ok(()),
        }
    }
    /// The policy for a warning about frames (a name that renames a moved
    /// frame): kept unless frames are `off`.
    pub fn warning(self, d: Diagnostic, warnings: &mut Vec<Diagnostic>) {
        if self != FrameMode::Off {
            warnings.push(d);
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
    /// The kind and frames the checker gave the name.
    pub ty: Ty,
    /// The value (for a `given` symbol, the symbol itself); None when only
    /// checked, with no numbers.
    pub val: Option<Value>,
    /// True for `given` symbols.
    pub symbolic: bool,
    /// True for a list or tuple holding values made from symbols: reading
    /// it puts the numbers bound since into its items (§7). [`Env::set`]
    /// and [`Env::set_value`] decide it from the value (a list is looked
    /// through once, when it is bound, not at every read).
    pub derived: bool,
    /// When it was bound: [`Env::set`] and [`Env::set_value`] give each
    /// binding a new stamp (a value bound later warns once per binding of
    /// the numbers it reads, `crate::calculus::warned`).
    pub stamp: u64,
    /// The `given` names (and rates `q'`) whose numbers the value was
    /// computed from: it holds those numbers, not the symbols, so `diff`
    /// and `subs` by them, which read the symbols ([`Env::hold`]), refuse
    /// it (§7, `crate::calculus::held`).
    pub absorbed: Vec<Name>,
}

impl Binding {
    /// A `given` symbol of type `ty` (its value the symbol itself).
    pub fn given(ty: Ty, val: Value) -> Binding {
        Binding {
            ty,
            val: Some(val),
            symbolic: true,
            derived: false,
            stamp: 0,
            absorbed: Vec::new(),
        }
    }
    /// The binding as the calculus on recipes reads it
    /// ([`crate::calculus::Bound`]).
    #[inline]
    pub fn bound(&self) -> crate::calculus::Bound<'_> {
        crate::calculus::Bound {
            val: self.val.as_ref(),
            kind: self.ty.kind,
            symbolic: self.symbolic,
            derived: self.derived,
        }
    }
}

/// A value a binding is made from ([`Env::set_made`]): lent, and
/// copied into the binding (its numbers shared), or given, and moved in.
pub enum Stored<'a> {
    /// Lent: copied into the binding, its numbers shared.
    Copied(&'a Value),
    /// Given: moved into the binding.
    Moved(Box<Value>),
}

impl Stored<'_> {
    /// The value.
    pub fn get(&self) -> &Value {
        match self {
            Stored::Copied(v) => v,
            Stored::Moved(v) => v,
        }
    }
    /// The value, owned: a copy of one lent.
    fn into_value(self) -> Value {
        match self {
            Stored::Copied(v) => v.clone(),
            Stored::Moved(v) => *v,
        }
    }
}

/// Whether a binding of `v` is [`Binding::derived`].
#[inline]
fn derived(v: Option<&Value>) -> bool {
    matches!(v, Some(v @ (Value::List(_) | Value::Tuple(_))) if crate::values::recipe::holds_symbols(v))
}

/// The builtins called so far, by name (none where a name is no builtin).
#[derive(Clone, Default)]
struct Called(NameMap<Option<(&'static Builtin, &'static str)>>);

impl std::fmt::Debug for Called {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let names = self.0.iter().map(|(k, b)| (k.0, b.map(|(b, _)| b.name)));
        f.debug_map().entries(names).finish()
    }
}

/// A binding whose closed form took `axes` as unit vectors (LANGUAGE.md
/// §7, `super::relied`): its name and the stamp of the binding (a name
/// bound again relies on nothing).
#[derive(Debug, Clone)]
pub struct Relied {
    pub(super) name: String,
    pub(super) stamp: u64,
    pub(super) axes: Vec<std::sync::Arc<str>>,
}

/// All bindings of a session. Statements only insert after they succeed,
/// so an error never leaves a partial change behind.
#[derive(Debug, Clone, Default)]
pub struct Env {
    /// Each bound name (values, `given` symbols, `ans`) with its binding.
    pub vars: NameMap<Binding>,
    /// The user functions `f(x) = …` by name.
    pub fns: NameMap<Rc<UserFn>>,
    /// What each name bound so far says about its value (the frames of its
    /// subscript, its book letter), read once per name.
    claims: NameMap<Claim>,
    /// The builtin each name called so far is ([`builtins::lookup`]), found
    /// in the builtins' table the first time only.
    builtins: Called,
    /// The types of the arguments of the builtin calls being checked, as a
    /// stack: each call pushes its own and pops them when it returns. Kept
    /// here so that its storage outlives one statement's interpreter.
    pub(super) arg_tys: Vec<Ty>,
    /// The numbers the bindings hold ([`numbers`]), for the run's memory
    /// budget ([`crate::budget`]).
    held: u64,
    /// The `given` axes already said to be assumed unit vectors (the note
    /// of `super::lower`, once a session).
    pub(super) units_noted: Vec<String>,
    /// The bindings whose closed form took some of those axes as unit
    /// vectors (`super::relied`).
    pub(super) relied: Vec<Relied>,
    /// The last stamp given to a binding ([`Binding::stamp`]).
    stamp: u64,
    /// The warnings given by reads of values bound later (once per
    /// binding of their numbers).
    pub(super) warned: crate::calculus::warned::Warned,
    /// The binding each `given` name was declared with (its symbol), kept
    /// after numbers are bound to it: [`Env::hold`] reads it again.
    givens: NameMap<Binding>,
    /// The names read as their `given` symbols, not their numbers, while
    /// `diff` or `subs` evaluates its operands ([`Env::hold`]).
    holding: Vec<Key>,
    /// The `given` names whose numbers the current statement has read, each
    /// with the name it read it through (`super::hold`); what it binds has
    /// them as [`Binding::absorbed`]. Kept here, as `arg_tys` is, so that
    /// its storage outlives one statement's interpreter.
    pub(super) numbers_read: Vec<(Name, Name)>,
    /// Which source text the session runs now (each script, prelude, REPL
    /// input or notebook cell is a new one): a function defined in another
    /// has spans that do not point into this text ([`UserFn::source`]).
    pub source: u64,
    /// The names bound to a number written with literals, each with the
    /// stamp of that binding (`super::literals`).
    pub(super) literals: NameMap<(u64, f64)>,
}

/// The numbers a value holds, as the memory budget counts them
/// ([`crate::budget`]): its entries, a list's or tuple's items' own, a
/// picture's items', one for anything else; and the recipe of an exact
/// form, a number for each 8 of its bytes ([`Exact::weight`]: `[sin(t)
/// for t in 0:0.001:500]` holds each sine's recipe). A list bound to two
/// names counts twice.
///
/// [`Exact::weight`]: crate::values::exact::Exact::weight
#[inline]
pub fn numbers(v: &Value) -> u64 {
    // (a number, vector or matrix in place; the containers out of line)
    match v {
        Value::Num { m, exact, .. } => m.len() as u64 + exact.weight() / 8,
        _ => numbers_within(v),
    }
}

/// [`numbers`] of a value that is not one array of numbers.
fn numbers_within(v: &Value) -> u64 {
    match v {
        Value::Num { m, exact, .. } => m.len() as u64 + exact.weight() / 8,
        Value::Tuple(vs) => vs.iter().map(numbers).sum(),
        Value::List(vs) => vs.iter().map(numbers).sum::<u64>() + vs.len() as u64,
        Value::Formula { m, .. } => (m.rows * m.cols) as u64,
        Value::Picture(p) => p
            .panels
            .iter()
            .flat_map(|p| &p.items)
            .map(|d| numbers(&d.value))
            .sum(),
        Value::Str(s) => s.len() as u64 / 8 + 1,
        _ => 1,
    }
}

fn binding_numbers(b: &Binding) -> u64 {
    b.val.as_ref().map_or(0, numbers)
}

impl Env {
    /// The binding of `name`; while [`Env::hold`] is in force, a `given`
    /// name bound to a number is read as its symbol.
    #[inline]
    pub fn get(&self, name: impl AsKey) -> Option<&Binding> {
        let key = name.key();
        if self.holding.is_empty() {
            return self.vars.get(&key);
        }
        self.get_held(key)
    }
    /// [`Env::get`] while [`Env::hold`] is in force.
    #[cold]
    fn get_held(&self, key: Key) -> Option<&Binding> {
        if self.holding.contains(&key) {
            // (a rate `q'` has no binding of its own: it is read as q's)
            return self.givens.get(&key);
        }
        self.vars.get(&key)
    }
    /// The binding of `name` as it is, held or not ([`Env::hold`]): what a
    /// call saves to restore.
    #[inline]
    pub fn get_unheld(&self, name: impl AsKey) -> Option<&Binding> {
        self.vars.get(&name.key())
    }
    /// Binds `name` to `b`, replacing any binding it had (a rebound name is
    /// no longer held).
    #[inline]
    pub fn set(&mut self, name: impl AsKey, mut b: Binding) {
        let key = name.key();
        b.derived = derived(b.val.as_ref());
        self.stamp += 1;
        b.stamp = self.stamp;
        self.held += binding_numbers(&b);
        if b.symbolic {
            self.givens.insert(key, b.clone());
        }
        // (a name bound anew, a function's parameter, is no longer held)
        if !self.holding.is_empty() {
            self.holding.retain(|k| *k != key);
        }
        if let Some(old) = self.vars.insert(key, b) {
            self.held = self.held.saturating_sub(binding_numbers(&old));
        }
    }
    /// Of `warnings`, given by reading `name` now, those that reading the
    /// same value with the same bindings of its symbols has not given
    /// already ([`crate::calculus::warned`]: once per binding of its numbers).
    pub(super) fn fresh_warnings(
        &mut self,
        name: &str,
        warnings: Vec<crate::diagnostics::Diagnostic>,
    ) -> Vec<crate::diagnostics::Diagnostic> {
        let mut warned = std::mem::take(&mut self.warned);
        let out = match self.get(name) {
            Some(Binding {
                val: Some(v),
                stamp,
                ..
            }) => {
                let stamp_of = |n: &str| self.get(n).map_or(0, |b| b.stamp);
                warned.keep(name, v, *stamp, &stamp_of, warnings)
            }
            _ => warnings,
        };
        self.warned = warned;
        out
    }
    /// The numbers the bindings hold ([`numbers`]).
    pub fn held(&self) -> u64 {
        self.held
    }
    /// Binds `name` to a copy of a checked value (not a `given` symbol),
    /// reusing the old binding's storage when the name is bound already.
    #[inline]
    pub fn set_value(&mut self, name: impl AsKey, ty: &Ty, val: Option<&Value>) {
        self.set_made(name, ty, val.map(Stored::Copied), &[]);
    }
    /// [`Env::set_value`] of a value lent (copied into the binding) or
    /// given (moved: a statement silenced by `;`, whose value nothing
    /// shows), computed from the numbers of the `given` names `absorbed`
    /// ([`Binding::absorbed`]).
    #[inline(always)]
    pub fn set_made(
        &mut self,
        name: impl AsKey,
        ty: &Ty,
        val: Option<Stored<'_>>,
        absorbed: &[Name],
    ) {
        let key = name.key();
        self.stamp += 1;
        let counted = val.as_ref().map_or(0, |v| numbers(v.get()));
        let derived = derived(val.as_ref().map(Stored::get));
        match self.vars.get_mut(&key) {
            Some(old) => {
                self.held = self.held.saturating_sub(binding_numbers(old)) + counted;
                old.ty = *ty;
                match (&mut old.val, val) {
                    (Some(o), Some(Stored::Copied(v))) => o.clone_from(v),
                    // Checking: no value before, none now.
                    (None, None) => {}
                    (o, v) => *o = v.map(Stored::into_value),
                }
                old.symbolic = false;
                old.derived = derived;
                old.stamp = self.stamp;
                if !(old.absorbed.is_empty() && absorbed.is_empty()) {
                    old.absorbed.clear();
                    old.absorbed.extend_from_slice(absorbed);
                }
            }
            None => {
                self.held += counted;
                let b = Binding {
                    ty: *ty,
                    val: val.map(Stored::into_value),
                    symbolic: false,
                    derived,
                    stamp: self.stamp,
                    absorbed: absorbed.to_vec(),
                };
                self.vars.insert(key, b);
            }
        }
    }
    /// What `name` says about a value bound to it ([`Claim::of`]), read
    /// from the name the first time only.
    #[inline]
    pub fn claim(&mut self, name: Name) -> Claim {
        *self
            .claims
            .entry(Key(name))
            .or_insert_with(|| Claim::of(name.as_str()))
    }
    /// `given name : free` (or `: point`): from now on `name` says its
    /// vector is `role` ([`crate::check::role`]); the claim it makes now.
    pub fn declare_role(&mut self, name: Name, role: crate::check::role::Role) -> Claim {
        let claim = self
            .claims
            .entry(Key(name))
            .or_insert_with(|| Claim::of(name.as_str()));
        claim.role = Some(role);
        claim.declared = true;
        *claim
    }
    /// Unbinds `name` (a function's parameter, a comprehension's variable,
    /// once its body is done).
    #[inline]
    pub fn remove(&mut self, name: impl AsKey) {
        if let Some(old) = self.vars.remove(&name.key()) {
            self.held = self.held.saturating_sub(binding_numbers(&old));
        }
    }
    /// Whether `name` was declared by `given`, or is a rate `q'`, `q''`
    /// of a given function of time.
    pub fn is_given(&self, name: Name) -> bool {
        if self.givens.is_empty() {
            return false;
        }
        let text = name.as_str();
        let base = text.trim_end_matches('\'');
        if base.len() == text.len() {
            return self.givens.contains_key(&Key(name));
        }
        self.givens.keys().any(|k| k.0.as_str() == base)
    }
    /// From now until [`Env::release`], every `given` name bound to a
    /// value, and every rate `q'` so bound, is read as its symbol
    /// ([`Env::get`]): `diff` and `subs` see the expression as written
    /// before the numbers were bound (§7: bound first or later, the same
    /// answer). False when no given name has a value (nothing to hold).
    pub fn hold(&mut self) -> bool {
        if self.givens.is_empty() {
            return false;
        }
        let held: Vec<Key> = self
            .vars
            .iter()
            .filter(|(k, b)| !b.symbolic && self.is_given(k.0))
            .map(|(k, _)| *k)
            .collect();
        self.holding = held;
        !self.holding.is_empty()
    }
    /// The binding `name` was declared with by `given` (its symbol).
    pub fn given(&self, name: Name) -> Option<&Binding> {
        self.givens.get(&Key(name))
    }
    /// Whether any name was declared by `given`.
    #[inline]
    pub fn has_givens(&self) -> bool {
        !self.givens.is_empty()
    }
    /// The names [`Env::hold`] holds now.
    pub fn held_names(&self) -> Vec<Name> {
        self.holding.iter().map(|k| k.0).collect()
    }
    /// The end of [`Env::hold`]: names read as their values again.
    pub fn release(&mut self) {
        self.holding.clear();
    }
    /// The user function `name`, if there is one.
    #[inline]
    pub fn func(&self, name: impl AsKey) -> Option<&Rc<UserFn>> {
        self.fns.get(&name.key())
    }
    /// The texts of the bound names, in no order.
    pub fn var_texts(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.vars.keys().map(|k| k.0.as_str())
    }
    /// The texts of the user functions' names, in no order.
    pub fn fn_texts(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.fns.keys().map(|k| k.0.as_str())
    }
    /// The builtin called `name` ([`builtins::lookup`]), looked up in the
    /// table the first time only, with the table's own text of the name
    /// (`Ad`, an alias of `Adjoint`): a recipe keeping the name by which
    /// it was called ([`crate::seam::apply::Op::owned`]) then finds it at
    /// once.
    #[inline]
    pub fn builtin(&mut self, name: Name) -> Option<(&'static Builtin, &'static str)> {
        *self.builtins.0.entry(Key(name)).or_insert_with(|| {
            let b = builtins::lookup(name.as_str())?;
            Some((b, b.names().find(|n| *n == name.as_str()).unwrap_or(b.name)))
        })
    }
    /// The bindings with their names, in the names' sorted order (for
    /// `:vars`, completion and derive's deterministic search).
    pub fn bindings(&self) -> Vec<(Name, &Binding)> {
        let mut v: Vec<(Name, &Binding)> = self.vars.iter().map(|(k, b)| (k.0, b)).collect();
        v.sort_by_key(|(n, _)| *n);
        v
    }
}

/// The calculus on recipes reads the session's bindings through this
/// ([`crate::calculus`]: values bound later, §7).
impl crate::calculus::Bindings for Env {
    #[inline]
    fn binding(&self, name: Name) -> Option<crate::calculus::Bound<'_>> {
        self.get(name).map(Binding::bound)
    }
    fn is_given(&self, name: Name) -> bool {
        Env::is_given(self, name)
    }
    fn declared(&self, name: Name) -> Option<&Value> {
        self.given(name).and_then(|b| b.val.as_ref())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostics::ErrorKind;

    #[test]
    fn the_frame_mode_decides_what_a_frame_mismatch_becomes() {
        let d = || Diagnostic::error(ErrorKind::Frame, Default::default(), "frames");
        let mut w = Vec::new();
        assert!(FrameMode::Strict.refusal(true, d(), &mut w).is_err());
        assert!(FrameMode::Warn.refusal(false, d(), &mut w).is_err());
        assert!(FrameMode::Off.refusal(true, d(), &mut w).is_ok());
        assert!(w.is_empty());
        assert!(FrameMode::Warn.refusal(true, d(), &mut w).is_ok());
        assert_eq!(w.len(), 1);
        assert_eq!(w[0].severity, Severity::Warning);
        FrameMode::Off.warning(d(), &mut w);
        assert_eq!(w.len(), 1);
    }
}
