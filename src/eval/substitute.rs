//! Numbers bound after a symbolic expression was built (LANGUAGE.md §7:
//! "binding numbers later makes them numeric"). `X = T_ab * T_bc` over
//! `given` symbols keeps the expression `T_ab T_bc`; once `T_ab` and `T_bc`
//! are bound to numbers, reading `X` substitutes them and evaluates what
//! has become numeric, so `X` is then the product's value. Partly numeric
//! expressions keep their symbols (`[1, 0, …] T_bc`). Types and frames are
//! not recomputed: they were checked when the expression was built.

use super::convert;
use super::env::{Binding, Env};
use super::ops;
use super::value::Sym;
use super::value::Value;
use crate::check::ty::Kind;

/// A value as a symbolic operand (numbers become constants).
pub(crate) fn to_sym(v: &Value) -> Sym {
    match v {
        Value::Sym(s) => s.clone(),
        other => Sym::Const(
            Box::new(other.clone()),
            crate::values::format::inline(other, 4),
        ),
    }
}

/// The value of a binding as of now: a value derived from symbols has the
/// numbers bound since substituted ([`resolve`]); a numeric result takes
/// the kind the checker gave the expression where that says more than the
/// numbers can (a twist, a wrench). `given` symbols are themselves.
pub fn current(b: &Binding, env: &Env) -> Option<Value> {
    match b.val.as_ref()? {
        Value::Sym(s) if !b.symbolic => Some(match resolve(s, env) {
            Sym::Const(v, _) => retag(*v, &b.ty.kind),
            s => Value::Sym(s),
        }),
        Value::Formula { kind, m } if !b.symbolic => Some(formula(kind, m, env)),
        v => Some(v.clone()),
    }
}

/// A formula with the numbers bound since substituted (numeric when all
/// its symbols have numbers).
fn formula(kind: &Kind, m: &crate::sym::Mat, env: &Env) -> Value {
    let lookup = |name: &str| match env.get(name) {
        Some(Binding {
            val: Some(v @ Value::Num { .. }),
            ..
        }) => v.as_scalar(),
        _ => None,
    };
    super::formula::substitute(kind, m, &lookup)
}

/// `v` with the checker's kind, unless that is only a shape (a plain
/// matrix or vector keeps the kind read from its entries).
fn retag(v: Value, kind: &Kind) -> Value {
    match (v, kind) {
        (v, Kind::Unknown | Kind::Matrix(..) | Kind::Vector(_)) => v,
        (Value::Num { m, .. }, k) => Value::Num { kind: k.clone(), m },
        (v, _) => v,
    }
}

/// `s` with every `given` name that is now bound to numbers replaced by
/// them, and every operation whose operands are all numbers evaluated.
/// An operation that fails numerically (it was checked on types only) is
/// left symbolic.
pub fn resolve(s: &Sym, env: &Env) -> Sym {
    match s {
        Sym::Name(n) => match env.get(n).and_then(|b| b.val.as_ref()) {
            Some(v @ Value::Num { .. }) => to_sym(v),
            _ if n == "deg" => to_sym(&Value::scalar(std::f64::consts::PI / 180.0)),
            _ => s.clone(),
        },
        Sym::Const(v, _) => match &**v {
            Value::Formula { kind, m } => to_sym(&formula(kind, m, env)),
            _ => s.clone(),
        },
        Sym::Identity => s.clone(),
        Sym::Product(fs) => {
            let mut out: Vec<Sym> = Vec::new();
            for f in fs.iter().map(|f| resolve(f, env)) {
                let merged = match (out.last().and_then(num), num(&f)) {
                    (Some(a), Some(b)) => ops::mul(a, b, &Kind::Unknown).ok(),
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
        Sym::Inv(x) => {
            let x = resolve(x, env);
            unary(&x, ops::inverse).unwrap_or_else(|| x.inverse())
        }
        Sym::Transpose(x) => {
            let x = resolve(x, env);
            unary(&x, |v| Ok(ops::transpose(v))).unwrap_or_else(|| x.transpose())
        }
        Sym::Neg(x) => {
            let x = resolve(x, env);
            unary(&x, |v| ops::neg(v, &v.kind())).unwrap_or_else(|| Sym::Neg(Box::new(x)))
        }
        Sym::Bracket(x) => {
            let x = resolve(x, env);
            unary(&x, |v| ops::brackets(&[vec![v.clone()]]))
                .unwrap_or_else(|| Sym::Bracket(Box::new(x)))
        }
        Sym::Member(x, m) => {
            let x = resolve(x, env);
            unary(&x, |v| ops::member(v, m)).unwrap_or_else(|| Sym::Member(Box::new(x), m.clone()))
        }
        Sym::Add(a, b) => binary(
            a,
            b,
            env,
            |l, r| ops::add(l, r, false, &Kind::Unknown),
            Sym::Add,
        ),
        Sym::Sub(a, b) => binary(
            a,
            b,
            env,
            |l, r| ops::add(l, r, true, &Kind::Unknown),
            Sym::Sub,
        ),
        Sym::Div(a, b) => binary(a, b, env, |l, r| ops::div(l, r, &l.kind()), Sym::Div),
        Sym::Pow(a, b) => binary(
            a,
            b,
            env,
            |l, r| {
                let e = r.as_scalar().ok_or("the exponent must be a number")?;
                ops::pow(l, e, &l.kind())
            },
            Sym::Pow,
        ),
        Sym::Block(rows) => {
            let rows: Vec<Vec<Sym>> = rows
                .iter()
                .map(|r| r.iter().map(|x| resolve(x, env)).collect())
                .collect();
            let vals: Option<Vec<Vec<Value>>> = rows
                .iter()
                .map(|r| r.iter().map(|x| num(x).cloned()).collect())
                .collect();
            vals.and_then(|v| ops::brackets(&v).ok())
                .map(constant)
                .unwrap_or(Sym::Block(rows))
        }
        Sym::Vector(parts) => {
            let parts: Vec<Sym> = parts.iter().map(|x| resolve(x, env)).collect();
            let vals: Option<Vec<f64>> = parts
                .iter()
                .map(|x| num(x).and_then(Value::as_scalar))
                .collect();
            match vals {
                Some(xs) => constant(Value::vector(Kind::Vector(Some(xs.len())), &xs)),
                None => Sym::Vector(parts),
            }
        }
        Sym::Index(x, sels) => {
            let x = resolve(x, env);
            let sel: Vec<ops::Sel> = sels
                .iter()
                .map(|s| s.map_or(ops::Sel::All, ops::Sel::At))
                .collect();
            unary(&x, |v| ops::index(v, &sel))
                .unwrap_or_else(|| Sym::Index(Box::new(x), sels.clone()))
        }
        Sym::Call(name, args) => {
            let args: Vec<Sym> = args.iter().map(|a| resolve(a, env)).collect();
            let vals: Option<Vec<Value>> = args.iter().map(|a| num(a).cloned()).collect();
            vals.and_then(|vals| call(name, vals))
                .map(constant)
                .unwrap_or_else(|| Sym::Call(name.clone(), args))
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
        } => Value::Num {
            kind: classify(&m),
            m,
        },
        other => other,
    };
    to_sym(&v)
}

fn classify(m: &crate::values::num::Num) -> Kind {
    if m.shape() == (1, 1) {
        Kind::Scalar
    } else if m.ncols() == 1 {
        Kind::Vector(Some(m.nrows()))
    } else {
        convert::classify(m)
    }
}

fn unary(x: &Sym, f: impl FnOnce(&Value) -> Result<Value, String>) -> Option<Sym> {
    num(x).and_then(|v| f(v).ok()).map(constant)
}

fn binary(
    a: &Sym,
    b: &Sym,
    env: &Env,
    f: impl FnOnce(&Value, &Value) -> Result<Value, String>,
    rebuild: fn(Box<Sym>, Box<Sym>) -> Sym,
) -> Sym {
    let (a, b) = (resolve(a, env), resolve(b, env));
    match (num(&a), num(&b)) {
        (Some(l), Some(r)) => match f(l, r) {
            Ok(v) => constant(v),
            Err(_) => rebuild(Box::new(a), Box::new(b)),
        },
        _ => rebuild(Box::new(a), Box::new(b)),
    }
}

/// A builtin applied to numbers, as the interpreter would; None for a user
/// function, an unknown name or an error.
fn call(name: &str, vals: Vec<Value>) -> Option<Value> {
    let b = crate::builtins::lookup(name)?;
    let mut warnings = Vec::new();
    let spans = vec![Default::default(); vals.len()];
    let mut args = crate::builtins::Args {
        name: b.name,
        signature: b.signature,
        vals,
        spans,
        call_span: Default::default(),
        warnings: &mut warnings,
        typed: Vec::new(),
    };
    (b.eval)(&mut args).ok()
}
