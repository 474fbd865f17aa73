//! Frame chains step by step: for `inv(T_ad T_db T_bc) T_ad T_de`, each
//! partial product in the order it is computed, which subscript cancels
//! (the subscript cancellation rule of §3.2.1.2 and §3.3.1.2) and what the
//! product maps; inverses swap their frames (Prop. 3.1, (3.64)). A wrench
//! changed by the transposed adjoint, `Ad(T_ab).T * F_a`, is (3.99).

use super::{Shown, transform};
use crate::check::ty::{Frames, Kind};
use crate::diagnostics::Diagnostic;
use crate::eval::interp::{Interp, Typed};
use crate::eval::value::Value;
use crate::syntax::ast::{BinOp, Expr, ExprKind, UnOp};

/// The source text of `e`.
fn src<'s>(it: &Interp<'s>, e: &Expr) -> &'s str {
    it.src.get(e.span.start..e.span.end).unwrap_or("?")
}

/// `X^-1` or `inv(X)` / `TransInv(X)` / `RotInv(X)`: X.
pub(super) fn inverse_of(e: &Expr) -> Option<&Expr> {
    match &e.kind {
        ExprKind::Call { func, args } if args.len() == 1 => {
            let b = crate::builtins::lookup(&func.name)?;
            matches!(b.name, "inv" | "TransInv" | "RotInv").then(|| &args[0])
        }
        ExprKind::Binary {
            op: BinOp::Pow,
            lhs,
            rhs,
            ..
        } => match &rhs.kind {
            ExprKind::Unary {
                op: UnOp::Neg,
                operand,
            } if operand.kind == ExprKind::Number(1.0) => Some(lhs),
            _ => None,
        },
        ExprKind::Paren(items) if items.len() == 1 => inverse_of(&items[0]),
        _ => None,
    }
}

/// The section of the cancellation rule for a product whose left factor
/// is of kind `k`.
fn rule_ref(k: &Kind) -> &'static str {
    match k {
        Kind::SO3 | Kind::So3 => "3.2.1.2",
        Kind::Adjoint { transposed: false } => "Prop. 3.14",
        Kind::Adjoint { transposed: true } => "3.99",
        _ => "3.3.1.2",
    }
}

/// `{a}←{b}` or `untagged`.
fn frames_text(f: &Frames) -> String {
    if f.is_none() {
        "untagged".to_string()
    } else {
        f.to_string()
    }
}

impl Interp<'_> {
    /// The steps of a product of framed values (or of matrices), None for
    /// a product of plain numbers (no chain to show).
    pub(super) fn chain_steps(&mut self, e: &Expr) -> Result<Option<Vec<Shown>>, Diagnostic> {
        if !matches!(e.kind, ExprKind::Binary { op: BinOp::Mul, .. }) {
            return Ok(None);
        }
        let warned = self.warnings.len();
        let units = self.env.units_noted.len();
        let mut out = Vec::new();
        let wrench = self.wrench_steps(e);
        let framed = match wrench {
            Ok(Some(steps)) => {
                out = steps;
                true
            }
            Ok(None) => {
                if let Err(d) = self.chain_into(e, &mut out) {
                    self.warnings.truncate(warned);
                    return Err(d);
                }
                // frames to follow, or at least matrices and vectors (a
                // product of plain numbers has no chain to show)
                out.iter().any(|s| {
                    !s.frames.is_empty()
                        || matches!(&s.value, Value::Num { m, .. } if m.len() > 1)
                        || matches!(s.value, Value::Formula { .. })
                })
            }
            Err(d) => {
                self.warnings.truncate(warned);
                return Err(d);
            }
        };
        self.warnings.truncate(warned);
        self.env.units_noted.truncate(units);
        Ok(framed.then_some(out))
    }

    /// A frame error of `explain e` explained the same way as a chain: the
    /// products that cancel, in order, then the one that does not.
    pub(in crate::eval) fn explain_frame_error(&mut self, e: &Expr, d: Diagnostic) -> Diagnostic {
        let warned = self.warnings.len();
        let units = self.env.units_noted.len();
        let mut lines = Vec::new();
        let _ = self.trace_frames(e, &mut lines);
        self.warnings.truncate(warned);
        self.env.units_noted.truncate(units);
        if lines.is_empty() {
            return d;
        }
        let trace = lines
            .iter()
            .enumerate()
            .map(|(i, l)| format!("  {}. {l}", i + 1))
            .collect::<Vec<_>>()
            .join("\n");
        let help = match &d.help {
            Some(h) => format!("{h}\nthe chain, step by step (§3.3.1.2):\n{trace}"),
            None => format!("the chain, step by step (§3.3.1.2):\n{trace}"),
        };
        d.with_help(help)
    }

    /// The lines of [`Interp::explain_frame_error`]; Err at the product
    /// that fails.
    fn trace_frames(&mut self, e: &Expr, lines: &mut Vec<String>) -> Result<(), ()> {
        let ExprKind::Binary {
            op: BinOp::Mul,
            lhs,
            rhs,
            ..
        } = &e.kind
        else {
            return match inverse_of(e) {
                Some(inner) => self.trace_frames(inner, lines),
                None => Ok(()),
            };
        };
        self.trace_frames(lhs, lines)?;
        self.trace_frames(rhs, lines)?;
        let (Ok(l), Ok(r)) = (self.expr(lhs), self.expr(rhs)) else {
            return Err(());
        };
        let (ls, rs) = (src(self, lhs), src(self, rhs));
        let (lf, rf) = (frames_text(&l.ty.frames), frames_text(&r.ty.frames));
        match self.expr(e) {
            Ok(t) => {
                lines.push(format!(
                    "{ls} · {rs}: ({lf}) · ({rf}) gives {}",
                    frames_text(&t.ty.frames)
                ));
                Ok(())
            }
            Err(_) => {
                let why = match (&l.ty.frames, &r.ty.frames) {
                    (Frames::Pair(_, b), Frames::Pair(c, _) | Frames::One(c)) => {
                        format!("{{{b}}} ≠ {{{c}}}: nothing cancels")
                    }
                    _ => "the frames do not compose".to_string(),
                };
                lines.push(format!("{ls} · {rs}: ({lf}) · ({rf}): {why}"));
                Err(())
            }
        }
    }

    /// `Ad(T_ab).T * F_a`: the steps of (3.99) with T_ab's adjoint.
    fn wrench_steps(&mut self, e: &Expr) -> Result<Option<Vec<Shown>>, Diagnostic> {
        let ExprKind::Binary { lhs, rhs, .. } = &e.kind else {
            return Ok(None);
        };
        let ExprKind::Member { base, member } = &lhs.kind else {
            return Ok(None);
        };
        let ExprKind::Call { func, args } = &base.kind else {
            return Ok(None);
        };
        let is_ad = crate::builtins::lookup(&func.name).is_some_and(|b| b.name == "Adjoint");
        if !is_ad || member.name.as_str() != "T" || args.len() != 1 {
            return Ok(None);
        }
        let t = self.expr(&args[0])?;
        let f = self.expr(rhs)?;
        let (Some(t), Some(f)) = (t.value().and_then(transform), f.value()) else {
            return Ok(None);
        };
        let Some(f) = super::mat::<6, 1>(f) else {
            return Ok(None);
        };
        let steps = crate::lie::steps::motion::wrench_change(&t, &f);
        Ok(Some(steps.into_iter().map(Shown::of).collect()))
    }

    /// Pushes the steps of the product (or factor) `e` and returns it.
    fn chain_into(&mut self, e: &Expr, out: &mut Vec<Shown>) -> Result<Typed, Diagnostic> {
        match &e.kind {
            ExprKind::Binary {
                op: BinOp::Mul,
                lhs,
                rhs,
                ..
            } => {
                let l = self.chain_into(lhs, out)?;
                let r = self.factor(rhs, out)?;
                let t = self.expr(e)?;
                out.push(self.product_step(lhs, rhs, &l, &r, &t));
                Ok(t)
            }
            _ => self.factor(e, out),
        }
    }

    /// A factor of a chain: an inverse of a chain shows the chain and the
    /// swap of its frames; anything else is evaluated as it is.
    fn factor(&mut self, e: &Expr, out: &mut Vec<Shown>) -> Result<Typed, Diagnostic> {
        let Some(inner) = inverse_of(e) else {
            return self.expr(e);
        };
        let x = self.chain_into(inner, out)?;
        let t = self.expr(e)?;
        let (reference, formula) = match x.ty.kind {
            Kind::SO3 => ("Prop. 3.1", "R⁻¹ = Rᵀ"),
            Kind::SE3 => ("3.64", "T⁻¹ = [Rᵀ, −Rᵀp; 0, 1]"),
            _ => ("3.3.1.2", "the inverse"),
        };
        out.push(Shown {
            reference,
            name: "inverse".to_string(),
            text: format!(
                "{}: {formula} maps the other way, {} becomes {}",
                src(self, e),
                frames_text(&x.ty.frames),
                frames_text(&t.ty.frames)
            ),
            latex: format!(r"\left({}\right)^{{-1}}", src(self, inner)),
            note: None,
            value: t.value().cloned().unwrap_or(Value::Bool(false)),
            frames: t.ty.frames.to_list(),
        });
        Ok(t)
    }

    /// The step of one product `lhs rhs` of a chain.
    fn product_step(&self, lhs: &Expr, rhs: &Expr, l: &Typed, r: &Typed, t: &Typed) -> Shown {
        let cancel = match (&l.ty.frames, &r.ty.frames) {
            (Frames::Pair(_, b), Frames::Pair(c, _) | Frames::One(c)) if b == c => {
                format!("{{{b}}} cancels")
            }
            (Frames::None, _) | (_, Frames::None) => {
                "an untagged factor keeps the other's frames".to_string()
            }
            _ => "the frames compose".to_string(),
        };
        let (ls, rs) = (src(self, lhs), src(self, rhs));
        if l.ty.frames.is_none() && r.ty.frames.is_none() {
            return Shown {
                reference: rule_ref(&l.ty.kind),
                name: "chain".to_string(),
                text: format!("{ls} · {rs}: the product as written (no frames to cancel)"),
                latex: format!(r"\left({ls}\right)\left({rs}\right)"),
                note: None,
                value: t.value().cloned().unwrap_or(Value::Bool(false)),
                frames: Vec::new(),
            };
        }
        Shown {
            reference: rule_ref(&l.ty.kind),
            name: "chain".to_string(),
            text: format!(
                "{ls} · {rs}: ({}) · ({}): {cancel}, giving {}",
                frames_text(&l.ty.frames),
                frames_text(&r.ty.frames),
                frames_text(&t.ty.frames)
            ),
            latex: format!(r"\left({ls}\right)\left({rs}\right)"),
            note: None,
            value: t.value().cloned().unwrap_or(Value::Bool(false)),
            frames: t.ty.frames.to_list(),
        }
    }
}
