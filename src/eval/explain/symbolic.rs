//! Closed-form steps over symbols: `exp([S] θ)` with a numeric screw axis
//! S and a symbolic θ is Proposition 3.16 — the axis's ω, v, the point q
//! and pitch h it passes through (§3.3.2.2; h = 0 for a revolute joint),
//! then e^{[ω]θ} by Rodrigues (3.51) and G(θ)v (3.89) as closed forms;
//! `exp([ω̂] θ)` is (3.51).

use super::{Shown, block, expc3, expc6};
use crate::check::ty::Kind;
use crate::diagnostics::Diagnostic;
use crate::eval::formula;
use crate::eval::interp::Interp;
use crate::eval::value::Value;
use crate::lie::steps::{self, Quantity, Step};
use crate::syntax::ast::{BinOp, Expr, ExprKind};

/// [`Shown::new`] with the formula's texts borrowed.
fn shown(reference: &'static str, name: &str, text: &str, latex: &str, value: Value) -> Shown {
    Shown::new(reference, name, text.to_string(), latex.to_string(), value)
}

/// The closed forms of an inverse (Prop. 3.1, (3.64)) or an adjoint
/// (Def. 3.6) over symbols, read from the blocks of the value as the book
/// writes them.
fn inverse_or_adjoint(name: &str, shape: (usize, usize), value: &Value) -> Option<Vec<Shown>> {
    let v3 = Kind::Vector(Some(3));
    let m3 = Kind::Matrix(Some(3), Some(3));
    Some(match (name, shape) {
        ("inv" | "TransInv", (4, 4)) => vec![
            shown(
                "3.64",
                "R_T",
                "Rᵀ (= R⁻¹, Prop. 3.1)",
                r"R^T",
                block(value, 0..3, 0..3, Kind::SO3)?,
            ),
            shown(
                "3.64",
                "p_inv",
                "−Rᵀp",
                r"-R^T p",
                block(value, 0..3, 3..4, v3)?,
            ),
            shown(
                "3.64",
                "T_inv",
                "T⁻¹ = [Rᵀ, −Rᵀp; 0, 1]",
                r"T^{-1} = \begin{bmatrix} R^T & -R^T p \\ 0 & 1 \end{bmatrix}",
                value.clone(),
            ),
        ],
        ("inv" | "RotInv", (3, 3)) => vec![shown(
            "Prop. 3.1",
            "R_inv",
            "R⁻¹ = Rᵀ",
            r"R^{-1} = R^T",
            value.clone(),
        )],
        ("Adjoint", (6, 6)) => vec![
            shown(
                "Def. 3.6",
                "R",
                "R",
                "R",
                block(value, 0..3, 0..3, Kind::SO3)?,
            ),
            shown(
                "Def. 3.6",
                "pR",
                "[p]R",
                r"[p]R",
                block(value, 3..6, 0..3, m3)?,
            ),
            shown(
                "Def. 3.6",
                "Ad",
                "[Ad_T] = [R, 0; [p]R, R]",
                r"[\mathrm{Ad}_T] = \begin{bmatrix} R & 0 \\ [p]R & R \end{bmatrix}",
                value.clone(),
            ),
        ],
        _ => return None,
    })
}

/// The closed form of a log over symbols (§3.2.3.3, §3.3.3.2): tr R
/// (3.54), p, and the parts of the value ([ω̂]θ, vθ) as the book names
/// them; the branch assumed is the statement's note.
fn log_steps(input: &Value, value: &Value) -> Option<Vec<Shown>> {
    let r = formula::mat_of(input)?;
    let v = formula::mat_of(value)?;
    let v3 = Kind::Vector(Some(3));
    let trace = shown(
        "3.54",
        "trace",
        "tr R = r₁₁ + r₂₂ + r₃₃ = 1 + 2 cos θ",
        r"\operatorname{tr} R = 1 + 2\cos\theta",
        formula::scalar(r.block(0..3, 0..3).trace()),
    );
    let expc3 = |m: &crate::sym::Mat| {
        formula::make(&v3, crate::sym::Mat::column(crate::sym::matrix::unskew(m)))
    };
    let mut out = Vec::new();
    match ((r.rows, r.cols), (v.rows, v.cols)) {
        ((3, 3), (3, 3)) => {
            out.push(trace);
            out.push(shown(
                "3.2.3.3",
                "expc",
                "ω̂θ (exponential coordinates)",
                r"\hat\omega\theta",
                expc3(&v),
            ));
        }
        ((3, 3), (3, 1)) => out.push(trace),
        ((4, 4), shape) => {
            out.push(shown(
                "3.62",
                "p",
                "T = [R, p; 0, 1]: p",
                "p",
                formula::make(&v3, r.block(0..3, 3..4)),
            ));
            out.push(trace);
            let (w, vt) = if shape == (4, 4) {
                (expc3(&v.block(0..3, 0..3)), v.block(0..3, 3..4))
            } else {
                (formula::make(&v3, v.block(0..3, 0..1)), v.block(3..6, 0..1))
            };
            out.push(shown(
                "3.2.3.3",
                "expc3",
                "ω̂θ of the rotation",
                r"\hat\omega\theta",
                w,
            ));
            out.push(shown(
                "3.93",
                "v_theta",
                "vθ = θG⁻¹(θ)p (3.93), (3.94)",
                r"v\theta = \theta G^{-1}(\theta) p",
                formula::make(&v3, vt),
            ));
        }
        _ => return None,
    }
    let name = match (v.rows, v.cols) {
        (3, 3) => "so3",
        (4, 4) => "se3",
        _ => "expc",
    };
    out.push(shown(
        "3.2.3.3",
        name,
        "the logarithm",
        r"\log",
        value.clone(),
    ));
    Some(out)
}

impl Interp<'_> {
    /// The closed-form steps of `name(arg)` whose value is symbolic, None
    /// when there is none to show.
    pub(super) fn symbolic_steps(
        &mut self,
        name: &str,
        arg: &Expr,
        value: &Value,
    ) -> Result<Option<Vec<Shown>>, Diagnostic> {
        let Some(m) = formula::mat_of(value) else {
            return Ok(None);
        };
        if let Some(steps) = inverse_or_adjoint(name, (m.rows, m.cols), value) {
            return Ok(Some(steps));
        }
        if matches!(name, "log" | "MatrixLog3" | "MatrixLog6") {
            let input = self.quiet_values(std::slice::from_ref(arg))?;
            return Ok(input.first().and_then(|a| log_steps(a, value)));
        }
        if !matches!(name, "exp" | "MatrixExp3" | "MatrixExp6") {
            return Ok(None);
        }
        // `[S] θ` or `θ [S]`: the numeric axis and the symbolic angle.
        let ExprKind::Binary {
            op: BinOp::Mul,
            lhs,
            rhs,
            ..
        } = &arg.kind
        else {
            return Ok(None);
        };
        let parts = self.quiet_values(&[(**lhs).clone(), (**rhs).clone()])?;
        let (axis, theta) = match (super::has_symbols(&parts[0]), super::has_symbols(&parts[1])) {
            (false, true) => (&parts[0], &parts[1]),
            (true, false) => (&parts[1], &parts[0]),
            _ => return Ok(None),
        };
        let mut out = Vec::new();
        if m.rows == 4 {
            let Some(s) = expc6(axis) else {
                return Ok(None);
            };
            out.push(Shown::of(Step::new(
                "Prop. 3.16",
                "S",
                "S = (ω, v), a screw axis with ‖ω‖ = 1",
                r"\mathcal{S} = (\omega, v)",
                Quantity::Screw(s),
            )));
            // q, ŝ, h of the axis: a revolute joint through q has h = 0.
            out.extend(
                steps::motion::screw_params(&s)
                    .into_iter()
                    .filter(|s| s.name != "case")
                    .map(Shown::of),
            );
            out.push(shown("Prop. 3.16", "theta", "θ", r"\theta", theta.clone()));
            out.push(shown(
                "3.51",
                "R",
                "e^{[ω]θ} = I + sin θ [ω] + (1 − cos θ)[ω]²",
                r"e^{[\omega]\theta} = I + \sin\theta\,[\omega] + (1 - \cos\theta)[\omega]^2",
                formula::make(&Kind::SO3, m.block(0..3, 0..3)),
            ));
            out.push(shown(
                "3.89",
                "p",
                "p = (Iθ + (1 − cos θ)[ω] + (θ − sin θ)[ω]²)v",
                r"p = \left(I\theta + (1 - \cos\theta)[\omega] + (\theta - \sin\theta)[\omega]^2\right) v",
                formula::make(&Kind::Vector(Some(3)), m.block(0..3, 3..4)),
            ));
            out.push(shown(
                "3.89",
                "T",
                "e^{[S]θ} = [e^{[ω]θ}, G(θ)v; 0, 1]",
                r"e^{[\mathcal{S}]\theta} = \begin{bmatrix} e^{[\omega]\theta} & G(\theta) v \\ 0 & 1 \end{bmatrix}",
                value.clone(),
            ));
        } else if m.rows == 3 {
            let Some(w) = expc3(axis) else {
                return Ok(None);
            };
            out.push(Shown::of(Step::new(
                "3.2.3.2",
                "omega_hat",
                "ω̂ (a unit axis)",
                r"\hat\omega",
                Quantity::Vector3(w),
            )));
            out.push(shown("3.2.3.2", "theta", "θ", r"\theta", theta.clone()));
            out.push(shown(
                "3.51",
                "R",
                "e^{[ω̂]θ} = I + sin θ [ω̂] + (1 − cos θ)[ω̂]²",
                r"e^{[\hat\omega]\theta} = I + \sin\theta\,[\hat\omega] + (1 - \cos\theta)[\hat\omega]^2",
                value.clone(),
            ));
        } else {
            return Ok(None);
        }
        Ok(Some(out))
    }
}
