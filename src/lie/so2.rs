//! SO(2) and so(2): planar rotations (Definition 3.2, §3.1), their Lie
//! algebra of 2×2 skew-symmetric matrices, exponential and logarithm.

use super::Mat2;
use std::f64::consts::PI;

/// Maps an angle from `atan2`'s [−π, π] onto (−π, π] (−π becomes π) and
/// turns −0 into +0.
pub(crate) fn wrap_pi(a: f64) -> f64 {
    if a <= -PI { PI } else { a + 0.0 }
}

/// `[ω] = [0, −ω; ω, 0] ∈ so(2)`: the planar angular velocity as a 2×2
/// skew-symmetric matrix (the planar case of (3.30)).
pub fn hat(w: f64) -> Mat2 {
    Mat2::new(0.0, -w, w, 0.0)
}

/// The scalar ω of a 2×2 skew-symmetric matrix `[ω] ∈ so(2)` (entry m₂₁).
pub fn vee(m: &Mat2) -> f64 {
    m[(1, 0)]
}

/// The planar rotation `e^{[θ]} = [cosθ, −sinθ; sinθ, cosθ] ∈ SO(2)`
/// (§3.1, Definition 3.2).
pub fn exp(theta: f64) -> Mat2 {
    let (s, c) = theta.sin_cos();
    Mat2::new(c, -s, s, c)
}

/// The logarithm of a planar rotation: the angle θ ∈ (−π, π] with
/// `R = e^{[θ]}`, computed as `atan2(r₂₁ − r₁₂, r₁₁ + r₂₂)` (all four
/// entries, so a slightly non-orthogonal R gives its nearest angle).
pub fn log(r: &Mat2) -> f64 {
    wrap_pi((r[(1, 0)] - r[(0, 1)]).atan2(r[(0, 0)] + r[(1, 1)]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exp_log_round_trip_and_range() {
        for &t in &[0.0, 1e-12, 0.5, -2.0, PI - 1e-9, PI, -PI] {
            let back = log(&exp(t));
            let want = if t == -PI { PI } else { t };
            assert!((back - want).abs() <= 4e-16 * want.abs().max(1.0), "{t}");
        }
        assert_eq!(vee(&hat(0.3)), 0.3);
    }
}
