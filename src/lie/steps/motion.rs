//! Inverses (Proposition 3.1, (3.64)), the adjoint (Definition 3.6), screw
//! axes from q, ŝ, h and back (§3.3.2.2), and the change of frame of a
//! wrench (3.99), step by step.

use super::{Quantity as Q, Step};
use crate::lie::{Mat3, Mat4, Mat6, Vec3, Vec6, se3, so3};

/// The steps of R⁻¹ = Rᵀ (Proposition 3.1), ending with the value of
/// [`so3::inv`].
pub fn inv3(r: &Mat3) -> Vec<Step> {
    vec![Step::new(
        "Prop. 3.1",
        "R_inv",
        "R⁻¹ = Rᵀ",
        r"R^{-1} = R^T",
        Q::Rotation(so3::inv(r)),
    )]
}

/// The steps of T⁻¹ = [Rᵀ, −Rᵀp; 0, 1] (3.64), ending with the value of
/// [`se3::inv`].
pub fn inv6(t: &Mat4) -> Vec<Step> {
    let (r, p) = se3::to_rp(t);
    let value = se3::inv(t);
    vec![
        Step::new("3.62", "R", "T = [R, p; 0, 1]: R", r"R", Q::Rotation(r)),
        Step::new("3.62", "p", "T = [R, p; 0, 1]: p", r"p", Q::Vector3(p)),
        Step::new(
            "3.64",
            "R_T",
            "Rᵀ (= R⁻¹, Prop. 3.1)",
            r"R^T",
            Q::Rotation(r.transpose()),
        ),
        Step::new(
            "3.64",
            "p_inv",
            "−Rᵀp",
            r"-R^T p",
            Q::Vector3(Vec3::new(value[(0, 3)], value[(1, 3)], value[(2, 3)])),
        ),
        Step::new(
            "3.64",
            "T_inv",
            "T⁻¹ = [Rᵀ, −Rᵀp; 0, 1]",
            r"T^{-1} = \begin{bmatrix} R^T & -R^T p \\ 0 & 1 \end{bmatrix}",
            Q::Transform(value),
        ),
    ]
}

/// The steps of \[Ad_T\] = [R, 0; \[p\]R, R] (Definition 3.6), ending with
/// the value of [`se3::adjoint`].
pub fn adjoint(t: &Mat4) -> Vec<Step> {
    let (r, p) = se3::to_rp(t);
    let pm = so3::hat(&p);
    vec![
        Step::new("3.62", "R", "T = [R, p; 0, 1]: R", r"R", Q::Rotation(r)),
        Step::new("3.62", "p", "T = [R, p; 0, 1]: p", r"p", Q::Vector3(p)),
        Step::new("3.30", "p_bracket", "[p]", r"[p]", Q::So3(pm)),
        Step::new("Def. 3.6", "pR", "[p]R", r"[p]R", Q::Matrix3(pm * r)),
        Step::new(
            "Def. 3.6",
            "Ad",
            "[Ad_T] = [R, 0; [p]R, R]",
            r"[\mathrm{Ad}_T] = \begin{bmatrix} R & 0 \\ [p]R & R \end{bmatrix}",
            Q::Adjoint(se3::adjoint(t)),
        ),
    ]
}

/// The steps of the screw axis S = (ŝ, −ŝ × q + hŝ) of a screw through q
/// along the unit ŝ with pitch h (§3.3.2.2), ending with S (the value of
/// [`se3::screw_to_axis`]: (0, ŝ) for h = ∞, (0, −ŝ) for h = −∞). `s` is
/// already unit.
pub fn screw_axis(q: &Vec3, s: &Vec3, h: f64) -> Vec<Step> {
    let mut out = vec![
        Step::new(
            "3.3.2.2",
            "q",
            "q (a point on the axis)",
            r"q",
            Q::Vector3(*q),
        ),
        Step::new(
            "3.3.2.2",
            "s_hat",
            "ŝ (the unit direction)",
            r"\hat s",
            Q::Vector3(*s),
        ),
        Step::new("3.3.2.2", "h", "h (the pitch)", r"h", Q::Scalar(h)),
    ];
    let value = se3::screw_to_axis(q, s, h);
    if h.is_infinite() {
        let (text, latex) = if h > 0.0 {
            (
                "h = ∞ (a pure translation): S = (0, ŝ)",
                r"h = \infty:\ \mathcal{S} = (0, \hat s)",
            )
        } else {
            (
                "h = −∞ (a pure translation, against ŝ): S = (0, −ŝ)",
                r"h = -\infty:\ \mathcal{S} = (0, -\hat s)",
            )
        };
        out.push(Step::new("3.3.2.2", "S", text, latex, Q::Screw(value)));
        return out;
    }
    out.push(Step::new(
        "3.3.2.2",
        "omega",
        "ω = ŝ",
        r"\omega = \hat s",
        Q::Vector3(*s),
    ));
    out.push(Step::new(
        "3.3.2.2",
        "v",
        "v = −ŝ × q + hŝ",
        r"v = -\hat s \times q + h \hat s",
        Q::Vector3(Vec3::new(value[3], value[4], value[5])),
    ));
    out.push(Step::new(
        "3.3.2.2",
        "S",
        "S = (ω, v)",
        r"\mathcal{S} = (\omega, v)",
        Q::Screw(value),
    ));
    out
}

/// The steps of `screw_params(S)`: the point q of the axis nearest the
/// origin, ŝ and h (§3.3.2.2), the values of [`se3::screw_params`]. The
/// last three steps are q, ŝ, h, the tuple's parts in order.
pub fn screw_params(sv: &Vec6) -> Vec<Step> {
    let (q, s, h) = se3::screw_params(sv);
    let w = Vec3::new(sv[0], sv[1], sv[2]);
    let mut out = Vec::new();
    // (the book's case ω = 0 exactly, as se3::screw_params decides it)
    if w.iter().all(|x| *x == 0.0) {
        out.push(Step::new(
            "3.3.2.2",
            "case",
            "ω = 0: a pure translation along ŝ = v/‖v‖, h = ∞ (q = 0 by convention)",
            r"\omega = 0:\ \hat s = v/\|v\|,\ h = \infty",
            Q::Case("pure_translation"),
        ));
        out.push(Step::new("3.3.2.2", "q", "q = 0", r"q = 0", Q::Vector3(q)));
        out.push(Step::new(
            "3.3.2.2",
            "s_hat",
            "ŝ = v/‖v‖",
            r"\hat s = v / \|v\|",
            Q::Vector3(s),
        ));
        out.push(Step::new(
            "3.3.2.2",
            "h",
            "h = ∞",
            r"h = \infty",
            Q::Scalar(h),
        ));
        return out;
    }
    out.push(Step::new(
        "3.3.2.2",
        "case",
        "ω ≠ 0: v = −ω × q + hω, so q = ω × v/‖ω‖², h = ωᵀv/‖ω‖²",
        r"v = -\omega \times q + h\omega",
        Q::Case("general"),
    ));
    out.push(Step::new(
        "3.3.2.2",
        "q",
        "q = ω × v/‖ω‖² (the point nearest the origin)",
        r"q = \frac{\omega \times v}{\|\omega\|^2}",
        Q::Vector3(q),
    ));
    out.push(Step::new(
        "3.3.2.2",
        "s_hat",
        "ŝ = ω/‖ω‖",
        r"\hat s = \omega / \|\omega\|",
        Q::Vector3(s),
    ));
    out.push(Step::new(
        "3.3.2.2",
        "h",
        "h = ωᵀv/‖ω‖²",
        r"h = \frac{\omega^T v}{\|\omega\|^2}",
        Q::Scalar(h),
    ));
    out
}

/// The steps of F_b = \[Ad_{T_ab}\]ᵀ F_a (3.99), ending with the value
/// of \[Ad_{T_ab}\]ᵀ F_a.
pub fn wrench_change(t_ab: &Mat4, f_a: &Vec6) -> Vec<Step> {
    let mut out = adjoint(t_ab);
    let ad: Mat6 = se3::adjoint(t_ab).transpose();
    out.push(Step::new(
        "3.99",
        "Ad_T",
        "[Ad_T]ᵀ",
        r"[\mathrm{Ad}_{T_{ab}}]^T",
        Q::Matrix6(ad),
    ));
    out.push(Step::new(
        "3.99",
        "F",
        "F_b = [Ad_{T_ab}]ᵀ F_a",
        r"\mathcal{F}_b = [\mathrm{Ad}_{T_{ab}}]^T \mathcal{F}_a",
        Q::Wrench(se3::wrench_change(t_ab, f_a)),
    ));
    out
}
