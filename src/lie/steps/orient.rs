//! Other representations of orientation step by step (the book's
//! Appendix B, with the conventions of LANGUAGE.md §8): ZYX and ZXZ Euler
//! angles and roll-pitch-yaw with their branch and gimbal lock, unit
//! quaternions and Cayley-Rodrigues parameters.

use super::{Quantity as Q, Step};
use crate::lie::Mat3;
use crate::lie::repr::{self, Angles};
use crate::lie::so3::rotz;

/// Which Euler-type extraction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Euler {
    /// `euler_zyx`: R = Rz(a) Ry(b) Rx(c), b ∈ [−π/2, π/2].
    Zyx,
    /// `euler_zxz`: R = Rz(a) Rx(b) Rz(c), b ∈ [0, π].
    Zxz,
    /// `rpy`: R = Rz(yaw) Ry(pitch) Rx(roll), as ZYX reversed.
    Rpy,
}

/// The steps of `euler_zyx(R)`, `euler_zxz(R)` or `rpy(R)`, with gimbal
/// lock decided by `gimbal` (from R's exact form) or from the floats as
/// [`repr::euler_zyx`] decides it. The last step is the angles, the value
/// of the plain function.
pub fn euler(r: &Mat3, which: Euler, gimbal: Option<bool>) -> Vec<Step> {
    let zxz = which == Euler::Zxz;
    let gimbal = gimbal.unwrap_or_else(|| {
        if zxz {
            r[(0, 2)].hypot(r[(1, 2)]) < 1e-15
        } else {
            r[(0, 0)].hypot(r[(1, 0)]) < 1e-15
        }
    });
    let angles: Angles = match which {
        Euler::Zyx => repr::euler_zyx_decided(r, gimbal),
        Euler::Zxz => repr::euler_zxz_decided(r, gimbal),
        Euler::Rpy => repr::rpy_decided(r, gimbal),
    };
    // (roll, pitch, yaw) = (c, b, a) of ZYX: the first and last angles
    // of the product, and the value in the function's order.
    let e = angles.angles;
    let (first, last) = if which == Euler::Rpy {
        (e.z, e.x)
    } else {
        (e.x, e.z)
    };
    let product = match which {
        Euler::Zyx => "R = Rz(a) Ry(b) Rx(c)",
        Euler::Zxz => "R = Rz(a) Rx(b) Rz(c)",
        Euler::Rpy => "R = Rz(yaw) Ry(pitch) Rx(roll)",
    };
    let mut out = vec![Step::new(
        "App. B",
        "convention",
        product,
        product
            .replace("Rz", "R_z")
            .replace("Ry", "R_y")
            .replace("Rx", "R_x"),
        Q::Case(match which {
            Euler::Zyx => "zyx",
            Euler::Zxz => "zxz",
            Euler::Rpy => "rpy",
        }),
    )];
    let (a_name, b_name, c_name) = if which == Euler::Rpy {
        ("yaw", "pitch", "roll")
    } else {
        ("a", "b", "c")
    };
    let case = if gimbal {
        Step::new(
            "App. B",
            "case",
            if zxz {
                "gimbal lock: r₁₃ = r₂₃ = 0 (sin b = 0), only a ± c is defined"
            } else {
                "gimbal lock: r₁₁ = r₂₁ = 0 (cos b = 0), only a ∓ c is defined"
            },
            r"\text{gimbal lock}",
            Q::Case("gimbal_lock"),
        )
        .note(angles.note.clone().unwrap_or_default())
    } else {
        Step::new(
            "App. B",
            "case",
            if zxz {
                "sin b ≠ 0: the angles are unique with b ∈ (0, π)"
            } else {
                "cos b ≠ 0: the angles are unique with b ∈ (−π/2, π/2)"
            },
            r"\text{regular}",
            Q::Case("general"),
        )
    };
    out.push(case);
    let (a_text, a_latex) = match (zxz, gimbal) {
        (false, false) => (
            "a = atan2(r₂₁, r₁₁)",
            r"a = \operatorname{atan2}(r_{21}, r_{11})",
        ),
        (false, true) => (
            "a = atan2(−r₁₂, r₂₂) (c = 0)",
            r"a = \operatorname{atan2}(-r_{12}, r_{22})",
        ),
        (true, false) => (
            "a = atan2(r₁₃, −r₂₃)",
            r"a = \operatorname{atan2}(r_{13}, -r_{23})",
        ),
        (true, true) => (
            "a = atan2(r₂₁, r₁₁) (c = 0)",
            r"a = \operatorname{atan2}(r_{21}, r_{11})",
        ),
    };
    out.push(Step::new(
        "App. B",
        a_name,
        a_text,
        a_latex,
        Q::Scalar(first),
    ));
    out.push(Step::new(
        "App. B",
        "R_prime",
        if zxz {
            "R' = Rz(−a) R = Rx(b) Rz(c)"
        } else {
            "R' = Rz(−a) R = Ry(b) Rx(c)"
        },
        r"R' = R_z(-a)\, R",
        Q::Matrix3(rotz(-first) * r),
    ));
    let (b_text, b_latex, c_text, c_latex) = if zxz {
        (
            "b = atan2(−r'₂₃, r'₃₃) ∈ [0, π]",
            r"b = \operatorname{atan2}(-r'_{23}, r'_{33})",
            "c = atan2(−r'₁₂, r'₁₁)",
            r"c = \operatorname{atan2}(-r'_{12}, r'_{11})",
        )
    } else {
        (
            "b = atan2(−r'₃₁, r'₁₁) ∈ [−π/2, π/2]",
            r"b = \operatorname{atan2}(-r'_{31}, r'_{11})",
            "c = atan2(−r'₂₃, r'₂₂)",
            r"c = \operatorname{atan2}(-r'_{23}, r'_{22})",
        )
    };
    out.push(Step::new("App. B", b_name, b_text, b_latex, Q::Scalar(e.y)));
    let c_step = Step::new(
        "App. B",
        c_name,
        if gimbal {
            "c = 0 (chosen: gimbal lock)"
        } else {
            c_text
        },
        if gimbal { "c = 0" } else { c_latex },
        Q::Scalar(last),
    );
    out.push(c_step);
    out.push(Step::new(
        "App. B",
        "angles",
        if which == Euler::Rpy {
            "(roll, pitch, yaw)"
        } else {
            "(a, b, c)"
        },
        if which == Euler::Rpy {
            r"(\text{roll}, \text{pitch}, \text{yaw})"
        } else {
            "(a, b, c)"
        },
        Q::Vector3(e),
    ));
    out
}

/// The steps of `quat(R)` by Shepperd's method: which of 1 + tr R,
/// 1 + 2r₁₁ − tr R, … is largest, and q = (cos θ/2, ω̂ sin θ/2) with w ≥ 0;
/// the last step is the value of [`repr::quat`].
pub fn quat(r: &Mat3) -> Vec<Step> {
    let tr = r.trace();
    let cands = [tr, r[(0, 0)], r[(1, 1)], r[(2, 2)]];
    let k = (0..4)
        .max_by(|&i, &j| cands[i].total_cmp(&cands[j]))
        .unwrap_or(0);
    let q = repr::quat(r);
    vec![
        Step::new(
            "3.54",
            "trace",
            "tr R = 1 + 2 cos θ",
            r"\operatorname{tr} R = 1 + 2\cos\theta",
            Q::Scalar(tr),
        ),
        Step::new(
            "App. B",
            "case",
            [
                "4w² = 1 + tr R is the largest: w first, then x, y, z = (r₃₂ − r₂₃, r₁₃ − r₃₁, r₂₁ − r₁₂)/(4w)",
                "4x² = 1 + r₁₁ − r₂₂ − r₃₃ is the largest: x first (θ near π)",
                "4y² = 1 − r₁₁ + r₂₂ − r₃₃ is the largest: y first (θ near π)",
                "4z² = 1 − r₁₁ − r₂₂ + r₃₃ is the largest: z first (θ near π)",
            ][k],
            r"\text{Shepperd: the largest of } 4w^2, 4x^2, 4y^2, 4z^2",
            Q::Case(["w", "x", "y", "z"][k]),
        )
        .note("no component is found from the square root of a small number; the sign makes w ≥ 0"),
        Step::new(
            "App. B",
            "quat",
            "q = (cos(θ/2), ω̂ sin(θ/2)), w ≥ 0",
            r"q = (\cos\tfrac{\theta}{2}, \hat\omega \sin\tfrac{\theta}{2})",
            Q::Vector4(q),
        ),
    ]
}

/// The steps of `cayley(R)`: the quaternion, then r = ω̂ tan(θ/2) = v/w;
/// the value of [`repr::cayley`] (an error at θ = π is the caller's).
pub fn cayley(r: &Mat3) -> Vec<Step> {
    let mut out = quat(r);
    if let Ok(c) = repr::cayley(r) {
        out.push(Step::new(
            "App. B",
            "cayley",
            "r = ω̂ tan(θ/2) = (x, y, z)/w",
            r"r = \hat\omega \tan\tfrac{\theta}{2} = (x, y, z)/w",
            Q::Vector3(c),
        ));
    }
    out
}
