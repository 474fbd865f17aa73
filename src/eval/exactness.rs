//! Exact forms of numeric results (LANGUAGE.md §3, §7; issue 21): every
//! operation on numbers that all have an exact form gives its result one —
//! numbers as typed stay as typed through operations that only move,
//! negate or pick entries, and any other operation records how to compute
//! its exact form through the operation's exact path ([`Op::formula`]),
//! run only when the form is asked for (`==`, a symbolic expression,
//! `--exact`). So exactness costs a flag where no one asks for it.

use super::apply::Op;
use super::formula;
use super::ops::Sel;
use super::value::Value;
use crate::check::ty::Kind;
use crate::values::exact::Exact;

impl Op<'_> {
    /// `v`, the result of this operation on numbers `args`, with its exact
    /// form ([`Op::exact_of`]) when it is a number.
    #[inline]
    pub fn with_exact(self, v: Value, args: &[&Value], kind: &Kind) -> Value {
        if !matches!(v, Value::Num { .. }) || !args.iter().all(|a| a.may_be_exact()) {
            return v;
        }
        v.with_exact(self.exact_of(args, kind))
    }

    /// The exact form of this operation on numbers `args` that all have one
    /// (LANGUAGE.md §3, §7): numbers as typed stay as typed through the
    /// operations that only move, negate or pick entries; any other
    /// operation records how to compute its exact form by its exact path
    /// ([`Op::formula`]) over the operands' exact forms, run only when the
    /// form is asked for (`==`, a symbolic expression, `--exact`).
    pub fn exact_of(self, args: &[&Value], kind: &Kind) -> Exact {
        if args.is_empty() || !args.iter().all(|a| a.may_be_exact()) {
            return Exact::Float;
        }
        // Builtins whose results are exact at exact arguments often enough
        // to be worth a recipe (square roots, trigonometry at multiples of
        // π/12, rotations by them, products); exp, log and the adjoint of
        // numbers are floats (issue 14's benchmark makes them by the
        // thousand).
        if let Op::Call(b, _) = self
            && !EXACT_CALLS.contains(&b.name)
        {
            return Exact::Float;
        }
        let typed = args.iter().all(|a| {
            matches!(
                a,
                Value::Num {
                    exact: Exact::Typed,
                    ..
                }
            )
        });
        let moves = matches!(
            self,
            Op::Neg | Op::Transpose | Op::Member(_) | Op::Index(_) | Op::Vector | Op::Block(_)
        );
        if typed && moves {
            return Exact::Typed;
        }
        let op = match self {
            Op::Index(sels) => Owned::Index(sels.to_vec()),
            Op::Block(widths) => Owned::Block(widths.to_vec()),
            Op::Call(b, _) => Owned::Plain(Op::Call(b, b.name)),
            Op::Neg => Owned::Plain(Op::Neg),
            Op::Degrees => Owned::Plain(Op::Degrees),
            Op::Arith(o) => Owned::Plain(Op::Arith(o)),
            Op::Inverse => Owned::Plain(Op::Inverse),
            Op::Transpose => Owned::Plain(Op::Transpose),
            Op::Member(part) => Owned::Plain(Op::Member(part)),
            Op::Vector => Owned::Plain(Op::Vector),
        };
        let vals: Vec<Value> = args.iter().map(|v| (*v).clone()).collect();
        let kind = *kind;
        Exact::later(move || {
            let forms = vals
                .iter()
                .map(|v| {
                    Some(Value::Formula {
                        kind: v.kind(),
                        m: v.exact_form()?,
                        how: None,
                    })
                })
                .collect::<Option<Vec<Value>>>()?;
            let refs: Vec<&Value> = forms.iter().collect();
            let out = match &op {
                Owned::Plain(op) => op.formula(&refs, &kind),
                Owned::Index(sels) => Op::Index(sels).formula(&refs, &kind),
                Owned::Block(widths) => {
                    let mut rest = forms.into_iter();
                    let rows: Vec<Vec<Value>> = widths
                        .iter()
                        .map(|&n| rest.by_ref().take(n).collect())
                        .collect();
                    Some(formula::brackets(&rows))
                }
            };
            match out?.ok()? {
                Value::Formula { m, .. } => crate::values::exact::is_exact(&m).then_some(m),
                v => v.exact_form(),
            }
        })
    }
}

/// The builtins [`Op::exact_of`] gives an exact form.
const EXACT_CALLS: &[&str] = &[
    "sqrt",
    "abs",
    "sin",
    "cos",
    "tan",
    "cot",
    "sec",
    "csc",
    "Rotx",
    "Roty",
    "Rotz",
    "Rot",
    "cross",
    "dot",
    "det",
    "trace",
    "inv",
    "RotInv",
    "TransInv",
    "VecToso3",
    "VecTose3",
    "so3ToVec",
    "se3ToVec",
    "RpToTrans",
    "norm",
    "transpose",
];

/// An operation as [`Op::exact_of`] keeps it until its exact form is
/// asked for (owning what [`Op`] borrows).
enum Owned {
    Plain(Op<'static>),
    Index(Vec<Sel>),
    Block(Vec<usize>),
}
