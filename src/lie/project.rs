//! Projection onto, and distance to, the groups SO(3), SE(3), SO(2), SE(2):
//! `ProjectToSO3`, `ProjectToSE3`, `DistanceToSO3`, `DistanceToSE3`,
//! `TestIfSO3`, `TestIfSE3` of the book's software (§3.6), and their planar
//! analogues. Useful for matrices that drift off the group (rounding,
//! measured data); meaningful only for matrices near the group.

use super::{Mat2, Mat3, Mat4, Vec2, so2};

/// The distance below which [`test_if_so3`] and friends accept a matrix
/// (the book's software).
pub const TEST_TOL: f64 = 1e-3;

/// The "large number" the book's software returns as the distance of a
/// matrix with det ≤ 0.
pub const FAR: f64 = 1e9;

/// `ProjectToSO3(M)`: the rotation nearest to M in the Frobenius norm,
/// `U Vᵀ` from the SVD `M = U Σ Vᵀ`; if det(U Vᵀ) = −1 the column of U for
/// the smallest singular value is negated so the result is in SO(3)
/// (the nearest rotation; for such M it may be far from M).
pub fn project_to_so3(m: &Mat3) -> Mat3 {
    let svd = m.svd(true, true);
    let (Some(mut u), Some(vt)) = (svd.u, svd.v_t) else {
        return Mat3::identity();
    };
    if (u * vt).determinant() < 0.0 {
        let k = (0..3)
            .min_by(|&i, &j| svd.singular_values[i].total_cmp(&svd.singular_values[j]))
            .unwrap_or(2);
        let col = -u.column(k);
        u.set_column(k, &col);
    }
    u * vt
}

/// `ProjectToSE3(M)`: `[ProjectToSO3(M₁:₃,₁:₃), M₁:₃,₄; 0, 1]` — the
/// rotation block projected onto SO(3), the position kept, the last row
/// set to (0, 0, 0, 1).
pub fn project_to_se3(m: &Mat4) -> Mat4 {
    let r = project_to_so3(&m.fixed_view::<3, 3>(0, 0).into_owned());
    let p = m.fixed_view::<3, 1>(0, 3).into_owned();
    super::se3::from_rp(&r, &p)
}

/// `DistanceToSO3(M)`: `‖MᵀM − I‖_F` if det M > 0, else 1e9 ([`FAR`]),
/// exactly as the book's software.
pub fn distance_to_so3(m: &Mat3) -> f64 {
    if m.determinant() > 0.0 {
        (m.transpose() * m - Mat3::identity()).norm()
    } else {
        FAR
    }
}

/// `DistanceToSE3(M)`: with R the top-left 3×3 block, `‖[RᵀR, 0; M₄,:] −
/// I‖_F` if det R > 0 (the last row of M counts, the position does not),
/// else 1e9 ([`FAR`]), exactly as the book's software.
pub fn distance_to_se3(m: &Mat4) -> f64 {
    let r = m.fixed_view::<3, 3>(0, 0).into_owned();
    if r.determinant() > 0.0 {
        let mut a = Mat4::zeros();
        a.fixed_view_mut::<3, 3>(0, 0)
            .copy_from(&(r.transpose() * r));
        a.set_row(3, &m.row(3));
        (a - Mat4::identity()).norm()
    } else {
        FAR
    }
}

/// `TestIfSO3(M)`: true if [`distance_to_so3`] is below 1e-3.
pub fn test_if_so3(m: &Mat3) -> bool {
    distance_to_so3(m).abs() < TEST_TOL
}

/// `TestIfSE3(M)`: true if [`distance_to_se3`] is below 1e-3.
pub fn test_if_se3(m: &Mat4) -> bool {
    distance_to_se3(m).abs() < TEST_TOL
}

/// The planar rotation nearest to M in the Frobenius norm: the angle
/// maximising tr(R(θ)ᵀM) is θ = atan2(m₂₁ − m₁₂, m₁₁ + m₂₂) (the 2×2 case
/// of `ProjectToSO3`, in closed form; the identity when both are zero).
pub fn project_to_so2(m: &Mat2) -> Mat2 {
    so2::exp(so2::log(m))
}

/// `‖MᵀM − I‖_F` if det M > 0, else 1e9: the planar `DistanceToSO3`.
pub fn distance_to_so2(m: &Mat2) -> f64 {
    if m.determinant() > 0.0 {
        (m.transpose() * m - Mat2::identity()).norm()
    } else {
        FAR
    }
}

/// The planar `ProjectToSE3`: rotation block projected onto SO(2),
/// position kept, last row set to (0, 0, 1).
pub fn project_to_se2(m: &Mat3) -> Mat3 {
    let r = project_to_so2(&m.fixed_view::<2, 2>(0, 0).into_owned());
    let p = Vec2::new(m[(0, 2)], m[(1, 2)]);
    super::se2::from_rp(&r, &p)
}

/// The planar `DistanceToSE3`: `‖[RᵀR, 0; M₃,:] − I‖_F` if det R > 0, else
/// 1e9, with R the top-left 2×2 block.
pub fn distance_to_se2(m: &Mat3) -> f64 {
    let r = m.fixed_view::<2, 2>(0, 0).into_owned();
    if r.determinant() > 0.0 {
        let mut a = Mat3::zeros();
        a.fixed_view_mut::<2, 2>(0, 0)
            .copy_from(&(r.transpose() * r));
        a.set_row(2, &m.row(2));
        (a - Mat3::identity()).norm()
    } else {
        FAR
    }
}

/// The planar `TestIfSO3`: [`distance_to_so2`] below 1e-3.
pub fn test_if_so2(m: &Mat2) -> bool {
    distance_to_so2(m).abs() < TEST_TOL
}

/// The planar `TestIfSE3`: [`distance_to_se2`] below 1e-3.
pub fn test_if_se2(m: &Mat3) -> bool {
    distance_to_se2(m).abs() < TEST_TOL
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn project_fixes_reflection() {
        let m = Mat3::new(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -0.5);
        let r = project_to_so3(&m);
        assert!((r.determinant() - 1.0).abs() < 1e-14);
        assert!(distance_to_so3(&r) < 1e-14);
        assert_eq!(distance_to_so3(&m), FAR);
    }

    #[test]
    fn so2_projection() {
        let m = Mat2::new(0.9, -0.1, 0.2, 1.1);
        let r = project_to_so2(&m);
        assert!(test_if_so2(&r));
        // Nearest: no other angle does better.
        let best = (r - m).norm();
        for k in -20..=20 {
            let t = so2::log(&r) + k as f64 * 1e-3;
            assert!((so2::exp(t) - m).norm() >= best - 1e-15);
        }
        assert!(test_if_se2(&project_to_se2(&Mat3::new(
            0.9, -0.1, 1.0, 0.2, 1.1, 2.0, 0.1, 0.0, 0.8
        ))));
    }
}
