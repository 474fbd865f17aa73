//! SE(2) and se(2): planar rigid-body motions (Definition 3.5, §3.1) as 3×3
//! homogeneous matrices, planar twists ordered `(ω, vx, vy)`, and the planar
//! exponential and logarithm (the special case of §3.3.3 worked in
//! Example 3.4).

use super::{Mat2, Mat3, Vec2, Vec3, so2};

/// Below this |θ| the coefficients come from their Taylor series.
const SERIES_THETA: f64 = 1e-4;

fn rp(t: &Mat3) -> (Mat2, Vec2) {
    (
        t.fixed_view::<2, 2>(0, 0).into_owned(),
        Vec2::new(t[(0, 2)], t[(1, 2)]),
    )
}

/// The planar transform `[R, p; 0, 1]` of a rotation and a position.
pub(crate) fn from_rp(r: &Mat2, p: &Vec2) -> Mat3 {
    Mat3::new(
        r[(0, 0)],
        r[(0, 1)],
        p.x,
        r[(1, 0)],
        r[(1, 1)],
        p.y,
        0.0,
        0.0,
        1.0,
    )
}

/// `[V] = [0, −ω, vx; ω, 0, vy; 0, 0, 0] ∈ se(2)` of a planar twist
/// `V = (ω, vx, vy)` (the planar case of (3.73), as in Example 3.4).
pub fn hat(v: &Vec3) -> Mat3 {
    Mat3::new(0.0, -v.x, v.y, v.x, 0.0, v.z, 0.0, 0.0, 0.0)
}

/// The planar twist `(ω, vx, vy)` of an se(2) matrix (inverse of [`hat`]).
pub fn vee(m: &Mat3) -> Vec3 {
    Vec3::new(m[(1, 0)], m[(0, 2)], m[(1, 2)])
}

/// `T = [R(θ), p; 0, 1] ∈ SE(2)` from the angle θ and position (x, y)
/// (Definition 3.5, (3.63)).
pub fn from_theta_xy(theta: f64, x: f64, y: f64) -> Mat3 {
    from_rp(&so2::exp(theta), &Vec2::new(x, y))
}

/// `T⁻¹ = [Rᵀ, −Rᵀp; 0, 1]`: the inverse of a planar motion (the planar
/// case of Proposition 3.10, (3.64)).
pub fn inv(t: &Mat3) -> Mat3 {
    let (r, p) = rp(t);
    let rt = r.transpose();
    from_rp(&rt, &(-(rt * p)))
}

/// The planar exponential `e^{[S]θ}` from exponential coordinates
/// `(θ, ρx, ρy)` (ω = θ): `[R(θ), V(θ)ρ; 0, 1]` with
/// `V(θ) = (sinθ/θ) I + ((1−cosθ)/θ) J`, J the 90° rotation — the planar
/// case of Proposition 3.16 (3.89); `[I, ρ; 0, 1]` for θ = 0 (3.90).
/// Series below |θ| = 1e-4.
pub fn exp(v: &Vec3) -> Mat3 {
    let theta = v.x;
    let rho = Vec2::new(v.y, v.z);
    let (a, b) = if theta.abs() < SERIES_THETA {
        let t2 = theta * theta;
        (1.0 - t2 / 6.0, theta * (0.5 - t2 / 24.0))
    } else {
        let h = (0.5 * theta).sin();
        (theta.sin() / theta, 2.0 * h * h / theta)
    };
    let p = Vec2::new(a * rho.x - b * rho.y, b * rho.x + a * rho.y);
    from_rp(&so2::exp(theta), &p)
}

/// The planar logarithm (Example 3.4): exponential coordinates `Sθ =
/// (θ, ρx, ρy)` with θ ∈ (−π, π] and `e^{[S]θ} = T`. With `V(θ)` as in
/// [`exp`], `ρ = V(θ)⁻¹p = (θ/2)cot(θ/2) p − (θ/2) J p` (the planar case of
/// (3.94)); (θ/2)cot(θ/2) = 1 − θ²/12 − θ⁴/720 by series for small θ, and
/// it is 0 at θ = π. A pure translation gives `(0, p)`.
pub fn log(t: &Mat3) -> Vec3 {
    let (r, p) = rp(t);
    let theta = so2::log(&r);
    let h = 0.5 * theta;
    let a = if theta.abs() < SERIES_THETA {
        let t2 = theta * theta;
        1.0 - t2 / 12.0 - t2 * t2 / 720.0
    } else {
        h / h.tan()
    };
    Vec3::new(theta, a * p.x + h * p.y, a * p.y - h * p.x)
}

/// The 3×3 adjoint of a planar motion acting on twists `(ω, vx, vy)`:
/// `[1, 0, 0; p_y, r₁₁, r₁₂; −p_x, r₂₁, r₂₂]` — the planar restriction of
/// `[Ad_T] = [R, 0; [p]R, R]` (Definition 3.6).
pub fn adjoint(t: &Mat3) -> Mat3 {
    Mat3::new(
        1.0,
        0.0,
        0.0,
        t[(1, 2)],
        t[(0, 0)],
        t[(0, 1)],
        -t[(0, 2)],
        t[(1, 0)],
        t[(1, 1)],
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn example_3_4() {
        // Example 3.4: T_sc T_sb⁻¹ = e^{[S]θ} with S = (1, 3.37, −3.37),
        // θ = π/6, and the screw axis through q = (3.37, 3.37).
        let d = PI / 180.0;
        let tsb = from_theta_xy(30.0 * d, 1.0, 2.0);
        let tsc = from_theta_xy(60.0 * d, 2.0, 1.0);
        let st = log(&(tsc * inv(&tsb)));
        let theta = st.x;
        assert!((theta - PI / 6.0).abs() < 1e-14);
        let s = st / theta;
        assert!((s - Vec3::new(1.0, 3.37, -3.37)).amax() < 5e-3);
        // Point on the axis: v = −ω × q ⇒ q = (−v_y, v_x)/ω... for ω = 1,
        // v = (q_y, −q_x).
        let q = Vec2::new(-s.z, s.y);
        assert!((q - Vec2::new(3.37, 3.37)).amax() < 5e-3);
        assert!((exp(&st) - tsc * inv(&tsb)).amax() < 1e-15);
    }

    #[test]
    fn adjoint_matches_conjugation() {
        let t = from_theta_xy(0.7, 1.5, -2.0);
        let v = Vec3::new(0.3, -1.0, 2.0);
        let lhs = hat(&(adjoint(&t) * v));
        let rhs = t * hat(&v) * inv(&t);
        assert!((lhs - rhs).amax() < 1e-14);
    }

    #[test]
    fn pi_and_translation() {
        let t = from_theta_xy(PI, 1.0, 2.0);
        assert!((exp(&log(&t)) - t).amax() < 1e-15);
        let t = from_theta_xy(0.0, 1.0, 2.0);
        assert_eq!(log(&t), Vec3::new(0.0, 1.0, 2.0));
    }
}
