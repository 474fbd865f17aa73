//! The exponentials step by step: Rodrigues' formula (3.51) term by term,
//! and the SE(3) exponential of Proposition 3.16 with G(θ) (3.88), the
//! translation (3.89) and the pure-translation case (3.90).

use super::{Quantity as Q, Step};
use crate::lie::{Mat3, Vec3, Vec6, se3, so3};

/// θ and ω̂ of exponential coordinates ω̂θ (AxisAng3, §3.2.3.2).
fn axis_steps(phi: &Vec3, out: &mut Vec<Step>) -> (Vec3, f64) {
    let (w, theta) = so3::axis_angle(phi);
    out.push(Step::new(
        "3.2.3.2",
        "theta",
        "θ = ‖ω̂θ‖",
        r"\theta = \|\hat\omega\theta\|",
        Q::Scalar(theta),
    ));
    let mut step = Step::new(
        "3.2.3.2",
        "omega_hat",
        "ω̂ = ω̂θ/θ",
        r"\hat\omega = \hat\omega\theta / \theta",
        Q::Vector3(w),
    );
    if theta == 0.0 {
        step = step.note("θ = 0: ω̂ is undefined and e^{[ω̂]θ} = I");
    }
    out.push(step);
    (w, theta)
}

/// The terms sin θ [ω̂] and (1 − cos θ)[ω̂]² of Rodrigues' formula (3.51).
fn rodrigues_terms(w: &Vec3, theta: f64, out: &mut Vec<Step>) {
    let wm = so3::hat(w);
    out.push(Step::new(
        "3.51",
        "sin_term",
        "sin θ [ω̂]",
        r"\sin\theta\,[\hat\omega]",
        Q::So3(theta.sin() * wm),
    ));
    out.push(Step::new(
        "3.51",
        "cos_term",
        "(1 − cos θ)[ω̂]²",
        r"(1 - \cos\theta)[\hat\omega]^2",
        Q::Matrix3(one_minus_cos(theta) * wm * wm),
    ));
}

/// 1 − cos θ as 2 sin²(θ/2) (series below 1e-4, [`so3::rodrigues_coeffs`]):
/// 1.0 - theta.cos() keeps no digit below θ ≈ 1e-8 (it is 0 at θ = 1e-9,
/// not 5e-19), and the (1 − cos θ) terms of (3.51) and (3.88) are shown
/// to full relative accuracy.
fn one_minus_cos(theta: f64) -> f64 {
    so3::rodrigues_coeffs(theta).1 * theta * theta
}

/// θ − sin θ without cancellation (its series below θ = 1e-2, as
/// `se3::exp` computes it): θ − theta.sin() is 0 at θ = 1e-9, not 1.7e-28.
fn theta_minus_sin(theta: f64) -> f64 {
    let a = so3::rodrigues_coeffs(theta).0;
    se3::g_coeff(theta, a) * theta * theta * theta
}

const RODRIGUES_NOTE: &str = "chasles sums the three terms entry by entry as (3.52) with \
     sin θ/θ and (1 − cos θ)/θ² = 2 sin²(θ/2)/θ² (series below θ = 1e-4), which keeps R orthogonal \
     to a few ulps also for θ near 0 and π";

/// The steps of `exp([ω̂]θ)` / `MatrixExp3(ω̂θ)` (3.51), ending with R: the
/// value of [`so3::exp`].
pub fn exp3(phi: &Vec3) -> Vec<Step> {
    let mut out = vec![Step::new(
        "3.2.3.2",
        "expc",
        "ω̂θ (exponential coordinates)",
        r"\hat\omega\theta",
        Q::Vector3(*phi),
    )];
    let (w, theta) = axis_steps(phi, &mut out);
    if theta > 0.0 {
        rodrigues_terms(&w, theta, &mut out);
    }
    out.push(
        Step::new(
            "3.51",
            "R",
            "R = e^{[ω̂]θ} = I + sin θ [ω̂] + (1 − cos θ)[ω̂]²",
            r"R = e^{[\hat\omega]\theta} = I + \sin\theta\,[\hat\omega] + (1 - \cos\theta)[\hat\omega]^2",
            Q::Rotation(so3::exp(phi)),
        )
        .note(RODRIGUES_NOTE),
    );
    out
}

/// The steps of `exp([S]θ)` / `MatrixExp6(Sθ)` (Proposition 3.16), ending
/// with T: the value of [`se3::exp`].
pub fn exp6(sv: &Vec6) -> Vec<Step> {
    let phi = Vec3::new(sv[0], sv[1], sv[2]);
    let rho = Vec3::new(sv[3], sv[4], sv[5]);
    let mut out = vec![Step::new(
        "3.3.3.1",
        "expc",
        "Sθ = (ωθ, vθ) (exponential coordinates)",
        r"\mathcal{S}\theta = (\omega\theta, v\theta)",
        Q::Vector6(*sv),
    )];
    let value = se3::exp(sv);
    let theta_w = phi.norm();
    if theta_w == 0.0 {
        let theta = rho.norm();
        out.push(Step::new(
            "Prop. 3.16",
            "case",
            "ω = 0: a pure translation, (3.90)",
            r"\omega = 0:\ \text{a pure translation (3.90)}",
            Q::Case("pure_translation"),
        ));
        out.push(Step::new(
            "3.3.3.1",
            "theta",
            "θ = ‖vθ‖",
            r"\theta = \|v\theta\|",
            Q::Scalar(theta),
        ));
        let v = if theta > 0.0 {
            rho / theta
        } else {
            Vec3::zeros()
        };
        out.push(Step::new(
            "3.3.3.1",
            "v",
            "v = vθ/θ (‖v‖ = 1)",
            r"v = v\theta / \theta",
            Q::Vector3(v),
        ));
        out.push(Step::new(
            "3.90",
            "T",
            "e^{[S]θ} = [I, vθ; 0, 1]",
            r"e^{[\mathcal{S}]\theta} = \begin{bmatrix} I & v\theta \\ 0 & 1 \end{bmatrix}",
            Q::Transform(value),
        ));
        return out;
    }
    out.push(Step::new(
        "Prop. 3.16",
        "case",
        "‖ω‖ ≠ 0: a rotation about the screw axis, (3.89)",
        r"\|\omega\| \ne 0:\ \text{(3.89)}",
        Q::Case("general"),
    ));
    let (w, theta) = axis_steps(&phi, &mut out);
    let v = rho / theta;
    out.push(Step::new(
        "3.3.3.1",
        "v",
        "v = vθ/θ",
        r"v = v\theta / \theta",
        Q::Vector3(v),
    ));
    let r: Mat3 = value.fixed_view::<3, 3>(0, 0).into_owned();
    out.push(
        Step::new(
            "3.51",
            "R",
            "e^{[ω]θ} = I + sin θ [ω] + (1 − cos θ)[ω]²",
            r"e^{[\omega]\theta} = I + \sin\theta\,[\omega] + (1 - \cos\theta)[\omega]^2",
            Q::Rotation(r),
        )
        .note(RODRIGUES_NOTE),
    );
    let wm = so3::hat(&w);
    let g = Mat3::identity() * theta + one_minus_cos(theta) * wm + theta_minus_sin(theta) * wm * wm;
    let mut step = Step::new(
        "3.88",
        "G",
        "G(θ) = Iθ + (1 − cos θ)[ω] + (θ − sin θ)[ω]²",
        r"G(\theta) = I\theta + (1 - \cos\theta)[\omega] + (\theta - \sin\theta)[\omega]^2",
        Q::Matrix3(g),
    );
    if theta < 1e-2 {
        step = step.note(
            "θ is small: θ − sin θ cancels, so chasles computes G(θ)v = vθ + ((1 − cos θ)/θ²)[ωθ]vθ + \
             ((θ − sin θ)/θ³)[ωθ]²vθ with the last coefficient from its series 1/6 − θ²/120 + …",
        );
    }
    out.push(step);
    out.push(Step::new(
        "3.89",
        "p",
        "p = G(θ)v",
        r"p = G(\theta)\, v",
        Q::Vector3(Vec3::new(value[(0, 3)], value[(1, 3)], value[(2, 3)])),
    ));
    out.push(Step::new(
        "3.89",
        "T",
        "e^{[S]θ} = [e^{[ω]θ}, G(θ)v; 0, 1]",
        r"e^{[\mathcal{S}]\theta} = \begin{bmatrix} e^{[\omega]\theta} & G(\theta) v \\ 0 & 1 \end{bmatrix}",
        Q::Transform(value),
    ));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn last_step_is_the_exponential_bit_for_bit() {
        let phi = Vec3::new(0.0, 0.866, 0.5) * 0.524;
        assert_eq!(
            exp3(&phi).last().unwrap().value,
            Q::Rotation(so3::exp(&phi))
        );
        let s = Vec6::new(0.0, 0.0, 1.0, 0.0, -2.0, 0.0) * 1.3;
        assert_eq!(exp6(&s).last().unwrap().value, Q::Transform(se3::exp(&s)));
        let t = Vec6::new(0.0, 0.0, 0.0, 3.0, 0.0, 4.0);
        let steps = exp6(&t);
        assert_eq!(steps[1].value, Q::Case("pure_translation"));
        assert_eq!(steps[2].value, Q::Scalar(5.0));
    }
}
