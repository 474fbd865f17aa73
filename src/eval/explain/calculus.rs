//! Derivatives step by step: twists from Ṫ — T⁻¹Ṫ = [V_b] (3.69)–(3.72)
//! and ṪT⁻¹ = [V_s] (3.73)–(3.75) with ω and v read from the blocks the
//! book names — and `diff(x, t)` with the rule used at each node of x
//! (sum, product, quotient, power, chain rule), bottom up.

use super::{Shown, block, chain_inverse};
use crate::check::ty::Kind;
use crate::diagnostics::Diagnostic;
use crate::eval::formula;
use crate::eval::interp::Interp;
use crate::eval::value::Value;
use crate::syntax::ast::{BinOp, Expr, ExprKind, Ident, Name, UnOp};

/// At most this many nodes of a `diff` are shown.
const MAX_NODES: usize = 24;

/// ω of the so(3) block of a numeric or symbolic 4×4 matrix: (m₃₂, m₁₃, m₂₁).
fn omega(v: &Value) -> Option<Value> {
    match v {
        Value::Num { m, .. } => {
            let d = m.to_dmatrix();
            Some(Value::vector(
                Kind::Vector(Some(3)),
                &[d[(2, 1)], d[(0, 2)], d[(1, 0)]],
            ))
        }
        Value::Formula { m, .. } => {
            let w = crate::sym::matrix::unskew(&m.block(0..3, 0..3));
            Some(formula::make(
                &Kind::Vector(Some(3)),
                crate::sym::Mat::column(w),
            ))
        }
        _ => None,
    }
}

/// Whether a value is in se(3): a 4×4 matrix with a skew-symmetric
/// rotation block (to rounding, or exactly for symbols) and a zero last
/// row — what T⁻¹Ṫ and ṪT⁻¹ are (3.72), (3.73).
fn se3_shaped(v: &Value) -> bool {
    match v {
        Value::Num { m, .. } if m.shape() == (4, 4) => {
            let d = m.to_dmatrix();
            let big = d.amax().max(1.0);
            (0..4).all(|j| d[(3, j)] == 0.0)
                && (0..3).all(|i| (0..3).all(|j| (d[(i, j)] + d[(j, i)]).abs() <= 1e-9 * big))
        }
        Value::Formula { m, .. } if (m.rows, m.cols) == (4, 4) => {
            let w = m.block(0..3, 0..3);
            let skew = w
                .add(&w.transpose(), false)
                .is_some_and(|s| s.data.iter().all(num_traits::Zero::is_zero));
            skew && (0..4).all(|j| num_traits::Zero::is_zero(m.get(3, j)))
        }
        _ => false,
    }
}

impl Interp<'_> {
    /// `inv(T) Ṫ` or `Ṫ inv(T)`: the body or space twist (3.69)–(3.75).
    pub(super) fn twist_steps(&mut self, e: &Expr, value: &Value) -> Option<Vec<Shown>> {
        let ExprKind::Binary {
            op: BinOp::Mul,
            lhs,
            rhs,
            ..
        } = &e.kind
        else {
            return None;
        };
        if !se3_shaped(value) {
            return None;
        }
        let (body, t, tdot) = match (chain_inverse(lhs), chain_inverse(rhs)) {
            (Some(t), None) => (true, t, &**rhs),
            (None, Some(t)) => (false, t, &**lhs),
            _ => return None,
        };
        let tv = self.expr(t).ok()?;
        if !matches!(tv.ty.kind, Kind::SE3 | Kind::Unknown)
            && !matches!(tv.value(), Some(Value::Formula { .. }))
        {
            return None;
        }
        let tdv = self.expr(tdot).ok()?.value()?.clone();
        let mut out = vec![
            Shown::new(
                "3.68",
                "T",
                "T = [R, p; 0, 1]".into(),
                r"T = \begin{bmatrix} R & p \\ 0 & 1 \end{bmatrix}".into(),
                tv.value()?.clone(),
            ),
            Shown::new(
                "3.69",
                "T_dot",
                "Ṫ = [Ṙ, ṗ; 0, 0]".into(),
                r"\dot T = \begin{bmatrix} \dot R & \dot p \\ 0 & 0 \end{bmatrix}".into(),
                tdv,
            ),
        ];
        if body {
            out.push(Shown::new(
                "3.69",
                "omega_b",
                "[ω_b] = RᵀṘ".into(),
                r"[\omega_b] = R^T \dot R".into(),
                omega(value)?,
            ));
            out.push(Shown::new(
                "3.70",
                "v_b",
                "v_b = Rᵀṗ".into(),
                r"v_b = R^T \dot p".into(),
                block(value, 0..3, 3..4, Kind::Vector(Some(3)))?,
            ));
            out.push(Shown::new(
                "3.72",
                "V_b",
                "T⁻¹Ṫ = [V_b] = [[ω_b], v_b; 0, 0]".into(),
                r"T^{-1}\dot T = [\mathcal{V}_b]".into(),
                value.clone(),
            ));
        } else {
            out.push(Shown::new(
                "3.73",
                "omega_s",
                "[ω_s] = ṘRᵀ".into(),
                r"[\omega_s] = \dot R R^T".into(),
                omega(value)?,
            ));
            out.push(Shown::new(
                "3.74",
                "v_s",
                "v_s = ṗ − ṘRᵀp = ṗ − ω_s × p".into(),
                r"v_s = \dot p - \omega_s \times p".into(),
                block(value, 0..3, 3..4, Kind::Vector(Some(3)))?,
            ));
            out.push(Shown::new(
                "3.73",
                "V_s",
                "ṪT⁻¹ = [V_s] = [[ω_s], v_s; 0, 0]".into(),
                r"\dot T T^{-1} = [\mathcal{V}_s]".into(),
                value.clone(),
            ));
        }
        Some(out)
    }

    /// `diff(x, t)`: the rule at each node of x, bottom up, each with its
    /// derivative; the last is the derivative of x.
    pub(super) fn diff_steps(&mut self, args: &[Expr]) -> Result<Option<Vec<Shown>>, Diagnostic> {
        let [x, t] = args else {
            return Ok(None);
        };
        let mut out = Vec::new();
        self.diff_node(x, t, &mut out)?;
        Ok((!out.is_empty()).then_some(out))
    }

    fn diff_node(&mut self, x: &Expr, t: &Expr, out: &mut Vec<Shown>) -> Result<(), Diagnostic> {
        // e^g is exp(g) (§4): the chain rule, not the power rule
        let euler = self.euler_call(x);
        let x = euler.as_ref().unwrap_or(x);
        let (rule, latex, children): (&str, &str, Vec<&Expr>) = match &x.kind {
            ExprKind::Binary { op, lhs, rhs, .. } => match op {
                BinOp::Add | BinOp::Sub => (
                    "sum rule: (f ± g)' = f' ± g'",
                    r"(f \pm g)' = f' \pm g'",
                    vec![lhs, rhs],
                ),
                BinOp::Mul => (
                    "product rule: (fg)' = f'g + fg'",
                    r"(fg)' = f'g + fg'",
                    vec![lhs, rhs],
                ),
                BinOp::Div => (
                    "quotient rule: (f/g)' = (f'g − fg')/g²",
                    r"(f/g)' = \frac{f'g - fg'}{g^2}",
                    vec![lhs, rhs],
                ),
                BinOp::Pow => (
                    "power rule: (fⁿ)' = n fⁿ⁻¹ f'",
                    r"(f^n)' = n f^{n-1} f'",
                    vec![lhs],
                ),
            },
            ExprKind::Unary {
                op: UnOp::Neg | UnOp::Pos,
                operand,
            } => ("(−f)' = −f'", r"(-f)' = -f'", vec![operand]),
            ExprKind::Paren(items) if items.len() == 1 => return self.diff_node(&items[0], t, out),
            ExprKind::Call { args, .. } if !args.is_empty() => (
                "chain rule: f(g)' = f'(g) g', entry by entry",
                r"f(g)' = f'(g)\, g'",
                args.iter().collect(),
            ),
            ExprKind::Var(_) => ("", r"\dot x", vec![]),
            _ => ("a constant: its derivative is 0", r"c' = 0", vec![]),
        };
        for c in children {
            if out.len() >= MAX_NODES {
                break;
            }
            self.diff_node(c, t, out)?;
        }
        let value = self.derivative(x, t)?;
        let rule = match (&x.kind, value.as_scalar()) {
            (ExprKind::Var(_), Some(0.0)) => "not a function of t: 0",
            (ExprKind::Var(_), _) => "a function of t: its rate (dt/dt = 1, θ(t) gives θ̇)",
            _ => rule,
        };
        let text = self.src.get(x.span.start..x.span.end).unwrap_or("?");
        out.push(Shown::new(
            "3.2.2",
            "diff",
            format!("d/dt {text}: {rule}"),
            format!(r"\tfrac{{d}}{{dt}}: {latex}"),
            value,
        ));
        Ok(())
    }

    /// `diff(x, t)` evaluated as the builtin does it.
    fn derivative(&mut self, x: &Expr, t: &Expr) -> Result<Value, Diagnostic> {
        let call = Expr {
            kind: ExprKind::Call {
                func: Ident {
                    name: Name::new("diff"),
                    span: x.span,
                },
                args: vec![x.clone(), t.clone()],
            },
            span: x.span,
        };
        Ok(self
            .expr(&call)?
            .value()
            .cloned()
            .unwrap_or(Value::Bool(false)))
    }
}
