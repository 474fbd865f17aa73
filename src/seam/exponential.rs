//! A power of an exponential over symbols (LANGUAGE.md §7): e^{X} commutes
//! with itself, so (e^{X})ⁿ = e^{nX} for every integer n, negative ones
//! included (3.51, 3.88: the book's exponentials of a multiple). The
//! interpreter rewrites `exp(X)^n` as written ([`crate::eval`]'s notation);
//! here the same holds of a value: a formula made by `exp(X)` keeps that
//! in its recipe ([`crate::values::recipe`]), so `E = exp(X); E^50` is the
//! closed form of `exp(50 X)` too, not the 50th power of its entries.
//!
//! A recipe holds no names: it is what the value was made of when it was
//! made, so binding X or E again later changes nothing it says, and any
//! operation on E (`E + 0`, `E[1, 1]`, `subs`) makes a new value with its
//! own recipe (or none). The exponent X is made again from its recipe by
//! the same operations over formulas, as it was made the first time.

use super::apply::Op;
use crate::check::ty::Kind;
use crate::syntax::ast::BinOp;
use crate::values::error::OpError;
use crate::values::recipe::{Operation, Recipe, Step};
use crate::values::value::Value;
use std::rc::Rc;

/// The deepest recipe of an exponent made again (a longer one keeps the
/// power: right, only longer to print).
const MAX_DEPTH: u32 = 12;

/// `E^n` for a square formula E made by `exp(X)` and an integer number n:
/// `exp(n X)` over formulas, with its own recipe. None for any other
/// operation or operands, or when X cannot be made again.
/// (The test of the operation and operands only, inlined where every
/// operation is applied; the rest is [`of_exp`].)
#[inline]
pub(super) fn power(op: Op, args: &[&Value], kind: &Kind) -> Option<Result<Value, OpError>> {
    match (op, args) {
        (Op::Arith(BinOp::Pow), [Value::Formula { how: Some(_), .. }, Value::Num { .. }]) => {
            of_exp(args, kind)
        }
        _ => None,
    }
}

/// [`power`] past its test.
#[cold]
#[inline(never)]
fn of_exp(args: &[&Value], kind: &Kind) -> Option<Result<Value, OpError>> {
    let [
        Value::Formula {
            how: Some(r), m, ..
        },
        n,
    ] = args
    else {
        return None;
    };
    let n = match n {
        Value::Num { .. } => n.as_scalar()?,
        _ => return None,
    };
    if m.rows < 2 || m.rows != m.cols || n.fract() != 0.0 || n.abs() > f64::from(i32::MAX) {
        return None;
    }
    let r = match (&r.step, r.args.as_slice()) {
        (Step::Retag, [made]) => made,
        _ => r,
    };
    let (Step::Op(Operation::Call(name)), [x]) = (&r.step, r.args.as_slice()) else {
        return None;
    };
    let b = crate::builtins::lookup(name).filter(|b| b.name == "exp")?;
    let x = made_again(x, MAX_DEPTH)?;
    if !matches!(x, Value::Formula { .. }) {
        return None;
    }
    let times = Op::Arith(BinOp::Mul);
    let multiple = match times.apply(&[&Value::scalar(n), &x], &x.kind()) {
        Ok(v @ Value::Formula { .. }) => v,
        _ => return None,
    };
    let out = Op::Call(b, name).exact_or_symbolic(&[&multiple], kind)?;
    match out {
        Ok(Value::Formula { .. }) | Err(_) => Some(out),
        Ok(_) => None,
    }
}

/// The value recipe `r` made, made again by its operations over formulas
/// (its leaves as they were); None past `depth` steps or for a step that
/// is not one operation of the seam.
fn made_again(r: &Rc<Recipe>, depth: u32) -> Option<Value> {
    if r.depth > depth {
        return None;
    }
    let op = match (&r.step, r.args.as_slice()) {
        (Step::Leaf(v), _) => return Some(v.clone()),
        (Step::Op(o), _) => Op::of(o)?,
        // (a closed form marked with its branch is the call, §7)
        (Step::Closed(on), [call]) if !on.guards => return made_again(call, depth),
        // (with the kind its name gave it: `w = (1, 2, 3) x`)
        (Step::Retag, [made]) => {
            return Some(match made_again(made, depth)? {
                Value::Formula { m, how, .. } => Value::Formula {
                    kind: r.kind,
                    m,
                    how,
                },
                v => v,
            });
        }
        _ => return None,
    };
    let args: Vec<Value> = r
        .args
        .iter()
        .map(|a| made_again(a, depth))
        .collect::<Option<_>>()?;
    let refs: Vec<&Value> = args.iter().collect();
    op.apply(&refs, &r.kind).ok()
}
