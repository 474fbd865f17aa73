//! Exact forms of numeric results (LANGUAGE.md §3, §7; issue 21): every
//! operation on numbers that all have an exact form gives its result one —
//! numbers as typed stay as typed through operations that only move,
//! negate or pick entries, and any other operation records how to compute
//! its exact form through the operation's exact path ([`Op::formula`]),
//! run only when the form is asked for (`==`, a symbolic expression,
//! `--exact`). So exactness costs a flag where no one asks for it.

use std::sync::OnceLock;

use super::apply::Op;
use crate::check::ty::Kind;
use crate::sym::Mat;
use crate::sym::coef::Rat;
use crate::syntax::ast::BinOp;
use crate::values::error::OpError;
use crate::values::exact::{Exact, Fraction, Fractions3, Operands, Operation, Pending};
use crate::values::formula;
use crate::values::value::Value;

impl Op<'_> {
    /// [`Op::apply`] on two operands the evaluator gives away: the recipe
    /// of the result's exact form keeps them as they are ([`Op::exact_of_pair`]).
    pub fn apply_pair(self, a: Box<Value>, b: Box<Value>, kind: &Kind) -> Result<Value, OpError> {
        if matches!(self, Op::Arith(BinOp::Add | BinOp::Sub)) {
            return self.apply_sum(a, b, kind);
        }
        self.pair::<false>(a, b, kind)
    }

    /// [`Op::apply_pair`] of a sum or difference: a result whose floats
    /// cancelled takes them from its exact form ([`Op::cancels`]). A
    /// function apart, so that products pay nothing for it.
    #[inline(never)]
    fn apply_sum(self, a: Box<Value>, b: Box<Value>, kind: &Kind) -> Result<Value, OpError> {
        self.pair::<true>(a, b, kind)
    }

    /// [`Op::apply_pair`]'s work; with `SUM`, the cancellation's too.
    #[inline(always)]
    fn pair<const SUM: bool>(
        self,
        a: Box<Value>,
        b: Box<Value>,
        kind: &Kind,
    ) -> Result<Value, OpError> {
        let args = [&*a, &*b];
        if let Some(v) = self.exact_or_symbolic(&args, kind) {
            return v;
        }
        let mut v = self.numeric(&args, Some(kind))?;
        if let Value::Num { exact, .. } = &mut v
            && a.may_be_exact()
            && b.may_be_exact()
        {
            let cancels = SUM && self.cancels(&args);
            // (only a scalar can be a fraction: a product of matrices
            // does not make the call)
            let fraction = match kind {
                Kind::Scalar => self.fraction(&args, kind),
                _ => None,
            };
            *exact = match fraction {
                Some(r) => Exact::Ratio(r),
                None => self.exact_of_pair(a, b, kind),
            };
            if cancels {
                from_exact_form(&mut v);
            }
        }
        Ok(v)
    }

    /// The exact form of `a + b`, `a - b`, `a b` or `a / b` of two numbers
    /// whose exact forms are fractions at hand (whole numbers as typed,
    /// fractions held inline, [`Exact::Ratio`], and decimals as typed
    /// beside one), made at once as a fraction held inline; None
    /// for anything else (a recipe then keeps the operands). The fraction
    /// is the one the recipe would make, typed mark and all (the sum and
    /// product of [`Rat`], as the symbolic path adds and multiplies the
    /// coefficients): `[k/100 for k in 1:100000]` holds no recipe.
    #[inline]
    fn fraction(self, args: &[&Value; 2], kind: &Kind) -> Option<Fraction> {
        let Op::Arith(op @ (BinOp::Add | BinOp::Sub | BinOp::Mul | BinOp::Div)) = self else {
            return None;
        };
        if !matches!(kind, Kind::Scalar) {
            return None;
        }
        // (in machine words where they fit, else as `Rat` does; decimals
        // as typed beside a fraction: `0.1 k` of two numbers typed keeps
        // its recipe, as a statement's literals cost no reading of digits)
        let inline = |v: &Value| {
            matches!(
                v,
                Value::Num {
                    exact: Exact::Ratio(_),
                    ..
                }
            )
        };
        let decimals = inline(args[0]) || inline(args[1]);
        let (a, b) = (at_hand(args[0], decimals)?, at_hand(args[1], decimals)?);
        let quick = match op {
            BinOp::Add => a.plus(b),
            BinOp::Sub => a.minus(b),
            BinOp::Mul => a.times(b),
            _ => a.over(b),
        };
        if quick.is_some() {
            return quick;
        }
        let (x, y) = (held_fraction(args[0])?, held_fraction(args[1])?);
        let r = match op {
            BinOp::Add => x.add(&y),
            BinOp::Sub => x.add(&y.neg()),
            BinOp::Mul => x.mul(&y),
            _ if y.is_zero() => return None,
            _ => x.mul(&y.inv()?),
        };
        Fraction::of(&r)
    }

    /// True when this is a sum or difference of numbers (that may be
    /// exact: the caller asks) whose floats cancelled: an entry of the result smaller than
    /// 2⁻²⁶ of its larger operand's, half the digits lost or more. Then
    /// the floats may be rounding's alone — `123456789012345678901 -
    /// 123456789012345678900` is 0 in floats and 1 exactly — and the
    /// result's floats are made from its exact form ([`from_exact_form`]),
    /// so that what prints, and JSON's full-precision numbers, are the
    /// value `==` decides on (LANGUAGE.md §7: "Arithmetic keeps exact
    /// numbers exact"). A broadcast operand (a scalar plus a matrix) is
    /// left as it is.
    #[inline(never)]
    fn cancels(self, args: &[&Value; 2]) -> bool {
        let [Value::Num { m: x, .. }, Value::Num { m: y, .. }] = args else {
            return false;
        };
        x.shape() == y.shape()
            && x.iter().zip(y.iter()).any(|(p, q)| {
                let big = p.abs().max(q.abs());
                let sum = if matches!(self, Op::Arith(BinOp::Add)) {
                    p + q
                } else {
                    p - q
                };
                big > 0.0 && big.is_finite() && sum.abs() <= big * CANCELLED
            })
    }

    /// `v`, the result of this operation on numbers `args`, with its exact
    /// form ([`Op::exact_of`]) when it is a number.
    #[inline]
    pub fn with_exact(self, mut v: Value, args: &[&Value], kind: &Kind) -> Value {
        self.set_exact(&mut v, args, kind);
        v
    }

    /// Gives `v`, the result of this operation on numbers `args`, its
    /// exact form ([`Op::exact_of`]) when it is a number.
    #[inline]
    pub fn set_exact(self, v: &mut Value, args: &[&Value], kind: &Kind) {
        if let Value::Num { exact, .. } = v {
            if args.iter().all(|a| a.may_be_exact()) {
                *exact = self.exact_of(args, kind);
            } else if matches!(self, Op::Vector) && args.iter().any(|a| a.may_be_exact()) {
                // (a vector of exact and float entries has no exact form,
                // but keeps its entries, for `==` to decide them one by
                // one: `(1, exp(0)) == (1 + 1e-20, 1)` is false by its
                // first entries; `values::exact_mat::entry_forms`)
                *exact = self.pending(Operands::of(args), kind);
            }
        }
    }

    /// The exact form of this operation on numbers `args` that all have one
    /// (LANGUAGE.md §3, §7): numbers as typed stay as typed through the
    /// operations that only move, negate or pick entries; any other
    /// operation records how to compute its exact form by its exact path
    /// ([`Op::formula`]) over the operands' exact forms, run only when the
    /// form is asked for (`==`, a symbolic expression, `--exact`).
    pub fn exact_of<V: std::borrow::Borrow<Value>>(self, args: &[V], kind: &Kind) -> Exact {
        match self.exactness(args) {
            Some(e) => e,
            None => match self {
                Op::Vector => match fractions(args) {
                    Some(rs) => Exact::Ratios(rs),
                    None => self.pending(Operands::of(args), kind),
                },
                _ => self.pending(Operands::of(args), kind),
            },
        }
    }

    /// [`Op::exact_of`] operands the evaluator gives away (a builtin
    /// call's arguments after the call): a recipe keeps them as they are,
    /// in the vector that held them (no copy of a 4×4 per `exp`).
    #[inline(always)]
    pub fn exact_of_owned(self, args: Vec<Value>, kind: &Kind) -> Exact {
        match self.exactness(&args) {
            Some(e) => e,
            None => self.pending(Operands::owned(args), kind),
        }
    }

    /// [`Op::exact_of`] two operands the evaluator gives away: a recipe
    /// keeps them as they are, boxed (no copy of a 4×4 per product).
    #[inline(always)]
    pub fn exact_of_pair(self, a: Box<Value>, b: Box<Value>, kind: &Kind) -> Exact {
        match self.exactness(&[&*a, &*b]) {
            Some(e) => e,
            None => self.pending(Operands::Pair(a, b), kind),
        }
    }

    /// The exact form of `[ ... ]` of numbers given its entries row by
    /// row ([`super::apply::block_numeric`]): `[x]` of numbers as typed is
    /// typed, with no list of the operands to make.
    pub fn exact_of_rows(rows: &[Vec<Value>]) -> Exact {
        match rows {
            [row] if row.len() == 1 => Op::Block(&[1]).exact_of(row, &Kind::Unknown),
            _ => {
                let widths: Vec<usize> = rows.iter().map(Vec::len).collect();
                let entries: Vec<&Value> = rows.iter().flatten().collect();
                if !entries.iter().all(|v| v.may_be_exact()) {
                    // (numbers of which some are exact keep their entries,
                    // for `==` to decide them one by one, as vectors do)
                    let scalars = entries.iter().all(|v| v.as_scalar().is_some());
                    return match scalars && entries.iter().any(|v| v.may_be_exact()) {
                        true => Op::Block(&widths).pending(Operands::of(&entries), &Kind::Unknown),
                        false => Exact::Float,
                    };
                }
                Op::Block(&widths).exact_of(&entries, &Kind::Unknown)
            }
        }
    }

    /// The exact form of this operation on `args` when it needs no recipe
    /// (a float, or numbers as typed moved about); None when it needs one.
    fn exactness<V: std::borrow::Borrow<Value>>(self, args: &[V]) -> Option<Exact> {
        // (what the builtin keeps, read first: a float result, `log` of a
        // transform, is known without looking at the operands)
        let keeps = match self {
            Op::Call(b, _) => call_keeps(b),
            _ => Keeps::Always,
        };
        if keeps == Keeps::Never {
            return Some(Exact::Float);
        }
        let mut typed = true;
        for a in args {
            match a.borrow() {
                Value::Num {
                    exact: Exact::Typed,
                    ..
                } => {}
                a if a.may_be_exact() => typed = false,
                _ => return Some(Exact::Float),
            }
        }
        if args.is_empty() {
            return Some(Exact::Float);
        }
        // (exp, log and the inverse trigonometric functions keep a recipe
        // of a number only: certified arithmetic and the normal forms of
        // `crate::decide::transcendental` read it; of a matrix they are floats)
        if matches!(keeps, Keeps::OfNumber | Keeps::OfNumberOrMotion)
            && args.iter().any(|a| a.borrow().as_scalar().is_none())
            && !(keeps == Keeps::OfNumberOrMotion
                && args.iter().all(|a| rotation_or_motion(a.borrow())))
        {
            return Some(Exact::Float);
        }
        let moves = matches!(
            self,
            Op::Neg | Op::Transpose | Op::Member(_) | Op::Index(_) | Op::Vector | Op::Block(_)
        );
        (typed && moves).then_some(Exact::Typed)
    }

    /// The recipe of this operation's exact form over `args`.
    fn pending(self, args: Operands, kind: &Kind) -> Exact {
        let op = self.owned();
        Exact::pending(Pending {
            op,
            args,
            kind: *kind,
            run,
        })
    }

    /// False for an operation whose result is never given an exact form:
    /// a builtin outside the list of `exact_name` (exp, log and the adjoint
    /// of numbers are floats: issue 14's benchmark makes them by the
    /// thousand).
    #[inline]
    pub fn may_be_exact(self) -> bool {
        match self {
            Op::Call(b, _) => exact_call(b),
            _ => true,
        }
    }
}

/// The entries of a 3-vector `(a, b, c)` as fractions held inline, when
/// every entry is a fraction at hand ([`at_hand`], decimals as typed
/// included) small enough to pack ([`Fractions3`]): its exact form at
/// once ([`Exact::Ratios`]), the one its recipe would make. None for
/// anything else, or another length (a recipe then keeps copies of the
/// entries).
#[inline(never)]
fn fractions<V: std::borrow::Borrow<Value>>(args: &[V]) -> Option<Fractions3> {
    let [a, b, c] = args else { return None };
    let one = |v: &V| at_hand(v.borrow(), true);
    Fractions3::of([one(a)?, one(b)?, one(c)?])
}

/// [`held_fraction`] in machine words: a whole number as typed, a
/// fraction held inline, and with `decimals` a decimal as typed
/// ([`Fraction::typed`]).
#[inline]
fn at_hand(v: &Value, decimals: bool) -> Option<Fraction> {
    match scalar_exact(v)? {
        (x, Exact::Typed) => match Fraction::whole(x) {
            None if decimals => Fraction::typed(x),
            whole => whole,
        },
        (_, Exact::Ratio(r)) => Some(*r),
        _ => None,
    }
}

/// A scalar's number and exact form; None for any other value.
#[inline]
fn scalar_exact(v: &Value) -> Option<(f64, &Exact)> {
    match v {
        Value::Num {
            kind: Kind::Scalar,
            m: crate::values::num::Num::Scalar(x),
            exact,
        } => Some((*x, exact)),
        _ => None,
    }
}

/// The exact form of a scalar when it is a fraction at hand: a number
/// as typed that [`Rat::typed_quick`] reads, or a fraction held inline.
#[inline]
fn held_fraction(v: &Value) -> Option<Rat> {
    match scalar_exact(v)? {
        (x, Exact::Typed) => Rat::typed_quick(x),
        (_, Exact::Ratio(r)) => Some(r.rat()),
        _ => None,
    }
}

/// Which results of a builtin keep an exact form's recipe ([`exact_name`],
/// [`scalar_only`]).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Keeps {
    /// None: its results are floats (`MatrixLog6`).
    Never,
    /// Every result of exact operands (`sqrt`, `Rotz`, `Adjoint`).
    Always,
    /// A number's only (`log`, `atan2`): of a matrix, a float.
    OfNumber,
    /// A number's, or that of so(3) and se(3) and their vectors
    /// ([`rotation_or_motion`]): `exp`.
    OfNumberOrMotion,
}

impl Keeps {
    /// What the builtin named `name` keeps.
    fn of(name: &str) -> Keeps {
        match (exact_name(name), scalar_only(name), name == "exp") {
            (false, _, _) => Keeps::Never,
            (true, false, _) => Keeps::Always,
            (true, true, false) => Keeps::OfNumber,
            (true, true, true) => Keeps::OfNumberOrMotion,
        }
    }
}

/// True for the builtins [`Op::exact_of`] gives an exact form.
fn exact_call(b: &crate::builtins::Builtin) -> bool {
    call_keeps(b) != Keeps::Never
}

/// The exact form of `op` on operands `vals` (a [`Pending`] recipe, run
/// when the form is first asked for): the operation's exact path
/// ([`Op::formula`]) over the operands' exact forms; None when an operand
/// or the result has none.
pub(super) fn run(op: &Operation, vals: &[&Value], kind: &Kind) -> Option<Mat> {
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
    let m = formula_of(op, forms, kind)?;
    crate::values::exact::is_exact(&m).then_some(m)
}

/// Operation `op` by its exact path ([`Op::formula`]) over operands given
/// as formulas `forms`: the canonical form of the result, exact or not
/// (`crate::decide::lift` gives it forms with a symbol in them).
pub(crate) fn formula_of(op: &Operation, forms: Vec<Value>, kind: &Kind) -> Option<Mat> {
    let refs: Vec<&Value> = forms.iter().collect();
    let out = match op {
        Operation::Block(widths) => {
            let mut rest = forms.into_iter();
            let rows: Vec<Vec<Value>> = widths
                .iter()
                .map(|&n| rest.by_ref().take(n).collect())
                .collect();
            Some(formula::brackets(&rows))
        }
        op => Op::of(op)?.formula(&refs, kind),
    };
    match out?.ok()? {
        Value::Formula { m, .. } => Some(m),
        v => v.exact_form(),
    }
}

/// What builtin `b` keeps ([`Keeps::of`] its name), read from a table made
/// once beside the builtins' table: the row is found by its place in the
/// table, not by comparing its name with every name of the lists.
fn call_keeps(b: &crate::builtins::Builtin) -> Keeps {
    static KEEPS: OnceLock<Vec<Keeps>> = OnceLock::new();
    let table = crate::builtins::table();
    let keeps = KEEPS.get_or_init(|| table.iter().map(|b| Keeps::of(b.name)).collect());
    let at = (b as *const crate::builtins::Builtin as usize).wrapping_sub(table.as_ptr() as usize)
        / std::mem::size_of::<crate::builtins::Builtin>().max(1);
    match (keeps.get(at), table.get(at)) {
        (Some(&k), Some(row)) if std::ptr::eq(row, b) => k,
        _ => Keeps::of(b.name),
    }
}

/// The builtins whose results are exact at exact arguments often enough
/// to be worth a recipe (square roots, trigonometry at multiples of π/12,
/// rotations by them, products, the adjoint of a transform: `Ad([Rotx(pi),
/// p; 0, 1]).T F` with a symbolic wrench F printed `1.2246e-16 fz`), and
/// exp, log and the inverse trigonometric functions of a number
/// ([`scalar_only`]: `exp(1)^2 == exp(2)` is decided from how its sides
/// were made); the exp and log of general matrices are floats.
fn exact_name(name: &str) -> bool {
    scalar_only(name)
        || matches!(
            name,
            "sqrt"
                | "abs"
                | "sin"
                | "cos"
                | "tan"
                | "cot"
                | "sec"
                | "csc"
                | "Rotx"
                | "Roty"
                | "Rotz"
                | "Rot"
                | "MatrixExp3"
                | "MatrixExp6"
                | "cross"
                | "dot"
                | "det"
                | "trace"
                | "inv"
                | "RotInv"
                | "TransInv"
                | "VecToso3"
                | "VecTose3"
                | "so3ToVec"
                | "se3ToVec"
                | "RpToTrans"
                | "Adjoint"
                | "norm"
                | "transpose"
        )
}

/// An so(3) or se(3) matrix, or the 3- or 6-vector of one
/// (`MatrixExp3((1, 0, 0) pi)`): `exp` of it, by Rodrigues (3.51) or
/// Proposition 3.16, is exact at exact angles as `Rotx(pi)` is (issue 35:
/// `exp([(1, 0, 0)] pi)` was a float matrix whose 1.2e-16 entries reached
/// symbolic products and decided `==`). A general square matrix's
/// exponential stays a float.
fn rotation_or_motion(v: &Value) -> bool {
    matches!(
        v.kind(),
        Kind::So3 | Kind::Se3 | Kind::Vector(Some(3)) | Kind::Twist | Kind::Screw
    )
}

/// The builtins that keep a recipe of a number, not of a matrix (the
/// matrix exponential and logarithm stay floats, but for `exp` of so(3)
/// and se(3): [`rotation_or_motion`]).
fn scalar_only(name: &str) -> bool {
    matches!(name, "exp" | "log" | "atan" | "asin" | "acos" | "atan2")
}

/// How small a sum's entry must be against its larger operand for the
/// floats to have cancelled ([`Op::cancels`]): 2⁻²⁶, half of a double's
/// 53 bits of precision lost.
pub(crate) const CANCELLED: f64 = 1.0 / 67_108_864.0;

/// Gives the numbers `v` the floats of its exact form (each entry the
/// float nearest its exact value, as far as `Expr::as_f64` reads it),
/// when it has one whose entries are all real numbers; leaves `v` as it is
/// otherwise (no exact form, or π's powers that do not fit a float).
pub(crate) fn from_exact_form(v: &mut Value) {
    let Some(form) = v.exact_form() else {
        return;
    };
    let Some(xs) = form.as_f64() else {
        return;
    };
    if let Value::Num { m, .. } = v
        && m.shape() == (form.rows, form.cols)
        && xs.iter().all(|x| x.is_finite())
    {
        *m = crate::values::num::Num::from_dmatrix(nalgebra::DMatrix::from_row_slice(
            form.rows, form.cols, &xs,
        ));
    }
}

#[cfg(test)]
mod tests;
