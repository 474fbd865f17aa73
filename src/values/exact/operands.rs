//! The operands of an exact form's recipe ([`super::Pending`]): the
//! values an operation was applied to, kept as the evaluator gave them
//! away, copied, or — a lone number as typed or a fraction held inline —
//! in the recipe's node itself.

use std::rc::Rc;

use super::{Exact, Fraction};
use crate::check::ty::Kind;
use crate::values::num::Num;
use crate::values::value::Value;

/// The operands of a [`super::Pending`] recipe: the two operands of an operator
/// moved in as the evaluator held them (boxed: no copy), copies, or a
/// lone number held in the node.
pub enum Operands {
    /// The two operands of a binary operator, moved in as the evaluator
    /// held them.
    Pair(Box<Value>, Box<Value>),
    /// Copies of the operands (or a builtin call's arguments given away),
    /// in order.
    Copied(Box<[Value]>),
    /// A lone scalar operand as typed (None) or a fraction held inline
    /// (`sin(t)` of a range's item, the θ of `Rotz(k/100)`): its float and
    /// fraction in the recipe's node, no box of a value.
    Scalar(f64, Option<Fraction>),
}

/// An operand of a recipe as it is read ([`Operands::refs`]): the value
/// kept, or a lone number's value made anew.
pub type Operand<'a> = std::borrow::Cow<'a, Value>;

impl Operands {
    /// Copies of the operands `args`.
    pub fn of<V: std::borrow::Borrow<Value>>(args: &[V]) -> Operands {
        if let [one] = args
            && let Some(s) = Operands::scalar(one.borrow())
        {
            return s;
        }
        Operands::Copied(args.iter().map(|v| v.borrow().clone()).collect())
    }
    /// The operands `args`, given away (a builtin call's arguments).
    pub fn owned(args: Vec<Value>) -> Operands {
        if let [one] = args.as_slice()
            && let Some(s) = Operands::scalar(one)
        {
            return s;
        }
        Operands::Copied(args.into_boxed_slice())
    }
    /// A lone scalar operand held in the node, when it is a number as
    /// typed or a fraction held inline.
    #[inline]
    fn scalar(v: &Value) -> Option<Operands> {
        match v {
            Value::Num {
                kind: Kind::Scalar,
                m: Num::Scalar(x),
                exact,
            } => match exact {
                Exact::Typed => Some(Operands::Scalar(*x, None)),
                Exact::Ratio(r) => Some(Operands::Scalar(*x, Some(*r))),
                _ => None,
            },
            _ => None,
        }
    }
    /// The longest chain of waiting recipes under the operands, and about
    /// the bytes they hold beyond the recipe's node, as the memory budget
    /// counts them ([`Exact::weight`]): each operand's value, and the
    /// recipe under it when no one else holds it (one that a binding or
    /// another item also holds is counted there, once). One pass.
    #[inline]
    pub(super) fn under(&self) -> (u32, u32) {
        const VALUE: u32 = std::mem::size_of::<Value>() as u32;
        let one = |v: &Value| match v {
            Value::Num {
                exact: Exact::Later(l),
                ..
            } => {
                let own = if Rc::strong_count(l) == 1 { l.bytes } else { 0 };
                // (a form found missing keeps its recipe, [`Exact::with_recipe`]:
                // it still counts, so that kept recipes stay as short as
                // waiting ones; a form known counts 0)
                let depth = match l.form.get() {
                    Some(Some(_)) => 0,
                    _ => l.depth,
                };
                (depth, VALUE.saturating_add(own))
            }
            _ => (0, VALUE),
        };
        let both = |(d, b): (u32, u32), (e, c): (u32, u32)| (d.max(e), b.saturating_add(c));
        match self {
            Operands::Pair(a, b) => both(one(a), one(b)),
            Operands::Copied(vs) => vs.iter().map(one).fold((0, 0), both),
            Operands::Scalar(..) => (0, 0),
        }
    }
    /// The operands in order (a lone number's value made anew: the same
    /// kind, float and exact form).
    pub fn refs(&self) -> Vec<Operand<'_>> {
        use std::borrow::Cow::Borrowed;
        match self {
            Operands::Pair(a, b) => vec![Borrowed(&**a), Borrowed(&**b)],
            Operands::Copied(vs) => vs.iter().map(Borrowed).collect(),
            Operands::Scalar(x, r) => vec![Operand::Owned(Value::Num {
                kind: Kind::Scalar,
                m: Num::Scalar(*x),
                exact: r.map_or(Exact::Typed, Exact::Ratio),
            })],
        }
    }
}

/// Operands as references, as an operation's exact path reads them.
pub fn deref<'a>(args: &'a [Operand<'_>]) -> Vec<&'a Value> {
    args.iter().map(|a| &**a).collect()
}
