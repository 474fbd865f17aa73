//! A value bound later warns once per binding of its numbers (LANGUAGE.md
//! §7: "exactly as if the numbers had been typed first"). Typed first,
//! `y = euler_zyx(Roty(a))` at a = π/2 warns of the gimbal lock once, at
//! the call. Bound later the call is made where `y` is read and becomes
//! numbers; read twice, it would warn twice. So each read that computes a
//! value remembers the warnings it gave, with what the value was made by
//! (its recipe, shared by `z = y`, or its binding) and the bindings of
//! the symbols it reads (each binding has its own stamp,
//! `Binding::stamp` in `crate::eval::env`). A later read of the same value with
//! the same bindings gives those warnings no more; once a symbol it reads
//! is bound again, the numbers are new and their warnings are given again.

use std::rc::Rc;

use crate::diagnostics::Diagnostic;
use crate::sym::Symbol;
use crate::values::operation::Operation;
use crate::values::recipe::{self, Recipe, Step};
use crate::values::value::{Sym, Value};

/// The most values remembered (the oldest are forgotten first: a value
/// forgotten warns again, which is the safe side).
const KEPT: usize = 64;

/// What made a value that was read: its recipe (the whole call for a part
/// of one, so that the parts of `(w, th) = AxisAng3(…)` warn once), or,
/// for a value kept as a tree, its binding.
#[derive(Debug, Clone)]
enum Origin {
    Made(Rc<Recipe>),
    Bound(String, u64),
}

impl PartialEq for Origin {
    fn eq(&self, o: &Origin) -> bool {
        match (self, o) {
            (Origin::Made(a), Origin::Made(b)) => Rc::ptr_eq(a, b),
            (Origin::Bound(a, s), Origin::Bound(b, t)) => a == b && s == t,
            _ => false,
        }
    }
}

/// A value read and the warnings its numbers gave.
#[derive(Debug, Clone)]
struct Entry {
    origin: Origin,
    /// The stamps of the bindings of the symbols it reads, in order.
    stamps: Vec<u64>,
    said: Vec<String>,
}

/// The warnings given by reads of values bound later ([`Warned::keep`]).
#[derive(Debug, Clone, Default)]
pub struct Warned(Vec<Entry>);

impl Warned {
    /// Of `warnings`, given by reading `name` (bound to `v` at `stamp`)
    /// with the numbers bound now (`stamp_of` a name's binding's stamp,
    /// 0 when unbound), those not given already by a read of the same
    /// value with the same bindings of its symbols; remembers them.
    pub fn keep(
        &mut self,
        name: &str,
        v: &Value,
        stamp: u64,
        stamp_of: &dyn Fn(&str) -> u64,
        warnings: Vec<Diagnostic>,
    ) -> Vec<Diagnostic> {
        let origin = origin(v).unwrap_or_else(|| Origin::Bound(name.to_string(), stamp));
        let mut syms = Vec::new();
        depends(v, &mut syms);
        let stamps: Vec<u64> = syms.iter().map(|s| stamp_of(&binding(s))).collect();
        let kept = &mut self.0;
        let mut entry = match kept.iter().position(|e| e.origin == origin) {
            Some(i) if kept[i].stamps == stamps => kept.remove(i),
            found => {
                if let Some(i) = found {
                    kept.remove(i);
                }
                Entry {
                    origin,
                    stamps,
                    said: Vec::new(),
                }
            }
        };
        let fresh: Vec<Diagnostic> = warnings
            .into_iter()
            .filter(|w| !entry.said.contains(&w.message))
            .collect();
        entry.said.extend(fresh.iter().map(|w| w.message.clone()));
        kept.push(entry);
        if kept.len() > KEPT {
            kept.remove(0);
        }
        fresh
    }
}

/// The recipe that made `v` (a tuple's: its parts' call), through the
/// part or entry of a call it is.
fn origin(v: &Value) -> Option<Origin> {
    let r = match v {
        Value::Formula { how: Some(r), .. } => r,
        Value::Tuple(vs) => match vs.iter().find(|x| matches!(x, Value::Formula { .. }))? {
            Value::Formula { how: Some(r), .. } => r,
            _ => return None,
        },
        _ => return None,
    };
    Some(Origin::Made(match (&r.step, r.args.as_slice()) {
        // a part of a call's tuple, or an entry of its vector (the angles
        // of `(r, p, w) = euler_zyx(…)`, each `v[i]`): the call's
        (Step::Part(_) | Step::Op(Operation::Index(_)), [whole]) => whole.clone(),
        _ => r.clone(),
    }))
}

/// The name whose binding gives symbol `s` its number (a vector's
/// component: the vector's).
fn binding(s: &Symbol) -> String {
    format!("{}{}", s.name, "'".repeat(s.dots as usize))
}

/// The symbols `v` depends on: its formulas' (canonical form and recipe),
/// the names of its trees.
fn depends(v: &Value, out: &mut Vec<Symbol>) {
    match v {
        Value::Formula { m, how, .. } => {
            m.data.iter().for_each(|e| e.symbols(out));
            if let Some(r) = how {
                recipe::symbols(r, out);
            }
        }
        Value::Sym(s) => tree(s, out),
        Value::Tuple(vs) => vs.iter().for_each(|x| depends(x, out)),
        Value::List(vs) => vs.iter().for_each(|x| depends(x, out)),
        _ => {}
    }
}

fn tree(s: &Sym, out: &mut Vec<Symbol>) {
    match s {
        Sym::Name(n) => {
            let s = Symbol::new(n);
            if !out.contains(&s) {
                out.push(s);
            }
        }
        Sym::Const(v, _) => depends(v, out),
        Sym::Identity(_) => {}
        Sym::Product(xs) | Sym::Vector(xs) | Sym::Call(_, xs) => {
            xs.iter().for_each(|x| tree(x, out))
        }
        Sym::Block(rows) => rows.iter().flatten().for_each(|x| tree(x, out)),
        Sym::Inv(x)
        | Sym::Neg(x)
        | Sym::Bracket(x)
        | Sym::Transpose(x)
        | Sym::Member(x, _)
        | Sym::Index(x, _) => tree(x, out),
        Sym::Add(a, b)
        | Sym::Sub(a, b)
        | Sym::Div(a, b)
        | Sym::Pow(a, b)
        | Sym::Compare(_, a, b) => {
            tree(a, out);
            tree(b, out);
        }
    }
}
