//! The pieces the chain rule builds derivatives from ([`super`]): the
//! shapes of values and of their derivatives, constants (exact where the
//! chain rule's own numbers are), nodes of a recipe, and sums, products
//! and quotients of derivatives, where None is 0 (so products with it
//! vanish).

use std::rc::Rc;

use super::D;
use crate::check::ty::Kind;
use crate::syntax::ast::BinOp;
use crate::values::exact::Exact;
use crate::values::recipe::{Operation, Recipe, Step};
use crate::values::value::Value;

/// The kind of a derivative of a value of kind `k`: its shape only (the
/// derivative of a rotation is no rotation); None for what has no shape.
pub(super) fn shape_of(k: &Kind) -> Option<Kind> {
    Some(match k {
        Kind::Scalar => Kind::Scalar,
        k if k.is_vector() => Kind::Vector(Some(k.vec_len()?)),
        k => match k.shape()? {
            (Some(r), Some(c)) => Kind::Matrix(Some(r), Some(c)),
            _ => return None,
        },
    })
}

/// The shape of the value `r` makes: its kind's, or a literal's.
pub(super) fn shape(r: &Recipe) -> Option<Kind> {
    shape_of(&r.kind).or_else(|| literal_shape(r))
}

/// The shape of a matrix literal of scalars whose recorded kind leaves it
/// open, as the literal's numbers give it: `[x]` a scalar, one row or one
/// column a vector (`[1, 2]` is the 2-vector (1, 2)), else rows × columns.
pub(super) fn literal_shape(r: &Recipe) -> Option<Kind> {
    let Step::Op(Operation::Block(widths)) = &r.step else {
        return None;
    };
    if r.args.iter().any(|a| a.kind != Kind::Scalar) {
        return None;
    }
    let (rows, cols) = (widths.len(), *widths.first()?);
    if widths.iter().any(|w| *w != cols) {
        return None;
    }
    Some(match (rows, cols) {
        (1, 1) => Kind::Scalar,
        (1, n) | (n, 1) => Kind::Vector(Some(n)),
        (r, c) => Kind::Matrix(Some(r), Some(c)),
    })
}

/// A zero of kind `k` (a shape).
pub(super) fn zero(k: &Kind) -> Rc<Recipe> {
    match k.shape() {
        Some((Some(r), Some(c))) if *k != Kind::Scalar => matrix(r, c, &vec![0.0; r * c], *k),
        _ => number(0.0),
    }
}

/// The constant r×c matrix with entries `xs` (row by row), of kind `k`:
/// exact where every entry is ([`exact_constant`]).
pub(super) fn matrix(r: usize, c: usize, xs: &[f64], k: Kind) -> Rc<Recipe> {
    let m = nalgebra::DMatrix::from_row_slice(r, c, xs).into();
    Recipe::leaf(Value::Num {
        kind: k,
        m,
        exact: exact_constant(xs),
    })
}

/// The exactness of the chain rule's own constants (0, ±1, 2, ½, a whole
/// exponent n): whole numbers and halves are the decimals they print as,
/// so a derivative replayed with exact numbers stays exact (`diff(sin(s)^2,
/// s)` at s = 0.3 is `sin(0.6)`, proven equal, not a float beside it).
/// Anything else is a float: an exponent 1/3 rounded is no decimal.
pub(super) fn exact_constant(xs: &[f64]) -> Exact {
    let plain = |x: &f64| x.abs() < 1e15 && (2.0 * x).fract() == 0.0;
    if xs.iter().all(plain) {
        Exact::Typed
    } else {
        Exact::Float
    }
}

pub(super) fn number(x: f64) -> Rc<Recipe> {
    Recipe::leaf(Value::Num {
        kind: Kind::Scalar,
        m: crate::values::num::Num::Scalar(x),
        exact: exact_constant(&[x]),
    })
}

pub(super) fn node(step: Step, args: Vec<Rc<Recipe>>) -> Option<Rc<Recipe>> {
    Recipe::node(step, args, Kind::Scalar)
}

/// `step` over `args`, of kind `k` (a shape).
pub(super) fn node_k(step: Step, args: Vec<Rc<Recipe>>, k: Kind) -> Option<Rc<Recipe>> {
    Recipe::node(step, args, k)
}

/// `a op b` whose result has the shape of the bigger operand (a scalar
/// times a matrix is a matrix).
pub(super) fn arith(op: BinOp, a: Rc<Recipe>, b: Rc<Recipe>) -> Option<Rc<Recipe>> {
    let k = match (op, shape(&a)?, shape(&b)?) {
        (BinOp::Mul, ka, kb) => product(&ka, &kb)?,
        (_, Kind::Scalar, kb) if op != BinOp::Pow => shape_of(&kb)?,
        (_, ka, _) => shape_of(&ka)?,
    };
    node_k(Step::Op(Operation::Arith(op)), vec![a, b], k)
}

/// The shape of a product of values of kinds `a` and `b`.
pub(super) fn product(a: &Kind, b: &Kind) -> Option<Kind> {
    let (a, b) = (shape_of(a)?, shape_of(b)?);
    Some(match (a, b) {
        (Kind::Scalar, k) | (k, Kind::Scalar) => k,
        (a, b) => match (a.shape()?, b.shape()?) {
            ((r, _), (_, Some(1))) => Kind::Vector(r),
            ((r, _), (_, c)) => Kind::Matrix(r, c),
        },
    })
}

pub(super) fn call(name: &'static str, args: Vec<Rc<Recipe>>) -> Option<Rc<Recipe>> {
    node(Step::Op(Operation::Call(name)), args)
}

/// `a + b` of derivatives (0 + b = b).
pub(super) fn plus(a: D, b: D) -> Option<D> {
    Some(match (a, b) {
        (Some(a), Some(b)) => Some(arith(BinOp::Add, a, b)?),
        (a, b) => a.or(b),
    })
}

/// `f du` (0 when du is).
pub(super) fn times(f: Option<Rc<Recipe>>, du: D) -> Option<D> {
    match du {
        None => Some(None),
        Some(du) => Some(Some(arith(BinOp::Mul, f?, du)?)),
    }
}

/// `u dv`, the second term of d(u v): where `u` is a homogeneous
/// transform acting on a point `v` (one row fewer, `T p` of §3.3.1), the
/// point's rate is a free vector, turned by u's rotation and not moved
/// by its translation: d(T p) = Ṫ p + R ṗ, written u dv − u 0.
pub(super) fn times_point(u: Rc<Recipe>, v: &Rc<Recipe>, dv: D) -> Option<D> {
    // (a matrix literal over symbols has no kind to tell: u dv − u 0 is
    // u dv for a linear u too)
    let homogeneous = match (u.kind.shape(), v.kind.shape()) {
        (Some((Some(r), Some(c))), Some((Some(n), Some(1)))) => r == c && n + 1 == r,
        (None | Some((None, _) | (_, None)), Some((_, Some(1)))) => v.kind.is_vector(),
        _ => false,
    };
    let Some(dv) = dv else { return Some(None) };
    let moved = arith(BinOp::Mul, u.clone(), dv)?;
    if !homogeneous {
        return Some(Some(moved));
    }
    let origin = arith(BinOp::Mul, u, zero(&v.kind))?;
    Some(Some(arith(BinOp::Sub, moved, origin)?))
}

/// `du f` (0 when du is): the order of a matrix product kept.
pub(super) fn times_after(du: D, f: Rc<Recipe>) -> Option<D> {
    match du {
        None => Some(None),
        Some(du) => Some(Some(arith(BinOp::Mul, du, f)?)),
    }
}

/// The same linear step (`transpose`, `x[i]`, `T.R`, …) over a
/// derivative, of kind `k`.
pub(super) fn linear(step: &Step, du: D, k: Kind) -> Option<D> {
    match du {
        None => Some(None),
        Some(du) => Some(Some(node_k(step.clone(), vec![du], k)?)),
    }
}

/// `-x`.
pub(super) fn neg(x: D) -> Option<D> {
    match x {
        None => Some(None),
        Some(x) => {
            let k = x.kind;
            Some(Some(node_k(Step::Op(Operation::Neg), vec![x], k)?))
        }
    }
}

/// `x^n`.
pub(super) fn pow(x: &Rc<Recipe>, n: f64) -> Option<Rc<Recipe>> {
    arith(BinOp::Pow, x.clone(), number(n))
}

/// The quotient rule, d(u/v) = du/v − u dv/v² (v a scalar; u a scalar,
/// vector or matrix).
pub(super) fn quotient(u: Rc<Recipe>, v: &Rc<Recipe>, du: D, dv: D) -> Option<D> {
    let a = match du {
        None => None,
        Some(du) => Some(arith(BinOp::Div, du, v.clone())?),
    };
    let b = match dv {
        None => None,
        Some(dv) => {
            let udv = arith(BinOp::Mul, u, dv)?;
            Some(arith(BinOp::Div, udv, pow(v, 2.0)?)?)
        }
    };
    plus(a, neg(b)?)
}
