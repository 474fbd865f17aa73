//! The rates of the exponential coordinates: how `MatrixLog3(R)` and
//! `MatrixLog6(T)` (§3.2.3.3, §3.3.3.2) move when R and T do.
//!
//! For R = `e^[φ]`, `Ṙ Rᵀ = [J(φ) φ̇]` (the spatial angular velocity ω_s
//! of (3.48) is J(φ) φ̇), with J the left Jacobian
//!
//! ```text
//! J(x) = Σ_k ad_x^k/(k + 1)! = I + (1 − cos θ)/θ² [φ] + (θ − sin θ)/θ³ [φ]²,
//! ```
//!
//! and likewise `Ṫ T⁻¹ = [J(V) V̇]` for T = `e^[V]`, with ad_V the 6×6 of
//! (3.83). So φ̇ = J(φ)⁻¹ ω_s and V̇ = J(V)⁻¹ V_s: right on every branch of
//! the logarithm (θ in [0, π)), unlike the derivative of a closed form,
//! which holds on its branch only. J(x) is the top-right block of
//! `exp([ad_x, I; 0, 0])` (the series Σ ad^k/(k+1)!, no cancellation near
//! θ = 0), and J is invertible for θ < 2π. At θ = π the logarithm jumps
//! (ω̂θ and −ω̂θ are both logs): there is no rate there.

use nalgebra::DMatrix;

use super::{Mat3, Mat4, Mat6, Vec3, Vec6, matexp, se3, so3};

/// How near θ may come to π before the rate is refused: the logarithm
/// jumps at π, and within rounding of it the side cannot be told.
pub const HALF_TURN_MARGIN: f64 = 1e-12;

/// Σ_k a^k/(k + 1)! of an n×n matrix a: the top-right block of
/// `exp([a, I; 0, 0])`.
fn phi1(a: &DMatrix<f64>) -> DMatrix<f64> {
    let n = a.nrows();
    let mut big = DMatrix::zeros(2 * n, 2 * n);
    big.view_mut((0, 0), (n, n)).copy_from(a);
    big.view_mut((0, n), (n, n)).fill_with_identity();
    let e = matexp::expm(&big);
    e.view((0, n), (n, n)).into_owned()
}

/// The left Jacobian J(φ) of SO(3): ω_s = J(φ) φ̇ for R = `e^[φ]`.
pub fn so3_left_jacobian(phi: &Vec3) -> Mat3 {
    let a = DMatrix::from_column_slice(3, 3, so3::hat(phi).as_slice());
    Mat3::from_column_slice(phi1(&a).as_slice())
}

/// The left Jacobian J(V) of SE(3): V_s = J(V) V̇ for T = `e^[V]`.
pub fn se3_left_jacobian(v: &Vec6) -> Mat6 {
    let a = DMatrix::from_column_slice(6, 6, se3::ad(v).as_slice());
    Mat6::from_column_slice(phi1(&a).as_slice())
}

/// d/dt of `MatrixLog3(R)` (the exponential coordinates φ = ω̂θ, θ in
/// [0, π]) at R moving with Ṙ = `dr`: φ̇ = J(φ)⁻¹ ω_s, ω_s = so3ToVec(Ṙ Rᵀ)
/// (3.48, its skew part). None within [`HALF_TURN_MARGIN`] of θ = π.
pub fn so3_log_rate(r: &Mat3, dr: &Mat3) -> Option<Vec3> {
    let phi = so3::log(r);
    if std::f64::consts::PI - phi.norm() <= HALF_TURN_MARGIN * std::f64::consts::PI {
        return None;
    }
    let w = so3::vee_skew(&(dr * r.transpose()));
    so3_left_jacobian(&phi).lu().solve(&w)
}

/// d/dt of `MatrixLog6(T)` (the exponential coordinates V = Sθ) at T moving
/// with Ṫ = `dt`: V̇ = J(V)⁻¹ V_s, `[V_s] = Ṫ T⁻¹` (3.70). None within
/// [`HALF_TURN_MARGIN`] of a half turn.
pub fn se3_log_rate(t: &Mat4, dt: &Mat4) -> Option<Vec6> {
    let v = se3::log(t);
    let theta = Vec3::new(v[0], v[1], v[2]).norm();
    if std::f64::consts::PI - theta <= HALF_TURN_MARGIN * std::f64::consts::PI {
        return None;
    }
    let vs = se3::vee(&(dt * se3::inv(t)));
    se3_left_jacobian(&v).lu().solve(&vs)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// J(φ) against its closed form I + (1 − cos θ)/θ² [φ] + (θ − sin θ)/θ³ [φ]².
    #[test]
    fn the_left_jacobian_of_so3_is_its_closed_form() {
        for phi in [
            Vec3::new(0.3, -0.2, 0.5),
            Vec3::new(1.0, 2.0, 2.0),
            Vec3::new(0.0, 0.0, 3.1),
        ] {
            let th = phi.norm();
            let w = so3::hat(&phi);
            let want = Mat3::identity()
                + w * ((1.0 - th.cos()) / (th * th))
                + w * w * ((th - th.sin()) / (th * th * th));
            assert!((so3_left_jacobian(&phi) - want).norm() < 1e-14, "{phi}");
        }
        // θ → 0: J → I + [φ]/2 (to rounding of its entries, which are 1
        // or near 0: no division by θ)
        let tiny = Vec3::new(1e-9, -2e-9, 0.0);
        let j = so3_left_jacobian(&tiny);
        assert!((j - (Mat3::identity() + so3::hat(&tiny) * 0.5)).norm() < 1e-15);
        assert_eq!(so3_left_jacobian(&Vec3::zeros()), Mat3::identity());
    }

    /// The rates against central differences of the logs along R(u) =
    /// e^{[a + b u]}, T(u) = e^{[A + B u]}, including angles where the
    /// logarithm wraps (θ past π, so the coordinates are not a + b u).
    #[test]
    fn rates_agree_with_differences_of_the_logs() {
        let h = 1e-6;
        for (a, b) in [
            (Vec3::new(0.3, -0.2, 0.5), Vec3::new(0.1, 0.4, -0.3)),
            (Vec3::new(2.0, 1.0, -1.5), Vec3::new(0.5, 0.2, 0.1)),
            (Vec3::new(0.0, 0.0, 4.0), Vec3::new(0.0, 0.0, 1.0)),
        ] {
            let r = |u: f64| so3::exp(&(a + b * u));
            let dr = (r(h) - r(-h)) / (2.0 * h);
            let rate = so3_log_rate(&r(0.0), &dr).expect("off a half turn");
            let fd = (so3::log(&r(h)) - so3::log(&r(-h))) / (2.0 * h);
            assert!((rate - fd).norm() < 1e-8, "{rate} vs {fd}");
        }
        for (a, b) in [
            (
                Vec6::new(0.3, -0.2, 0.5, 1.0, 2.0, -1.0),
                Vec6::new(0.1, 0.4, -0.3, 0.5, 0.0, 2.0),
            ),
            (
                Vec6::new(0.0, 0.0, 4.0, 1.0, 0.0, 0.0),
                Vec6::new(0.0, 0.0, 1.0, 0.0, 0.0, 0.0),
            ),
            (
                Vec6::new(0.0, 0.0, 0.0, 1.0, 2.0, 3.0),
                Vec6::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0),
            ),
        ] {
            let t = |u: f64| se3::exp(&(a + b * u));
            let dt = (t(h) - t(-h)) / (2.0 * h);
            let rate = se3_log_rate(&t(0.0), &dt).expect("off a half turn");
            let fd = (se3::log(&t(h)) - se3::log(&t(-h))) / (2.0 * h);
            assert!((rate - fd).norm() < 1e-7, "{rate} vs {fd}");
        }
        // at a half turn there is no rate
        let half = so3::exp(&Vec3::new(0.0, 0.0, std::f64::consts::PI));
        assert!(so3_log_rate(&half, &so3::hat(&Vec3::z())).is_none());
    }
}
