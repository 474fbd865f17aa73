//! Arithmetic on values: products (including `T * p` for a point), sums,
//! powers, inverses in closed form, members, indexing and MATLAB-style
//! block concatenation. Errors are one enum, [`OpError`], whose text is
//! the message a user sees; the interpreter adds the span and the error's
//! kind. Sizes are bounded so that no input can exhaust memory.

use nalgebra::DMatrix;

use super::convert;
use super::domain::Decided;
pub use super::error::{MAX_DIM, MAX_ELEMENTS, MAX_WORK, OpError};
use super::num::Num;
use super::value::Value;
use crate::check::ty::Kind;
use crate::lie::{LieGroup, SE2, SE3, SO3, Vec3, se3};

fn num(v: &Value) -> Result<(&Kind, &Num), OpError> {
    match v {
        Value::Num { kind, m, .. } => Ok((kind, m)),
        other => Err(OpError::NotNumbers(other.kind())),
    }
}

/// The value of kind `kind` holding `m`; plain matrices that are exactly
/// group elements are recognized (a product of rotations stays a rotation).
fn out(kind: &Kind, m: Num) -> Value {
    let kind = match kind {
        Kind::Matrix(..) | Kind::Unknown => convert::classify(&m),
        Kind::Vector(_) => Kind::Vector(Some(m.nrows())),
        k => *k,
    };
    let kind = if m.shape() == (1, 1) && !matches!(kind, Kind::Scalar) && kind.vec_len().is_none() {
        Kind::Scalar
    } else {
        kind
    };
    Value::Num {
        kind,
        m,
        exact: Default::default(),
    }
}

/// `l * r` with the result kind the checker found.
pub fn mul(l: &Value, r: &Value, kind: &Kind) -> Result<Value, OpError> {
    let (lk, lm) = num(l)?;
    let (rk, rm) = num(r)?;
    if let (Num::Scalar(x), Kind::Scalar) = (lm, lk) {
        return Ok(Value::Num {
            kind: *kind,
            m: rm.map(|y| y * x),
            exact: Default::default(),
        });
    }
    if let (Num::Scalar(y), Kind::Scalar) = (rm, rk) {
        return Ok(Value::Num {
            kind: *kind,
            m: lm.map(|x| x * y),
            exact: Default::default(),
        });
    }
    // The book's products of fixed shapes, without a general matrix:
    // T₁T₂ (3.63), [Ad_T]V (3.83), Rp, and so on.
    let fixed = match (lm, rm) {
        (Num::M4(a), Num::M4(b)) => Some(Num::M4(std::rc::Rc::new(**a * **b))),
        (Num::M3(a), Num::M3(b)) => Some(Num::M3(std::rc::Rc::new(**a * **b))),
        (Num::M6(a), Num::M6(b)) => Some(Num::M6(std::rc::Rc::new(**a * **b))),
        (Num::M3(a), Num::V3(b)) => Some(Num::V3(**a * b)),
        (Num::M4(a), Num::V4(b)) => Some(Num::V4(**a * b)),
        (Num::M6(a), Num::V6(b)) => Some(Num::V6(**a * b)),
        _ => None,
    };
    if let Some(m) = fixed {
        return Ok(out(kind, m));
    }
    // A point transformed by a homogeneous transform: T p = R p + t.
    if let (Num::M4(t), Num::V3(x)) = (lm, rm) {
        // A transform moves the point (T x = R x + p, (3.65)); an se(3)
        // matrix gives its velocity ([V] x = [ω] x + v, last row zero).
        let last = |w: f64| (0..4).all(|j| (t[(3, j)] - w * f64::from(j == 3)).abs() <= 1e-9);
        if !last(1.0) && !last(0.0) {
            return Err(OpError::NotATransform);
        }
        let p = t.fixed_view::<3, 3>(0, 0) * x + t.fixed_view::<3, 1>(0, 3);
        return Ok(Value::Num {
            kind: *kind,
            m: Num::V3(p),
            exact: Default::default(),
        });
    }
    if let (Num::M3(t), (2, 1), Kind::SE2 | Kind::Se2) = (lm, rm.shape(), lk) {
        let p = t.fixed_view::<2, 2>(0, 0) * nalgebra::Vector2::new(rm[0], rm[1])
            + t.fixed_view::<2, 1>(0, 2);
        return Ok(Value::Num {
            kind: *kind,
            m: Num::from_slice(2, 1, p.as_slice()),
            exact: Default::default(),
        });
    }
    if lm.ncols() != rm.nrows() {
        return Err(OpError::Multiply(lm.shape(), rm.shape()));
    }
    check_size(lm.nrows(), rm.ncols())?;
    check_work(lm.nrows(), lm.ncols(), rm.ncols(), 1)?;
    let product = product(&lm.to_dmatrix(), &rm.to_dmatrix())?;
    Ok(out(kind, Num::from_dmatrix(product)))
}

/// Refuses `times` products of an r×k by a k×c matrix beyond [`MAX_WORK`].
pub fn check_work(r: usize, k: usize, c: usize, times: u64) -> Result<(), OpError> {
    let work = r as u128 * k as u128 * c as u128 * times as u128;
    check_cost(work, || {
        format!(
            "a {r}×{k} by {k}×{c} product{}",
            if times > 1 {
                format!(", {times} times")
            } else {
                String::new()
            }
        )
    })
}

/// Refuses an operation that costs `work` multiply-adds beyond
/// [`MAX_WORK`]; `what` names the operation in the message.
pub fn check_cost(work: u128, what: impl FnOnce() -> String) -> Result<(), OpError> {
    if work > MAX_WORK {
        return Err(OpError::TooMuchWork {
            work: u64::try_from(work).unwrap_or(u64::MAX),
            what: what(),
        });
    }
    Ok(())
}

/// The cube n³ of a matrix side, the unit of cost of LU and products.
pub fn cube(n: usize) -> u128 {
    let n = n as u128;
    n * n * n
}

/// Refuses results larger than [`MAX_ELEMENTS`], or than the evaluation
/// budget lets the statement hold ([`crate::budget::room`]).
pub fn check_size(r: usize, c: usize) -> Result<(), OpError> {
    if r > MAX_DIM || c > MAX_DIM || r.saturating_mul(c) > MAX_ELEMENTS {
        return Err(OpError::TooLarge { rows: r, cols: c });
    }
    crate::budget::room((r * c) as u64).map_err(|stop| OpError::Message(stop.to_string()))
}

/// The multiply-adds of one block of a large product: a few milliseconds.
const BLOCK_WORK: usize = 1 << 22;

/// A B for general matrices; a large product goes by blocks of columns,
/// asking the evaluation budget ([`crate::budget`]) between blocks, so an
/// interrupt or a deadline stops it within milliseconds.
pub fn product(a: &DMatrix<f64>, b: &DMatrix<f64>) -> Result<DMatrix<f64>, OpError> {
    let per_column = a.nrows().saturating_mul(a.ncols()).max(1);
    if per_column.saturating_mul(b.ncols()) <= BLOCK_WORK {
        return Ok(a * b);
    }
    let width = (BLOCK_WORK / per_column).max(1);
    let mut out = DMatrix::zeros(a.nrows(), b.ncols());
    let mut j = 0;
    while j < b.ncols() {
        crate::budget::check().map_err(|stop| OpError::Message(stop.to_string()))?;
        let w = width.min(b.ncols() - j);
        out.columns_mut(j, w).copy_from(&(a * b.columns(j, w)));
        j += w;
    }
    Ok(out)
}

/// `l + r` or `l - r`.
pub fn add(l: &Value, r: &Value, subtract: bool, kind: &Kind) -> Result<Value, OpError> {
    let (_, lm) = num(l)?;
    let (_, rm) = num(r)?;
    if lm.shape() != rm.shape() {
        return Err(OpError::Add(lm.shape(), rm.shape()));
    }
    let mut sum = lm.clone();
    for (x, y) in sum.as_mut_slice().iter_mut().zip(rm.iter()) {
        *x = if subtract { *x - y } else { *x + y };
    }
    Ok(out(kind, sum))
}

/// `-x`.
pub fn neg(v: &Value, kind: &Kind) -> Result<Value, OpError> {
    let (_, m) = num(v)?;
    Ok(Value::Num {
        kind: *kind,
        m: m.map(|x| -x),
        exact: Default::default(),
    })
}

/// `l / r` with a scalar divisor: by zero when its exact form is 0
/// (`1/cos(π/2)` is refused, not 1.6e16), else by its float
/// ([`Decided`]).
pub fn div(l: &Value, r: &Value, kind: &Kind) -> Result<Value, OpError> {
    let (_, lm) = num(l)?;
    let d = Decided::of(r).ok_or(OpError::DivisorNotANumber)?;
    if d.is_zero() {
        return Err(OpError::DivisionByZero);
    }
    let d = d.value();
    Ok(Value::Num {
        kind: *kind,
        m: lm.map(|x| x / d),
        exact: Default::default(),
    })
}

/// `b ^ e`: real powers of numbers, integer powers of square matrices
/// (by repeated squaring; `X^-1` is the inverse). A scalar base and the exponent are read by their exact forms when they
/// have them ([`Decided`]): `sin(2π)^0.5` is 0, `(-8)^(√2²)` is 64.
pub fn pow(b: &Value, e: f64, kind: &Kind) -> Result<Value, OpError> {
    let (bk, bm) = num(b)?;
    if *bk == Kind::Scalar {
        let x0 = Decided::of(b).map_or(bm[0], |d| d.value());
        if x0 == 0.0 && e < 0.0 {
            return Err(OpError::DivisionByZero);
        }
        let x = x0.powf(e);
        if x.is_nan() && !x0.is_nan() && !e.is_nan() {
            let base = format!("({})^{}", fmt_exp(x0), fmt_exp(e));
            // p/q with q odd has a real root: −(|b|^e) when p is odd.
            let odd_root = [3.0, 5.0, 7.0, 9.0].into_iter().any(|q: f64| {
                let p = (e * q).round();
                (e * q - p).abs() < 1e-12 && p.rem_euclid(2.0) == 1.0
            });
            return Err(OpError::NotReal {
                base,
                real_root: odd_root.then(|| format!("{}^{}", fmt_exp(-x0), fmt_exp(e))),
            });
        }
        return Ok(Value::scalar(x));
    }
    if !bm.is_square() {
        return Err(OpError::PowerOfNonSquare);
    }
    if e.is_finite() && e.fract() == 0.0 && e.abs() > 1e15 {
        return Err(OpError::ExponentTooLarge(e));
    }
    if e.fract() != 0.0 || !e.is_finite() {
        return Err(OpError::ExponentNotWhole(e));
    }
    let mut base = if e < 0.0 {
        num_inverse(bk, bm)?.0.into_dmatrix()
    } else {
        bm.to_dmatrix().into_owned()
    };
    let mut n = e.abs() as u64;
    // Squaring: at most two products per bit of the exponent.
    let side = bm.nrows();
    check_work(side, side, side, 2 * u64::from(64 - n.leading_zeros()))?;
    let mut acc = DMatrix::identity(bm.nrows(), bm.ncols());
    while n > 0 {
        if n & 1 == 1 {
            acc = product(&acc, &base)?;
        }
        n >>= 1;
        if n > 0 {
            base = product(&base, &base)?;
        }
    }
    // A power of a plain matrix is a plain matrix, even when it happens to
    // be a group element (`[1, 2; 3, 4]^0` is I, not labelled SO(2)).
    let acc = Num::from_dmatrix(acc);
    if let Kind::Matrix(..) = kind
        && convert::classify(&acc).is_group()
    {
        let (r, c) = acc.shape();
        return Ok(Value::Num {
            kind: Kind::Matrix(Some(r), Some(c)),
            m: acc,
            exact: Default::default(),
        });
    }
    Ok(out(kind, acc))
}

/// The inverse: closed forms for group elements (Prop. 3.3, (3.64)),
/// LU with partial pivoting for other square matrices, an error for
/// singular ones (judged by conditioning, [`super::linalg`]).
pub fn inverse(v: &Value) -> Result<Value, OpError> {
    inverse_conditioned(v).map(|(v, _)| v)
}

/// [`inverse`], with the reciprocal condition number of a plain matrix's
/// inverse (see [`super::linalg`]); None for closed forms and scalars.
pub fn inverse_conditioned(v: &Value) -> Result<(Value, Option<f64>), OpError> {
    let (k, m) = num(v)?;
    if *k == Kind::Scalar {
        // (0 by its exact form when it has one, [`Decided`])
        let d = Decided::of(v).map_or(m[0], |d| if d.is_zero() { 0.0 } else { d.value() });
        if d == 0.0 {
            return Err(OpError::InverseOfZero);
        }
        return Ok((Value::scalar(1.0 / d), None));
    }
    let (inv, rcond) = num_inverse(k, m)?;
    Ok((out(k, inv), rcond))
}

/// The inverse: a closed form for a group element, else LU (with its
/// reciprocal condition number).
fn num_inverse(k: &Kind, m: &Num) -> Result<(Num, Option<f64>), OpError> {
    Ok((
        match (k, m) {
            // Closed forms: Rᵀ (Prop. 3.3), (3.64) for transforms.
            (Kind::SO3, Num::M3(r)) => {
                Num::M3(std::rc::Rc::new(*SO3::assume(**r).inverse().matrix()))
            }
            (Kind::SO3 | Kind::SO2, _) => m.transpose(),
            (Kind::SE3, Num::M4(t)) => {
                Num::M4(std::rc::Rc::new(*SE3::assume(**t).inverse().matrix()))
            }
            (Kind::SE2, Num::M3(t)) => {
                Num::M3(std::rc::Rc::new(*SE2::assume(**t).inverse().matrix()))
            }
            _ if m.is_square() => {
                let r = m.nrows();
                check_cost(cube(r), || format!("the inverse of a {r}×{r} matrix"))?;
                if m.iter().any(|x| !x.is_finite()) {
                    return Err(OpError::InverseNotFinite);
                }
                let inv = super::linalg::inverse(&m.to_dmatrix())?;
                return Ok((Num::from_dmatrix(inv.m), Some(inv.rcond)));
            }
            _ => {
                return Err(OpError::InverseOfNonSquare(m.nrows(), m.ncols()));
            }
        },
        None,
    ))
}

/// `x.T`.
pub fn transpose(v: &Value) -> Value {
    match v {
        Value::Num { kind, m, .. } => {
            let kind = match kind {
                // [ω]ᵀ = −[ω]: the transpose of so(3) is in so(3).
                Kind::SO3 | Kind::SO2 | Kind::So3 | Kind::So2 | Kind::Scalar => *kind,
                Kind::Adjoint { transposed } => Kind::Adjoint {
                    transposed: !transposed,
                },
                _ if m.nrows() == 1 => Kind::Vector(Some(m.ncols())),
                _ => Kind::Matrix(Some(m.ncols()), Some(m.nrows())),
            };
            Value::Num {
                kind,
                m: m.transpose(),
                exact: Default::default(),
            }
        }
        other => other.clone(),
    }
}

/// `x.member` (`.R .p .w .v .m .f`; `.T` is [`transpose`]).
pub fn member(v: &Value, name: &'static str) -> Result<Value, OpError> {
    if name == "T" {
        return Ok(transpose(v));
    }
    let (k, m) = num(v)?;
    let v3 = |v: Vec3| Value::Num {
        kind: Kind::Vector(Some(3)),
        m: Num::V3(v),
        exact: Default::default(),
    };
    match (name, m) {
        // (a rotation only when the 4×4 is a transform, (3.62))
        ("R", Num::M4(t)) => Ok(Value::Num {
            kind: if *k == Kind::SE3 {
                Kind::SO3
            } else {
                Kind::Matrix(Some(3), Some(3))
            },
            m: Num::M3(std::rc::Rc::new(t.fixed_view::<3, 3>(0, 0).into_owned())),
            exact: Default::default(),
        }),
        ("R", Num::M3(t)) if *k == Kind::SE2 => Ok(Value::Num {
            kind: Kind::SO2,
            m: Num::from_slice(2, 2, t.fixed_view::<2, 2>(0, 0).into_owned().as_slice()),
            exact: Default::default(),
        }),
        ("p", Num::M4(t)) => Ok(v3(t.fixed_view::<3, 1>(0, 3).into_owned())),
        ("p", Num::M3(t)) if *k == Kind::SE2 => Ok(Value::vector(
            Kind::Vector(Some(2)),
            &[t[(0, 2)], t[(1, 2)]],
        )),
        ("w" | "m", Num::V6(s)) => Ok(v3(s.fixed_rows::<3>(0).into_owned())),
        ("v" | "f", Num::V6(s)) => Ok(v3(s.fixed_rows::<3>(3).into_owned())),
        ("w" | "v", Num::M4(t)) => {
            let s = se3::vee(t);
            Ok(v3(s
                .fixed_rows::<3>(if name == "w" { 0 } else { 3 })
                .into_owned()))
        }
        _ => Err(OpError::NoMember { kind: *k, name }),
    }
}

/// One subscript after evaluation: a 1-based index or `:`.
#[derive(Debug, Clone, Copy)]
pub enum Sel {
    /// The book's 1-based index as evaluated (not yet checked whole or in
    /// range).
    At(f64),
    /// `:`, every row or column.
    All,
}

/// The 0-based position of the book's 1-based index `x` among `n`
/// entries, or the error a user sees for an index that is not a whole
/// number (`x[1.5]`) or is out of range.
pub(crate) fn position(x: f64, n: usize) -> Result<usize, OpError> {
    if x.fract() != 0.0 || !x.is_finite() {
        return Err(OpError::IndexNotWhole(x));
    }
    if x < 1.0 || x > n as f64 {
        return Err(OpError::IndexOutOfRange { index: x, n });
    }
    Ok(x as usize - 1)
}

/// `x[i]`, `M[i, j]`, `M[i, :]`, `M[:, j]` — 1-based.
pub fn index(v: &Value, sels: &[Sel]) -> Result<Value, OpError> {
    if let Value::Tuple(items) = v {
        return match sels {
            [Sel::At(i)] => Ok(items[position(*i, items.len())?].clone()),
            _ => Err(OpError::TupleIndex),
        };
    }
    let (_, m) = num(v)?;
    match sels {
        [Sel::At(i)] if m.ncols() == 1 => Ok(Value::scalar(m[position(*i, m.nrows())?])),
        [Sel::At(i)] if m.nrows() == 1 => Ok(Value::scalar(m[position(*i, m.ncols())?])),
        [Sel::At(_)] => Err(OpError::MatrixIndex),
        [Sel::At(i), Sel::At(j)] => Ok(Value::scalar(
            m[(position(*i, m.nrows())?, position(*j, m.ncols())?)],
        )),
        [Sel::At(i), Sel::All] => {
            let row: Vec<f64> = m.row(position(*i, m.nrows())?).collect();
            Ok(Value::Num {
                kind: Kind::Matrix(Some(1), Some(m.ncols())),
                m: Num::from_slice(1, m.ncols(), &row),
                exact: Default::default(),
            })
        }
        [Sel::All, Sel::At(j)] => {
            let (n, j) = (m.nrows(), position(*j, m.ncols())?);
            Ok(Value::Num {
                kind: Kind::Vector(Some(n)),
                m: Num::vector(&m.as_slice()[j * n..(j + 1) * n]),
                exact: Default::default(),
            })
        }
        [Sel::All, Sel::All] | [Sel::All] => Ok(v.clone()),
        _ => Err(OpError::TooManyIndices),
    }
}

/// `[ ... ]` after evaluation: the book's bracket for one 3- or 6-vector,
/// a column vector for one row of numbers, MATLAB block concatenation
/// otherwise (LANGUAGE.md §4).
/// `[x]` of numbers: the so(3) or se(3) matrix of a 3- or 6-vector (3.30,
/// (3.85)), else `x` itself ([`brackets`] of one entry).
pub fn bracket(x: &Value) -> Result<Value, OpError> {
    let (k, m) = num(x)?;
    Ok(match m {
        Num::V3(w) => Value::of(Kind::So3, crate::lie::so3::hat(w)),
        Num::V6(v) => Value::of(Kind::Se3, se3::hat(v)),
        _ => Value::Num {
            kind: *k,
            m: m.clone(),
            exact: Default::default(),
        },
    })
}

/// The value of a bracket literal `[ ... ]` from its evaluated rows: one
/// element is the book's bracket `[ω]` (3.30) or `[V]` (3.70) of a 3- or
/// 6-vector ([`bracket`]); one row of scalars is a column vector; anything
/// else is MATLAB block concatenation (`[R, p; 0, 0, 0, 1]`, (3.62)).
pub fn brackets(rows: &[Vec<Value>]) -> Result<Value, OpError> {
    if rows.len() == 1 && rows[0].len() == 1 {
        return bracket(&rows[0][0]);
    }
    let all_scalars = rows
        .iter()
        .flatten()
        .all(|v| v.as_scalar().is_some() && matches!(v.kind(), Kind::Scalar));
    if all_scalars && rows.len() == 1 {
        let xs: Vec<f64> = rows[0].iter().filter_map(Value::as_scalar).collect();
        return Ok(Value::vector(Kind::Vector(Some(xs.len())), &xs));
    }
    let mut blocks: Vec<DMatrix<f64>> = Vec::with_capacity(rows.len());
    for (ri, row) in rows.iter().enumerate() {
        let mut parts = Vec::with_capacity(row.len());
        for v in row {
            parts.push(num(v)?.1.to_dmatrix());
        }
        let h = parts[0].nrows();
        if let Some(bad) = parts.iter().find(|p| p.nrows() != h) {
            return Err(OpError::RowHeights(ri + 1, h, bad.nrows()));
        }
        let w: usize = parts.iter().map(|p| p.ncols()).sum();
        check_size(h, w)?;
        let mut block = DMatrix::zeros(h, w);
        let mut c0 = 0;
        for p in parts {
            block.view_mut((0, c0), (h, p.ncols())).copy_from(&*p);
            c0 += p.ncols();
        }
        blocks.push(block);
    }
    let w = blocks[0].ncols();
    if let Some((i, bad)) = blocks.iter().enumerate().find(|(_, b)| b.ncols() != w) {
        return Err(OpError::RowWidths(w, bad.ncols(), i + 1));
    }
    let h: usize = blocks.iter().map(|b| b.nrows()).sum();
    check_size(h, w)?;
    let mut m = DMatrix::zeros(h, w);
    let mut r0 = 0;
    for b in &blocks {
        m.view_mut((r0, 0), (b.nrows(), w)).copy_from(b);
        r0 += b.nrows();
    }
    let m = Num::from_dmatrix(m);
    Ok(Value::Num {
        kind: convert::classify(&m),
        m,
        exact: Default::default(),
    })
}

/// A number in a message: short, and exact fractions of 1/3 shown as such.
fn fmt_exp(x: f64) -> String {
    for d in [2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0] {
        let n = (x * d).round();
        if (x * d - n).abs() < 1e-12 && n.abs() < 100.0 && n != 0.0 && (n / d).fract() != 0.0 {
            return format!("({n}/{d})");
        }
    }
    super::number::fmt_num(x, 6)
}
