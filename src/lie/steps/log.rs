//! The logarithms step by step: of a rotation (§3.2.3.3, its three cases
//! and the sub-cases (3.58)–(3.60) of a half turn) and of a transform
//! (§3.3.3.2 with G⁻¹(θ) (3.94) and v (3.93)).

use super::{Quantity as Q, Step, num};
use crate::lie::so3::{self, HalfTurn, LogParts};
use crate::lie::{Mat3, Mat4, Vec3, Vec6, se3};

/// Within this of 0 or π, θ from cos⁻¹ (3.54) loses digits and the step
/// says what chasles does instead.
const NEAR: f64 = 1e-2;

/// The branch decision of [`so3::log`] read from R's floats (as
/// the logarithm itself reads it).
pub fn decide(r: &Mat3) -> HalfTurn {
    let skew = so3::skew_part(r);
    HalfTurn {
        skew,
        cos: 0.5 * (r.trace() - 1.0),
        half_turn: skew.norm() <= so3::HALF_TURN_SKEW,
    }
}

/// Which of the book's (3.58), (3.59), (3.60) gives ω̂ at θ = π: the first
/// whose 1 + rᵢᵢ is not near zero (the book's library's order and test).
fn half_turn_formula(r: &Mat3) -> (usize, &'static str) {
    if 1.0 + r[(2, 2)] >= 1e-6 {
        (2, "3.58")
    } else if 1.0 + r[(1, 1)] >= 1e-6 {
        (1, "3.59")
    } else {
        (0, "3.60")
    }
}

/// The steps of the SO(3) logarithm up to ω̂ (no final value), and what
/// [`so3::log_parts_with`] computed.
fn rotation_steps(r: &Mat3, d: &HalfTurn, out: &mut Vec<Step>) -> LogParts {
    let parts = so3::log_parts_with(r, d);
    out.push(Step::new(
        "3.54",
        "trace",
        "tr R = r₁₁ + r₂₂ + r₃₃ = 1 + 2 cos θ",
        r"\operatorname{tr} R = r_{11} + r_{22} + r_{33} = 1 + 2\cos\theta",
        Q::Scalar(r.trace()),
    ));
    let theta = parts.theta;
    if theta == 0.0 {
        out.push(Step::new(
            "3.2.3.3",
            "case",
            "case (i): R = I, so θ = 0 and ω̂ is undefined",
            r"\text{case (i): } R = I,\ \theta = 0,\ \hat\omega \text{ undefined}",
            Q::Case("identity"),
        ));
        out.push(Step::new(
            "3.2.3.3",
            "theta",
            "θ = 0",
            r"\theta = 0",
            Q::Scalar(theta),
        ));
        return parts;
    }
    if d.half_turn {
        let (k, eq) = half_turn_formula(r);
        let sub = |n: usize| ['₁', '₂', '₃'][n];
        let kk = sub(k);
        let mut case = Step::new(
            "3.2.3.3",
            "case",
            format!("case (ii): tr R = −1, so θ = π; ω̂ by ({eq}) since 1 + r{kk}{kk} ≠ 0"),
            format!(
                r"\text{{case (ii): }} \operatorname{{tr}} R = -1,\ \theta = \pi;\ \hat\omega \text{{ by ({eq})}}"
            ),
            Q::Case(match k {
                2 => "half_turn_3.58",
                1 => "half_turn_3.59",
                _ => "half_turn_3.60",
            }),
        );
        if r.trace() != -1.0 {
            case = case.note(format!(
                "tr R = {} is −1 up to the rounding of R's entries: R = Rᵀ (sin θ = ‖R − Rᵀ‖/(2√2) \
                 is 0 to rounding), so θ = π",
                r.trace()
            ));
        }
        out.push(case);
        let mut step = Step::new(
            "3.2.3.3",
            "theta",
            "θ = π",
            r"\theta = \pi",
            Q::Scalar(theta),
        );
        if theta != std::f64::consts::PI {
            step = step.note(format!(
                "R − Rᵀ is rounding noise (sin θ = {:.1e}), so θ = π; chasles keeps θ = atan2(sin θ, \
                 cos θ) = {theta:?}, which is π to within {:.0e}",
                parts.sin,
                std::f64::consts::PI - theta
            ));
        }
        out.push(step);
        let w = so3::near_pi_axis(r, d.cos, &d.skew, true);
        let (text, latex) = match k {
            2 => (
                "ω̂ = (r₁₃, r₂₃, 1 + r₃₃)/√(2(1 + r₃₃))".to_string(),
                r"\hat\omega = \frac{1}{\sqrt{2(1 + r_{33})}} (r_{13}, r_{23}, 1 + r_{33})"
                    .to_string(),
            ),
            1 => (
                "ω̂ = (r₁₂, 1 + r₂₂, r₃₂)/√(2(1 + r₂₂))".to_string(),
                r"\hat\omega = \frac{1}{\sqrt{2(1 + r_{22})}} (r_{12}, 1 + r_{22}, r_{32})"
                    .to_string(),
            ),
            _ => (
                "ω̂ = (1 + r₁₁, r₂₁, r₃₁)/√(2(1 + r₁₁))".to_string(),
                r"\hat\omega = \frac{1}{\sqrt{2(1 + r_{11})}} (1 + r_{11}, r_{21}, r_{31})"
                    .to_string(),
            ),
        };
        out.push(
            Step::new(eq, "omega_hat", text, latex, Q::Vector3(w)).note(format!(
                "chasles reads ω̂ from the best-conditioned column of (R + Rᵀ)/2 − cos θ·I = (1 − cos θ)ω̂ω̂ᵀ (3.52), \
                 signed as ({eq}) signs it (ω̂{kk} ≥ 0): the same axis without dividing by a small √(2(1 + rᵢᵢ)); \
                 −ω̂ is an equally valid answer"
            )),
        );
        return parts;
    }
    let mut case = Step::new(
        "3.2.3.3",
        "case",
        "case (iii): R ≠ I and tr R ≠ −1, so θ ∈ (0, π)",
        r"\text{case (iii): } R \ne I,\ \operatorname{tr} R \ne -1,\ \theta \in (0, \pi)",
        Q::Case("general"),
    );
    if r.trace() <= -1.0 {
        case = case.note(format!(
            "tr R rounds to {} here, but R ≠ Rᵀ (sin θ = ‖R − Rᵀ‖/(2√2) = {:.3e} ≠ 0): θ is just \
             below π, not π, so case (iii)",
            r.trace(),
            d.skew.norm()
        ));
    }
    out.push(case);
    let book = d.cos.clamp(-1.0, 1.0).acos();
    let mut step = Step::new(
        "3.54",
        "theta",
        "θ = cos⁻¹((tr R − 1)/2)",
        r"\theta = \cos^{-1}\left(\frac{\operatorname{tr} R - 1}{2}\right)",
        Q::Scalar(theta),
    );
    if theta < NEAR || std::f64::consts::PI - theta < NEAR {
        step = step.note(format!(
            "θ near {}: chasles takes θ = atan2(‖R − Rᵀ‖/(2√2), (tr R − 1)/2) = atan2(sin θ, cos θ) instead, \
             because cos⁻¹ has an infinite slope at ±1 and turns a rounding of tr R into an error of √ε ≈ 1e-8 in θ \
             (cos⁻¹ gives {} here)",
            if theta < NEAR { "0" } else { "π" },
            num(book),
        ));
    }
    out.push(step);
    let c = d.cos;
    let s = parts.sin;
    let (w, note) = if c > 0.0 {
        let note = (theta < so3::SERIES_THETA).then(|| {
            "θ is tiny: chasles multiplies vee(R − Rᵀ)/2 = sin θ ω̂ by θ/sin θ from its series \
             1 + θ²/6 + 7θ⁴/360, so ω̂θ stays exact as θ → 0"
                .to_string()
        });
        (d.skew / s, note)
    } else {
        let note = format!(
            "θ ≥ π/2: chasles reads ω̂ from the symmetric part (R + Rᵀ)/2 − cos θ·I = (1 − cos θ)ω̂ω̂ᵀ (3.52), \
             signed by R − Rᵀ, because dividing by 2 sin θ (sin θ = {} here) loses accuracy as θ → π",
            num(s)
        );
        (so3::near_pi_axis(r, c, &d.skew, false), Some(note))
    };
    let mut step = Step::new(
        "3.61",
        "omega_hat",
        "[ω̂] = (R − Rᵀ)/(2 sin θ)",
        r"[\hat\omega] = \frac{1}{2\sin\theta}\left(R - R^T\right)",
        Q::Vector3(w),
    );
    step.note = note;
    out.push(step);
    parts
}

/// The steps of `log(R)` (§3.2.3.3), ending with \[ω̂\]θ ∈ so(3): the value
/// of [`so3::log_decided`] with the branch `d` (from R's exact form) or,
/// when none, [`so3::log`].
pub fn log3(r: &Mat3, d: Option<&HalfTurn>) -> Vec<Step> {
    let d = d.copied().unwrap_or_else(|| decide(r));
    let mut out = Vec::new();
    let parts = rotation_steps(r, &d, &mut out);
    out.push(so3_step(&parts.phi));
    out
}

/// The steps of `MatrixLog3(R)`: those of [`log3`], ending with the
/// exponential coordinates ω̂θ (§3.2.3.3).
pub fn matrix_log3(r: &Mat3, d: Option<&HalfTurn>) -> Vec<Step> {
    let d = d.copied().unwrap_or_else(|| decide(r));
    let mut out = Vec::new();
    let parts = rotation_steps(r, &d, &mut out);
    out.push(Step::new(
        "3.2.3.3",
        "expc",
        "ω̂θ (exponential coordinates)",
        r"\hat\omega\theta",
        Q::Vector3(parts.phi),
    ));
    out
}

fn so3_step(phi: &Vec3) -> Step {
    Step::new(
        "3.2.3.3",
        "so3",
        "log R = [ω̂]θ",
        r"\log R = [\hat\omega]\theta",
        Q::So3(so3::hat(phi)),
    )
}

/// The steps of the SE(3) logarithm (§3.3.3.2) and its exponential
/// coordinates Sθ (the value of [`se3::log_decided`] or [`se3::log`]).
fn transform_steps(t: &Mat4, d: Option<&HalfTurn>, out: &mut Vec<Step>) -> Vec6 {
    let r: Mat3 = t.fixed_view::<3, 3>(0, 0).into_owned();
    let p = Vec3::new(t[(0, 3)], t[(1, 3)], t[(2, 3)]);
    let d = d.copied().unwrap_or_else(|| decide(&r));
    let value = se3::log_decided(t, &d);
    out.push(Step::new(
        "3.62",
        "p",
        "T = [R, p; 0, 1]: p",
        r"T = \begin{bmatrix} R & p \\ 0 & 1 \end{bmatrix}",
        Q::Vector3(p),
    ));
    let parts = so3::log_parts_with(&r, &d);
    if parts.theta == 0.0 {
        out.push(Step::new(
            "3.3.3.2",
            "case",
            "case (i): R = I, so ω = 0, v = p/‖p‖ and θ = ‖p‖ (a pure translation)",
            r"\text{case (i): } R = I,\ \omega = 0,\ v = p/\|p\|,\ \theta = \|p\|",
            Q::Case("pure_translation"),
        ));
        let n = p.norm();
        out.push(Step::new(
            "3.3.3.2",
            "theta",
            "θ = ‖p‖",
            r"\theta = \|p\|",
            Q::Scalar(n),
        ));
        let v = if n > 0.0 { p / n } else { Vec3::zeros() };
        let mut step = Step::new("3.3.3.2", "v", "v = p/‖p‖", r"v = p / \|p\|", Q::Vector3(v));
        if n == 0.0 {
            step = step.note("T = I: θ = 0 and the axis is undefined; Sθ = 0");
        }
        out.push(step);
        return value;
    }
    out.push(Step::new(
        "3.3.3.2",
        "case",
        if d.half_turn {
            "case (ii): tr R = −1, so θ = π and [ω] from the SO(3) logarithm's case (ii); v = G⁻¹(θ)p"
        } else {
            "case (iii): R ≠ I, tr R ≠ −1: θ and [ω] from the SO(3) logarithm (3.95); v = G⁻¹(θ)p (3.96)"
        },
        if d.half_turn {
            r"\text{case (ii): } \operatorname{tr} R = -1,\ \theta = \pi"
        } else {
            r"\text{case (iii): } \theta = \cos^{-1}\frac{\operatorname{tr} R - 1}{2},\ [\omega] = \frac{R - R^T}{2\sin\theta}"
        },
        Q::Case(if d.half_turn { "half_turn" } else { "general" }),
    ));
    let parts = rotation_steps(&r, &d, out);
    out.push(Step::new(
        "3.95",
        "so3",
        "[ω]θ = log R",
        r"[\omega]\theta = \log R",
        Q::So3(so3::hat(&parts.phi)),
    ));
    let theta = parts.theta;
    let w = parts.phi / theta;
    let wm = so3::hat(&w);
    // (1/θ − ½cot(θ/2)) = θ·k with k the coefficient se3::log uses.
    let k = se3::ginv_coeff(theta, parts.sin, parts.cos);
    let g_inv = Mat3::identity() / theta - 0.5 * wm + (theta * k) * wm * wm;
    let mut step = Step::new(
        "3.94",
        "G_inv",
        "G⁻¹(θ) = I/θ − [ω]/2 + (1/θ − ½ cot(θ/2))[ω]²",
        r"G^{-1}(\theta) = \frac{1}{\theta} I - \frac{1}{2}[\omega] + \left(\frac{1}{\theta} - \frac{1}{2}\cot\frac{\theta}{2}\right)[\omega]^2",
        Q::Matrix3(g_inv),
    );
    step = step.note(if theta < se3::SERIES_THETA {
        "θ is small: 1/θ − ½cot(θ/2) cancels, so chasles takes θ(1/θ − ½cot(θ/2))/θ² from its series \
         1/12 + θ²/720 + …, and computes vθ = p − ½[ωθ]p + …[ωθ]²p without dividing by θ"
            .to_string()
    } else {
        "cot(θ/2) from sin θ and cos θ by the half-angle identities; chasles computes vθ = θG⁻¹(θ)p directly \
         (the same product, without forming 1/θ)"
            .to_string()
    });
    out.push(step);
    out.push(Step::new(
        "3.93",
        "v",
        "v = G⁻¹(θ)p",
        r"v = G^{-1}(\theta)\, p",
        Q::Vector3(Vec3::new(value[3], value[4], value[5]) / theta),
    ));
    value
}

/// The steps of `log(T)` (§3.3.3.2), ending with \[S\]θ ∈ se(3): the value
/// of [`se3::log_decided`] with the branch `d`, or [`se3::log`].
pub fn log6(t: &Mat4, d: Option<&HalfTurn>) -> Vec<Step> {
    let mut out = Vec::new();
    let v = transform_steps(t, d, &mut out);
    out.push(Step::new(
        "3.3.3.2",
        "se3",
        "log T = [S]θ = [[ω]θ, vθ; 0, 0]",
        r"\log T = [\mathcal{S}]\theta = \begin{bmatrix} [\omega]\theta & v\theta \\ 0 & 0 \end{bmatrix}",
        Q::Se3(se3::hat(&v)),
    ));
    out
}

/// The steps of `MatrixLog6(T)`: those of [`log6`], ending with the
/// exponential coordinates Sθ = (ωθ, vθ).
pub fn matrix_log6(t: &Mat4, d: Option<&HalfTurn>) -> Vec<Step> {
    let mut out = Vec::new();
    let v = transform_steps(t, d, &mut out);
    out.push(Step::new(
        "3.3.3.2",
        "expc",
        "Sθ = (ωθ, vθ) (exponential coordinates)",
        r"\mathcal{S}\theta = (\omega\theta, v\theta)",
        Q::Vector6(v),
    ));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn value_of(steps: &[Step]) -> &Q {
        &steps.last().unwrap().value
    }

    #[test]
    fn last_step_is_the_log_bit_for_bit() {
        let r = so3::exp(&Vec3::new(0.3, -1.2, 0.7));
        assert_eq!(value_of(&log3(&r, None)), &Q::So3(so3::hat(&so3::log(&r))));
        assert_eq!(value_of(&matrix_log3(&r, None)), &Q::Vector3(so3::log(&r)));
        let t = se3::from_rp(&r, &Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(value_of(&matrix_log6(&t, None)), &Q::Vector6(se3::log(&t)));
    }

    #[test]
    fn half_turn_sub_cases_follow_the_book() {
        // Rotx(π): 1 + r₃₃ = 0 and 1 + r₂₂ = 0, so (3.60), ω̂ = (1, 0, 0).
        let r = Mat3::new(1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0);
        let s = log3(&r, None);
        let w = s.iter().find(|s| s.name == "omega_hat").unwrap();
        assert_eq!(w.reference, "3.60");
        assert_eq!(w.value, Q::Vector3(Vec3::new(1.0, 0.0, 0.0)));
        // Roty(π): (3.59), ω̂ = (0, 1, 0).
        let r = Mat3::new(-1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0);
        let s = log3(&r, None);
        let w = s.iter().find(|s| s.name == "omega_hat").unwrap();
        assert_eq!(w.reference, "3.59");
        assert_eq!(w.value, Q::Vector3(Vec3::new(0.0, 1.0, 0.0)));
    }

    #[test]
    fn identity_and_pure_translation() {
        let s = log3(&Mat3::identity(), None);
        assert_eq!(s[1].value, Q::Case("identity"));
        let t = se3::trans(&Vec3::new(3.0, 0.0, 4.0));
        let s = log6(&t, None);
        let theta = s.iter().find(|s| s.name == "theta").unwrap();
        assert_eq!(theta.value, Q::Scalar(5.0));
        let v = s.iter().find(|s| s.name == "v").unwrap();
        assert_eq!(v.value, Q::Vector3(Vec3::new(0.6, 0.0, 0.8)));
    }
}
