//! What `diff` and `subs` by a symbol that already has a number may read
//! (LANGUAGE.md §7: "once every symbol of a value has a number, the value
//! is a number … exactly as if the numbers had been typed first").
//!
//! `x = diff(sin(s), s); s = 1; x` is cos 1, and typed the other way round,
//! `s = 1; diff(sin(s), s)` must be cos 1 too: while `diff` or `subs`
//! evaluates its operands, every `given` name bound to a value is read as
//! its symbol, and the result is read with the numbers, as a value bound
//! later is ([`super::substitute::now`]). A value computed *after* its
//! symbols had numbers holds the numbers, not the symbols (`s = 1;
//! y = sin(s); diff(y, s)`): differentiating it would give a plausible 0.
//! So each binding records the given names whose numbers it absorbed
//! ([`absorbed`]: those it was computed from, and the symbols now bound of
//! a value made from symbols), and a `diff` or `subs` by a name whose
//! number moves with one of them ([`moves_with`]) is refused. The
//! interpreter's side (holding the names while the operands are
//! evaluated, the refusal's text) is `crate::eval`'s `hold`.

use super::Bindings;
use crate::syntax::name::Name;
use crate::values::value::{Sym, Value};

/// Adds to `out` the `given` names whose numbers reading `name` (bound to
/// `val`, computed from the numbers of the given names `made_from`) gives,
/// each with `name`: a given name or rate bound to a value, the names a
/// value computed from such numbers absorbed, the symbols now bound of a
/// value made from symbols (reading it puts their numbers in). Held names
/// read as symbols and give none.
pub fn absorbed(
    env: &dyn Bindings,
    name: Name,
    val: Option<&Value>,
    made_from: &[Name],
    out: &mut Vec<(Name, Name)>,
) {
    let mut add = |s: Name| {
        if !out.contains(&(s, name)) {
            out.push((s, name));
        }
    };
    if env.is_given(name) {
        add(name);
    }
    made_from.iter().for_each(|s| add(*s));
    if let Some(v) = val {
        bound_symbols(env, v, &mut add);
    }
}

/// Calls `add` with the names of the symbols of `v` (and of how it was
/// made) that are bound to numbers now.
fn bound_symbols(env: &dyn Bindings, v: &Value, add: &mut impl FnMut(Name)) {
    match v {
        Value::Formula { m, how, .. } => {
            let mut syms = Vec::new();
            m.data.iter().for_each(|e| e.symbols(&mut syms));
            if let Some(r) = how {
                crate::values::recipe::symbols(r, &mut syms);
            }
            for s in &syms {
                if super::resolve::bound(env, s).is_some() {
                    add(Name::new(&crate::values::formula::binding_name(s)));
                }
            }
        }
        Value::Sym(t) => {
            t.any(&mut |node| {
                if let Sym::Name(n) = node {
                    let n = Name::new(n);
                    if env.is_given(n) && env.binding(n).is_some_and(|b| !b.symbolic) {
                        add(n);
                    }
                }
                false
            });
        }
        Value::Tuple(vs) => vs.iter().for_each(|x| bound_symbols(env, x, add)),
        Value::List(vs) => vs.iter().for_each(|x| bound_symbols(env, x, add)),
        _ => {}
    }
}

/// Whether the number of `absorbed` (a given name or rate) moves with
/// `by` (`diff(x, by)`, `subs(x, by, v)`): it is `by`, or `by` is the time
/// variable of the function of time it is (or is a rate of). Other
/// numbers are constants to a partial derivative and to a substitution:
/// putting them in first changes nothing.
pub fn moves_with(env: &dyn Bindings, absorbed: Name, by: Name) -> bool {
    if absorbed == by {
        return true;
    }
    let base = absorbed.as_str().trim_end_matches('\'');
    let time = env
        .declared(Name::new(base))
        .and_then(|v| match v {
            Value::Formula { m, .. } => m.data.first().and_then(crate::sym::expr::as_symbol),
            _ => None,
        })
        .and_then(|s| s.time.clone());
    time.is_some_and(|t| *t == *by.as_str())
}
