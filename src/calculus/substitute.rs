//! Numbers bound after a symbolic expression was built (LANGUAGE.md §7:
//! "binding numbers later makes them numeric"). `X = T_ab * T_bc` over
//! `given` symbols keeps the expression `T_ab T_bc`; once `T_ab` and `T_bc`
//! are bound to numbers, reading `X` substitutes them and evaluates what
//! has become numeric, so `X` is then the product's value. A symbolic
//! scalar, vector or matrix whose symbols all have numbers is computed by
//! replaying how it was made ([`crate::decide::replay`]), as if the numbers had
//! been typed first. Partly numeric expressions keep their symbols
//! (`[1, 0, …] T_bc`). Types and frames are not recomputed: they were
//! checked when the expression was built.
use super::resolve::{self, resolve};
use super::{Bindings, Bound};
use crate::check::ty::Kind;
use crate::decide::replay;
use crate::diagnostics::Diagnostic;
use crate::sym::Symbol;
use crate::values::recipe;
use crate::values::value::{Sym, Value};
use std::rc::Rc;

/// The value of a binding as of now: a value derived from symbols has the
/// numbers bound since substituted ([`resolve()`], [`resolve::formula_now`]; the items of
/// a list or tuple too); a numeric result takes the kind the checker gave
/// the expression where that says more than the numbers can (a twist, a
/// wrench). `given` symbols are themselves. The warnings of the steps
/// replayed with numbers (a gimbal lock) go to `warnings`, as when the
/// numbers are typed first.
///
/// Err when replaying it with the numbers fails as the numbers typed
/// first would (a division by zero the canonical form cancelled).
#[inline]
pub fn current(
    b: Bound<'_>,
    env: &dyn Bindings,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Option<Value>, replay::Failed> {
    let Some(v) = b.val else {
        return Ok(None);
    };
    Ok(Some(match v {
        Value::Sym(s) if !b.symbolic => match resolve(s, env, warnings)? {
            Sym::Const(v, _) => retag(*v, &b.kind),
            s => identity_now(&s, &b.kind, env).unwrap_or(Value::Sym(s)),
        },
        v @ Value::Formula { .. } if !b.symbolic => resolve::formula_now(v, env, warnings)?,
        v @ (Value::Tuple(_) | Value::List(_)) if b.derived => now(v, env, warnings)?,
        v => v.clone(),
    }))
}

/// An item of a list or tuple as of now ([`current`] of a value not bound
/// to a name of its own). A tuple whose items are the parts of one
/// operation's result (`rpy(R)`'s angles) is that operation's value once
/// its symbols have numbers: a vector, as typed first.
pub fn now(
    v: &Value,
    env: &dyn Bindings,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Value, replay::Failed> {
    Ok(match v {
        Value::Sym(s) => match resolve(s, env, warnings)? {
            Sym::Const(v, _) => *v,
            s => Value::Sym(s),
        },
        Value::Formula { .. } => resolve::formula_now(v, env, warnings)?,
        Value::Tuple(vs) if vs.iter().any(recipe::holds_symbols) => {
            let whole = parts_of_one(vs);
            if let Some(whole) = &whole
                && let Some(x) = numbers(whole, env, warnings)?
                && is_made_of(&x, vs, env)
            {
                return Ok(x);
            }
            let items: Vec<Value> = vs
                .iter()
                .map(|x| now(x, env, warnings))
                .collect::<Result<_, _>>()?;
            match whole {
                // partly bound: the parts stay parts of one call (rebased once)
                Some(whole) => {
                    let lookup = |s: &Symbol| resolve::bound(env, s);
                    let shared = replay::at_numbers(&whole, &lookup);
                    Value::Tuple(
                        items
                            .into_iter()
                            .enumerate()
                            .map(|(i, x)| match x {
                                Value::Formula { kind, m, .. } => Value::Formula {
                                    kind,
                                    m,
                                    how: recipe::Recipe::node(
                                        recipe::Step::Part(i),
                                        vec![shared.clone()],
                                        kind,
                                    ),
                                },
                                x => x,
                            })
                            .collect(),
                    )
                }
                None => Value::Tuple(items),
            }
        }
        Value::List(vs) if vs.iter().any(recipe::holds_symbols) => Value::List(std::rc::Rc::new(
            vs.iter()
                .map(|x| now(x, env, warnings))
                .collect::<Result<_, _>>()?,
        )),
        v => v.clone(),
    })
}

/// The recipe whose result a tuple is, when each of its items is that
/// result's part of the same place (`euler_zyx(R)` gives its three
/// angles as parts 0, 1, 2 of one call); numbers among them are parts
/// that came out as numbers.
fn parts_of_one(vs: &[Value]) -> Option<Rc<recipe::Recipe>> {
    let mut whole: Option<Rc<recipe::Recipe>> = None;
    for (i, v) in vs.iter().enumerate() {
        let Value::Formula { how: Some(r), .. } = v else {
            continue;
        };
        match (&r.step, r.args.as_slice()) {
            (recipe::Step::Part(j), [w]) if *j == i => match &whole {
                Some(x) if !Rc::ptr_eq(x, w) => return None,
                _ => whole = Some(w.clone()),
            },
            _ => return None,
        }
    }
    whole
}

/// True when `whole`, the value of the one operation a tuple's items are
/// parts of ([`parts_of_one`]), is that tuple: as many parts, and the items
/// that are not its parts (numbers, symbols) equal to its parts there as of
/// now. `(TransToRp(T)[1], -1)` and `(TransToRp(T)[1], a)` are not
/// `TransToRp(T)`, though their one formula is a part of it.
fn is_made_of(whole: &Value, vs: &[Value], env: &dyn Bindings) -> bool {
    let part = |i: usize| -> Option<Value> {
        match whole {
            Value::Tuple(ws) => ws.get(i).cloned(),
            Value::Num { m, .. } if m.ncols() == 1 => (i < m.nrows()).then(|| Value::scalar(m[i])),
            _ => None,
        }
    };
    let len = match whole {
        Value::Tuple(ws) => ws.len(),
        Value::Num { m, .. } if m.ncols() == 1 => m.nrows(),
        _ => return false,
    };
    len == vs.len()
        && vs.iter().enumerate().all(|(i, v)| match v {
            // (a formula made as a part is part i of `whole`: parts_of_one)
            Value::Formula { how: Some(r), .. } if matches!(r.step, recipe::Step::Part(_)) => true,
            v => match (now(v, env, &mut Vec::new()), part(i)) {
                (Ok(Value::Num { m, .. }), Some(Value::Num { m: w, .. })) => m == w,
                _ => false,
            },
        })
}

/// The value of recipe `r` once every symbol it reads has a number
/// (replayed as typed first); None while one is free.
fn numbers(
    r: &Rc<recipe::Recipe>,
    env: &dyn Bindings,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Option<Value>, replay::Failed> {
    let lookup = |s: &Symbol| resolve::bound(env, s);
    let mut syms = Vec::new();
    recipe::symbols(r, &mut syms);
    if !syms.iter().all(|s| lookup(s).is_some()) {
        return Ok(None);
    }
    replay::numbers(r, &lookup, warnings)
}

/// `v` with the checker's kind, unless that is only a shape (a plain
/// matrix or vector keeps the kind read from its entries).
pub fn retag(v: Value, kind: &Kind) -> Value {
    match (v, kind) {
        (v, Kind::Unknown | Kind::Matrix(..) | Kind::Vector(_)) => v,
        (Value::Num { m, exact, .. }, k) => Value::Num { kind: *k, m, exact },
        (v, _) => v,
    }
}

/// The identity a product over `given` names cancelled to (`inv(T) * T`:
/// `I`, `crate::values::symbolic::Tree::Identity`) once every one of those
/// names has numbers: the numbers' identity of the kind's size, as typed
/// first (§7: the value *is* a number then, and its JSON type the
/// kind's, not "symbolic"). None while a name is free, or for any other
/// value.
fn identity_now(s: &Sym, kind: &Kind, env: &dyn Bindings) -> Option<Value> {
    let Sym::Identity(names) = s else {
        return None;
    };
    let numbers = |n: &String| {
        env.binding(crate::syntax::name::Name::new(n))
            .is_some_and(|b| !b.symbolic && matches!(b.val, Some(Value::Num { .. })))
    };
    if names.is_empty() || !names.iter().all(numbers) {
        return None;
    }
    let n = match kind.shape()? {
        (Some(r), Some(c)) if r == c => r,
        _ => return None,
    };
    Some(Value::Num {
        kind: *kind,
        m: crate::values::num::Num::identity(n),
        exact: crate::values::exact::Exact::Typed,
    })
}
