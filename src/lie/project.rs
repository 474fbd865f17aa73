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
///
/// For det M > 0 and M well conditioned, `U Vᵀ` is M's orthogonal polar
/// factor, found by Newton's iteration (`polar_newton`) instead of the
/// SVD: the same matrix to rounding, and an entry that is 0 in every
/// iterate (the zeros of a rotation about a coordinate axis, of a
/// block-diagonal M) stays exactly 0 where the SVD leaves a residue of
/// 1e-17.
pub fn project_to_so3(m: &Mat3) -> Mat3 {
    if let Some(r) = polar_newton(m) {
        return r;
    }
    let svd = m.svd(true, true);
    let (Some(mut u), Some(vt)) = (svd.u, svd.v_t) else {
        return Mat3::identity();
    };
    if (u * vt).determinant() < 0.0 {
        // (the last of equal smallest values: for −I, diag(−1, −1, 1),
        // modern_robotics' answer; any is as near, [`so3_tie`])
        let k = (0..3)
            .rev()
            .min_by(|&i, &j| svd.singular_values[i].total_cmp(&svd.singular_values[j]))
            .unwrap_or(2);
        let col = -u.column(k);
        u.set_column(k, &col);
    }
    u * vt
}

/// Why the rotation nearest M is not unique, when it is not.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tie {
    /// M = 0: every rotation is as near.
    Zero,
    /// σ₂ = σ₃ = 0 (rank 1): every rotation taking v₁ to u₁.
    RankOne {
        /// σ₁, the one nonzero singular value.
        sigma: f64,
    },
    /// det M < 0 and σ₂ = σ₃: the reflection is undone along any direction
    /// of their plane.
    Reflection {
        /// σ₂ = σ₃.
        sigma: f64,
    },
}

/// Whether [`project_to_so3`]'s answer is one of many equally near
/// rotations. With M = U Σ Vᵀ, σ₁ ≥ σ₂ ≥ σ₃ ≥ 0, and s = det(U Vᵀ) (the
/// sign of det M), the rotations maximising tr(RᵀM) are U W Vᵀ with W
/// maximising σ₁w₁₁ + σ₂w₂₂ + sσ₃w₃₃ over {W : det W = s}; the maximiser
/// W = diag(1, 1, s) is unique iff σ₂ + sσ₃ > 0 — ties are M = 0, rank one,
/// and det M < 0 with σ₂ = σ₃ (−I: every half turn).
/// Decided within 1e-12·σ₁, about the rounding of the singular values.
pub fn so3_tie(m: &Mat3) -> Option<Tie> {
    let svd = m.svd(true, true);
    let (Some(u), Some(vt)) = (svd.u, svd.v_t) else {
        return None;
    };
    let s = svd.singular_values;
    let tol = 1e-12 * s[0];
    if s[0] == 0.0 {
        return Some(Tie::Zero);
    }
    if s[1] + s[2] <= tol {
        return Some(Tie::RankOne { sigma: s[0] });
    }
    let reflected = (u * vt).determinant() < 0.0;
    (reflected && s[1] - s[2] <= tol).then_some(Tie::Reflection { sigma: s[1] })
}

/// The condition number ‖M‖_F‖M⁻¹‖_F above which [`polar_newton`] leaves
/// the projection to the SVD.
const POLAR_CONDITION: f64 = 1e6;

/// The orthogonal polar factor of M (det M > 0), by Newton's iteration
/// X ← ½(γX + γ⁻¹X⁻ᵀ) with Higham's scaling γ = (‖X⁻¹‖_F/‖X‖_F)^½,
/// unscaled once the steps are small (Higham, *Functions of Matrices*,
/// §8.6); it converges quadratically to U Vᵀ. None for det M ≤ 0, for M
/// worse conditioned than [`POLAR_CONDITION`], or for an iteration that
/// does not settle. The inverse of a 3×3 is its cofactors over the
/// determinant, so an entry 0 in X with the zero pattern of its cofactor is
/// 0 in every iterate.
fn polar_newton(m: &Mat3) -> Option<Mat3> {
    let det = m.determinant();
    // (a determinant of rounding size: a rank-deficient M, whose cofactor
    // inverse is rounding noise of moderate size — the condition test
    // below then passed, and a rank-1 M converged to a reflection. With
    // κ ≤ 1e6, det M = σ₁σ₂σ₃ ≥ 1e-12σ₁³ ≥ 1.9e-13‖M‖³.)
    let scale = m.norm().powi(3);
    if det.is_nan() || det <= 1e-14 * scale {
        return None;
    }
    let mut x = *m;
    let mut scaled = true;
    let mut last = false;
    for _ in 0..60 {
        let inv = x.try_inverse()?;
        let (nx, ni) = (x.norm(), inv.norm());
        let condition = nx * ni;
        if condition.is_nan() || condition > POLAR_CONDITION {
            return None;
        }
        let gamma = if scaled { (ni / nx).sqrt() } else { 1.0 };
        let next = (x * gamma + inv.transpose() / gamma) * 0.5;
        let step = (next - x).norm();
        x = next;
        if last {
            // (a rotation, or the SVD decides)
            let gap = (x.transpose() * x - Mat3::identity()).norm();
            return (gap < 1e-12 && x.determinant() > 0.0).then_some(x);
        }
        scaled = step >= 1e-3;
        // the error after a step of size s is about s²: one more step past
        // 1e-8 leaves only rounding
        last = step < 1e-8;
    }
    None
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

/// The book's distance from the group (§3.6, `DistanceToSO3`,
/// `DistanceToSE3` and their planar analogues) of the n×n matrix `m`
/// (column-major) whose rotation block is its top-left k×k block R:
/// ‖RᵀR − I‖_F, with, when n > k, the last row's difference from
/// (0, …, 0, 1). Each entry of RᵀR − I is summed with `−δᵢⱼ` as one
/// compensated sum ([`super::dot_compensated`]): near the group the plain
/// product cancels, and a distance of 1e-12 kept only five of its digits.
/// The sign of det R (a distance of [`FAR`]) is the caller's to decide.
pub fn gram_distance(m: &[f64], n: usize, k: usize) -> f64 {
    let at = |i: usize, j: usize| m[i + j * n];
    let mut off = Vec::with_capacity(k * k + n);
    for i in 0..k {
        for j in 0..k {
            let delta = if i == j { -1.0 } else { 0.0 };
            let terms = (0..k).map(|l| (at(l, i), at(l, j)));
            off.push(super::dot_compensated(terms.chain([(delta, 1.0)])));
        }
    }
    if n > k {
        for j in 0..n {
            off.push(at(n - 1, j) - if j == n - 1 { 1.0 } else { 0.0 });
        }
    }
    super::norm(&nalgebra::DVector::from_vec(off))
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
    use crate::lie::{Vec3, so3};

    #[test]
    fn project_fixes_reflection() {
        let m = Mat3::new(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -0.5);
        let r = project_to_so3(&m);
        assert!((r.determinant() - 1.0).abs() < 1e-14);
        assert!(distance_to_so3(&r) < 1e-14);
        assert_eq!(distance_to_so3(&m), FAR);
    }

    /// The SVD's U Vᵀ, as the book's software computes it.
    fn by_svd(m: &Mat3) -> Mat3 {
        let svd = m.svd(true, true);
        svd.u.unwrap() * svd.v_t.unwrap()
    }

    /// Newton's polar factor is the SVD's U Vᵀ to rounding, near SO(3)
    /// and far from it (scaled, sheared, badly conditioned up to the bound),
    /// and orthogonal to machine precision.
    #[test]
    fn polar_newton_agrees_with_the_svd() {
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let mut tried = 0;
        for k in 0..2000 {
            let noise = [1e-9, 1e-3, 0.3, 3.0][k % 4];
            let r = so3::exp(&Vec3::new(3.0 * next(), 3.0 * next(), 3.0 * next()));
            let e = Mat3::from_fn(|_, _| noise * next());
            let m = (r + e) * (1.0 + 5.0 * next().abs());
            let Some(p) = polar_newton(&m) else { continue };
            tried += 1;
            let q = by_svd(&m);
            assert!((p - q).norm() < 1e-13, "{m}: {p} vs {q}");
            assert!((p.transpose() * p - Mat3::identity()).norm() < 2e-15);
            assert!((p.determinant() - 1.0).abs() < 2e-15);
        }
        assert!(tried > 1500, "Newton took {tried} of 2000");
    }

    /// A scaled rotation about y keeps its four zeros exactly (the SVD
    /// left 1.9e-17 at [1, 2]: matrix differential seed 702232), and is
    /// returned to rounding; a matrix Newton refuses goes to the SVD.
    #[test]
    fn projection_keeps_structural_zeros() {
        let t = (9.34f64).sin();
        let (c, s) = (t.cos(), t.sin());
        let r = Mat3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c);
        let p = project_to_so3(&(r.transpose() * 3.46));
        for (i, j) in [(0, 1), (1, 0), (1, 2), (2, 1)] {
            assert_eq!(p[(i, j)], 0.0, "entry ({i}, {j})");
        }
        assert!((p - r.transpose()).norm() < 1e-15);
        // det < 0 and a nearly singular matrix: the SVD's answer
        let flat = Mat3::new(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1e-9);
        assert!(polar_newton(&flat).is_none());
        assert!((project_to_so3(&flat) - Mat3::identity()).norm() < 1e-15);
    }

    /// −I: the last of the equal singular values' columns is turned, as
    /// modern_robotics does; the answer is a half turn, as near as any.
    #[test]
    fn ties_are_found_and_answered_with_one_of_the_nearest() {
        let minus = -Mat3::identity();
        let r = project_to_so3(&minus);
        assert_eq!(r, Mat3::new(-1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0));
        assert_eq!(so3_tie(&minus), Some(Tie::Reflection { sigma: 1.0 }));
        assert_eq!(so3_tie(&Mat3::zeros()), Some(Tie::Zero));
        let rank_one = Mat3::new(0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        assert_eq!(so3_tie(&rank_one), Some(Tie::RankOne { sigma: 2.0 }));
        // A rank-1 M with det M = 4.7e-19 from rounding: Newton's
        // iteration on its noise gave a reflection (det −1).
        let m = Mat3::new(
            0.1366963853729478,
            0.8500276686476482,
            -1.1714031011733639,
            -0.02899153119641787,
            -0.18027984870398495,
            0.24843941160984825,
            0.01915951075732261,
            0.11914078208464096,
            -0.16418510450630905,
        );
        let r = project_to_so3(&m);
        assert!((r.determinant() - 1.0).abs() < 1e-14, "{r}");
        assert!(matches!(so3_tie(&m), Some(Tie::RankOne { .. })));
        // as near as the best: ‖R − M‖² = ‖M‖² + 3 − 2σ₁
        let best = m.norm_squared() + 3.0 - 2.0 * 1.5;
        assert!(((r - m).norm_squared() - best).abs() < 1e-13);
        // unique: a rank-2 matrix, a reflection with σ₂ > σ₃, a rotation
        for m in [
            Mat3::new(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0),
            Mat3::new(-1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, -0.999),
            Mat3::new(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -0.5),
            Mat3::identity(),
        ] {
            assert_eq!(so3_tie(&m), None, "{m}");
        }
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
