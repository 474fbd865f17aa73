//! The logarithm of an exponential (the book's §3.2.3.3 and §3.3.3.2;
//! LANGUAGE.md §7): `log(exp([ω̂] 0.5))` is [ω̂] 0.5 exactly, so
//! `log(exp([ω̂] 0.5)) == [ω̂] 0.5` and `MatrixLog6(MatrixExp6(V)) == V` are
//! true, not floats that differ by rounding.
//!
//! The book's logarithms are principal: θ ∈ [0, π] (the algorithm of
//! §3.2.3.3; for a transform, v = G⁻¹(θ)p, (3.92)). For X in so(3) or
//! se(3) whose rotation part ω has ‖ω‖ < π, e^X is the rotation by
//! θ = ‖ω‖ about ω̂ (with its translation), and the logarithm's one answer
//! with θ in [0, π) is X itself. So when X has an exact form of that
//! shape (skew, its bottom row 0) and the bound is certified by ball
//! arithmetic, the logarithm's exact form is X's, in the logarithm's
//! shape (the 3- or 6-vector of `MatrixLog3` and `MatrixLog6`), and every
//! proof of `==` reads it as it reads X. At ‖ω‖ = π the logarithm has two
//! answers (±ω̂, the θ = π note), and beyond it, it returns another X: the
//! logarithm stays a float there, as it does for an X with no exact form
//! (and in so(2) and se(2), whose exponentials keep no recipe).

use super::ball;
use super::certify::PRECISIONS;
use crate::check::ty::Kind;
use crate::sym::matrix::{skew, twist_matrix, unskew};
use crate::sym::{Expr, Mat};
use crate::values::exact::{Exact, Operation};
use crate::values::value::Value;

/// The exact form of `out`, the result of builtin `name` on `args`, when
/// it is the logarithm of an exponential on the principal branch (the
/// module's doc): X in `out`'s shape. None for any other call (the
/// caller asks only for results of a Lie algebra's kinds).
pub(crate) fn exact_of(name: &str, args: &[Value], out: &Value) -> Option<Exact> {
    if !matches!(name, "log" | "MatrixLog3" | "MatrixLog6") {
        return None;
    }
    let ([arg], Value::Num { m, .. }) = (args, out) else {
        return None;
    };
    let (group, x) = exponent(arg)?;
    let v = algebra_vector(&x.exact_form()?, group)?;
    let (rows, cols) = m.shape();
    // (the logarithm's shape is its group's: a vector of v's length, or
    // that vector's matrix)
    let side = if v.len() == 3 { 3 } else { 4 };
    let fits = (rows, cols) == (v.len(), 1) || (rows, cols) == (side, side);
    (fits && principal(&v[..3])).then(|| Exact::known(in_shape(&v, rows, cols)))
}

/// The group of e^X and the argument X, when `e` was made by an
/// exponential (`exp`, `MatrixExp3`, `MatrixExp6`) of X and still keeps
/// that recipe (read without working out any form: `log(T_ac)` of a
/// product reads one operation name, no more).
fn exponent(e: &Value) -> Option<(Kind, Value)> {
    let Value::Num { exact, kind, .. } = e else {
        return None;
    };
    let x = exact
        .peek_recipe(|p| {
            let Operation::Call(name) = p.op else {
                return None;
            };
            let exp = crate::builtins::lookup(name)?.name;
            if !matches!(exp, "exp" | "MatrixExp3" | "MatrixExp6") {
                return None;
            }
            match p.args.refs().as_slice() {
                [x] => Some((*x).clone()),
                _ => None,
            }
        })
        .flatten()?;
    Some((*kind, x))
}

/// The vector of X, an exact element of the Lie algebra of `group`: ω
/// (so(3)) or (ω, v) (se(3)), of the vector itself or of the matrix
/// (3.30, 3.70); None when X is not exactly of that form (not skew, a
/// bottom row that is not 0, another shape).
fn algebra_vector(x: &Mat, group: Kind) -> Option<Vec<Expr>> {
    let v = match (x.rows, x.cols) {
        (3 | 6, 1) => x.data.clone(),
        (3, 3) => unskew(x),
        (4, 4) => {
            let mut v = unskew(x);
            v.extend((0..3).map(|i| x.get(i, 3).clone()));
            v
        }
        _ => return None,
    };
    let fits = matches!((group, v.len()), (Kind::SO3, 3) | (Kind::SE3, 6));
    (fits && (x.cols == 1 || in_shape(&v, x.rows, x.cols) == *x)).then_some(v)
}

/// The vector `v` of an element of so(3) or se(3) in a logarithm's shape:
/// as it is (`MatrixLog3`, `MatrixLog6`), or its matrix [ω] (3.30) or
/// [V] (3.70) (`log`).
fn in_shape(v: &[Expr], rows: usize, cols: usize) -> Mat {
    match (rows, cols) {
        (3, 3) => skew(v),
        (4, 4) => twist_matrix(v),
        _ => Mat::column(v.to_vec()),
    }
}

/// True when ‖ω‖ < π is certified: π² − Σ ωᵢ² is a ball that excludes 0
/// and lies above it.
fn principal(omega: &[Expr]) -> bool {
    let square = omega.iter().fold(Expr::default(), |s, w| s.add(&w.mul(w)));
    let prec = PRECISIONS[0];
    let pi = ball::pi(prec);
    let Some(pi2) = ball::mul(&pi, &pi, prec) else {
        return false;
    };
    let Some(s) = ball::exact(&square, prec) else {
        return false;
    };
    ball::sub(&pi2, &s, prec).is_some_and(|d| ball::nonzero(&d) && ball::floats(&d).0 > 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::coef::{Coef, Rat};

    fn q(n: i128, d: i128) -> Expr {
        Expr::constant(Coef::rat(Rat::new(n, d).expect("a fraction")))
    }

    #[test]
    fn the_vector_of_each_algebra() {
        // [(1, 2, 3)] with v = (4, 5, 6) beside it, row by row
        let m = Mat {
            rows: 4,
            cols: 4,
            data: [0, -3, 2, 4, 3, 0, -1, 5, -2, 1, 0, 6, 0, 0, 0, 0]
                .iter()
                .map(|&k| q(k, 1))
                .collect(),
        };
        let v: Vec<Expr> = (1..=6).map(|k| q(k, 1)).collect();
        assert_eq!(algebra_vector(&m, Kind::SE3), Some(v.clone()));
        assert_eq!(in_shape(&v, 4, 4), m);
        assert_eq!(in_shape(&v, 6, 1).data, v);
        // not skew, or a bottom row that is not 0: not of se(3)
        let mut bent = m.clone();
        bent.data[0] = q(1, 1);
        assert_eq!(algebra_vector(&bent, Kind::SE3), None);
        let mut bent = m.clone();
        bent.data[15] = q(1, 1);
        assert_eq!(algebra_vector(&bent, Kind::SE3), None);
        // the same 4×4 is no element of so(3); a 3-vector is, and its [ω]
        assert_eq!(algebra_vector(&m, Kind::SO3), None);
        let hat = in_shape(&v[..3], 3, 3);
        assert_eq!(algebra_vector(&hat, Kind::SO3), Some(v[..3].to_vec()));
        assert_eq!(
            algebra_vector(&Mat::column(v[..3].to_vec()), Kind::SE3),
            None
        );
    }

    #[test]
    fn the_principal_branch_is_strict() {
        // ‖(3, 0, 0)‖ = 3 < π; 3.15 > π; π itself is not strictly inside
        assert!(principal(&[q(3, 1), q(0, 1), q(0, 1)]));
        assert!(!principal(&[q(315, 100), q(0, 1), q(0, 1)]));
        assert!(!principal(&[Expr::pi(), q(0, 1), q(0, 1)]));
        assert!(principal(&[q(0, 1), q(0, 1), q(0, 1)]));
    }
}
