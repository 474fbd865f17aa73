//! The rates of the book's maps whose derivatives no closed step gives:
//! how `exp(A)`, `‖x‖`, `x/‖x‖` and `AxisAng6(V)` (§3.2.3, §3.3.3) move
//! when their operand moves with rate `dx`, at numbers, to rounding.
//!
//! The rate of the matrix exponential is the top-right block of the
//! exponential of the block-triangular `[A, dA; 0, A]` (Van Loan 1978;
//! Higham, *Functions of Matrices*, (3.16)):
//!
//! ```text
//! exp([A, E; 0, A]) = [exp(A), L(A, E); 0, exp(A)],  L(A, E) = d/ds exp(A + sE) at s = 0,
//! ```
//!
//! so it is computed by the same exponential as the value (no finite
//! difference, no series cut off by hand), for so(3), se(3) and any
//! square matrix alike. The norm and the direction of a vector have no
//! rate where the vector is 0; there each is None, and the caller refuses.

use nalgebra::{DMatrix, DVector};

use super::{Vec3, Vec6, matexp, near_zero, norm};

/// d exp(A) along dA: the top-right block of `exp([A, dA; 0, A])`. None
/// when the matrices are not square of one size or not finite.
pub fn exp_rate(a: &DMatrix<f64>, da: &DMatrix<f64>) -> Option<DMatrix<f64>> {
    let n = a.nrows();
    if !a.is_square() || da.shape() != (n, n) {
        return None;
    }
    let mut big = DMatrix::zeros(2 * n, 2 * n);
    big.view_mut((0, 0), (n, n)).copy_from(a);
    big.view_mut((n, n), (n, n)).copy_from(a);
    big.view_mut((0, n), (n, n)).copy_from(da);
    let e = matexp::try_expm(&big)?;
    Some(e.view((0, n), (n, n)).into_owned())
}

/// d‖x‖ along dx: x·dx/‖x‖. None where x is 0 (the norm has a corner).
pub fn norm_rate(x: &DVector<f64>, dx: &DVector<f64>) -> Option<f64> {
    let n = norm(x);
    (n > 0.0 && n.is_finite()).then(|| (x / n).dot(dx))
}

/// d(x/‖x‖) along dx: the part of dx across x̂, over ‖x‖. For a
/// 3-vector that part is x̂ × (dx × x̂), whose differences are of small
/// terms; dx − x̂ (x̂·dx) cancels where dx is nearly along x (x = (0, a,
/// 2a²) at a = 1e-9 lost the −4e-9 of the rate's second entry). None
/// where x is 0 (no direction).
pub fn direction_rate(x: &DVector<f64>, dx: &DVector<f64>) -> Option<DVector<f64>> {
    let n = norm(x);
    if !(n > 0.0 && n.is_finite()) {
        return None;
    }
    let u = x / n;
    let across = if x.len() == 3 {
        let (u3, d3) = (
            Vec3::from_column_slice(u.as_slice()),
            Vec3::from_column_slice(dx.as_slice()),
        );
        let a = u3.cross(&d3.cross(&u3));
        DVector::from_column_slice(a.as_slice())
    } else {
        dx - &u * u.dot(dx)
    };
    Some(across / n)
}

/// The rates of `AxisAng6(V)` = (S, θ) along dV, as the book's
/// `AxisAng6` chooses θ (§3.6 software, [`super::se3::axis_angle`]):
/// θ = ‖ω‖, or ‖v‖ where ω is near zero; S = V/θ. So dθ is the rate of
/// that norm and dS = (dV − S dθ)/θ. None where that θ is 0.
pub fn axis_angle6_rate(v: &Vec6, dv: &Vec6) -> Option<(Vec6, f64)> {
    let (w, lin) = (v.fixed_rows::<3>(0), v.fixed_rows::<3>(3));
    let rows = if near_zero(norm(&w)) && norm(&lin) > 0.0 {
        3
    } else {
        0
    };
    let part = DVector::from_column_slice(v.fixed_rows::<3>(rows).as_slice());
    let dpart = DVector::from_column_slice(dv.fixed_rows::<3>(rows).as_slice());
    let theta = norm(&part);
    let dtheta = norm_rate(&part, &dpart)?;
    let mut ds = (dv - v / theta * dtheta) / theta;
    // (the part θ is the norm of: its direction's rate, without the
    // cancellation of dpart − part̂ dθ)
    let across = direction_rate(&part, &dpart)?;
    ds.fixed_rows_mut::<3>(rows)
        .copy_from_slice(across.as_slice());
    Some((ds, dtheta))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lie::{se3, so3};

    /// Each rate against a central difference of its map (h = 1e-6).
    #[test]
    fn rates_agree_with_central_differences() {
        let h = 1e-6;
        let (w, dw) = (Vec3::new(0.3, -1.2, 0.5), Vec3::new(0.7, 0.1, -0.4));
        let hat = |x: &Vec3| DMatrix::from_column_slice(3, 3, so3::hat(x).as_slice());
        let fd = (so3::exp(&(w + dw * h)) - so3::exp(&(w - dw * h))) / (2.0 * h);
        let rate = exp_rate(&hat(&w), &hat(&dw)).expect("square");
        assert!((rate - DMatrix::from_column_slice(3, 3, fd.as_slice())).norm() < 1e-8);
        let (v, dv) = (
            Vec6::new(0.3, -1.2, 0.5, 1.0, 2.0, -0.5),
            Vec6::new(0.7, 0.1, -0.4, 0.2, 0.0, 1.0),
        );
        let se = |x: &Vec6| DMatrix::from_column_slice(4, 4, se3::hat(x).as_slice());
        let fd = (se3::exp(&(v + dv * h)) - se3::exp(&(v - dv * h))) / (2.0 * h);
        let rate = exp_rate(&se(&v), &se(&dv)).expect("square");
        assert!((rate - DMatrix::from_column_slice(4, 4, fd.as_slice())).norm() < 1e-8);
        for (v, dv) in [
            (v, dv),
            // a pure translation: θ = ‖v‖
            (
                Vec6::new(0.0, 0.0, 0.0, 1.0, 2.0, -0.5),
                Vec6::new(0.0, 0.0, 0.0, 0.2, 0.0, 1.0),
            ),
        ] {
            let (ds, dt) = axis_angle6_rate(&v, &dv).expect("θ > 0");
            let (sp, tp) = se3::axis_angle(&(v + dv * h));
            let (sm, tm) = se3::axis_angle(&(v - dv * h));
            assert!((ds - (sp - sm) / (2.0 * h)).norm() < 1e-8);
            assert!((dt - (tp - tm) / (2.0 * h)).abs() < 1e-8);
        }
        // a direction nearly along its rate: x = (0, a, 2a²) at a = 1e-9,
        // x̂' = (0, −4a, 2)/(1 + 4a²)^(3/2)
        let a = 1e-9;
        let x = DVector::from_column_slice(&[0.0, a, 2.0 * a * a]);
        let dx = DVector::from_column_slice(&[0.0, 1.0, 4.0 * a]);
        let d = direction_rate(&x, &dx).expect("x ≠ 0");
        let k = (1.0 + 4.0 * a * a).powf(1.5);
        assert!(
            (d[1] - (-4.0 * a / k)).abs() < 1e-20 && (d[2] - 2.0 / k).abs() < 1e-15,
            "{d}"
        );
        let zero = DVector::zeros(3);
        let d = DVector::from_column_slice(&[1.0, 0.0, 0.0]);
        assert!(norm_rate(&zero, &d).is_none() && direction_rate(&zero, &d).is_none());
    }
}
