//! Values whose entries are symbolic expressions (LANGUAGE.md §7): `given
//! t1 : scalar` is a 1×1 formula, `Rotz(t1)` a 3×3 one. They go through the
//! same operations as numbers — products, sums, `.T`, `.R`, indexing,
//! matrix literals — with the canonical forms of [`crate::sym`]; a result
//! whose entries are all numbers is numeric again. Types and frames are
//! checked before, exactly as for numbers.

use super::ops::{self, Sel};
use super::value::Value;
use crate::check::ty::Kind;
use crate::sym::matrix::{self, Mat};
use crate::sym::{Expr, Symbol};
use crate::syntax::ast::BinOp;
use num_traits::{One, Zero};

pub use super::equality::{equal, rounding_only};
pub use super::limits::{CHEAP_WORK, MAX_WORK, fits, fits_inverse, fits_sums};

/// A numeric or symbolic value as a matrix of expressions: a number
/// enters with its exact form when it has one (LANGUAGE.md §7: `0.866` is
/// 866/1000, `1/sqrt(2)` is 1/√2, `20 deg` is (1/9) π), else as a float
/// ([`Expr::num`] guesses no closed form).
pub fn mat_of(v: &Value) -> Option<Mat> {
    match v {
        Value::Formula { m, .. } => Some(m.clone()),
        Value::Num { m, exact, .. } => {
            if let Some(e) = exact.form(m) {
                return Some(e);
            }
            let rows = (0..m.nrows())
                .map(|i| (0..m.ncols()).map(|j| Expr::num(m[(i, j)])).collect())
                .collect();
            Mat::from_rows(rows).or_else(|| Some(Mat::zeros(m.nrows(), m.ncols())))
        }
        _ => None,
    }
}

/// Why formula `v` has no real value whatever its symbols are (an entry
/// with a call of numbers outside its domain, [`Expr::undefined`]).
pub fn undefined(v: &Value) -> Option<String> {
    match v {
        Value::Formula { m, .. } => m.data.iter().find_map(Expr::undefined),
        _ => None,
    }
}

/// The one expression of a scalar value.
pub fn scalar_of(v: &Value) -> Option<Expr> {
    mat_of(v)
        .filter(|m| m.data.len() == 1)
        .map(|m| m.data[0].clone())
}

/// True when some value is a formula and none is a tree of `given`
/// matrices ([`Value::Sym`]), so the formula path applies.
pub fn applies(vals: &[&Value]) -> bool {
    vals.iter().any(|v| matches!(v, Value::Formula { .. }))
        && vals
            .iter()
            .all(|v| matches!(v, Value::Formula { .. } | Value::Num { .. }))
}

/// The kind by shape, where the checker's says only "a matrix".
fn settle_kind(kind: &Kind, m: &Mat) -> Kind {
    match kind {
        Kind::Unknown | Kind::Matrix(..) | Kind::Vector(None) => match (m.rows, m.cols) {
            (1, 1) => Kind::Scalar,
            (r, 1) => Kind::Vector(Some(r)),
            (r, c) => match classify(m) {
                Kind::Unknown => Kind::Matrix(Some(r), Some(c)),
                k => k,
            },
        },
        k => *k,
    }
}

/// A value from a matrix of expressions: numeric when every entry is a
/// number (binding numbers later makes a value numeric, §7), carrying its
/// exact form when every entry is exact.
pub fn make(kind: &Kind, m: Mat) -> Value {
    let kind = settle_kind(kind, &m);
    match m.as_f64() {
        Some(xs) => Value::Num {
            kind,
            m: nalgebra::DMatrix::from_row_slice(m.rows, m.cols, &xs).into(),
            exact: if super::exact::is_exact(&m) {
                super::exact::Exact::known(m)
            } else {
                super::exact::Exact::Float
            },
        },
        None => Value::Formula { kind, m, how: None },
    }
}

/// A formula whose canonical form is numbers (it depends on symbols only
/// through how it was made: `a/a` is 1) as it is shown: those numbers;
/// a tuple of values with such parts, each shown so. None when there is
/// nothing to show otherwise.
pub fn constant_shown(v: &Value) -> Option<Value> {
    match v {
        // (a comparison decided over symbols: a bool; one that waits for
        // numbers, `super::waiting`, shows nothing else)
        Value::Formula {
            kind: Kind::Bool,
            m,
            ..
        } => (m.rows == 1 && m.cols == 1)
            .then(|| Value::Bool(m.as_f64().is_some_and(|x| x.iter().any(|x| *x != 0.0)))),
        Value::Formula { kind, m, .. } if m.as_f64().is_some() => Some(make(kind, m.clone())),
        Value::Tuple(vs) if vs.iter().any(|x| constant_shown(x).is_some()) => Some(Value::Tuple(
            vs.iter()
                .map(|x| constant_shown(x).unwrap_or_else(|| x.clone()))
                .collect(),
        )),
        Value::List(vs) if vs.iter().any(|x| constant_shown(x).is_some()) => {
            Some(Value::List(std::rc::Rc::new(
                vs.iter()
                    .map(|x| constant_shown(x).unwrap_or_else(|| x.clone()))
                    .collect(),
            )))
        }
        _ => None,
    }
}

/// The numbers of operands that are all numbers or formulas whose
/// canonical form is numbers (symbols that cancelled: `a − a`); None when
/// one has a symbol or is no number.
pub fn all_numbers(args: &[&Value]) -> Option<Vec<Value>> {
    args.iter()
        .map(|v| match v {
            Value::Num { .. } => Some((*v).clone()),
            Value::Formula { kind, .. } if *kind != Kind::Bool => constant_shown(v),
            _ => None,
        })
        .collect()
}

/// A scalar formula.
pub fn scalar(e: Expr) -> Value {
    make(&Kind::Scalar, Mat::scalar(e))
}

fn too_large() -> String {
    format!(
        "symbolic expression too large (more than {} terms)",
        super::symbolic::MAX_SYM_NODES
    )
}

fn sizes(a: &Mat, b: &Mat) -> String {
    format!("{}×{} and {}×{}", a.rows, a.cols, b.rows, b.cols)
}

/// `a op b` for formulas; `kind` is the checker's kind of the result.
pub fn binary(op: BinOp, a: &Value, b: &Value, kind: &Kind) -> Result<Value, String> {
    let (x, y) = match (mat_of(a), mat_of(b)) {
        (Some(x), Some(y)) => (x, y),
        _ => return Err("these operands have no symbolic form".into()),
    };
    if op == BinOp::Mul {
        fits(&x, &y, "product")?;
    }
    let m = match op {
        BinOp::Mul => mul(&x, &y)?,
        BinOp::Add | BinOp::Sub => x
            .add(&y, op == BinOp::Sub)
            .ok_or_else(|| format!("cannot add matrices of sizes {}", sizes(&x, &y)))?,
        BinOp::Div => match y.data.as_slice() {
            [d] => {
                let r = d.recip().ok_or("division by zero")?;
                x.scale(&r)
            }
            _ => return Err("only division by a scalar".into()),
        },
        BinOp::Pow => return pow(&x, &y, a.kind(), kind),
    };
    // a quotient's common factors cancel: (a² − b²)/(a − b) = a + b
    // (and a sum over its square root: (a + 1)/sqrt(a + 1) = sqrt(a + 1))
    let m = if m
        .data
        .iter()
        .any(|e| e.has_recip() || e.has_root_quotient())
    {
        m.map(Expr::cancel)
    } else {
        m
    };
    Ok(make(kind, m))
}

/// The product: scalar times matrix, matrix times matrix, and a transform
/// times a point (homogeneous, §3.3.1): an SE(3) matrix times a 3-vector,
/// and an SE(2) one (last row 0, 0, 1) times a 2-vector, as with numbers.
pub fn mul(x: &Mat, y: &Mat) -> Result<Mat, String> {
    if x.data.len() == 1 {
        return Ok(y.scale(&x.data[0]));
    }
    if y.data.len() == 1 {
        return Ok(x.scale(&y.data[0]));
    }
    let planar = (x.rows, x.cols, y.rows, y.cols) == (3, 3, 2, 1)
        && x.data[6..]
            .iter()
            .map(Expr::as_f64)
            .eq([0.0, 0.0, 1.0].map(Some));
    if planar || (x.rows, x.cols, y.rows, y.cols) == (4, 4, 3, 1) {
        let mut p = y.data.clone();
        p.push(Expr::one());
        let q = x.mul(&Mat::column(p)).ok_or("size")?;
        return Ok(Mat::column(q.data[..y.rows].to_vec()));
    }
    x.mul(y)
        .ok_or_else(|| format!("cannot multiply matrices of sizes {}", sizes(x, y)))
}

/// `a op b` over formulas ([`binary`]); an error with an inf or NaN
/// number; None for a power of a scalar whose
/// exponent is no integer (`2^a`, `a^0.5`): it has no exact form here and
/// stays a tree, computed as typed first once its symbols have numbers —
/// except a half-integer power of an exact rational, a power of its
/// square root (`(9/4)^0.5 = 3/2`, `5^1.5 = 5√5`, LANGUAGE.md §7).
pub fn binary_or_tree(
    op: BinOp,
    a: &Value,
    b: &Value,
    kind: &Kind,
) -> Option<Result<Value, String>> {
    let integer = |v: &Value| match v {
        Value::Num { m, .. } => m.shape() == (1, 1) && m[(0, 0)].fract() == 0.0,
        Value::Formula { m, .. } => {
            matches!(m.data.as_slice(), [e] if e.as_f64().is_some_and(|n| n.fract() == 0.0))
        }
        _ => false,
    };
    // (inf and NaN have no exact form: `a inf` printed 0, `a + 0 inf` NaNe0 + a)
    let not_finite = |v: &Value| matches!(v, Value::Num { m, .. } if !m.all_finite());
    if not_finite(a) || not_finite(b) {
        return Some(Err(
            "inf or NaN with symbols has no closed form: bind the symbols' numbers first".into(),
        ));
    }
    let is_scalar = matches!(a.kind(), Kind::Scalar);
    if op == BinOp::Pow && is_scalar && !integer(b) {
        return half_power(a, b).map(|e| Ok(scalar(e)));
    }
    Some(binary(op, a, b, kind))
}

/// a^(n/2) for an odd n: (√a)ⁿ. For an exact rational a ≥ 0 (> 0 when
/// n < 0), exact when √a is; for a symbolic a, `sqrt(a)` to the n, as
/// the book and SymPy write it (`a^(1/2)` is `sqrt(a)`, `a^(-1/2)` is
/// `1/sqrt(a)`, `a^(3/2)` is `a sqrt(a)`), with the same domain (a ≥ 0,
/// as typed: the replay refuses a negative base); None for any other
/// power.
fn half_power(a: &Value, b: &Value) -> Option<Expr> {
    let n = scalar_of(b)?
        .as_const()?
        .as_rat()?
        .mul(&crate::sym::coef::Rat::int(2))
        .as_int()?;
    if n.unsigned_abs() > 1 << 20 {
        return None;
    }
    let base = scalar_of(a)?;
    let Some(x) = base.as_const() else {
        // (a power past the integer bound of `pow`, or an integer one,
        // is left to it or to the tree)
        if n % 2 == 0 || n.unsigned_abs() >= 1 << 10 {
            return None;
        }
        return Expr::sqrt(&base).powi(n);
    };
    let x = x.as_rat()?;
    if x.is_negative() || (x.is_zero() && n < 0) {
        return None;
    }
    Expr::sqrt(&Expr::constant(crate::sym::coef::Coef::rat(x))).powi(n)
}

fn pow(x: &Mat, y: &Mat, base: Kind, kind: &Kind) -> Result<Value, String> {
    let n = match y.data.as_slice() {
        [e] => e.as_f64().filter(|n| n.fract() == 0.0 && n.abs() < 1e6),
        _ => None,
    }
    .ok_or("a symbolic power needs an integer exponent")? as i64;
    if x.data.len() == 1 {
        let base = match n {
            0.. => x.data[0].clone(),
            _ => x.data[0].recip().ok_or("division by zero")?,
        };
        let mut acc = Mat::scalar(Expr::one());
        let m = checked_power(&Mat::scalar(base), n.unsigned_abs(), &mut acc)?;
        return Ok(scalar(m.data[0].clone()));
    }
    if x.rows != x.cols {
        return Err("only a square matrix has powers".into());
    }
    let b = if n < 0 {
        fits_inverse(&base, x)?;
        inverse(&base, x)
            .ok_or("the matrix is singular (its determinant is identically 0) or larger than 4×4")?
    } else {
        x.clone()
    };
    let mut acc = Mat::identity(x.rows);
    Ok(make(kind, checked_power(&b, n.unsigned_abs(), &mut acc)?))
}

/// `acc · xⁿ` by squaring, refusing a product whose work or result passes
/// the limits ([`MAX_WORK`], [`super::symbolic::MAX_SYM_NODES`]).
fn checked_power(x: &Mat, mut n: u64, acc: &mut Mat) -> Result<Mat, String> {
    // a scalar power's terms, counted before any is formed
    if let [e] = x.data.as_slice()
        && let Some(k) = crate::sym::size::power(e, n, super::symbolic::MAX_SYM_NODES)
        && k > super::symbolic::MAX_SYM_NODES
    {
        return Err(format!(
            "symbolic expression too large: the power would have {k} terms or more before \
             cancellation (more than {})",
            super::symbolic::MAX_SYM_NODES
        ));
    }
    let step = |a: &Mat, b: &Mat| -> Result<Mat, String> {
        fits(a, b, "power")?;
        let m = mul(a, b)?;
        if m.size() > super::symbolic::MAX_SYM_NODES {
            return Err(too_large());
        }
        Ok(m)
    };
    let mut base = x.clone();
    while n > 0 {
        if n & 1 == 1 {
            *acc = step(acc, &base)?;
        }
        n >>= 1;
        if n > 0 {
            base = step(&base, &base)?;
        }
    }
    Ok(acc.clone())
}

/// The inverse by the book's formulas: Rᵀ (3.23's Rᵀ = R⁻¹), the SE(3)
/// inverse of §3.3.1, the adjoint's of Prop. 3.20, 1/x for a scalar, else
/// adj(A)/det(A) up to 4×4;
/// None when the determinant is identically 0 (or the matrix larger).
pub fn inverse(kind: &Kind, x: &Mat) -> Option<Mat> {
    match (kind, x.rows, x.cols) {
        (_, 1, 1) => Some(Mat::scalar(x.data[0].recip()?)),
        (Kind::SO3 | Kind::SO2, _, _) => Some(x.transpose()),
        (Kind::SE3, 4, 4) => matrix::trans_inv(x),
        // (Proposition 3.20: [Ad_T]⁻¹ = [Ad_{T⁻¹}], and its transpose's)
        (Kind::Adjoint { transposed: false }, 6, 6) => matrix::adjoint_inverse(x),
        (Kind::Adjoint { transposed: true }, 6, 6) => {
            Some(matrix::adjoint_inverse(&x.transpose())?.transpose())
        }
        _ => matrix::inverse(x),
    }
}

/// `-x`.
pub fn neg(v: &Value) -> Option<Value> {
    let m = mat_of(v)?;
    Some(make(&v.kind(), m.map(Expr::neg)))
}

/// `.T .R .p .w .v .m .f` of a formula.
pub fn member(v: &Value, name: &str) -> Result<Value, String> {
    let m = mat_of(v).ok_or("no symbolic form")?;
    let k = v.kind();
    let col = |r: std::ops::Range<usize>| make(&Kind::Vector(Some(3)), m.block(r, 0..1));
    match (name, m.rows, m.cols) {
        ("T", _, _) => Ok(make(&transposed_kind(&k), m.transpose())),
        // (a rotation only when the 4×4 is a transform, (3.62))
        ("R", 4, 4) if k == Kind::SE3 => Ok(make(&Kind::SO3, m.block(0..3, 0..3))),
        ("R", 4, 4) => Ok(make(&Kind::Matrix(Some(3), Some(3)), m.block(0..3, 0..3))),
        ("p", 4, 4) => Ok(make(&Kind::Vector(Some(3)), m.block(0..3, 3..4))),
        ("w" | "m", 6, 1) => Ok(col(0..3)),
        ("v" | "f", 6, 1) => Ok(col(3..6)),
        _ => Err(format!("a {k} has no member .{name}")),
    }
}

fn transposed_kind(k: &Kind) -> Kind {
    match k {
        Kind::SO3 | Kind::SO2 | Kind::So3 | Kind::So2 => *k,
        Kind::Adjoint { transposed } => Kind::Adjoint {
            transposed: !transposed,
        },
        _ => Kind::Unknown,
    }
}

/// [`ops::position`] with its error as the message.
fn position(x: f64, n: usize) -> Result<usize, String> {
    ops::position(x, n).map_err(|e| e.to_string())
}

/// `x[i]`, `M[i, j]`, `M[i, :]`, `M[:, j]` (1-based).
pub fn index(v: &Value, sels: &[Sel]) -> Result<Value, String> {
    let m = mat_of(v).ok_or("no symbolic form")?;
    let one = |e: &Expr| scalar(e.clone());
    match sels {
        [Sel::At(i)] if m.cols == 1 => Ok(one(&m.data[position(*i, m.rows)?])),
        [Sel::At(i)] if m.rows == 1 => Ok(one(&m.data[position(*i, m.cols)?])),
        [Sel::At(_)] => Err("a matrix takes two indices: M[i, j], M[i, :] or M[:, j]".into()),
        [Sel::At(i), Sel::At(j)] => Ok(one(m.get(position(*i, m.rows)?, position(*j, m.cols)?))),
        [Sel::At(i), Sel::All] => {
            let r = position(*i, m.rows)?;
            Ok(make(&Kind::Unknown, m.block(r..r + 1, 0..m.cols)))
        }
        [Sel::All, Sel::At(j)] => {
            let c = position(*j, m.cols)?;
            Ok(make(
                &Kind::Vector(Some(m.rows)),
                m.block(0..m.rows, c..c + 1),
            ))
        }
        [Sel::All, Sel::All] | [Sel::All] => Ok(v.clone()),
        _ => Err("at most two indices".into()),
    }
}

/// `(a, b, c)` with symbolic entries: a column vector.
pub fn vector(parts: &[Value]) -> Option<Value> {
    let es: Option<Vec<Expr>> = parts.iter().map(scalar_of).collect();
    let es = es?;
    Some(make(&Kind::Vector(Some(es.len())), Mat::column(es)))
}

/// `[ ... ]` with symbolic entries: the book's bracket \[ω\], \[V\] of one
/// vector (3.30, 3.70), a column for one row of scalars, else block
/// concatenation (LANGUAGE.md §4).
pub fn brackets(rows: &[Vec<Value>]) -> Result<Value, String> {
    let mats: Vec<Vec<Mat>> = rows
        .iter()
        .map(|r| {
            r.iter()
                .map(|v| mat_of(v).ok_or("no symbolic form"))
                .collect()
        })
        .collect::<Result<_, _>>()?;
    if let [row] = mats.as_slice()
        && let [m] = row.as_slice()
    {
        return Ok(match (m.rows, m.cols) {
            (3, 1) => make(&Kind::So3, matrix::skew(&m.data)),
            (6, 1) => make(&Kind::Se3, matrix::twist_matrix(&m.data)),
            _ => make(&rows[0][0].kind(), m.clone()),
        });
    }
    if mats.len() == 1 && mats[0].iter().all(|m| m.data.len() == 1) {
        let es = mats[0].iter().map(|m| m.data[0].clone()).collect();
        return Ok(make(&Kind::Unknown, Mat::column(es)));
    }
    let mut blocks = Vec::with_capacity(mats.len());
    for (ri, row) in mats.iter().enumerate() {
        let h = row[0].rows;
        if let Some(bad) = row.iter().find(|p| p.rows != h) {
            return Err(format!(
                "row {} of the bracket joins blocks of {} and {} rows",
                ri + 1,
                h,
                bad.rows
            ));
        }
        let w = row.iter().map(|p| p.cols).sum();
        let mut b = Mat::zeros(h, w);
        let mut c0 = 0;
        for p in row {
            b.put(0, c0, p);
            c0 += p.cols;
        }
        blocks.push(b);
    }
    let w = blocks[0].cols;
    if let Some((i, bad)) = blocks.iter().enumerate().find(|(_, b)| b.cols != w) {
        return Err(format!(
            "rows of the bracket have different widths: {} and {} (row {})",
            w,
            bad.cols,
            i + 1
        ));
    }
    let h = blocks.iter().map(|b| b.rows).sum();
    let mut m = Mat::zeros(h, w);
    let mut r0 = 0;
    for b in &blocks {
        m.put(r0, 0, b);
        r0 += b.rows;
    }
    let kind = classify(&m);
    Ok(make(&kind, m))
}

/// What a symbolic matrix is, decided exactly: SO(3) when R Rᵀ = I and
/// det R = 1, SE(3) when its blocks are [R, p; 0, 1] with such an R, so(3)
/// when skew-symmetric; SO(2) and SE(2) alike for 2×2 and planar 3×3
/// matrices; else by shape.
pub fn classify(m: &Mat) -> Kind {
    // (a look at one point first: the exact product of large entries
    // costs seconds, and most matrices are no rotation; a product too
    // large to form, as `fits` counts it, is not formed: such a matrix is
    // named by its shape, as one that cannot be told is — the inverse of
    // a 3×3 of 15th powers of sums of cosines took minutes here)
    let orthonormal = |r: &Mat, n: usize| {
        !r.surely_not_orthogonal()
            && fits(r, &r.transpose(), "").is_ok()
            && r.mul(&r.transpose()) == Some(Mat::identity(n))
            && r.det() == Some(Expr::one())
    };
    let rotation = |r: &Mat| orthonormal(r, 3);
    let planar = |r: &Mat| orthonormal(r, 2);
    let last_row = |n: usize| {
        let mut row = Mat::zeros(1, n);
        row.set(0, n - 1, Expr::one());
        row
    };
    match (m.rows, m.cols) {
        (2, 2) if planar(m) => Kind::SO2,
        (3, 3) if rotation(m) => Kind::SO3,
        (3, 3) if m.block(2..3, 0..3) == last_row(3) && planar(&m.block(0..2, 0..2)) => Kind::SE2,
        (3, 3) if m.add(&m.transpose(), false) == Some(Mat::zeros(3, 3)) => Kind::So3,
        (4, 4)
            if m.block(3..4, 0..4)
                == Mat::from_rows(vec![vec![
                    Expr::zero(),
                    Expr::zero(),
                    Expr::zero(),
                    Expr::one(),
                ]])
                .unwrap_or_else(|| Mat::zeros(1, 4))
                && rotation(&m.block(0..3, 0..3)) =>
        {
            Kind::SE3
        }
        _ => Kind::Unknown,
    }
}

/// The name a symbol is bound under: `theta`, `theta'` for θ̇.
pub fn binding_name(s: &Symbol) -> String {
    if s.index > 0 {
        // a vector's component has no binding of its own
        return format!("{}[{}]", s.name, s.index);
    }
    format!("{}{}", s.name, "'".repeat(s.dots as usize))
}

/// The formula with the numbers now bound to its symbols substituted
/// (`lookup` gives a symbol's number, by its binding name).
pub fn substitute(kind: &Kind, m: &Mat, lookup: &dyn Fn(&str) -> Option<f64>) -> Value {
    let by = |s: &Symbol| lookup(&binding_name(s)).map(Expr::num);
    make(kind, m.map(|e| e.subst(&by)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sym(name: &str) -> Expr {
        Expr::symbol(Symbol::new(name))
    }

    #[test]
    fn canonical_forms_decide_equality() {
        let t = sym("t");
        let r = make(&Kind::SO3, matrix::rot_axis(2, &t));
        let rt = make(&Kind::SO3, matrix::rot_axis(2, &t).transpose());
        let rrt = binary(BinOp::Mul, &r, &rt, &Kind::SO3).unwrap();
        let eye = Value::Num {
            kind: Kind::SO3,
            m: nalgebra::DMatrix::identity(3, 3).into(),
            exact: Default::default(),
        };
        assert_eq!(equal(&rrt, &eye, false), Ok(Some(true)));
        assert_eq!(equal(&r, &eye, false), Ok(Some(false)));
        // sqrt(t²) is kept as a call: not decided either way
        let root = scalar(Expr::sqrt(&t.mul(&t)));
        assert_eq!(equal(&root, &scalar(t.clone()), false), Ok(None));
        assert!(equal(&r, &scalar(t), false).is_err());
    }
}
