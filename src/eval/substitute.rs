//! Numbers bound after a symbolic expression was built (LANGUAGE.md §7:
//! "binding numbers later makes them numeric"). `X = T_ab * T_bc` over
//! `given` symbols keeps the expression `T_ab T_bc`; once `T_ab` and `T_bc`
//! are bound to numbers, reading `X` substitutes them and evaluates what
//! has become numeric, so `X` is then the product's value. Partly numeric
//! expressions keep their symbols (`[1, 0, …] T_bc`). Types and frames are
//! not recomputed: they were checked when the expression was built.

use super::apply::{self, Op};
use super::convert;
use super::env::{Binding, Env};
use super::ops::Sel;
use super::value::Sym;
use super::value::Value;
use crate::check::ty::Kind;
use crate::sym::Symbol;
use crate::syntax::ast::BinOp;

pub(crate) use super::apply::to_sym;

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

/// A formula with the numbers bound since substituted. Once every symbol
/// has a number the value *is* a number (§7): each entry is evaluated at
/// those numbers to machine precision (never left as calls of numbers such
/// as `cos((1/9) π)`), typed by what it is — the formula's kind where the
/// canonical form earned it exactly (a rotation, a scalar, a vector), else
/// what the numbers are, as for numbers typed first (π alone is a number
/// too: it is no symbol). Partly bound, the
/// numbers are put in ([`crate::sym::Expr::at_numbers`]).
fn formula(kind: &Kind, m: &crate::sym::Mat, env: &Env) -> Value {
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
        return super::formula::make(kind, m.clone());
    }
    if syms.iter().all(|s| lookup(s).is_some()) {
        let xs: Option<Vec<f64>> = m.data.iter().map(|e| e.eval(&lookup)).collect();
        if let Some(xs) = xs {
            return numeric(kind, m.rows, m.cols, &xs);
        }
    }
    super::formula::make(kind, m.map(|e| e.at_numbers(&lookup)))
}

/// The numbers of a fully bound formula with their kind: the formula's
/// when it is a decided kind, else classified from the numbers.
fn numeric(kind: &Kind, rows: usize, cols: usize, xs: &[f64]) -> Value {
    let m: crate::values::num::Num = nalgebra::DMatrix::from_row_slice(rows, cols, xs).into();
    let kind = match kind {
        Kind::Unknown | Kind::Matrix(..) | Kind::Vector(None) => classify(&m),
        k => *k,
    };
    Value::Num {
        kind,
        m,
        exact: Default::default(),
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
            Value::Formula { kind, m } => to_sym(&formula(kind, m, env)),
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
            kind: classify(&m),
            m,
            exact,
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
