//! SO(3) and so(3): rotation matrices (§3.2.1), angular velocities (§3.2.2),
//! and the exponential coordinates of rotation (§3.2.3): Rodrigues' formula
//! (3.51) and the matrix logarithm (§3.2.3.3).
//!
//! Accuracy: `exp(log(R))` reproduces `R` to a few units in the last place
//! for every rotation angle θ ∈ [0, π], including θ → 0 and θ → π, where the
//! book's formulas (3.54) and (3.61) lose all their digits. See [`log`].

use super::{Mat3, Vec3};
use nalgebra::{Matrix, U3, storage::Storage};

/// A 3×3 block of any nalgebra storage: a `Mat3`, or the rotation block of a
/// 4×4 transform viewed in place (`t.fixed_view::<3, 3>(0, 0)`).
pub(crate) type Block3<S> = Matrix<f64, U3, U3, S>;

/// Below this angle the coefficients sinθ/θ and (1−cosθ)/θ² of Rodrigues'
/// formula are evaluated by their Taylor series (truncation error < 1e-24).
pub(crate) const SERIES_THETA: f64 = 1e-4;

/// `VecToso3(ω)`: the 3×3 skew-symmetric matrix `[ω] ∈ so(3)` of
/// Definition 3.3 (3.30), so that `[ω] x = ω × x`.
pub fn hat(w: &Vec3) -> Mat3 {
    Mat3::new(0.0, -w.z, w.y, w.z, 0.0, -w.x, -w.y, w.x, 0.0)
}

/// `so3ToVec([ω])`: the 3-vector ω of a skew-symmetric matrix `[ω] ∈ so(3)`
/// (inverse of (3.30)); reads the entries `(m₃₂, m₁₃, m₂₁)` as the book's
/// software does.
pub fn vee(m: &Mat3) -> Vec3 {
    Vec3::new(m[(2, 1)], m[(0, 2)], m[(1, 0)])
}

/// The ω of the skew-symmetric part `(M − Mᵀ)/2` of a matrix: equal to
/// [`vee`] for an exact element of so(3), and the least-squares answer for a
/// matrix that is only nearly skew-symmetric (rounding, finite differences).
pub fn vee_skew(m: &Mat3) -> Vec3 {
    skew_part(m)
}

/// [`vee_skew`] of any 3×3 block (see [`Block3`]).
#[inline]
pub(crate) fn skew_part<S: Storage<f64, U3, U3>>(m: &Block3<S>) -> Vec3 {
    0.5 * Vec3::new(
        m[(2, 1)] - m[(1, 2)],
        m[(0, 2)] - m[(2, 0)],
        m[(1, 0)] - m[(0, 1)],
    )
}

/// The coefficients `(sinθ/θ, (1−cosθ)/θ²)` of Rodrigues' formula written
/// for exponential coordinates φ = ω̂θ: `e^{[φ]} = I + (sinθ/θ)[φ] +
/// ((1−cosθ)/θ²)[φ]²`, which is (3.51) with `[ω̂] = [φ]/θ`.
///
/// Both are evaluated stably: (1−cosθ) is computed as 2 sin²(θ/2), which has
/// no cancellation (1 − cosθ loses all digits below θ ≈ 1e-8), and for
/// θ < 1e-4 both come from their Taylor series
/// sinθ/θ = 1 − θ²/6 + θ⁴/120 and (1−cosθ)/θ² = 1/2 − θ²/24 + θ⁴/720,
/// so θ = 0 needs no special case.
pub fn rodrigues_coeffs(theta: f64) -> (f64, f64) {
    let (a, b, _) = coeffs(theta);
    (a, b)
}

/// `(sinθ/θ, (1−cosθ)/θ², cosθ)`: sinθ = 2 sin(θ/2)cos(θ/2) and
/// 1 − cosθ = 2 sin²(θ/2) from one sin/cos of θ/2 (relative accuracy of a
/// couple of ulps, also near 0 and π), and cosθ itself directly (the
/// diagonal of [`exp`] near π relies on its correct rounding). Series
/// below θ = 1e-4.
pub(crate) fn coeffs(theta: f64) -> (f64, f64, f64) {
    if theta < SERIES_THETA {
        let t2 = theta * theta;
        (
            1.0 - t2 / 6.0 * (1.0 - t2 / 20.0),
            0.5 - t2 / 24.0 * (1.0 - t2 / 30.0),
            1.0 - t2 / 2.0 * (1.0 - t2 / 12.0),
        )
    } else {
        let (sh, ch) = (0.5 * theta).sin_cos();
        let h = sh / theta;
        (2.0 * h * ch, 2.0 * h * h, theta.cos())
    }
}

/// `MatrixExp3(ω̂θ)`: the rotation `e^{[ω̂]θ} = I + sinθ[ω̂] + (1−cosθ)[ω̂]²`
/// of Rodrigues' formula (3.51, Proposition 3.9), from exponential
/// coordinates `ω̂θ ∈ ℝ³`. Zero coordinates give the identity.
///
/// Written entry by entry as (3.52) with φ = ω̂θ, a = sinθ/θ and
/// b = (1−cosθ)/θ² from [`rodrigues_coeffs`] (series for small θ):
/// off-diagonal `b φᵢφⱼ ∓ a φₖ`; diagonal either `1 − b(φⱼ² + φₖ²)` or the
/// equal `cosθ + b φᵢ²`, whichever adds the smaller correction term (its
/// rounding error is proportional to its size), which keeps the result
/// orthogonal to a couple of ulps even at θ → π.
pub fn exp(expc: &Vec3) -> Mat3 {
    let theta = super::norm(expc);
    if theta > 1e150 && theta.is_finite() {
        // (φᵢφⱼ would overflow: Rodrigues with the unit axis, 3.51)
        let (s, c) = theta.sin_cos();
        let w = hat(&(expc / theta));
        return Mat3::identity() + s * w + (1.0 - c) * w * w;
    }
    let (a, b, c) = coeffs(theta);
    exp_with(expc, a, b, c)
}

/// [`exp`] with the coefficients of [`coeffs`] already computed (shared
/// with the SE(3) exponential).
pub(crate) fn exp_with(expc: &Vec3, a: f64, b: f64, c: f64) -> Mat3 {
    let (x, y, z) = (expc.x, expc.y, expc.z);
    let (xx, yy, zz) = (x * x, y * y, z * z);
    let diag = |ii: f64, rest: f64| {
        if ii <= rest {
            c + b * ii
        } else {
            1.0 - b * rest
        }
    };
    let (bxy, bxz, byz) = (b * x * y, b * x * z, b * y * z);
    let (ax, ay, az) = (a * x, a * y, a * z);
    Mat3::new(
        diag(xx, yy + zz),
        bxy - az,
        bxz + ay,
        bxy + az,
        diag(yy, xx + zz),
        byz - ax,
        bxz - ay,
        byz + ax,
        diag(zz, xx + yy),
    )
}

/// `MatrixLog3(R)`: the exponential coordinates `ω̂θ ∈ ℝ³`, θ ∈ [0, π], of
/// the matrix logarithm `[ω̂]θ = log R` (algorithm of §3.2.3.3). The identity
/// gives the zero vector (case (i): ω̂ undefined, θ = 0). At θ = π (case
/// (ii)) both ±ω̂π are logarithms; one of them is returned, consistently.
///
/// Why not the book's formulas verbatim: θ = cos⁻¹((tr R − 1)/2) (3.54) has
/// an infinite derivative at θ = 0 and θ = π, so an O(ε) rounding error in
/// tr R becomes an O(√ε) ≈ 1e-8 error in θ; and [ω̂] = (R − Rᵀ)/(2 sinθ)
/// (3.61) divides a vanishing O(sinθ) quantity by sinθ near π, so the axis
/// error grows like ε/sinθ. Instead:
///
/// * θ = atan2(‖vee(R − Rᵀ)‖/2, (tr R − 1)/2), i.e. atan2(sinθ, cosθ) from
///   (3.54) and the skew part of (3.52): accurate to O(ε) everywhere.
/// * For θ < π/2 (cosθ > 0) the axis comes from the skew part as in (3.61):
///   ω̂θ = vee(R − Rᵀ)/2 · θ/sinθ, with θ/sinθ by its series
///   1 + θ²/6 + 7θ⁴/360 for tiny θ, so θ → 0 needs no special case.
/// * For θ ≥ π/2 the axis comes from the symmetric part: by (3.52),
///   (R + Rᵀ)/2 − cosθ·I = (1 − cosθ) ω̂ω̂ᵀ, whose column with the largest
///   diagonal entry is the best-conditioned multiple of ω̂ (this generalises
///   the book's case (ii), (3.58)–(3.60), to all θ near π). Its sign is
///   fixed by the skew part (sinθ ω̂ = vee(R − Rᵀ)/2); at θ = π, where the
///   skew part is rounding noise and fixes no sign, ±ω̂ are both valid and
///   the sign is the one the book's formulas give, tried in its order: (3.58)
///   (ω̂₃ > 0) unless 1 + r₃₃ is near zero, then (3.59) (ω̂₂ > 0), then (3.60)
///   (ω̂₁ > 0) — so the axis agrees with the book and its library
///   ([`is_half_turn`] tells a caller to say so).
pub fn log(r: &Mat3) -> Vec3 {
    log_parts(r).phi
}

/// What [`log`] computes on the way to ω̂θ, kept for callers that need the
/// angle's sine and cosine too (the SE(3) logarithm's G⁻¹, (3.94)).
#[derive(Clone, Copy, Debug)]
pub(crate) struct LogParts {
    /// The exponential coordinates ω̂θ.
    pub phi: Vec3,
    /// θ ∈ [0, π].
    pub theta: f64,
    /// sinθ, read from the skew part of R: ‖vee(R − Rᵀ)‖/2.
    pub sin: f64,
    /// cosθ = (tr R − 1)/2 (3.54).
    pub cos: f64,
}

/// The body of [`log`]; see there for the formulation.
///
/// Generic over the storage so that the SE(3) logarithm reads the rotation
/// block of T in place: copying it into a temporary `Mat3` first costs
/// ~25 ns per call in store-forwarding stalls (measured), more than the
/// arithmetic.
#[inline]
pub(crate) fn log_parts<S: Storage<f64, U3, U3>>(r: &Block3<S>) -> LogParts {
    let s_vec = skew_part(r); // = sinθ · ω̂
    let c = 0.5 * (r.trace() - 1.0); // = cosθ (3.54)
    let half_turn = s_vec.norm() <= HALF_TURN_SKEW;
    log_parts_with(
        r,
        &HalfTurn {
            skew: s_vec,
            cos: c,
            half_turn,
        },
    )
}

/// What decides the branch of the logarithm of a rotation R (§3.2.3.3):
/// sinθ ω̂ = vee(R − Rᵀ)/2, cosθ = (tr R − 1)/2 (3.54), and whether θ = π
/// (case (ii): tr R = −1). [`log`] reads them from R's floats; a caller
/// that knows R exactly decides them exactly ([`log_decided`]): a skew
/// part of exactly −1e-20 is 0 in floats, yet fixes ω̂'s sign.
#[derive(Clone, Copy, Debug)]
pub struct HalfTurn {
    /// sinθ ω̂ = vee(R − Rᵀ)/2 (0 at a half turn).
    pub skew: Vec3,
    /// cosθ = (tr R − 1)/2 (3.54).
    pub cos: f64,
    /// θ = π: tr R = −1, ω̂ from (3.58)–(3.60) with the book's sign.
    pub half_turn: bool,
}

/// `MatrixLog3(R)` ([`log`]) with its branch decided by the caller: the
/// skew part, cosθ and whether θ = π given in `d` (from R's exact form).
pub fn log_decided(r: &Mat3, d: &HalfTurn) -> Vec3 {
    log_parts_with(r, d).phi
}

/// The body of [`log_parts`] with the branch given.
#[inline]
pub(crate) fn log_parts_with<S: Storage<f64, U3, U3>>(r: &Block3<S>, d: &HalfTurn) -> LogParts {
    let (s_vec, c) = (d.skew, d.cos);
    let s = s_vec.norm();
    let theta = s.atan2(c);
    let phi = if c > 0.0 {
        // θ ∈ [0, π/2): skew part, (3.61).
        let k = if theta < SERIES_THETA {
            let t2 = theta * theta;
            1.0 + t2 / 6.0 + 7.0 * t2 * t2 / 360.0
        } else {
            theta / s
        };
        s_vec * k
    } else {
        // θ ∈ [π/2, π]: symmetric part, generalising (3.58)–(3.60).
        near_pi_axis(r, c, &s_vec, d.half_turn) * theta
    };
    LogParts {
        phi,
        theta,
        sin: s,
        cos: c,
    }
}

/// Below this, the skew part ‖vee(R − Rᵀ)‖/2 = sinθ of a rotation with
/// cosθ < 0 is rounding noise: θ = π, and ω̂ and −ω̂ give the same R (their
/// exponentials differ by about 2 sinθ ≤ 1e-15).
pub const HALF_TURN_SKEW: f64 = 4.0 * f64::EPSILON;

/// The book library's `NearZero` tolerance, used to pick among (3.58)–(3.60).
const BOOK_NEAR_ZERO: f64 = 1e-6;

/// Whether R is a half turn (θ = π within rounding), where the log's axis
/// is one of two equally valid answers ±ω̂ (§3.2.3.3, case (ii)).
pub fn is_half_turn(r: &Mat3) -> bool {
    let c = 0.5 * (r.trace() - 1.0);
    c < 0.0 && skew_part(r).norm() <= HALF_TURN_SKEW
}

/// The sign of ±ω̂ that the book's formulas give at θ = π, in its order:
/// (3.58) ω̂ = (r₁₃, r₂₃, 1 + r₃₃)/√(2(1 + r₃₃)) has ω̂₃ > 0 unless 1 + r₃₃
/// is near zero; then (3.59) with ω̂₂ > 0; else (3.60) with ω̂₁ > 0.
fn book_sign<S: Storage<f64, U3, U3>>(r: &Block3<S>, w: Vec3) -> Vec3 {
    let k = if 1.0 + r[(2, 2)] >= BOOK_NEAR_ZERO {
        2
    } else if 1.0 + r[(1, 1)] >= BOOK_NEAR_ZERO {
        1
    } else {
        0
    };
    if w[k] < 0.0 { -w } else { w }
}

/// The unit axis ω̂ of a rotation with cosθ = `c` ≤ 0, from the symmetric
/// part (R + Rᵀ)/2 − cosθ·I = (1 − cosθ) ω̂ω̂ᵀ (3.52): its column with the
/// largest diagonal entry, signed to agree with `s_vec` = sinθ ω̂, or the
/// book's sign at a half turn. Zero for input that is not a rotation (e.g.
/// NaN entries).
pub(crate) fn near_pi_axis<S: Storage<f64, U3, U3>>(
    r: &Block3<S>,
    c: f64,
    s_vec: &Vec3,
    half_turn: bool,
) -> Vec3 {
    let d = [r[(0, 0)] - c, r[(1, 1)] - c, r[(2, 2)] - c];
    // The largest diagonal entry; on a tie the later one.
    let k = if d[2] >= d[1] && d[2] >= d[0] {
        2
    } else if d[1] >= d[0] {
        1
    } else {
        0
    };
    let sym = |i: usize| {
        if i == k {
            d[k]
        } else {
            0.5 * (r[(i, k)] + r[(k, i)])
        }
    };
    let col = Vec3::new(sym(0), sym(1), sym(2));
    let n = col.norm();
    if n.is_nan() || n == 0.0 {
        return Vec3::zeros();
    }
    let w = col / n;
    if half_turn {
        return book_sign(r, w);
    }
    if w.dot(s_vec) < 0.0 { -w } else { w }
}

/// `AxisAng3(ω̂θ)`: splits exponential coordinates into the unit rotation
/// axis ω̂ and the angle θ = ‖ω̂θ‖ (§3.2.3.2). The zero vector gives
/// `(0, 0.0)`: the axis is undefined for θ = 0 (case (i) of §3.2.3.3).
pub fn axis_angle(expc: &Vec3) -> (Vec3, f64) {
    if super::norm(expc) > 0.0 {
        super::direction(expc)
    } else {
        (Vec3::zeros(), 0.0)
    }
}

/// `RotInv(R)`: the inverse of a rotation, `R⁻¹ = Rᵀ` (Proposition 3.1).
pub fn inv(r: &Mat3) -> Mat3 {
    r.transpose()
}

/// `Rot(ω̂, θ) = e^{[ω̂]θ}` (3.51): the rotation by θ about `axis`, which is
/// normalized here. A zero (or non-finite) axis gives the identity.
pub fn rot(axis: &Vec3, theta: f64) -> Mat3 {
    let n = super::norm(axis);
    if n > 0.0 && n.is_finite() {
        exp(&(axis * (theta / n)))
    } else {
        Mat3::identity()
    }
}

/// `Rot(x̂, θ)`: rotation by θ about the x-axis (§3.2.1.2).
pub fn rotx(theta: f64) -> Mat3 {
    let (s, c) = theta.sin_cos();
    Mat3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c)
}

/// `Rot(ŷ, θ)`: rotation by θ about the y-axis (§3.2.1.2).
pub fn roty(theta: f64) -> Mat3 {
    let (s, c) = theta.sin_cos();
    Mat3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c)
}

/// `Rot(ẑ, θ)`: rotation by θ about the z-axis (§3.2.1.2).
pub fn rotz(theta: f64) -> Mat3 {
    let (s, c) = theta.sin_cos();
    Mat3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0)
}

/// The spatial and body angular velocities `(ω_s, ω_b)` of a rotating frame
/// from `R` and `Ṙ` (§3.2.2, Proposition 3.6): `[ω_s] = ṘR⁻¹ = ṘRᵀ` (3.37)
/// and `[ω_b] = R⁻¹Ṙ = RᵀṘ` (3.38). The vectors are read from the
/// skew-symmetric parts ([`vee_skew`]), exact for a consistent `(R, Ṙ)`.
pub fn angular_velocities(r: &Mat3, rdot: &Mat3) -> (Vec3, Vec3) {
    let ws = vee_skew(&(rdot * r.transpose()));
    let wb = vee_skew(&(r.transpose() * rdot));
    (ws, wb)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: &Mat3, b: &Mat3, tol: f64) -> bool {
        (a - b).amax() <= tol
    }

    #[test]
    fn hat_vee_book_example() {
        let m = hat(&Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(m, Mat3::new(0.0, -3.0, 2.0, 3.0, 0.0, -1.0, -2.0, 1.0, 0.0));
        assert_eq!(vee(&m), Vec3::new(1.0, 2.0, 3.0));
    }

    #[test]
    fn exp_zero_and_pi() {
        assert_eq!(exp(&Vec3::zeros()), Mat3::identity());
        let r = exp(&Vec3::new(std::f64::consts::PI, 0.0, 0.0));
        assert!(close(
            &r,
            &Mat3::new(1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0),
            1e-15
        ));
    }

    #[test]
    fn log_identity_is_zero() {
        assert_eq!(log(&Mat3::identity()), Vec3::zeros());
    }

    #[test]
    fn log_at_pi_on_axes() {
        let pi = std::f64::consts::PI;
        for r in [rotx(pi), roty(pi), rotz(pi)] {
            let w = log(&r);
            assert!((w.norm() - pi).abs() < 1e-15);
            assert!(close(&exp(&w), &r, 2e-15));
        }
    }

    /// At θ = π the axis is the book's: (3.58) when 1 + r₃₃ ≠ 0, so
    /// ω̂₃ > 0, whichever sign the rounding of R would suggest.
    #[test]
    fn half_turn_follows_the_book_order() {
        let pi = std::f64::consts::PI;
        let w = Vec3::new(0.8, 0.0, -0.6);
        let r = rot(&w, pi);
        assert!(is_half_turn(&r));
        let l = log(&r);
        assert!((l / pi - (-w)).norm() < 1e-15, "{l}");
        // 1 + r₃₃ = 0: (3.59), ω̂₂ > 0.
        let w = Vec3::new(0.6, -0.8, 0.0);
        let l = log(&rot(&w, pi));
        assert!((l / pi - (-w)).norm() < 1e-15, "{l}");
        // Away from π the skew part decides: no flip.
        let r = rot(&Vec3::new(0.8, 0.0, -0.6), pi - 1e-9);
        assert!(!is_half_turn(&r));
        assert!((log(&r) - Vec3::new(0.8, 0.0, -0.6) * (pi - 1e-9)).norm() < 1e-14);
    }

    #[test]
    fn axis_angle_zero() {
        assert_eq!(axis_angle(&Vec3::zeros()), (Vec3::zeros(), 0.0));
    }

    #[test]
    fn rot_matches_rotx() {
        let r = rot(&Vec3::new(2.0, 0.0, 0.0), 0.7);
        assert!(close(&r, &rotx(0.7), 1e-15));
        assert_eq!(rot(&Vec3::zeros(), 1.0), Mat3::identity());
    }
}
