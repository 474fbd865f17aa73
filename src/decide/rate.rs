//! The rate of a builtin at numbers (`recipe::Step::Rate`): how the call
//! moves when its operand moves with a given rate, for the derivative of a
//! call kept over symbols (LANGUAGE.md §7: `diff(Rot((1, a, 2), a), a)`
//! once a has a number). The numbers are read here and the rates computed
//! by [`crate::lie`] (the exponential's by the exponential itself,
//! [`crate::lie::rates`]; the logarithms' by [`crate::lie::dlog`]), so
//! no map of the book is written twice. Where the call has no derivative
//! at the numbers the rate is refused, never guessed.

use nalgebra::{DMatrix, DVector};

use crate::check::ty::Kind;
use crate::lie::{Mat3, Mat4, Vec3, Vec6, dlog, rates, se3, so3};
use crate::values::exact::Exact;
use crate::values::num::Num;
use crate::values::value::Value;

/// The rate of builtin `name` (part `part` of its tuple) at numbers `x`
/// moving with `dx`, of shape `kind`. Ok(None) where the operands are not
/// what the rate takes (the derivative is then not known); Err where the
/// call has no derivative at these numbers.
pub(crate) fn of(
    name: &str,
    part: Option<usize>,
    x: &Value,
    dx: &Value,
    kind: Kind,
) -> Result<Option<Value>, String> {
    let (Value::Num { m: x, .. }, Value::Num { m: dx, .. }) = (x, dx) else {
        return Ok(None);
    };
    if x.shape() != dx.shape() {
        return Ok(None);
    }
    let (x, dx) = (x.to_dmatrix().into_owned(), dx.to_dmatrix().into_owned());
    let col = |m: &DMatrix<f64>| DVector::from_column_slice(m.as_slice());
    let out: DMatrix<f64> = match (name, part) {
        ("exp" | "MatrixExp3" | "MatrixExp6", None) => {
            let (a, da) = match x.shape() {
                (3, 1) => (hat3(&x), hat3(&dx)),
                (6, 1) => (hat6(&x), hat6(&dx)),
                _ => (x, dx),
            };
            match rates::exp_rate(&a, &da) {
                Some(d) => d,
                None => return Ok(None),
            }
        }
        ("log" | "MatrixLog3" | "MatrixLog6", None) => {
            let rate = match x.shape() {
                (3, 3) => dlog::so3_log_rate(
                    &Mat3::from_column_slice(x.as_slice()),
                    &Mat3::from_column_slice(dx.as_slice()),
                )
                .map(|v| DMatrix::from_column_slice(3, 1, v.as_slice())),
                (4, 4) => dlog::se3_log_rate(
                    &Mat4::from_column_slice(x.as_slice()),
                    &Mat4::from_column_slice(dx.as_slice()),
                )
                .map(|v| DMatrix::from_column_slice(6, 1, v.as_slice())),
                _ => return Ok(None),
            };
            let Some(v) = rate else {
                return Err(format!(
                    "the rate of {name} at a half turn (θ = π): the logarithm jumps there, \
                     so it has no derivative"
                ));
            };
            // (as the call gives it: the matrix [φ̇] where it gives [φ])
            match (v.nrows(), kind.shape()) {
                (3, Some((Some(3), Some(3)))) => hat3(&v),
                (6, Some((Some(4), Some(4)))) => hat6(&v),
                _ => v,
            }
        }
        ("norm", None) | ("AxisAng3", Some(1)) => match rates::norm_rate(&col(&x), &col(&dx)) {
            Some(d) => DMatrix::from_element(1, 1, d),
            // (at 0 moving with rate 0, ‖x‖ grows as the square of the
            // step: its rate is 0)
            None if dx.iter().all(|d| *d == 0.0) => DMatrix::zeros(1, 1),
            None => return Err(corner(name)),
        },
        // d|u| = sign(u) du (0 at u = 0 moving with rate 0, as the norm)
        ("abs", None) if x.shape() == (1, 1) => match (x[(0, 0)], dx[(0, 0)]) {
            (u, du) if u != 0.0 => DMatrix::from_element(1, 1, u.signum() * du),
            (_, 0.0) => DMatrix::zeros(1, 1),
            _ => return Err(corner(name)),
        },
        ("Normalize", None) | ("AxisAng3", Some(0)) => {
            match rates::direction_rate(&col(&x), &col(&dx)) {
                Some(d) => DMatrix::from_column_slice(d.len(), 1, d.as_slice()),
                None => return Err(corner(name)),
            }
        }
        ("AxisAng6", Some(i @ (0 | 1))) if x.shape() == (6, 1) => {
            let v = Vec6::from_column_slice(x.as_slice());
            let dv = Vec6::from_column_slice(dx.as_slice());
            match rates::axis_angle6_rate(&v, &dv) {
                Some((ds, _)) if i == 0 => DMatrix::from_column_slice(6, 1, ds.as_slice()),
                Some((_, dt)) => DMatrix::from_element(1, 1, dt),
                None => return Err(corner(name)),
            }
        }
        // (T = [R, p; 0, 1]: the blocks of Ṫ)
        ("TransToRp", Some(0)) if x.shape() == (4, 4) => dx.view((0, 0), (3, 3)).into_owned(),
        ("TransToRp", Some(1)) if x.shape() == (4, 4) => dx.view((0, 3), (3, 1)).into_owned(),
        _ => return Ok(None),
    };
    let m = if out.shape() == (1, 1) {
        Num::Scalar(out[(0, 0)])
    } else {
        Num::from_dmatrix(out)
    };
    Ok(Some(Value::Num {
        kind,
        m,
        exact: Exact::Float,
    }))
}

/// The refusal of a norm or direction at a zero vector (abs at 0).
fn corner(name: &str) -> String {
    if name == "abs" {
        return "abs(…) has no derivative where its operand is 0 and moves (a corner)".into();
    }
    format!(
        "{name}(…) has no derivative where its vector is 0 (a norm has a corner there, and \
         a direction none)"
    )
}

/// `[ω]` of a 3-vector, as a 3×3.
fn hat3(v: &DMatrix<f64>) -> DMatrix<f64> {
    let w = Vec3::from_column_slice(v.as_slice());
    DMatrix::from_column_slice(3, 3, so3::hat(&w).as_slice())
}

/// `[V]` of a 6-vector, as a 4×4.
fn hat6(v: &DMatrix<f64>) -> DMatrix<f64> {
    let w = Vec6::from_column_slice(v.as_slice());
    DMatrix::from_column_slice(4, 4, se3::hat(&w).as_slice())
}
