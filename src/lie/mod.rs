//! The Lie-group core: SO(3), SE(3), SO(2), SE(2), their algebras, adjoints,
//! exponentials and logarithms, and other representations of orientation.
//! Plain Rust on nalgebra; knows nothing of the chasles language.
//!
//! Section and equation numbers refer to Modern Robotics (Lynch & Park),
//! chapter 3, as in the seed text of the book (e.g. Rodrigues' formula
//! (3.51), the SO(3) logarithm algorithm of §3.2.3.3, the SE(3) exponential
//! of Proposition 3.16 / (3.89), the SE(3) logarithm of §3.3.3.2, the adjoint
//! of Definition 3.6, the software list of §3.6).
//!
//! Submodules:
//! - [`so3`]: rotations, so(3), Rodrigues, the logarithm (§3.2);
//! - [`se3`]: rigid-body motions, twists, screws, wrenches (§3.3, §3.4);
//! - [`so2`], [`se2`]: the planar groups (Definitions 3.2, 3.5, Example 3.4);
//! - [`repr`]: Euler angles, roll-pitch-yaw, quaternions, Cayley parameters;
//! - [`project`]: projection onto and distance to the groups (§3.6 software);
//! - [`matexp`]: the exponential of a general square matrix (§3.2.3.1);
//! - [`steps`]: the same algorithms recording the book's steps (`explain`,
//!   LANGUAGE.md §14);
//! - [`dlog`]: the rates of the exponential coordinates (log R, log T);
//! - [`rates`]: the rates of exp, the norm, the direction and `AxisAng6`;
//! - [`group`]: the groups as types ([`SO3`], [`SE3`], [`SO2`], [`SE2`])
//!   with the [`LieGroup`] operations, over the functions above.
#![deny(missing_docs)]

pub mod dlog;
pub mod group;
pub mod matexp;
pub mod project;
pub mod rates;
pub mod repr;
pub mod se2;
pub mod se3;
pub mod so2;
pub mod so3;
pub mod steps;

pub use group::{LieGroup, SE2, SE3, SO2, SO3};

/// A 3-vector (angular velocity, position, exponential coordinates).
pub type Vec3 = nalgebra::Vector3<f64>;
/// A 4-vector (unit quaternion `(w, x, y, z)`, homogeneous point).
pub type Vec4 = nalgebra::Vector4<f64>;
/// A 6-vector: twist `(ω, v)`, screw axis, or wrench `(m, f)`.
pub type Vec6 = nalgebra::Vector6<f64>;
/// A 2-vector.
pub type Vec2 = nalgebra::Vector2<f64>;
/// 2×2 (SO(2), so(2)).
pub type Mat2 = nalgebra::Matrix2<f64>;
/// 3×3 (SO(3), so(3), SE(2), se(2)).
pub type Mat3 = nalgebra::Matrix3<f64>;
/// 4×4 (SE(3), se(3)).
pub type Mat4 = nalgebra::Matrix4<f64>;
/// 6×6 (the adjoint representation `[Ad_T]`).
pub type Mat6 = nalgebra::Matrix6<f64>;

/// The tolerance of the book's `NearZero` (§3.6 software): `|x| < 1e-6`.
pub const NEAR_ZERO_TOL: f64 = 1e-6;

/// `NearZero(z)` of the book's software (§3.6): true when `|z| < 1e-6`
/// ([`NEAR_ZERO_TOL`]), i.e. the scalar is small enough to be treated as zero.
pub fn near_zero(x: f64) -> bool {
    x.abs() < NEAR_ZERO_TOL
}

/// The Euclidean (Frobenius) norm `‖v‖ = √Σ vᵢ²`, scaled by the largest
/// entry before the square root when the plain sum of squares would
/// underflow or overflow (hypot-style): ‖(1e-170, 1e-170)‖ is 1.4e-170, not
/// 0, and ‖(1e200, 1e200)‖ is 1.4e200, not inf. Every norm of the book's
/// functions (‖ω‖ of §3.2.3.2, ‖q‖ of a quaternion, ‖r‖ of Cayley
/// parameters, `Normalize`) goes through it, so no finite input is refused
/// for a norm that is 0 or inf only in floats.
pub fn norm<R, C, S>(v: &nalgebra::Matrix<f64, R, C, S>) -> f64
where
    R: nalgebra::Dim,
    C: nalgebra::Dim,
    S: nalgebra::Storage<f64, R, C>,
{
    // (the squares summed in order, as the exact forms' floats are: a
    // norm in range rounds as theirs does; within this range no square
    // lost matters and none overflowed)
    let n = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    if (1e-140..=1e140).contains(&n) || n == 0.0 && v.iter().all(|x| *x == 0.0) {
        return n;
    }
    let big = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if big == 0.0 || !big.is_finite() || v.iter().any(|x| x.is_nan()) {
        return n;
    }
    big * v.iter().map(|x| (x / big) * (x / big)).sum::<f64>().sqrt()
}

/// The unit vector `v/‖v‖` and the norm `‖v‖` of a nonzero vector, the
/// direction found without losing digits however small or large `v` is:
/// ω̂ = ω̂θ/θ of `AxisAng3` (§3.2.3.2) at θ = 1.4e-320, whose quotient by
/// the subnormal θ keeps only a few digits, is scaled by the largest entry
/// first and is a unit vector to the last digit. `v` must not be zero.
pub fn direction<const D: usize>(
    v: &nalgebra::SVector<f64, D>,
) -> (nalgebra::SVector<f64, D>, f64) {
    let n = norm(v);
    if (1e-150..=1e150).contains(&n) || !n.is_finite() {
        return (v / n, n);
    }
    let w = v / v.amax();
    (w / w.norm(), n)
}

/// `Σ aᵢbᵢ` as if in twice the working precision (Ogita, Rump and Oishi's
/// Dot2, with fused multiply-adds): each product's and each sum's rounding
/// is kept and added at the end, so that a sum that cancels to a small
/// number (the pitch of a screw whose v is nearly perpendicular to ω; an
/// entry of RᵀR − I of a matrix near SO(3)) keeps its digits.
pub fn dot_compensated(pairs: impl Iterator<Item = (f64, f64)>) -> f64 {
    let (mut s, mut c) = (0.0f64, 0.0f64);
    for (a, b) in pairs {
        let p = a * b;
        let pe = a.mul_add(b, -p);
        let t = s + p;
        let z = t - s;
        c += pe + ((s - (t - z)) + (p - z));
        s = t;
    }
    s + c
}

/// `Normalize(V)` of the book's software (§3.6): the unit vector `V/‖V‖` in
/// the direction of `V`. `None` when V is zero or has an entry that is not
/// finite (the direction is then undefined); a tiny or huge V is
/// normalized (its norm is found without underflow or overflow).
pub fn normalize(v: &nalgebra::DVector<f64>) -> Option<nalgebra::DVector<f64>> {
    if v.iter().any(|x| !x.is_finite()) {
        return None;
    }
    let n = v.norm();
    if (1e-150..=1e150).contains(&n) {
        return Some(v / n);
    }
    // (scaled by the largest entry first: ‖(1e-200, 0)‖² underflows to 0
    // and ‖(3e200, 4e200)‖² overflows)
    let big = v.amax();
    if big == 0.0 {
        return None;
    }
    let w = v / big;
    Some(&w / norm(&w))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_zero_book_example() {
        // NearZero(-1e-7) = True (Python docstring).
        assert!(near_zero(-1e-7));
        assert!(!near_zero(1e-6));
    }

    #[test]
    fn norms_neither_underflow_nor_overflow() {
        let tiny = Vec3::new(1e-170, 1e-170, 0.0);
        assert!((norm(&tiny) / 1e-170 - 2f64.sqrt()).abs() < 1e-15);
        let huge = Vec3::new(3e200, 4e200, 0.0);
        assert!((norm(&huge) / 5e200 - 1.0).abs() < 1e-15);
        let sub = Vec4::new(1e-320, 0.0, 0.0, 0.0);
        assert_eq!(norm(&sub), 1e-320);
        assert_eq!(norm(&Vec3::new(3.0, 4.0, 0.0)), 5.0);
        assert_eq!(norm(&Vec3::zeros()), 0.0);
        assert!(norm(&Vec3::new(f64::INFINITY, 0.0, 0.0)).is_infinite());
        assert!(norm(&Vec3::new(f64::NAN, 1.0, 0.0)).is_nan());
    }

    #[test]
    fn normalize_book_example() {
        let v = nalgebra::DVector::from_vec(vec![1.0, 2.0, 3.0]);
        let n = normalize(&v).unwrap();
        let want = [0.26726124, 0.53452248, 0.80178373];
        for i in 0..3 {
            assert!((n[i] - want[i]).abs() < 1e-8);
        }
        assert!(normalize(&nalgebra::DVector::zeros(3)).is_none());
        assert!(normalize(&nalgebra::DVector::from_vec(vec![f64::NAN, 1.0])).is_none());
    }
}
