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
use crate::sym::Symbol;
use crate::syntax::ast::BinOp;
use crate::values::recipe;

pub(crate) use super::apply::to_sym;

/// The value of a binding as of now: a value derived from symbols has the
/// numbers bound since substituted ([`resolve`], [`formula`]; the items of
/// a list or tuple too); a numeric result takes the kind the checker gave
/// the expression where that says more than the numbers can (a twist, a
/// wrench). `given` symbols are themselves.
pub fn current(b: &Binding, env: &Env) -> Option<Value> {
    match b.val.as_ref()? {
        Value::Sym(s) if !b.symbolic => Some(match resolve(s, env) {
            Sym::Const(v, _) => retag(*v, &b.ty.kind),
            s => Value::Sym(s),
        }),
        v @ Value::Formula { .. } if !b.symbolic => Some(formula(v, env)),
        v @ (Value::Tuple(_) | Value::List(_)) if b.derived => Some(now(v, env)),
        v => Some(v.clone()),
    }
}

/// An item of a list or tuple as of now ([`current`] of a value not bound
/// to a name of its own).
fn now(v: &Value, env: &Env) -> Value {
    match v {
        Value::Sym(s) => match resolve(s, env) {
            Sym::Const(v, _) => *v,
            s => Value::Sym(s),
        },
        Value::Formula { .. } => formula(v, env),
        Value::Tuple(vs) if vs.iter().any(recipe::holds_symbols) => {
            Value::Tuple(vs.iter().map(|x| now(x, env)).collect())
        }
        Value::List(vs) if vs.iter().any(recipe::holds_symbols) => {
            Value::List(std::rc::Rc::new(vs.iter().map(|x| now(x, env)).collect()))
        }
        v => v.clone(),
    }
}

/// A formula with the numbers bound since substituted. Once every symbol
/// has a number the value *is* a number (§7), computed by replaying how
/// it was made with those numbers ([`replay::numbers`]: the operations
/// as typed, as if the numbers had been typed first), never from its
/// expanded canonical form, whose coefficients can cancel; only a formula
/// made by no replayable operation (a symbol, a derivative) is evaluated
/// from its canonical form. It is typed by what it is — the formula's kind
/// where the canonical form earned it exactly (a rotation, a scalar, a
/// vector), else what the numbers are, as for numbers typed first (π
/// alone is a number too: it is no symbol). Partly bound, the numbers are
/// put in ([`crate::sym::Expr::at_numbers`], and into how it was made).
fn formula(v: &Value, env: &Env) -> Value {
    let Value::Formula { kind, m, how } = v else {
        return v.clone();
    };
    let lookup = |s: &Symbol| match env.get(&*super::formula::binding_name(s)) {
        Some(Binding {
            val: Some(v @ Value::Num { .. }),
            ..
        }) => v.as_scalar(),
        _ => None,
    };
    let mut syms = Vec::new();
    m.data.iter().for_each(|e| e.symbols(&mut syms));
    if !syms.iter().any(|s| lookup(s).is_some()) && !syms.is_empty() {
        return v.clone();
    }
    if syms.iter().all(|s| lookup(s).is_some()) {
        let replayed = how
            .as_ref()
            .and_then(|r| replay::numbers(r, &lookup))
            .and_then(|x| match x {
                Value::Num { m: xs, .. } if xs.shape() == (m.rows, m.cols) => Some(xs),
                _ => None,
            });
        if let Some(xs) = replayed {
            let kind = if recipe::vague(kind) {
                replay::classify(&xs)
            } else {
                *kind
            };
            return Value::Num {
                kind,
                m: xs,
                exact: Default::default(),
            };
        }
        if let Some(v) = replay::canonical(kind, m, &lookup) {
            return v;
        }
    }
    match super::formula::make(kind, m.map(|e| e.at_numbers(&lookup))) {
        Value::Formula { kind, m, .. } => Value::Formula {
            kind,
            m,
            how: how.as_ref().map(|r| replay::at_numbers(r, &lookup)),
        },
        v => v,
    }
}

/// `v` with the checker's kind, unless that is only a shape (a plain
/// matrix or vector keeps the kind read from its entries).
fn retag(v: Value, kind: &Kind) -> Value {
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
            v @ Value::Formula { .. } => to_sym(&formula(v, env)),
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
