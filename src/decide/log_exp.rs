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
    let form = x.exact_form()?;
    if !principal(&rotation(&form, group)?) {
        return None;
    }
    let (rows, cols) = m.shape();
    Some(Exact::known(in_shape(&form, rows, cols)?))
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

/// The rotation part ω of X, an exact element of the Lie algebra of
/// `group` (so(3), se(3): of the matrix or of the 3- or 6-vector); None
/// when X is not exactly of that form.
fn rotation(x: &Mat, group: Kind) -> Option<Vec<Expr>> {
    let at = |i: usize, j: usize| &x.data[i * x.cols + j];
    let skew = |n: usize| (0..n).all(|i| (0..n).all(|j| *at(i, j) == at(j, i).neg()));
    let zero_row = |i: usize| (0..x.cols).all(|j| *at(i, j) == Expr::default());
    let omega = || vec![at(2, 1).clone(), at(0, 2).clone(), at(1, 0).clone()];
    match (group, x.rows, x.cols) {
        (Kind::SO3, 3, 1) | (Kind::SE3, 6, 1) => Some(x.data[..3].to_vec()),
        (Kind::SO3, 3, 3) if skew(3) => Some(omega()),
        (Kind::SE3, 4, 4) if skew(3) && zero_row(3) => Some(omega()),
        _ => None,
    }
}

/// X in the logarithm's shape: as it is, its 3- or 6-vector (X a matrix
/// of so(3) or se(3), `MatrixLog3`, `MatrixLog6`), or the matrix of its
/// vector (`log(MatrixExp3(v))`); None for any other pair of shapes.
fn in_shape(x: &Mat, rows: usize, cols: usize) -> Option<Mat> {
    if (x.rows, x.cols) == (rows, cols) {
        return Some(x.clone());
    }
    let at = |i: usize, j: usize| x.data[i * x.cols + j].clone();
    let data = match ((x.rows, x.cols), (rows, cols)) {
        ((3, 3), (3, 1)) => vec![at(2, 1), at(0, 2), at(1, 0)],
        ((4, 4), (6, 1)) => vec![at(2, 1), at(0, 2), at(1, 0), at(0, 3), at(1, 3), at(2, 3)],
        ((3, 1), (3, 3)) | ((6, 1), (4, 4)) => {
            let v = &x.data;
            let z = Expr::default;
            let mut m = vec![
                z(),
                v[2].neg(),
                v[1].clone(),
                v[2].clone(),
                z(),
                v[0].neg(),
                v[1].neg(),
                v[0].clone(),
                z(),
            ];
            if rows == 4 {
                // ([ω], v; 0, 0), row by row
                m.insert(3, v[3].clone());
                m.insert(7, v[4].clone());
                m.push(v[5].clone());
                m.extend((0..4).map(|_| z()));
            }
            m
        }
        _ => return None,
    };
    Some(Mat { rows, cols, data })
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
    fn the_rotation_part_of_each_algebra() {
        // [(1, 2, 3)] with v = (4, 5, 6) below, row by row
        let m = Mat {
            rows: 4,
            cols: 4,
            data: [0, -3, 2, 4, 3, 0, -1, 5, -2, 1, 0, 6, 0, 0, 0, 0]
                .iter()
                .map(|&k| q(k, 1))
                .collect(),
        };
        assert_eq!(
            rotation(&m, Kind::SE3),
            Some(vec![q(1, 1), q(2, 1), q(3, 1)])
        );
        // not skew, or a bottom row that is not 0: no rotation part
        let mut bent = m.clone();
        bent.data[0] = q(1, 1);
        assert_eq!(rotation(&bent, Kind::SE3), None);
        let mut bent = m.clone();
        bent.data[15] = q(1, 1);
        assert_eq!(rotation(&bent, Kind::SE3), None);
        // the same 4×4 is no element of so(3)
        assert_eq!(rotation(&m, Kind::SO3), None);
        // its 6-vector and back
        let v = in_shape(&m, 6, 1).expect("the 6-vector");
        let want: Vec<Expr> = (1..=6).map(|k| q(k, 1)).collect();
        assert_eq!(v.data, want);
        assert_eq!(in_shape(&v, 4, 4), Some(m.clone()));
        // an so(3) matrix's 3-vector and back; no 2-vector of it
        let w = Mat {
            rows: 3,
            cols: 1,
            data: want[..3].to_vec(),
        };
        let hat = in_shape(&w, 3, 3).expect("[ω]");
        assert_eq!(rotation(&hat, Kind::SO3), Some(want[..3].to_vec()));
        assert_eq!(in_shape(&hat, 3, 1), Some(w));
        assert_eq!(in_shape(&hat, 2, 1), None);
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
