//! SE(3) and se(3): homogeneous transformations (§3.3.1), twists and the
//! adjoint representation (§3.3.2), screw axes (§3.3.2.2), exponential
//! coordinates of rigid-body motion (§3.3.3) and wrenches (§3.4).
//!
//! Twists and screw axes are ordered `(ω, v)`; wrenches `(m, f)` (3.97).

use super::{Mat3, Mat4, Mat6, Vec3, Vec6, near_zero, so3};

/// Below this angle the coefficients of (3.89) and (3.94) come from their
/// Taylor series (see [`exp`] and [`log`]).
pub(crate) const SERIES_THETA: f64 = 1e-2;

fn split(v: &Vec6) -> (Vec3, Vec3) {
    (Vec3::new(v[0], v[1], v[2]), Vec3::new(v[3], v[4], v[5]))
}

fn join(w: &Vec3, v: &Vec3) -> Vec6 {
    Vec6::new(w.x, w.y, w.z, v.x, v.y, v.z)
}

/// `VecTose3(V)`: the 4×4 matrix `[V] = [[ω], v; 0, 0] ∈ se(3)` of a twist
/// (or screw axis) `V = (ω, v)` (3.73, 3.86).
pub fn hat(v: &Vec6) -> Mat4 {
    let (w, lin) = split(v);
    let mut m = Mat4::zeros();
    m.fixed_view_mut::<3, 3>(0, 0).copy_from(&so3::hat(&w));
    m.fixed_view_mut::<3, 1>(0, 3).copy_from(&lin);
    m
}

/// `se3ToVec([V])`: the 6-vector twist `(ω, v)` of an se(3) matrix (inverse
/// of (3.73)); ω is read as in [`so3::vee`], v from the last column.
pub fn vee(m: &Mat4) -> Vec6 {
    let w = so3::vee(&m.fixed_view::<3, 3>(0, 0).into_owned());
    Vec6::new(w.x, w.y, w.z, m[(0, 3)], m[(1, 3)], m[(2, 3)])
}

/// `RpToTrans(R, p)`: the homogeneous transformation `T = [R, p; 0, 1]`
/// (Definition 3.4, (3.62)).
pub fn from_rp(r: &Mat3, p: &Vec3) -> Mat4 {
    let mut t = Mat4::identity();
    t.fixed_view_mut::<3, 3>(0, 0).copy_from(r);
    t.fixed_view_mut::<3, 1>(0, 3).copy_from(p);
    t
}

/// `Trans(p)`: the pure translation `[I, p; 0, 1]` (a convenience; §3.3.1).
pub fn trans(p: &Vec3) -> Mat4 {
    from_rp(&Mat3::identity(), p)
}

/// `TransToRp(T)`: the rotation `R` and position `p` of `T = [R, p; 0, 1]`.
pub fn to_rp(t: &Mat4) -> (Mat3, Vec3) {
    (
        t.fixed_view::<3, 3>(0, 0).into_owned(),
        t.fixed_view::<3, 1>(0, 3).into_owned(),
    )
}

/// `TransInv(T)`: `T⁻¹ = [Rᵀ, −Rᵀp; 0, 1]` (Proposition 3.10, (3.64)),
/// computed in this exact form rather than by a general matrix inverse.
pub fn inv(t: &Mat4) -> Mat4 {
    let (r, p) = to_rp(t);
    let rt = r.transpose();
    from_rp(&rt, &(-(rt * p)))
}

/// The coefficient `(θ−sinθ)/θ³ = (1 − sinθ/θ)/θ²` of (3.88)–(3.89) written
/// for exponential coordinates: `G(θ)v = ρ + ((1−cosθ)/θ²)[φ]ρ +
/// ((θ−sinθ)/θ³)[φ]²ρ` with φ = ω̂θ, ρ = vθ; `a` is sinθ/θ.
///
/// 1 − sinθ/θ cancels catastrophically for small θ, so below θ = 1e-2 it
/// comes from the series 1/6 − θ²/120 + θ⁴/5040 − θ⁶/362880 (truncation
/// < 1e-24); above, its absolute error ε/θ² is multiplied by
/// ‖[φ]²ρ‖ ≤ θ²‖ρ‖, i.e. costs only O(ε‖ρ‖).
pub(crate) fn g_coeff(theta: f64, a: f64) -> f64 {
    if theta < SERIES_THETA {
        let t2 = theta * theta;
        1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0 - t2 * t2 * t2 / 362_880.0
    } else {
        (1.0 - a) / (theta * theta)
    }
}

/// `MatrixExp6(Sθ)`: the homogeneous transformation `e^{[S]θ}` of
/// Proposition 3.16 from exponential coordinates `Sθ = (ω̂θ, vθ) ∈ ℝ⁶`:
/// `[e^{[ω̂]θ}, G(θ)v; 0, 1]` with `G(θ) = Iθ + (1−cosθ)[ω̂] +
/// (θ−sinθ)[ω̂]²` (3.88)–(3.89), and `[I, vθ; 0, 1]` when ω = 0 (3.90).
///
/// Evaluated without dividing by θ (see the private `g_coeff`), so the
/// pure-translation case (3.90) is the θ → 0 limit of the same formula and
/// small rotations keep full precision.
pub fn exp(expc: &Vec6) -> Mat4 {
    let (phi, rho) = split(expc);
    let theta = phi.norm();
    let (a, b, cos) = so3::coeffs(theta);
    let r = so3::exp_with(&phi, a, b, cos);
    let c = g_coeff(theta, a);
    let wr = phi.cross(&rho);
    let wwr = phi.cross(&wr);
    let p = rho + wr * b + wwr * c;
    from_rp(&r, &p)
}

/// The coefficient `(1 − (θ/2)cot(θ/2))/θ²` of `[φ]²p` in `θG⁻¹(θ)p`, i.e.
/// (3.94) multiplied by θ and written for φ = ω̂θ:
/// `θG⁻¹(θ)p = p − ½[φ]p + ((1/θ − ½cot(θ/2))/θ)[φ]²p`.
///
/// `sin` and `cos` are sinθ and cosθ as read from R by the SO(3) logarithm,
/// and cot(θ/2) comes from them by the half-angle identities, with no
/// trigonometric call: (1 + cosθ)/sinθ while cosθ > 0, where 1 + cosθ ≥ 1
/// and θ/sinθ is well conditioned (θ = atan2(sinθ, cosθ) moves with sinθ);
/// sinθ/(1 − cosθ) for θ ≥ π/2, where 1 − cosθ ≥ 1. (The second form alone
/// would cancel near θ = 0: 1 − cosθ ≈ θ²/2.)
///
/// 1 − (θ/2)cot(θ/2) ≈ θ²/12 itself cancels for small θ (relative error
/// ε/θ²), so below θ = 1e-2 the series 1/12 + θ²/720 + θ⁴/30240 +
/// θ⁶/1209600 is used (truncation < 1e-20). At θ = π, cot(π/2) = 0 and the
/// coefficient is 1/π²: no singularity on [0, π].
pub(crate) fn ginv_coeff(theta: f64, sin: f64, cos: f64) -> f64 {
    if theta < SERIES_THETA {
        let t2 = theta * theta;
        1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30_240.0 + t2 * t2 * t2 / 1_209_600.0
    } else {
        let half_cot = if cos > 0.0 {
            0.5 * (1.0 + cos) / sin
        } else {
            0.5 * sin / (1.0 - cos)
        };
        (1.0 - theta * half_cot) / (theta * theta)
    }
}

/// `MatrixLog6(T)`: the exponential coordinates `Sθ ∈ ℝ⁶`, θ ∈ [0, π], of
/// the matrix logarithm `[S]θ = log T` (algorithm of §3.3.3.2).
///
/// The three cases of the book are one formula here:
/// (i) R = I: ω = 0 and Sθ = (0, p), i.e. v = p/‖p‖, θ = ‖p‖;
/// (ii) tr R = −1: θ = π and ω̂ from the SO(3) logarithm, v = G⁻¹(π)p;
/// (iii) otherwise [ω̂]θ from the SO(3) logarithm and v = G⁻¹(θ)p (3.93).
/// The rotation part is [`so3::log`] (accurate at θ → 0 and θ → π), and
/// `vθ = θG⁻¹(θ)p = p − ½[φ]p + k(θ)[φ]²p` with φ = ω̂θ and
/// k(θ) = (1/θ − ½cot(θ/2))/θ from (3.94), by series for small θ. At
/// φ = 0 this is exactly case (i), so a nearly-identity rotation loses
/// nothing (the book's software rounds such rotations to zero).
pub fn log(t: &Mat4) -> Vec6 {
    log_from(t, so3::log_parts(&t.fixed_view::<3, 3>(0, 0)))
}

/// `MatrixLog6(T)` ([`log`]) with the branch of its rotation's logarithm
/// decided by the caller (θ = π or not, from T's exact form:
/// [`so3::log_decided`]).
pub fn log_decided(t: &Mat4, d: &so3::HalfTurn) -> Vec6 {
    log_from(t, so3::log_parts_with(&t.fixed_view::<3, 3>(0, 0), d))
}

/// [`log`] from the rotation block's logarithm.
#[inline]
fn log_from(t: &Mat4, parts: so3::LogParts) -> Vec6 {
    let p = Vec3::new(t[(0, 3)], t[(1, 3)], t[(2, 3)]);
    let so3::LogParts {
        phi,
        theta,
        sin,
        cos,
    } = parts;
    let wp = phi.cross(&p);
    let wwp = phi.cross(&wp);
    let v = p - 0.5 * wp + ginv_coeff(theta, sin, cos) * wwp;
    join(&phi, &v)
}

/// `Adjoint(T)`: the adjoint representation
/// `[Ad_T] = [R, 0; [p]R, R] ∈ ℝ⁶ˣ⁶` of `T = (R, p)` (Definition 3.6), so
/// that `[Ad_T]V` is the twist `V` in the other frame (Proposition 3.14).
///
/// Built column by column from T in place: column j of `[p]R` is p × rⱼ.
pub fn adjoint(t: &Mat4) -> Mat6 {
    let p = Vec3::new(t[(0, 3)], t[(1, 3)], t[(2, 3)]);
    let mut a = Mat6::zeros();
    for j in 0..3 {
        let rj = Vec3::new(t[(0, j)], t[(1, j)], t[(2, j)]);
        let prj = p.cross(&rj);
        for i in 0..3 {
            a[(i, j)] = rj[i];
            a[(i + 3, j + 3)] = rj[i];
            a[(i + 3, j)] = prj[i];
        }
    }
    a
}

/// `ad(V)`: the small adjoint `[ad_V] = [[ω], 0; [v], [ω]] ∈ ℝ⁶ˣ⁶` of a twist
/// `V = (ω, v)`, so that `[ad_V₁]V₂` is the Lie bracket `[V₁, V₂]` (the
/// derivative of `[Ad_T]` at the identity; the book's software `ad`).
pub fn ad(v: &Vec6) -> Mat6 {
    let (w, lin) = split(v);
    let wm = so3::hat(&w);
    let mut a = Mat6::zeros();
    a.fixed_view_mut::<3, 3>(0, 0).copy_from(&wm);
    a.fixed_view_mut::<3, 3>(3, 3).copy_from(&wm);
    a.fixed_view_mut::<3, 3>(3, 0).copy_from(&so3::hat(&lin));
    a
}

/// `ScrewToAxis(q, ŝ, h)`: the screw axis `S = (ŝ, −ŝ × q + hŝ)` of a screw
/// through the point `q` with unit direction `ŝ` and pitch `h`
/// (§3.3.2.2, Definition 3.7, §3.5 table). `ŝ` is used as given, like the
/// book's software: pass a unit vector to get a normalized axis. An
/// infinite pitch is a pure translation, `S = (0, ŝ)` (§3.3.2.2; q plays no
/// part), and `h = −∞` its limit `(0, −ŝ)` (the axis of pitch h → −∞,
/// normalized); a NaN pitch gives NaN entries.
pub fn screw_to_axis(q: &Vec3, s: &Vec3, h: f64) -> Vec6 {
    if h.is_infinite() {
        return join(&Vec3::zeros(), &(s * h.signum()));
    }
    let v = q.cross(s) + h * s;
    join(s, &v)
}

/// `AxisAng6(Sθ)`: splits exponential coordinates into the normalized screw
/// axis `S` and the distance θ travelled along it (§3.3.3.1, Definition
/// 3.7): θ = ‖ω‖, or θ = ‖v‖ when ω is near zero (`NearZero`, a pure
/// translation). The zero vector gives `(0, 0.0)`.
pub fn axis_angle(expc: &Vec6) -> (Vec6, f64) {
    let (w, v) = split(expc);
    let mut theta = super::norm(&w);
    // (a tiny rotation with no translation is still a rotation: θ = ‖ω‖)
    if near_zero(theta) && super::norm(&v) > 0.0 {
        theta = super::norm(&v);
    }
    if theta >= 1e-150 {
        (expc / theta, theta)
    } else if theta > 0.0 {
        // (scaled by the largest entry of the part whose norm θ is: a
        // quotient by a subnormal θ keeps only a few digits)
        let part = if theta == super::norm(&w) { w } else { v };
        let big = part.amax();
        (expc / big / super::norm(&(part / big)), theta)
    } else {
        (Vec6::zeros(), 0.0)
    }
}

/// The screw parameters `(q, ŝ, h)` of a twist or screw axis `V = (ω, v)`
/// (§3.3.2.2): `ŝ = ω/‖ω‖`, pitch `h = ŝᵀv/‖ω‖`, and `q = ω × v/‖ω‖²`, the
/// point of the axis nearest the origin (so that `v = −ω × q + hω`). For a
/// pure translation (ω = 0, the book's case: "if ω = 0 … the pitch is
/// infinite") `h = f64::INFINITY`, `q = 0`, `ŝ = v/‖v‖`. A small ω that is
/// not zero is a rotation about a far axis, not a translation: (1e-7, 0, 0,
/// 0, 0, 1) turns about x̂ through q = (0, −1e7, 0) with h = 0. The zero
/// twist gives `(0, 0, 0.0)`.
pub fn screw_params(v: &Vec6) -> (Vec3, Vec3, f64) {
    let (w, lin) = split(v);
    if w.iter().all(|x| *x == 0.0) {
        if super::norm(&lin) > 0.0 {
            (Vec3::zeros(), super::direction(&lin).0, f64::INFINITY)
        } else {
            (Vec3::zeros(), Vec3::zeros(), 0.0)
        }
    } else {
        // ω scaled by a power of two 2⁻ᵏ to a norm near 1 (exactly, so
        // that ‖ω‖² neither underflows nor overflows; q and h scale by
        // 2ᵏ back), and ω × v and ωᵀv with
        // their roundings kept: of a screw of large pitch, v is nearly
        // hŝ, and the plain products cancel to q with the digits of h
        // (h = 1e8 left q right to 1e-9 only).
        let k = w.amax().log2().floor() as i32;
        let w = scale2(&w, -k);
        let n2 = w.norm_squared();
        let cross = Vec3::new(
            diff_of_products(w.y, lin.z, w.z, lin.y),
            diff_of_products(w.z, lin.x, w.x, lin.z),
            diff_of_products(w.x, lin.y, w.y, lin.x),
        );
        let q = scale2(&(cross / n2), -k);
        let h = scale2(
            &Vec3::new(
                super::dot_compensated(w.iter().zip(lin.iter()).map(|(a, b)| (*a, *b))) / n2,
                0.0,
                0.0,
            ),
            -k,
        )
        .x;
        (q, w / n2.sqrt(), h)
    }
}

/// `v · 2^k`, exact unless it overflows or underflows (in two steps, so
/// that 2^k itself is never out of range).
fn scale2(v: &Vec3, k: i32) -> Vec3 {
    let half = k / 2;
    v * 2f64.powi(half) * 2f64.powi(k - half)
}

/// `ab − cd` to within an ulp or two (Kahan's algorithm with a fused
/// multiply-add: the rounding of `cd` is found exactly and put back).
fn diff_of_products(a: f64, b: f64, c: f64, d: f64) -> f64 {
    let cd = c * d;
    let err = (-c).mul_add(d, cd);
    a.mul_add(b, -cd) + err
}

/// The spatial and body twists `(V_s, V_b)` of a moving frame from `T` and
/// `Ṫ` (Proposition 3.15, §3.3.2): `[V_s] = ṪT⁻¹` (3.83) and
/// `[V_b] = T⁻¹Ṫ` (3.82). ω is read from the skew-symmetric part of the
/// rotation block ([`so3::vee_skew`]), exact for a consistent `(T, Ṫ)`.
pub fn twists_from_derivative(t: &Mat4, tdot: &Mat4) -> (Vec6, Vec6) {
    let ti = inv(t);
    let read = |m: Mat4| {
        let w = so3::vee_skew(&m.fixed_view::<3, 3>(0, 0).into_owned());
        Vec6::new(w.x, w.y, w.z, m[(0, 3)], m[(1, 3)], m[(2, 3)])
    };
    (read(tdot * ti), read(ti * tdot))
}

/// Change of frame of a wrench `F = (m, f)` (3.97): `F_b = [Ad_{T_ab}]ᵀ F_a`
/// (Proposition 3.17, (3.99)/(3.101)), from the power invariance
/// `V_bᵀF_b = V_aᵀF_a` (3.98).
pub fn wrench_change(t_ab: &Mat4, f_a: &Vec6) -> Vec6 {
    adjoint(t_ab).transpose() * f_a
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exp_pure_translation() {
        let t = exp(&Vec6::new(0.0, 0.0, 0.0, 1.0, 2.0, 3.0));
        assert_eq!(t, trans(&Vec3::new(1.0, 2.0, 3.0)));
    }

    #[test]
    fn log_identity_and_translation() {
        assert_eq!(log(&Mat4::identity()), Vec6::zeros());
        let s = log(&trans(&Vec3::new(1.0, -2.0, 0.5)));
        assert_eq!(s, Vec6::new(0.0, 0.0, 0.0, 1.0, -2.0, 0.5));
    }

    #[test]
    fn screw_params_cases() {
        let s = screw_to_axis(&Vec3::new(3.0, 0.0, 0.0), &Vec3::z(), 2.0);
        let (q, sh, h) = screw_params(&s);
        assert!((q - Vec3::new(3.0, 0.0, 0.0)).norm() < 1e-15);
        assert_eq!(sh, Vec3::z());
        assert_eq!(h, 2.0);
        let (q, sh, h) = screw_params(&Vec6::new(0.0, 0.0, 0.0, 0.0, 3.0, 4.0));
        assert_eq!(
            (q, sh, h),
            (Vec3::zeros(), Vec3::new(0.0, 0.6, 0.8), f64::INFINITY)
        );
        assert_eq!(
            screw_params(&Vec6::zeros()),
            (Vec3::zeros(), Vec3::zeros(), 0.0)
        );
    }

    #[test]
    fn ginv_series_matches_direct() {
        let t: f64 = SERIES_THETA;
        let h = 0.5 * t;
        let direct = (1.0 - h / h.tan()) / (t * t);
        let u = t * 0.999_999;
        assert!((ginv_coeff(u, u.sin(), u.cos()) - direct).abs() < 1e-12);
        let direct_c = (t - t.sin()) / (t * t * t);
        let s = t * 0.999_999;
        assert!((g_coeff(s, s.sin() / s) - direct_c).abs() < 1e-10);
    }

    /// Above the series, cot(θ/2) from (sinθ, cosθ) by either half-angle
    /// form, on both sides of the switch at θ = π/2, against
    /// (1 − (θ/2)cot(θ/2))/θ² evaluated at 40 digits (mpmath) for the same
    /// f64 θ. What is bounded is the error's share of v = θG⁻¹(θ)p relative
    /// to ‖p‖: the coefficient multiplies ‖[φ]²p‖ ≤ θ²‖p‖. (The coefficient
    /// alone, ≈ 1/12 after cancelling 1 − θ²/12, carries an error up to
    /// ε/θ² in any formula: 1.9e-14 at θ = 0.02, 7.7e-18 in v.)
    #[test]
    #[allow(clippy::excessive_precision)] // the reference digits as computed
    fn ginv_half_angle_forms_match_reference() {
        use std::f64::consts::{FRAC_PI_2, PI};
        let reference = [
            (0.02, 0.083_333_888_894_179_947_091),
            (0.3, 0.083_458_601_794_527_613_311),
            (0.7, 0.084_021_927_185_052_769_336),
            (1.0, 0.084_756_139_143_774_040_366),
            (FRAC_PI_2 - 1e-9, 0.086_974_848_380_632_710_993),
            (FRAC_PI_2, 0.086_974_848_385_560_413_936),
            (FRAC_PI_2 + 1e-9, 0.086_974_848_390_488_116_883),
            (2.0, 0.089_476_846_016_417_324_248),
            (2.8, 0.096_751_605_081_056_128_78),
            (3.1, 0.100_703_542_735_565_755_4),
            (PI - 1e-9, 0.101_321_183_627_263_365_68),
        ];
        for (t, want) in reference {
            let ours = ginv_coeff(t, t.sin(), t.cos());
            let in_v = (ours - want).abs() * t * t;
            assert!(in_v <= 2e-16, "θ = {t}: {ours} vs {want}");
        }
        let at_pi = ginv_coeff(PI, PI.sin(), PI.cos());
        assert!((at_pi - 1.0 / (PI * PI)).abs() < 1e-16);
    }
}
