//! Other representations of orientation (§3.2.1.3; the book's Appendix B,
//! not in the seed — conventions as fixed in LANGUAGE.md §8): ZYX and ZXZ
//! Euler angles, roll–pitch–yaw, unit quaternions and Cayley–Rodrigues
//! parameters.
//!
//! The extractions never return NaN: at a singularity (gimbal lock) they
//! return a valid set of angles and say in [`Angles::note`] which angle was
//! chosen.

use super::so2::wrap_pi;
use super::so3::{hat, rotx, rotz};
use super::{Mat3, Vec3, Vec4};

/// Below this `cos b` (ZYX) or `sin b` (ZXZ) the first and third axes are
/// treated as aligned (gimbal lock). It is at the rounding-noise level
/// (cos(π/2) = 6e-17 in f64): at gimbal lock the split of the rotation
/// between a and c is arbitrary and setting c = 0 loses at most this much,
/// while just above it the regular formulas (through `R' = Rz(−a)R`) are
/// still accurate to a few ulps.
const GIMBAL_TOL: f64 = 1e-15;

/// Below this quaternion w = cos(θ/2) the Cayley parameters ω̂ tan(θ/2) are
/// treated as infinite (θ ≈ π).
const CAYLEY_TOL: f64 = 1e-9;

/// Euler-type angles extracted from a rotation, with a note when the
/// extraction was singular.
#[derive(Debug, Clone, PartialEq)]
pub struct Angles {
    /// The three angles, in the order of the function that produced them.
    pub angles: Vec3,
    /// At gimbal lock, which angle was chosen (set to zero) and why;
    /// `None` otherwise.
    pub note: Option<String>,
}

/// ZYX Euler angles: `R = Rot(ẑ, a) Rot(ŷ, b) Rot(x̂, c)` (rotations about
/// the body axes z, then y, then x).
pub fn rot_zyx(a: f64, b: f64, c: f64) -> Mat3 {
    rotz(a) * super::so3::roty(b) * rotx(c)
}

/// The ZYX Euler angles `(a, b, c)` of a rotation, `R = Rz(a) Ry(b) Rx(c)`,
/// with b ∈ [−π/2, π/2] and a, c ∈ (−π, π].
///
/// a = atan2(r₂₁, r₁₁); then `R' = Rz(−a) R = Ry(b) Rx(c)` gives
/// b = atan2(−r'₃₁, r'₁₁) and c = atan2(−r'₂₃, r'₂₂), which stay well
/// conditioned even when cos b is small. At gimbal lock (cos b ≈ 0, b = ±π/2) only
/// a ∓ c is defined: c is set to 0 and a carries the whole rotation about z,
/// as the note says.
pub fn euler_zyx(r: &Mat3) -> Angles {
    euler_zyx_decided(r, r[(0, 0)].hypot(r[(1, 0)]) < GIMBAL_TOL)
}

/// [`euler_zyx`] with gimbal lock (cos b = 0: r₁₁ = r₂₁ = 0) decided by
/// the caller, from R's exact form or certified entries: cos b = 1e-20 is
/// below the floats' tolerance, and yet no gimbal lock.
pub fn euler_zyx_decided(r: &Mat3, gimbal: bool) -> Angles {
    let a = if gimbal {
        (-r[(0, 1)]).atan2(r[(1, 1)])
    } else {
        r[(1, 0)].atan2(r[(0, 0)])
    };
    let rp = rotz(-a) * r; // = Ry(b) Rx(c)
    let b = (-rp[(2, 0)]).atan2(rp[(0, 0)].max(0.0));
    let (c, note) = if gimbal {
        (
            0.0,
            Some(format!(
                "gimbal lock (b = {}π/2): the first and third axes coincide; \
                 c set to 0, a carries the rotation",
                if b > 0.0 { "" } else { "−" }
            )),
        )
    } else {
        ((-rp[(1, 2)]).atan2(rp[(1, 1)]), None)
    };
    Angles {
        angles: Vec3::new(wrap_pi(a), b + 0.0, wrap_pi(c)),
        note,
    }
}

/// ZXZ Euler angles: `R = Rot(ẑ, a) Rot(x̂, b) Rot(ẑ, c)`.
pub fn rot_zxz(a: f64, b: f64, c: f64) -> Mat3 {
    rotz(a) * rotx(b) * rotz(c)
}

/// The ZXZ Euler angles `(a, b, c)` of a rotation, `R = Rz(a) Rx(b) Rz(c)`,
/// with b ∈ [0, π] and a, c ∈ (−π, π].
///
/// a = atan2(r₁₃, −r₂₃) (sin b ≥ 0); then `R' = Rz(−a) R = Rx(b) Rz(c)`
/// gives b and c. At gimbal lock (sin b ≈ 0: b = 0 or π) only a ± c is
/// defined: c is set to 0 and a carries the rotation, as the note says.
pub fn euler_zxz(r: &Mat3) -> Angles {
    euler_zxz_decided(r, r[(0, 2)].hypot(r[(1, 2)]) < GIMBAL_TOL)
}

/// [`euler_zxz`] with gimbal lock (sin b = 0: r₁₃ = r₂₃ = 0) decided by
/// the caller (see [`euler_zyx_decided`]).
pub fn euler_zxz_decided(r: &Mat3, gimbal: bool) -> Angles {
    let a = if gimbal {
        r[(1, 0)].atan2(r[(0, 0)])
    } else {
        r[(0, 2)].atan2(-r[(1, 2)])
    };
    let rp = rotz(-a) * r; // = Rx(b) Rz(c)
    let b = (-rp[(1, 2)]).max(0.0).atan2(rp[(2, 2)]);
    let (c, note) = if gimbal {
        (
            0.0,
            Some(format!(
                "gimbal lock (b = {}): the first and third axes coincide; \
                 c set to 0, a carries the rotation",
                if b > 1.0 { "π" } else { "0" }
            )),
        )
    } else {
        ((-rp[(0, 1)]).atan2(rp[(0, 0)]), None)
    };
    Angles {
        angles: Vec3::new(wrap_pi(a), b, wrap_pi(c)),
        note,
    }
}

/// Roll–pitch–yaw: `R = Rot(ẑ, yaw) Rot(ŷ, pitch) Rot(x̂, roll)` (the ZYX
/// Euler angles in reverse order: roll about x first in the fixed frame).
pub fn rot_rpy(roll: f64, pitch: f64, yaw: f64) -> Mat3 {
    rot_zyx(yaw, pitch, roll)
}

/// The roll–pitch–yaw angles `(roll, pitch, yaw)` of a rotation with
/// pitch ∈ [−π/2, π/2] and roll, yaw ∈ (−π, π]; see [`euler_zyx`]. At
/// gimbal lock (pitch = ±π/2) roll is set to 0 and yaw carries the rotation.
pub fn rpy(r: &Mat3) -> Angles {
    rpy_of(euler_zyx(r))
}

/// [`rpy`] with gimbal lock (pitch = ±π/2) decided by the caller (see
/// [`euler_zyx_decided`]).
pub fn rpy_decided(r: &Mat3, gimbal: bool) -> Angles {
    rpy_of(euler_zyx_decided(r, gimbal))
}

/// Roll–pitch–yaw from the ZYX angles.
fn rpy_of(e: Angles) -> Angles {
    let note = e.note.map(|_| {
        format!(
            "gimbal lock (pitch = {}π/2): roll and yaw axes coincide; \
             roll set to 0, yaw carries the rotation",
            if e.angles.y > 0.0 { "" } else { "−" }
        )
    });
    Angles {
        angles: Vec3::new(e.angles.z, e.angles.y, e.angles.x),
        note,
    }
}

/// The unit quaternion `q = (w, x, y, z) = (cos(θ/2), ω̂ sin(θ/2))` of a
/// rotation `R = Rot(ω̂, θ)`, with w ≥ 0.
///
/// Shepperd's method: of the four quantities 4w² = 1 + tr R and
/// 4x² = 1 + r₁₁ − r₂₂ − r₃₃ (etc.), the largest is square-rooted and the
/// other components come from sums and differences of off-diagonal entries
/// divided by it, so no component is found from a small square root.
pub fn quat(r: &Mat3) -> Vec4 {
    let (r00, r11, r22) = (r[(0, 0)], r[(1, 1)], r[(2, 2)]);
    let tr = r00 + r11 + r22;
    let cands = [tr, r00, r11, r22];
    let k = (0..4)
        .max_by(|&i, &j| cands[i].total_cmp(&cands[j]))
        .unwrap_or(0);
    let d = |i: usize, j: usize| r[(i, j)] - r[(j, i)];
    let s = |i: usize, j: usize| r[(i, j)] + r[(j, i)];
    let q = match k {
        0 => {
            let t = (1.0 + tr).max(0.0).sqrt() * 2.0; // 4w
            Vec4::new(0.25 * t, d(2, 1) / t, d(0, 2) / t, d(1, 0) / t)
        }
        1 => {
            let t = (1.0 + r00 - r11 - r22).max(0.0).sqrt() * 2.0; // 4x
            Vec4::new(d(2, 1) / t, 0.25 * t, s(0, 1) / t, s(0, 2) / t)
        }
        2 => {
            let t = (1.0 - r00 + r11 - r22).max(0.0).sqrt() * 2.0; // 4y
            Vec4::new(d(0, 2) / t, s(0, 1) / t, 0.25 * t, s(1, 2) / t)
        }
        _ => {
            let t = (1.0 - r00 - r11 + r22).max(0.0).sqrt() * 2.0; // 4z
            Vec4::new(d(1, 0) / t, s(0, 2) / t, s(1, 2) / t, 0.25 * t)
        }
    };
    let n = q.norm();
    if !(n > 0.0 && n.is_finite()) {
        return Vec4::new(1.0, 0.0, 0.0, 0.0); // not a rotation (NaN input)
    }
    let q = q / n;
    if q.x < 0.0 { -q } else { q }
}

/// The rotation of a quaternion `(w, x, y, z)`, normalized first:
/// `R = I + 2w[v] + 2[v]²` with v = (x, y, z), i.e. `Rot(ω̂, θ)` for
/// q = (cos(θ/2), ω̂ sin(θ/2)). `None` for a zero (or non-finite) q.
pub fn rot_quat(q: &Vec4) -> Option<Mat3> {
    let n = super::norm(q);
    if !(n > 0.0 && n.is_finite()) {
        return None;
    }
    // (by the largest entry first: a subnormal q keeps its digits)
    let q = q / q.amax();
    let q = q / super::norm(&q);
    let v = Vec3::new(q.y, q.z, q.w);
    let vm = hat(&v);
    Some(Mat3::identity() + 2.0 * q.x * vm + 2.0 * vm * vm)
}

/// The Hamilton product `q ⊗ p = (q_w p_w − q_v·p_v, q_w p_v + p_w q_v +
/// q_v × p_v)`, so that `rot_quat(q ⊗ p) = rot_quat(q) · rot_quat(p)`.
pub fn quat_mul(q: &Vec4, p: &Vec4) -> Vec4 {
    let (qw, pw) = (q.x, p.x);
    let qv = Vec3::new(q.y, q.z, q.w);
    let pv = Vec3::new(p.y, p.z, p.w);
    let w = qw * pw - qv.dot(&pv);
    let v = qw * pv + pw * qv + qv.cross(&pv);
    Vec4::new(w, v.x, v.y, v.z)
}

/// The Cayley–Rodrigues parameters `r = ω̂ tan(θ/2)` of a rotation
/// `Rot(ω̂, θ)`, computed as v/w from [`quat`]. An error at θ ≈ π
/// (cos(θ/2) < 1e-9), where the parameters are infinite.
pub fn cayley(r: &Mat3) -> Result<Vec3, String> {
    let q = quat(r);
    if q.x < CAYLEY_TOL {
        return Err(
            "Cayley parameters ω̂·tan(θ/2) are infinite for a rotation by θ = π \
             (this rotation is within 2e-9 of θ = π)"
                .to_string(),
        );
    }
    Ok(Vec3::new(q.y, q.z, q.w) / q.x)
}

/// The rotation of Cayley–Rodrigues parameters r = ω̂ tan(θ/2):
/// `R = I + 2([r] + [r]²)/(1 + rᵀr)` (the Cayley transform
/// `(I + [r])(I − [r])⁻¹`); any r ∈ ℝ³ gives a rotation with θ < π.
pub fn rot_cayley(r: &Vec3) -> Mat3 {
    // With n = ‖r‖ and û = r/n: I + 2[û]·n/(1 + n²) + 2[û]²·n²/(1 + n²),
    // written so that no square is formed (a huge r is a turn near π, a
    // tiny one near the identity; neither overflows to NaN).
    let big = r.amax();
    if big == 0.0 || !big.is_finite() {
        let rm = hat(r);
        let k = 2.0 / (1.0 + r.norm_squared());
        return Mat3::identity() + k * (rm + rm * rm);
    }
    // (the direction from r scaled by its largest entry; n itself may
    // overflow to inf, where the weights below are their limits 0 and 1)
    let s = r / big;
    let m = super::norm(&s);
    let u = hat(&(s / m));
    let n = big * m;
    let (k1, k2) = if n <= 1.0 {
        (n / (1.0 + n * n), n * n / (1.0 + n * n))
    } else {
        (1.0 / (n + 1.0 / n), 1.0 / (1.0 + (1.0 / n) / n))
    };
    Mat3::identity() + 2.0 * k1 * u + 2.0 * k2 * u * u
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, PI};

    #[test]
    fn cayley_parameters_at_every_scale() {
        // huge r: the half turn about r̂, even when ‖r‖ overflows
        for big in [1e200, 1e308] {
            let r = rot_cayley(&Vec3::new(big, big, big));
            let want = crate::lie::so3::rot(&Vec3::new(1.0, 1.0, 1.0), PI);
            assert!((r - want).amax() < 1e-15, "{big}: {r}");
        }
        // tiny r: I + 2[r] to first order
        let r = rot_cayley(&Vec3::new(0.0, 0.0, 1e-170));
        assert_eq!(r[(1, 0)], 2e-170);
        // ordinary r: r = ẑ tan(π/4) is Rot(ẑ, π/2), as the old formula gave
        let r = rot_cayley(&Vec3::new(0.0, 0.0, 1.0));
        assert!((r - rotz(FRAC_PI_2)).amax() < 1e-15);
    }

    #[test]
    fn zyx_gimbal_lock_is_finite_and_noted() {
        for b in [FRAC_PI_2, -FRAC_PI_2] {
            let r = rot_zyx(0.3, b, 0.2);
            let e = euler_zyx(&r);
            assert!(e.note.is_some());
            assert!(e.angles.iter().all(|x| x.is_finite()));
            assert_eq!(e.angles.z, 0.0);
            let back = rot_zyx(e.angles.x, e.angles.y, e.angles.z);
            assert!((back - r).amax() < 1e-15);
        }
    }

    #[test]
    fn zxz_gimbal_lock() {
        for b in [0.0, PI] {
            let r = rot_zxz(0.3, b, 0.2);
            let e = euler_zxz(&r);
            assert!(e.note.is_some());
            let back = rot_zxz(e.angles.x, e.angles.y, e.angles.z);
            assert!((back - r).amax() < 1e-15);
        }
    }

    #[test]
    fn quat_of_rotx_pi() {
        let q = quat(&rotx(PI));
        assert!((q - Vec4::new(0.0, 1.0, 0.0, 0.0)).amax() < 1e-15);
        assert!(rot_quat(&Vec4::zeros()).is_none());
    }

    #[test]
    fn cayley_errors_at_pi() {
        assert!(cayley(&rotx(PI)).is_err());
        let r = cayley(&rotx(FRAC_PI_2)).unwrap();
        assert!((r - Vec3::new(1.0, 0.0, 0.0)).amax() < 1e-15);
    }
}
