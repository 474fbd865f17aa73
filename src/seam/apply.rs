//! The one operation seam (issue 14): every operation of the language as
//! one variant of [`Op`], and for each, in this one place, its
//! type-and-frame rule ([`Op::rule`], the rules of LANGUAGE.md §6 in
//! [`crate::check::rules`]), its numeric function ([`Op::numeric`], over
//! [`crate::values::ops`]), its exact form over symbolic scalars ([`Op::formula`],
//! chapter 3 with symbols) and its form over `given` symbols
//! ([`Op::symbolic`], LANGUAGE.md §7). [`Op::apply`] picks among the three
//! value paths. The evaluator evaluates a node's children and applies its
//! operation; the substitution of numbers into symbols
//! (`calculus::substitute`) applies the same operations to the numbers it
//! finds. Adding an operation is one variant, one rule, one numeric
//! function and one symbolic form.
//!
//! The frame-mode policy (strict, warn, off: what a frame mismatch becomes)
//! is [`crate::eval::env::FrameMode::refusal`] and [`crate::eval::env::FrameMode::warning`].

use std::f64::consts::PI;

pub use super::call::{Site, call, call_keeping, call_nowhere};
use super::shapes::{block_type, bracket_type, index_type};
pub use crate::builtins::Spans;
use crate::builtins::{Builtin, Role};
use crate::check::rules::{self, Operands, RuleError};
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{BinOp, Span};
use crate::values::formula;
use crate::values::ops::{self, OpError, Sel};
use crate::values::recipe::{self, Made, Step};
use crate::values::symbolic::{Fun, Part};
use crate::values::value::{Sym, Value};

/// One operation of the language: what a node of an expression does with
/// the values of its children.
#[derive(Clone, Copy)]
pub enum Op<'a> {
    /// `-x`.
    Neg,
    /// `x deg`, `x°`: an angle in degrees, as radians.
    Degrees,
    /// `a + b`, `a - b`, `a b`, `a / b`, `a ^ b`.
    Arith(BinOp),
    /// The inverse `X⁻¹` of symbols that become numbers (`inv`, `^-1`).
    Inverse,
    /// `x.T`, the transpose (`[ω]ᵀ = −[ω]`, `[Ad_T]ᵀ` acts on wrenches).
    Transpose,
    /// `T.R`, `T.p`, `V.w`, `V.v`, `F.m`, `F.f`: a part of a value.
    Member(Part),
    /// `x[i]`, `M[i, j]`, `M[:, j]` (1-based).
    Index(&'a [Sel]),
    /// `[x]`, the book's bracket of a 3- or 6-vector (3.30, 3.70), and
    /// `[a, b; c, d]`, a block matrix: the number of entries of each row
    /// (`[x]` is `Block(&[1])`); its operands are the entries, row by row.
    Block(&'a [usize]),
    /// `(a, b, c)`: a column vector of scalars.
    Vector,
    /// A call of a builtin, by the name it was called with (`Ad` or
    /// `Adjoint`); its rule is its table row's [`Builtin::check`].
    Call(&'static Builtin, &'a str),
}

/// An operand of [`Op::rule`]: a type, or a reference to one. A builtin's
/// rule reads a slice of types ([`Builtin::check`]), the operators' rules
/// references; each gets its own without a copy when it is what it has.
pub trait Operand: std::borrow::Borrow<Ty> + Sized {
    /// `f` of the operands as types (copied only when they are references).
    fn with_tys<R>(args: &[Self], f: impl FnOnce(&[Ty]) -> R) -> R;
    /// `f` of the operands as references (collected only when they are types).
    fn with_refs<R>(args: &[Self], f: impl FnOnce(&[&Ty]) -> R) -> R;
}

impl Operand for Ty {
    #[inline(always)]
    fn with_tys<R>(args: &[Ty], f: impl FnOnce(&[Ty]) -> R) -> R {
        f(args)
    }
    fn with_refs<R>(args: &[Ty], f: impl FnOnce(&[&Ty]) -> R) -> R {
        f(&args.iter().collect::<Vec<_>>())
    }
}

impl Operand for &Ty {
    fn with_tys<R>(args: &[&Ty], f: impl FnOnce(&[Ty]) -> R) -> R {
        f(&args.iter().map(|t| **t).collect::<Vec<_>>())
    }
    #[inline(always)]
    fn with_refs<R>(args: &[&Ty], f: impl FnOnce(&[&Ty]) -> R) -> R {
        f(args)
    }
}

/// What a rule may need besides the operands' types: the operands as
/// written (for help text) and a literal exponent (`X^-1`).
#[derive(Debug, Clone, Copy, Default)]
pub struct Hints<'a> {
    /// Both operands as written.
    pub operands: Operands<'a>,
    /// The exponent of `X ^ e` when known: a literal, or its value.
    pub exponent: Option<f64>,
}

impl<'a> Op<'a> {
    /// The operation of a member name: `.T` is the transpose; None for a
    /// name that is no member.
    pub fn member(name: &str) -> Option<Op<'a>> {
        if name == "T" {
            Some(Op::Transpose)
        } else {
            Part::of(name).map(Op::Member)
        }
    }

    /// The kind and frames of the result from the operands' (LANGUAGE.md
    /// §6), checked without numbers: every operation's rule is here. A
    /// block's is `shapes::block_type`; a call's its table row's
    /// [`Builtin::check`] (a refusal says which argument, with the
    /// signature as help), then [`rules::settle`] (a vector or Lie-algebra
    /// result is in one frame); the inverse's [`rules::inverse`].
    /// The operands are types or references to them ([`Operand`]): a
    /// builtin's arguments are a slice of types, an operator's references.
    #[inline(always)]
    pub fn rule<T: Operand>(self, args: &[T], hints: Hints) -> Result<Ty, RuleError> {
        match self {
            Op::Block(widths) => Ok(match args {
                [t] => bracket_type(std::borrow::Borrow::borrow(t)),
                _ => T::with_refs(args, |args| block_type(widths, args)),
            }),
            Op::Call(b, _) => T::with_tys(args, |args| call_rule(b, args)),
            _ => T::with_refs(args, |args| self.operator_rule(args, hints)),
        }
    }

    /// [`Op::rule`] of the operators (all but brackets and calls).
    #[inline(always)]
    fn operator_rule(self, args: &[&Ty], hints: Hints) -> Result<Ty, RuleError> {
        match (self, args) {
            (Op::Neg, [t]) => rules::neg(t),
            (Op::Degrees, _) => Ok(Ty::scalar()),
            (Op::Arith(op), [a, b]) => match op {
                BinOp::Mul => rules::mul(a, b, hints.operands),
                BinOp::Add | BinOp::Sub => rules::add(a, b),
                BinOp::Div => rules::div(a, b),
                BinOp::Pow => rules::pow(a, b, hints.exponent),
            },
            (Op::Transpose, [t]) => rules::member(t, "T"),
            (Op::Member(part), [t]) => rules::member(t, part.name()),
            (Op::Index(sels), [t]) => index_type(t, sels),
            (Op::Vector, _) => Ok(Ty::plain(Kind::Vector(Some(args.len())))),
            (Op::Inverse, [t]) => rules::inverse(t),
            _ => Ok(Ty::plain(Kind::Unknown)),
        }
    }

    /// The operation on numbers. `kind` is the result's kind as checked;
    /// None when symbols are re-evaluated with numbers (the operation then
    /// finds the kind from its operands). Blocks take rows:
    /// [`block_numeric`].
    #[inline(always)]
    pub fn numeric(self, args: &[&Value], kind: Option<&Kind>) -> Result<Value, OpError> {
        let unknown = &Kind::Unknown;
        match (self, args) {
            (Op::Neg, [v]) => match kind {
                Some(k) => ops::neg(v, k),
                None => ops::neg(v, &v.kind()),
            },
            (Op::Degrees, [v]) => Ok(Value::scalar(
                v.as_scalar().unwrap_or(f64::NAN) * PI / 180.0,
            )),
            (Op::Arith(op), [a, b]) => {
                let own = || a.kind();
                match op {
                    BinOp::Mul => ops::mul(a, b, kind.unwrap_or(unknown)),
                    BinOp::Add => ops::add(a, b, false, kind.unwrap_or(unknown)),
                    BinOp::Sub => ops::add(a, b, true, kind.unwrap_or(unknown)),
                    BinOp::Div => match kind {
                        Some(k) => ops::div(a, b, k),
                        None => ops::div(a, b, &own()),
                    },
                    BinOp::Pow => {
                        // (by its exact form when it has one: √2² is 2)
                        let e = crate::values::domain::Decided::of(b)
                            .map(|d| d.value())
                            .ok_or(OpError::ExponentNotANumber)?;
                        match kind {
                            Some(k) => ops::pow(a, e, k),
                            None => ops::pow(a, e, &own()),
                        }
                    }
                }
            }
            (Op::Inverse, [v]) => ops::inverse(v),
            (Op::Transpose, [v]) => Ok(ops::transpose(v)),
            (Op::Member(part), [v]) => ops::member(v, part.name()),
            (Op::Index(sels), [v]) => ops::index(v, sels),
            (Op::Vector, _) => {
                let xs: Vec<f64> = args
                    .iter()
                    .map(|v| v.as_scalar().unwrap_or(f64::NAN))
                    .collect();
                Ok(Value::vector(Kind::Vector(Some(xs.len())), &xs))
            }
            (Op::Block(widths), _) => block_numeric(&super::shapes::rows_of(widths, args)),
            (Op::Call(b, _), _) => call_nowhere(b, args.iter().map(|v| (*v).clone()).collect()),
            _ => Err(OpError::Operands),
        }
    }

    /// The exact operation over symbolic scalars (chapter 3 with symbols,
    /// [`formula`]); None when it has no such form (the value stays a
    /// tree, or — for a builtin — is computed another way).
    pub fn formula(self, args: &[&Value], kind: &Kind) -> Option<Result<Value, String>> {
        match (self, args) {
            (Op::Neg, [v]) => formula::neg(v).map(Ok),
            (Op::Degrees, [v]) => formula::scalar_of(v).map(|x| {
                use crate::sym::coef::{Coef, Rat};
                let deg =
                    crate::sym::Expr::pi().scale(&Coef::rat(Rat::new(1, 180).unwrap_or(Rat::ONE)));
                Ok(formula::scalar(x.mul(&deg)))
            }),
            (Op::Arith(op), [a, b]) => formula::binary_or_tree(op, a, b, kind),
            (Op::Transpose, [v]) => Some(formula::member(v, "T")),
            (Op::Member(part), [v]) => Some(formula::member(v, part.name())),
            (Op::Index(sels), [v]) => Some(formula::index(v, sels)),
            (Op::Vector, _) => {
                let vals: Vec<Value> = args.iter().map(|v| (*v).clone()).collect();
                formula::vector(&vals).map(Ok)
            }
            (Op::Call(b, _), _) => {
                let vals: Vec<Value> = args.iter().map(|v| (*v).clone()).collect();
                crate::builtins::eval_symbolic(b.name, &vals, kind)
            }
            // (as the evaluator's [`block`]: `[S]` of a 6-vector formula is se(3))
            (Op::Block(widths), _) => {
                Some(formula::brackets(&super::shapes::rows_of(widths, args)))
            }
            _ => None,
        }
    }

    /// The operation over `given` symbols (LANGUAGE.md §7): a node of the
    /// symbolic tree, simplified where the book's identities allow
    /// (`inv(inv(X)) = X`, `(A B)ᵀ = Bᵀ Aᵀ`).
    pub fn symbolic(self, mut args: Vec<Sym>) -> Sym {
        let one = |args: &mut Vec<Sym>| args.pop().unwrap_or_else(Sym::identity);
        match self {
            Op::Neg => Sym::Neg(Box::new(one(&mut args))),
            Op::Degrees => Sym::times(one(&mut args), Sym::Name("deg".into())),
            Op::Arith(op) => {
                let b = one(&mut args);
                let a = one(&mut args);
                match op {
                    BinOp::Mul => super::powers::scaled(&a, &b, true)
                        .or_else(|| super::powers::scaled(&b, &a, true))
                        .or_else(|| super::powers::joined(&a, &b))
                        .unwrap_or_else(|| Sym::times(a, b)),
                    BinOp::Add => Sym::Add(Box::new(a), Box::new(b)),
                    BinOp::Sub => Sym::Sub(Box::new(a), Box::new(b)),
                    BinOp::Div => super::powers::scaled(&a, &b, false)
                        .unwrap_or_else(|| Sym::Div(Box::new(a), Box::new(b))),
                    BinOp::Pow if constant(&b).and_then(Value::as_scalar) == Some(-1.0) => {
                        a.inverse()
                    }
                    BinOp::Pow => Sym::Pow(Box::new(a), Box::new(b)),
                }
            }
            Op::Inverse => one(&mut args).inverse(),
            Op::Transpose => one(&mut args).transpose(),
            // (`[R, p; 0, 1].R` is R, 3.62)
            Op::Member(part) => {
                let x = one(&mut args);
                super::transform::member(&x, part).unwrap_or_else(|| Sym::Member(Box::new(x), part))
            }
            Op::Index(sels) => Sym::Index(
                Box::new(one(&mut args)),
                sels.iter()
                    .map(|s| match s {
                        Sel::At(x) => Some(*x),
                        Sel::All => None,
                    })
                    .collect(),
            ),
            Op::Block([1]) => Sym::Bracket(Box::new(one(&mut args))),
            Op::Block(widths) => {
                let mut rest = args.into_iter();
                Sym::Block(
                    widths
                        .iter()
                        .map(|&n| rest.by_ref().take(n).collect())
                        .collect(),
                )
            }
            Op::Vector => Sym::Vector(args),
            Op::Call(b, name) => match b.role() {
                Role::Inverse => one(&mut args).inverse(),
                // (a tree over symbols is already in its simplest form: the
                // result prints the form, never the call)
                _ if matches!(b.name, "simplify" | "expand") && args.len() == 1 => one(&mut args),
                // (exp(log(u)) = u wherever log u is defined)
                _ if b.name == "exp"
                    && matches!(args.as_slice(), [Sym::Call(f, a)] if f.name == "log" && a.len() == 1) =>
                {
                    match one(&mut args) {
                        Sym::Call(_, mut a) => a.pop().unwrap_or_else(Sym::identity),
                        other => other,
                    }
                }
                role => Sym::Call(
                    Fun {
                        name: b.names().find(|n| *n == name).unwrap_or(b.name),
                        role,
                    },
                    args,
                ),
            },
        }
    }

    /// What replaying this operation with numbers does (LANGUAGE.md §7,
    /// [`recipe`]): its own step, for every operation whose numeric
    /// function computes what its exact form does; `diff` and `subs` read
    /// their operands' symbols (their results are leaves, or for `diff` of
    /// a scalar the chain rule's steps, `super::chain`), `simplify` and
    /// `expand` give their operand's value.
    fn made(self) -> Made {
        match self {
            Op::Call(b, _) if matches!(b.name, "diff" | "subs") => Made::Opaque,
            Op::Call(b, _) if matches!(b.name, "simplify" | "expand") => Made::Same,
            // (no exact form makes an inverse: `inv` is a call)
            Op::Inverse => Made::Opaque,
            op => Made::Step(Step::Op(op.owned())),
        }
    }

    /// Whether a formula operand, with no `given` symbol, makes the result
    /// symbolic when the exact path gives none (arithmetic and vectors of
    /// formulas have always an exact form or none at all).
    fn formula_is_symbolic(self) -> bool {
        !matches!(self, Op::Vector) && !matches!(self, Op::Arith(o) if o != BinOp::Pow)
    }

    /// The error of this operation on values ([`Op::apply`]) as the
    /// evaluator reports it at `span`: a type error for a part or a
    /// bracket the value has not (`.R` of a vector, blocks that do not
    /// fit), else a domain error (the values are outside the operation's
    /// domain: a singular inverse, an index out of range).
    pub fn failure(self, e: OpError, span: Span) -> Diagnostic {
        let kind = match self {
            Op::Transpose | Op::Member(_) | Op::Block(_) => ErrorKind::Type,
            _ => ErrorKind::Domain,
        };
        Diagnostic::error(kind, span, e.to_string())
    }

    /// The operation on values: the exact path when a symbolic scalar is
    /// among numbers ([`Op::formula`]), the symbolic one when a `given`
    /// symbol is among the operands ([`Op::symbolic`]), else numbers
    /// ([`Op::numeric`]). `kind` is the result's kind as checked.
    pub fn apply(self, args: &[&Value], kind: &Kind) -> Result<Value, OpError> {
        match self.exact_or_symbolic(args, kind) {
            Some(v) => v,
            None => {
                let mut v = self.numeric(args, Some(kind))?;
                self.set_exact(&mut v, args, kind);
                Ok(v)
            }
        }
    }

    /// The first two paths of [`Op::apply`]: None when the operands are
    /// numbers (a builtin call then computes with its spans and warnings).
    #[inline]
    pub fn exact_or_symbolic(self, args: &[&Value], kind: &Kind) -> Option<Result<Value, OpError>> {
        // Every path needs a symbolic operand (an expression or a formula):
        // numbers, the common case, leave at once, without a call.
        if !args
            .iter()
            .any(|v| matches!(v, Value::Sym(_) | Value::Formula { .. }))
        {
            return None;
        }
        self.symbolic_paths(args, kind)
    }

    /// [`Op::exact_or_symbolic`] of operands of which one is symbolic.
    #[inline(never)]
    fn symbolic_paths(self, args: &[&Value], kind: &Kind) -> Option<Result<Value, OpError>> {
        if let Some(v) = super::exponential::power(self, args, kind) {
            return Some(v);
        }
        if formula::applies(args)
            && let Some(v) = self.formula(args, kind)
        {
            // (symbols that cancel leave numbers: `csc(a − a)` is csc 0, refused)
            let v = v.and_then(|v| match formula::undefined(&v) {
                Some(why) => Err(why),
                None => Ok(v),
            });
            // how it was made, to be replayed with numbers (§7)
            return Some(
                v.map(|v| {
                    let call = if let Op::Call(b, _) = self {
                        b.name
                    } else {
                        ""
                    };
                    super::chain::made(call, v, args, |v| {
                        recipe::record(v, self.made(), args, kind)
                    })
                })
                .map_err(OpError::Message),
            );
        }
        // the transform `[R, p; 0, 1]`: inverse, products, points (3.62–3.64)
        if let Some(t) = super::transform::of_op(self, args, kind) {
            return Some(Ok(Value::Sym(super::transform::cancelled(t, args))));
        }
        if let Op::Call(b, _) = self
            && let Some(zero) = crate::builtins::constant_derivative(b.name, args, kind)
        {
            return Some(Ok(zero));
        }
        // (numbers the symbols cancelled to, `csc(a − a)`: refused as typed)
        if let Some(nums) = formula::all_numbers(args)
            && let Err(e) = self.numeric(&nums.iter().collect::<Vec<_>>(), Some(kind))
            && !matches!(e, OpError::NotNumbers(_) | OpError::Operands)
        {
            return Some(Err(e));
        }
        let formulas = self.formula_is_symbolic();
        args.iter()
            .any(|v| v.is_symbolic() || (formulas && matches!(v, Value::Formula { .. })))
            .then(|| {
                // (a law of exponents may leave a number: 2^x 2^(-x) is 1)
                Ok(
                    match self.symbolic(args.iter().map(|v| to_sym(v)).collect()) {
                        Sym::Const(v, _) => *v,
                        s => Value::Sym(super::transform::cancelled(s, args)),
                    },
                )
            })
    }
}

/// `[ ... ]` ([`Op::Block`]) by the first two paths of [`Op::apply`]:
/// None when every entry is a number.
pub fn block(rows: &[Vec<Value>]) -> Option<Result<Value, OpError>> {
    let refs: Vec<&Value> = rows.iter().flatten().collect();
    if formula::applies(&refs) {
        return Some(
            formula::brackets(rows)
                .map(|v| {
                    let widths: Vec<usize> = rows.iter().map(Vec::len).collect();
                    recipe::record(v, Op::Block(&widths).made(), &refs, &Kind::Unknown)
                })
                .map_err(OpError::Message),
        );
    }
    refs.iter()
        .any(|v| v.is_symbolic() || matches!(v, Value::Formula { .. }))
        .then(|| {
            Ok(Value::Sym(block_symbolic(
                rows.iter().map(|r| r.iter().map(to_sym).collect()),
            )))
        })
}

/// [`Op::Call`]'s rule: the table row's [`Builtin::check`] (a refusal
/// names the argument, with the signature as help), then
/// [`rules::settle`].
#[inline(always)]
fn call_rule(b: &Builtin, args: &[Ty]) -> Result<Ty, RuleError> {
    let ty = b.check(args).map_err(|e| {
        RuleError::from(crate::check::rules::Refusal {
            kind: Some(e.kind),
            message: e.message,
            help: Some(format!("signature: {}", b.signature)),
            arg: e.arg.and_then(|i| u16::try_from(i).ok()),
            ..Default::default()
        })
    })?;
    rules::settle(ty, b.name)
}

/// `[ ... ]` on numbers: [`ops::brackets`], with its exact form when
/// every entry has one ([`Op::exact_of`]).
pub fn block_numeric(rows: &[Vec<Value>]) -> Result<Value, OpError> {
    let mut v = ops::brackets(rows)?;
    v.set_exact(Op::exact_of_rows(rows));
    Ok(v)
}

/// `[x]` of one number ([`block_numeric`] of one entry, with no rows to
/// make): `[S]` of a screw axis.
pub fn bracket_numeric(x: &Value) -> Result<Value, OpError> {
    let mut v = ops::bracket(x)?;
    v.set_exact(Op::Block(&[1]).exact_of(std::slice::from_ref(x), &Kind::Unknown));
    Ok(v)
}

/// `[ ... ]` over symbols: the bracket `[x]` of one entry, else a block.
pub fn block_symbolic(rows: impl Iterator<Item = Vec<Sym>>) -> Sym {
    let mut rows: Vec<Vec<Sym>> = rows.collect();
    if let [row] = rows.as_mut_slice()
        && row.len() == 1
        && let Some(x) = row.pop()
    {
        return Op::Block(&[1]).symbolic(vec![x]);
    }
    Sym::Block(rows)
}

/// A value as a symbolic operand (numbers become constants).
pub(crate) fn to_sym(v: &Value) -> Sym {
    match v {
        Value::Sym(s) => s.clone(),
        other => Sym::Const(Box::new(other.clone()), constant_text(other)),
    }
}

/// A constant's text inside a tree over symbols: 4 digits where they read
/// back as the number (`0.5`, `2`), else a scalar's every digit, so that
/// the printed tree is its value (issue 35: `sin(1)^y` printed
/// `0.8415^y`, a different number); matrices keep 4 digits a cell.
fn constant_text(v: &Value) -> String {
    if let Some(text) = crate::values::exact::not_decimal_text(v) {
        return text;
    }
    let short = crate::values::format::inline(v, 4);
    match v.as_scalar() {
        Some(x) if x.is_finite() && short.parse::<f64>().ok() != Some(x) => format!("{x}"),
        _ => short,
    }
}

/// The value of a constant operand.
fn constant(s: &Sym) -> Option<&Value> {
    match s {
        Sym::Const(v, _) => Some(v),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn num(x: f64) -> Value {
        Value::scalar(x)
    }

    #[test]
    fn numbers_go_through_the_numeric_function() {
        let (a, b) = (num(6.0), num(4.0));
        let v = Op::Arith(BinOp::Div)
            .apply(&[&a, &b], &Kind::Scalar)
            .unwrap();
        assert_eq!(v.as_scalar(), Some(1.5));
        let v = Op::Degrees.apply(&[&num(180.0)], &Kind::Scalar).unwrap();
        assert_eq!(v.as_scalar(), Some(PI));
        let p = Value::vector(Kind::Vector(Some(3)), &[1.0, 2.0, 3.0]);
        let sel = [Sel::At(2.0)];
        let v = Op::Index(&sel).numeric(&[&p], None).unwrap();
        assert_eq!(v.as_scalar(), Some(2.0));
    }

    #[test]
    fn a_symbol_among_the_operands_gives_a_symbolic_form() {
        let t = Value::Sym(Sym::Name("T_ab".into()));
        let m1 = num(-1.0);
        let inv = Op::Arith(BinOp::Pow).apply(&[&t, &m1], &Kind::SE3).unwrap();
        let Value::Sym(s) = &inv else {
            panic!("not symbolic: {inv:?}")
        };
        assert_eq!(s.to_string(), "inv(T_ab)");
        let inv_b = crate::builtins::lookup("inv").unwrap();
        let back = Op::Call(inv_b, "inv").apply(&[&inv], &Kind::SE3).unwrap();
        let Value::Sym(s) = back else { panic!() };
        assert_eq!(s.to_string(), "T_ab");
        let ad = crate::builtins::lookup("Ad").unwrap();
        assert_eq!(ad.role(), Role::Adjoint);
        let s = Op::Call(ad, "Ad").symbolic(vec![Sym::Name("T_ab".into())]);
        assert_eq!(s.to_string(), "Ad(T_ab)");
    }
}
