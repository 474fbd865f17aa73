//! Numbers bound after a symbolic expression was built (LANGUAGE.md §7:
//! "binding numbers later makes them numeric"). `X = T_ab * T_bc` over
//! `given` symbols keeps the expression `T_ab T_bc`; once `T_ab` and `T_bc`
//! are bound to numbers, reading `X` substitutes them and evaluates what
//! has become numeric, so `X` is then the product's value. A symbolic
//! scalar, vector or matrix whose symbols all have numbers is computed by
//! replaying how it was made ([`super::replay`]), as if the numbers had
//! been typed first. Partly numeric expressions keep their symbols
//! (`[1, 0, …] T_bc`). Types and frames are not recomputed: they were
//! checked when the expression was built.
use super::apply::{self, Op};
use super::env::{Binding, Env};
use super::ops::Sel;
use super::replay;
use super::value::Sym;
use super::value::Value;
use crate::check::ty::Kind;
use crate::diagnostics::Diagnostic;
use crate::sym::{Mat, Symbol};
use crate::syntax::ast::BinOp;
use crate::values::recipe;
use std::rc::Rc;

pub(crate) use super::apply::to_sym;

/// The value of a binding as of now: a value derived from symbols has the
/// numbers bound since substituted ([`resolve`], [`formula`]; the items of
/// a list or tuple too); a numeric result takes the kind the checker gave
/// the expression where that says more than the numbers can (a twist, a
/// wrench). `given` symbols are themselves. The warnings of the steps
/// replayed with numbers (a gimbal lock) go to `warnings`, as when the
/// numbers are typed first.
///
/// Err when replaying it with the numbers fails as the numbers typed
/// first would (a division by zero the canonical form cancelled).
pub fn current(
    b: &Binding,
    env: &Env,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Option<Value>, replay::Failed> {
    let Some(v) = b.val.as_ref() else {
        return Ok(None);
    };
    Ok(Some(match v {
        Value::Sym(s) if !b.symbolic => match resolve(s, env) {
            Sym::Const(v, _) => retag(*v, &b.ty.kind),
            s => match stuck(&s) {
                Some(why) => return Err(replay::Failed(why)),
                None => Value::Sym(s),
            },
        },
        v @ Value::Formula { .. } if !b.symbolic => formula(v, env, warnings)?,
        v @ (Value::Tuple(_) | Value::List(_)) if b.derived => now(v, env, warnings)?,
        v => v.clone(),
    }))
}

/// An item of a list or tuple as of now ([`current`] of a value not bound
/// to a name of its own). A tuple whose items are the parts of one
/// operation's result (`rpy(R)`'s angles) is that operation's value once
/// its symbols have numbers: a vector, as typed first.
fn now(v: &Value, env: &Env, warnings: &mut Vec<Diagnostic>) -> Result<Value, replay::Failed> {
    Ok(match v {
        Value::Sym(s) => match resolve(s, env) {
            Sym::Const(v, _) => *v,
            s => Value::Sym(s),
        },
        Value::Formula { .. } => formula(v, env, warnings)?,
        Value::Tuple(vs) if vs.iter().any(recipe::holds_symbols) => {
            if let Some(whole) = parts_of_one(vs)
                && let Some(x) = numbers(&whole, env, warnings)?
            {
                return Ok(x);
            }
            Value::Tuple(
                vs.iter()
                    .map(|x| now(x, env, warnings))
                    .collect::<Result<_, _>>()?,
            )
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

/// The symbols a formula depends on: those of its canonical form and of
/// how it was made (`a/a` is 1, yet depends on `a`).
fn symbols_of(m: &Mat, how: Option<&Rc<recipe::Recipe>>) -> Vec<Symbol> {
    let mut syms = Vec::new();
    m.data.iter().for_each(|e| e.symbols(&mut syms));
    if let Some(r) = how {
        recipe::symbols(r, &mut syms);
    }
    syms
}

/// The value bound to a symbol now, if it is a number.
fn bound(env: &Env, s: &Symbol) -> Option<Value> {
    match env.get(&*super::formula::binding_name(s)) {
        Some(Binding {
            val: Some(v @ Value::Num { .. }),
            ..
        }) => Some(v.clone()),
        _ => None,
    }
}

/// The value of recipe `r` once every symbol it reads has a number
/// (replayed as typed first); None while one is free.
fn numbers(
    r: &Rc<recipe::Recipe>,
    env: &Env,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Option<Value>, replay::Failed> {
    let lookup = |s: &Symbol| bound(env, s);
    let mut syms = Vec::new();
    recipe::symbols(r, &mut syms);
    if !syms.iter().all(|s| lookup(s).is_some()) {
        return Ok(None);
    }
    replay::numbers(r, &lookup, warnings)
}

/// A formula with the numbers bound since substituted. Once every symbol
/// it depends on has a number (those of its canonical form and of how it
/// was made: `a/a` at a = 0 is a division by zero, as typed first) the
/// value *is* a number (§7), computed by replaying how it was made with
/// those numbers ([`replay::numbers`]: the operations as typed, with the
/// numbers' exact forms, as if the numbers had been typed first), never
/// from its expanded canonical form, whose coefficients can cancel; only
/// a formula made by no replayable operation (a symbol, a derivative) is
/// evaluated from its canonical form. It is typed by what it is: what the
/// operations give the numbers, as typed first. Partly bound, the numbers
/// are put in, exactly where they are exact ([`replay::put_numbers`], and
/// into how it was made).
fn formula(v: &Value, env: &Env, warnings: &mut Vec<Diagnostic>) -> Result<Value, replay::Failed> {
    let Value::Formula { kind, m, how } = v else {
        return Ok(v.clone());
    };
    let lookup = |s: &Symbol| bound(env, s);
    let syms = symbols_of(m, how.as_ref());
    if !syms.iter().any(|s| lookup(s).is_some()) {
        return Ok(v.clone());
    }
    if syms.iter().all(|s| lookup(s).is_some()) {
        // (with the kind its binding gave it: `V_b = (…)` is a twist)
        if how.is_some()
            && let Some(x) = replay::numbers(&recipe::Recipe::of(v), &lookup, warnings)?
            && replay::same_shape(&x, m)
        {
            return Ok(x);
        }
        if let Some(v) = replay::canonical(kind, m, &lookup) {
            return Ok(v);
        }
    }
    Ok(
        match super::formula::make(kind, m.map(|e| replay::put_numbers(e, &lookup))) {
            Value::Formula { kind, m, .. } => Value::Formula {
                kind,
                m,
                how: how.as_ref().map(|r| replay::at_numbers(r, &lookup)),
            },
            // (numbers with symbols left in how it was made stay a formula)
            Value::Num { kind, m: xs, exact } => match how {
                Some(r) => Value::Formula {
                    kind,
                    m: m.map(|e| replay::put_numbers(e, &lookup)),
                    how: Some(replay::at_numbers(r, &lookup)),
                },
                None => Value::Num { kind, m: xs, exact },
            },
            v => v,
        },
    )
}

/// `v` with the checker's kind, unless that is only a shape (a plain
/// matrix or vector keeps the kind read from its entries).
pub(super) fn retag(v: Value, kind: &Kind) -> Value {
    match (v, kind) {
        (v, Kind::Unknown | Kind::Matrix(..) | Kind::Vector(_)) => v,
        (Value::Num { m, exact, .. }, k) => Value::Num { kind: *k, m, exact },
        (v, _) => v,
    }
}

/// `s` with every `given` name that is now bound to numbers replaced by
/// them, and every operation whose operands are all numbers evaluated by
/// its numeric function ([`Op::numeric`], the evaluator's). An operation
/// that fails numerically (it was checked on types only) is left symbolic.
pub fn resolve(s: &Sym, env: &Env) -> Sym {
    match s {
        Sym::Name(n) => match env.get(n).and_then(|b| b.val.as_ref()) {
            Some(v @ Value::Num { .. }) => to_sym(v),
            _ if n == "deg" => to_sym(&Value::scalar(std::f64::consts::PI / 180.0)),
            _ => s.clone(),
        },
        Sym::Const(v, _) => match &**v {
            // (a factor whose numbers fail stays symbolic: the operation
            // over it reports, as for any failing numeric operand)
            v @ Value::Formula { .. } => match formula(v, env, &mut Vec::new()) {
                Ok(x) => to_sym(&x),
                Err(_) => s.clone(),
            },
            _ => s.clone(),
        },
        Sym::Identity => s.clone(),
        Sym::Product(fs) => {
            let mut out: Vec<Sym> = Vec::new();
            for f in fs.iter().map(|f| resolve(f, env)) {
                let merged = match (out.last().and_then(num), num(&f)) {
                    (Some(a), Some(b)) => Op::Arith(BinOp::Mul).numeric(&[a, b], None).ok(),
                    _ => None,
                };
                match merged {
                    Some(v) => {
                        out.pop();
                        out.push(constant(v));
                    }
                    None => out.push(f),
                }
            }
            Sym::product(out)
        }
        Sym::Inv(x) => unary(Op::Inverse, x, env),
        Sym::Transpose(x) => unary(Op::Transpose, x, env),
        Sym::Neg(x) => unary(Op::Neg, x, env),
        Sym::Member(x, part) => unary(Op::Member(*part), x, env),
        Sym::Index(x, sels) => {
            let sel: Vec<Sel> = sels.iter().map(|s| s.map_or(Sel::All, Sel::At)).collect();
            unary(Op::Index(&sel), x, env)
        }
        Sym::Add(a, b) => binary(BinOp::Add, a, b, env),
        Sym::Sub(a, b) => binary(BinOp::Sub, a, b, env),
        Sym::Div(a, b) => binary(BinOp::Div, a, b, env),
        Sym::Pow(a, b) => binary(BinOp::Pow, a, b, env),
        Sym::Bracket(x) => {
            let x = resolve(x, env);
            num(&x)
                .and_then(|v| apply::block_numeric(&[vec![v.clone()]]).ok())
                .map(constant)
                .unwrap_or_else(|| Sym::Bracket(Box::new(x)))
        }
        Sym::Block(rows) => {
            let rows: Vec<Vec<Sym>> = rows
                .iter()
                .map(|r| r.iter().map(|x| resolve(x, env)).collect())
                .collect();
            let vals: Option<Vec<Vec<Value>>> = rows
                .iter()
                .map(|r| r.iter().map(|x| num(x).cloned()).collect())
                .collect();
            vals.and_then(|v| apply::block_numeric(&v).ok())
                .map(constant)
                .unwrap_or(Sym::Block(rows))
        }
        Sym::Vector(parts) => {
            let parts: Vec<Sym> = parts.iter().map(|x| resolve(x, env)).collect();
            let vals: Option<Vec<&Value>> = parts
                .iter()
                .map(|x| num(x).filter(|v| v.as_scalar().is_some()))
                .collect();
            match vals.and_then(|vals| Op::Vector.numeric(&vals, None).ok()) {
                Some(v) => constant(v),
                None => Sym::Vector(parts),
            }
        }
        Sym::Call(fun, args) => {
            let args: Vec<Sym> = args.iter().map(|a| resolve(a, env)).collect();
            let vals: Option<Vec<Value>> = args.iter().map(|a| num(a).cloned()).collect();
            vals.zip(crate::builtins::lookup(fun.name))
                .and_then(|(vals, b)| apply::call_nowhere(b, vals).ok())
                .map(constant)
                .unwrap_or_else(|| Sym::Call(*fun, args))
        }
    }
}

/// The numbers of a constant operand.
fn num(s: &Sym) -> Option<&Value> {
    match s {
        Sym::Const(v, _) if matches!(**v, Value::Num { .. }) => Some(v),
        _ => None,
    }
}

/// A computed value as a constant, its kind recognized when the operation
/// could not tell it (a product of transforms is a transform).
fn constant(v: Value) -> Sym {
    let v = match v {
        Value::Num {
            kind: Kind::Unknown | Kind::Matrix(..),
            m,
            exact,
        } => Value::Num {
            kind: replay::classify(&m),
            m,
            exact,
        },
        other => other,
    };
    to_sym(&v)
}

/// A unary operation on a resolved operand: its value when that is a
/// number, else its symbolic form.
fn unary(op: Op, x: &Sym, env: &Env) -> Sym {
    let x = resolve(x, env);
    match num(&x).and_then(|v| op.numeric(&[v], None).ok()) {
        Some(v) => constant(v),
        None => op.symbolic(vec![x]),
    }
}

/// An arithmetic operation on resolved operands, evaluated when both are
/// numbers.
fn binary(op: BinOp, a: &Sym, b: &Sym, env: &Env) -> Sym {
    let (a, b) = (resolve(a, env), resolve(b, env));
    if let (Some(l), Some(r)) = (num(&a), num(&b))
        && let Ok(v) = Op::Arith(op).numeric(&[l, r], None)
    {
        return constant(v);
    }
    let (a, b) = (Box::new(a), Box::new(b));
    match op {
        BinOp::Add => Sym::Add(a, b),
        BinOp::Sub => Sym::Sub(a, b),
        BinOp::Div => Sym::Div(a, b),
        BinOp::Pow => Sym::Pow(a, b),
        BinOp::Mul => Sym::times(*a, *b),
    }
}

/// Why a resolved symbolic value whose `given` names all have numbers is
/// still not a number: the message of its first operation whose operands
/// are all numbers and which fails with them (`Rot(w, θ)` with w = 0), as
/// when the numbers are typed first. None while a name or a formula with
/// free symbols is left (the value is only partly bound).
fn stuck(s: &Sym) -> Option<String> {
    let parts: Vec<&Sym> = match s {
        Sym::Name(_) => return None,
        Sym::Const(..) | Sym::Identity => return None,
        Sym::Product(fs) => fs.iter().collect(),
        Sym::Inv(x) | Sym::Transpose(x) | Sym::Neg(x) | Sym::Member(x, _) | Sym::Bracket(x) => {
            vec![&**x]
        }
        Sym::Index(x, _) => vec![&**x],
        Sym::Add(a, b) | Sym::Sub(a, b) | Sym::Div(a, b) | Sym::Pow(a, b) => vec![&**a, &**b],
        Sym::Block(rows) => rows.iter().flatten().collect(),
        Sym::Vector(xs) | Sym::Call(_, xs) => xs.iter().collect(),
    };
    if let Some(why) = parts.iter().find_map(|p| stuck(p)) {
        return Some(why);
    }
    let vals: Vec<&Value> = parts.iter().map(|p| num(p)).collect::<Option<_>>()?;
    let failed = match s {
        Sym::Call(fun, _) => crate::builtins::lookup(fun.name)
            .map(|b| apply::call_nowhere(b, vals.into_iter().cloned().collect())),
        Sym::Div(..) => Some(Op::Arith(BinOp::Div).numeric(&vals, None)),
        Sym::Pow(..) => Some(Op::Arith(BinOp::Pow).numeric(&vals, None)),
        Sym::Inv(_) => Some(Op::Inverse.numeric(&vals, None)),
        _ => None,
    };
    match failed {
        Some(Err(e)) => Some(e.to_string()),
        _ => None,
    }
}
