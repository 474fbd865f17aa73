//! Comparisons and `assert` (LANGUAGE.md §3): `a == b` is exact, `a ≈ b`
//! (typed `~=`) holds within 1e-9 relative, both give a bool; `assert cond`
//! stops a script with an `assert` error that shows both sides. Without
//! numbers (`chasles check`) only the kinds and frames of the two sides are
//! checked: they must have the same shape and the same frames.
//!
//! [`equal`] is the one place that decides equality of two values; for
//! symbolic sides it asks [`crate::decide::equality::symbolic_equal`] (trees over `given` matrices)
//! or the canonical forms of [`super::formula::equal`] (symbolic scalars).

use super::interp::{Interp, Typed};
use super::value::Value;
use crate::decide::witness::AtPoints;

use crate::check::rules::{self, RuleError};
use crate::check::ty::{Frames, Kind, Ty};
pub use crate::decide::equality::{APPROX_TOL, equal, largest_difference};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{BinOp, CmpOp, Expr, ExprKind, Span};

/// How `op` reads in messages.
fn op_text(op: CmpOp) -> &'static str {
    op.text()
}

/// The static rule: both sides of one shape (when known) and one frame
/// tag (or one untagged, or a displacement in the outer frame of the
/// other); the result is a bool.
pub fn compare_rule(l: &Ty, r: &Ty) -> Result<Ty, RuleError> {
    let type_error = |message: String| {
        RuleError::from(crate::check::rules::Refusal {
            kind: Some(ErrorKind::Type),
            message,
            ..Default::default()
        })
    };
    let comparable = match (&l.kind, &r.kind) {
        (Kind::Unknown, _) | (_, Kind::Unknown) => true,
        (Kind::Bool, Kind::Bool) => true,
        // part by part, each with its own kind and frames, as the values
        // are compared
        (Kind::Tuple(a), Kind::Tuple(b)) if a.len() == b.len() => {
            for i in 0..a.len() {
                if let (Some(x), Some(y)) = (l.part(i), r.part(i)) {
                    compare_rule(&x, &y)?;
                }
            }
            return Ok(Ty::plain(Kind::Bool));
        }
        (Kind::Tuple(_), Kind::Tuple(_)) => false,
        (Kind::Mechanism | Kind::Function, _) | (_, Kind::Mechanism | Kind::Function) => false,
        (a, b) => match (a.shape(), b.shape()) {
            (Some((ar, ac)), Some((br, bc))) => agree(ar, br) && agree(ac, bc),
            _ => false,
        },
    };
    if !comparable {
        let mut e = type_error(format!("cannot compare {} with {}", l.kind.a(), r.kind.a()));
        if matches!(l.kind, Kind::Mechanism) || matches!(r.kind, Kind::Mechanism) {
            e.help = Some("compare their degrees of freedom: dof(m1) == dof(m2)".into());
        } else {
            e.help = Some("both sides of == and ≈ must have the same shape".into());
        }
        return Err(e);
    }
    // A displacement in {a} (`exp(log(T_ab))`) may equal a map out of {a}.
    let displacement_of =
        |d: &Frames, f: &Frames| matches!(d, Frames::Disp(a) if f.outer() == Some(a));
    // A moved frame may be the frame it is compared with, as a binding
    // names it (`T_sc = exp([S] θ) T_sb`): Example 3.4's T_sc = e^{[S]θ} T_sb
    // compares {s}←{b'} with {s}←{c}.
    let moved_onto = matches!(
        (&l.frames, &r.frames),
        (Frames::Pair(x, y), Frames::Pair(a, b)) if x == a && (y.is_moved() || b.is_moved())
    );
    if !moved_onto
        && !displacement_of(&l.frames, &r.frames)
        && !displacement_of(&r.frames, &l.frames)
    {
        rules::same_frames("compare", l, r)?;
    }
    Ok(Ty::plain(Kind::Bool))
}

/// True for the literal `0`.
fn literal_zero(e: &Expr) -> bool {
    matches!(&e.kind, ExprKind::Number(x) if *x == 0.0)
}

impl Interp<'_> {
    /// The zero vector or matrix of the shape of `t` (not a scalar), for
    /// the `0` of `M == 0`; None when `t` has no such shape.
    fn zero_like(&self, t: &Typed) -> Option<Typed> {
        let (Some(r), Some(c)) = t.ty.kind.shape()? else {
            return None;
        };
        if (r, c) == (1, 1) {
            return None;
        }
        let kind = if c == 1 {
            Kind::Vector(Some(r))
        } else {
            Kind::Matrix(Some(r), Some(c))
        };
        let val = self.running().then(|| Value::Num {
            kind,
            m: crate::values::num::Num::zeros(r, c),
            exact: crate::values::exact::Exact::Typed,
        });
        Some(Typed::new(Ty::plain(kind), val))
    }
}

/// True when both sides are numbers (no symbol to wait for).
fn numbers(a: &Value, b: &Value) -> bool {
    matches!(a, Value::Num { .. }) && matches!(b, Value::Num { .. })
}

fn agree(a: Option<usize>, b: Option<usize>) -> bool {
    a.is_none() || b.is_none() || a == b
}

/// Both sides of a comparison, checked and evaluated.
struct Sides {
    l: Typed,
    r: Typed,
    verdict: Option<bool>,
    /// Both sides have values, and the comparison cannot be decided
    /// while their symbols are free.
    undecided: bool,
}

impl Interp<'_> {
    /// `lhs == rhs`, `lhs ≈ rhs`: a bool.
    pub(super) fn compare(
        &mut self,
        op: CmpOp,
        lhs: &Expr,
        rhs: &Expr,
        op_span: Span,
    ) -> Result<Typed, Diagnostic> {
        let sides = self.sides(op, lhs, rhs, op_span)?;
        // (over symbols, the bool is decided again once they have numbers)
        let val = match (sides.verdict, sides.l.value(), sides.r.value()) {
            (Some(v), Some(a), Some(b)) => Some(match self.lowered_sides(a, b, op_span) {
                // (over given vectors: their components, decided again)
                Some((x, y)) => crate::values::recipe::compared(v, op, &x, &y),
                // (decided by taking a `given` axis as a unit vector: the
                // comparison is kept, shown decided, and decided again
                // with the numbers bound later, §7, `super::relied`)
                None => self
                    .relied_comparison(op, a, b)
                    .unwrap_or_else(|| crate::values::recipe::compared(v, op, a, b)),
            }),
            // Undecided while its symbols are free: a bool that waits for
            // their numbers and is then decided as typed first (§7).
            (None, Some(a), Some(b)) if sides.undecided => {
                if numbers(a, b) {
                    return Err(self.too_close(op, lhs, rhs, op_span, (a, b)));
                }
                match crate::values::waiting::make(op, a, b) {
                    Some(w) => Some(w),
                    // (a side a tree of `given` matrices: the tree waits)
                    None if matches!(a, Value::Sym(_)) || matches!(b, Value::Sym(_)) => {
                        let mut note = self.undecided(op, lhs, rhs, op_span, false);
                        note.severity = crate::diagnostics::Severity::Note;
                        note.message += ": it is decided once its symbols have numbers";
                        note.help = None;
                        self.warnings.push(note);
                        Some(Value::Sym(super::value::Sym::Compare(
                            op,
                            Box::new(crate::seam::apply::to_sym(a)),
                            Box::new(crate::seam::apply::to_sym(b)),
                        )))
                    }
                    None => return Err(self.undecided(op, lhs, rhs, op_span, false)),
                }
            }
            (v, ..) => v.map(Value::Bool),
        };
        Ok(Typed::new(Ty::plain(Kind::Bool), val))
    }

    /// "cannot decide `a < b`" of two exact numbers closer than their
    /// bounds can tell apart (π against 50 digits of it); "cannot decide
    /// `a == b`" of numbers made from exact ones whose certified values
    /// agree far past rounding, though no proof says they are equal
    /// (`cos(pi/7) + cos(3*pi/7) + cos(5*pi/7) == 1/2`, `crate::decide::certify`).
    fn too_close(
        &self,
        op: CmpOp,
        lhs: &Expr,
        rhs: &Expr,
        op_span: Span,
        (a, b): (&Value, &Value),
    ) -> Diagnostic {
        let shown = format!(
            "{} {} {}",
            self.text(lhs.span).trim(),
            op_text(op),
            self.text(rhs.span).trim()
        );
        if let Some(n) = crate::decide::equality::agreement(a, b) {
            let proof = if op == CmpOp::Eq {
                ", but chasles cannot prove this identity"
            } else {
                ", closer than chasles can tell apart"
            };
            return Diagnostic::error(
                ErrorKind::Domain,
                op_span,
                format!("cannot decide `{shown}`: the two sides agree to {n} digits{proof}"),
            )
            .with_help("compare within rounding with ≈ (typed ~=)");
        }
        Diagnostic::error(
            ErrorKind::Domain,
            op_span,
            format!("cannot decide `{shown}`: the two sides agree to 50 decimal places"),
        )
        .with_help("compare within rounding with ≈ (typed ~=)")
    }

    /// "cannot decide `a < b` without numbers"; in an `assert`, which
    /// checks its condition when it runs, the help says to bind first.
    fn undecided(
        &self,
        op: CmpOp,
        lhs: &Expr,
        rhs: &Expr,
        op_span: Span,
        assert: bool,
    ) -> Diagnostic {
        Diagnostic::error(
            ErrorKind::Domain,
            op_span,
            format!(
                "cannot decide `{} {} {}` without numbers",
                self.text(lhs.span).trim(),
                op_text(op),
                self.text(rhs.span).trim()
            ),
        )
        .with_help(if assert {
            "an assert checks its condition when it runs: bind numbers to the given names before it"
        } else {
            "bind numbers to the given names, then compare"
        })
    }

    fn sides(
        &mut self,
        op: CmpOp,
        lhs: &Expr,
        rhs: &Expr,
        op_span: Span,
    ) -> Result<Sides, Diagnostic> {
        // `R Rᵀ == I`: an `I` takes its size from the other side, as in a sum.
        let (l, r) = self.operands(BinOp::Sub, lhs, rhs)?;
        // `M == 0`: a 0 stands for the zero matrix that fits (§7)
        let (l, r) = match (literal_zero(lhs), literal_zero(rhs), op.is_order()) {
            (false, true, false) => {
                let z = self.zero_like(&l);
                (l, z.unwrap_or(r))
            }
            (true, false, false) => {
                let z = self.zero_like(&r);
                (z.unwrap_or(l), r)
            }
            _ => (l, r),
        };
        let rule = if op.is_order() {
            crate::decide::order::order_rule
        } else {
            compare_rule
        };
        if let Err(e) = rule(&l.ty, &r.ty) {
            self.rule_failure(e, op_span, Some(lhs.span), Some(rhs.span), Some(op_span))?;
        }
        let mut undecided = false;
        let verdict = match (l.val.as_deref(), r.val.as_deref()) {
            (Some(a), Some(b)) => match self
                .lowered_equal(a, b, op, op_span)
                .unwrap_or_else(|| self.equal_trees(a, b, op))
            {
                // (a verdict over symbols that rests on a number with no
                // exact form is found at points: `crate::decide::witness`)
                Ok(Some(v)) if op == CmpOp::Eq => {
                    match crate::decide::witness::at_points(a, b, false) {
                        Some(AtPoints::Differ(d)) => {
                            if v {
                                self.warnings.push(Diagnostic::note(
                                ErrorKind::Domain,
                                op_span,
                                format!(
                                    "the two sides print alike but are different functions: with numbers for their symbols they differ by {}",
                                    format!("{:.1e}", d.abs()).replace(".0e", "e")
                                ),
                            ));
                            }
                            Some(false)
                        }
                        Some(AtPoints::Identity) => Some(true),
                        Some(AtPoints::Agree(n)) => {
                            self.warnings.push(Diagnostic::note(
                            ErrorKind::Domain,
                            op_span,
                            format!(
                                "with numbers for their symbols the two sides agree to {n} digits, but chasles cannot prove they are the same function"
                            ),
                        ).with_help("compare within rounding with ≈ (typed ~=)"));
                            undecided = true;
                            None
                        }
                        // (false by rounding only, of sides made from exact
                        // numbers that no point decided: not known to differ)
                        // (and of symbolic sides whose float coefficients,
                        // with no exact form, cancel to rounding: a float
                        // coefficient never decides `==`, issue 35)
                        None if !v
                            && !numbers(a, b)
                            && crate::decide::equality::rounding_only(a, b) =>
                        {
                            let message = if crate::decide::witness::on_float(a, b) {
                                "the two sides differ only by the rounding of numbers made from exact ones, and chasles cannot prove them equal or different"
                            } else {
                                "the two sides differ only by the rounding of float coefficients (numbers with no exact form), so chasles cannot decide whether they are equal"
                            };
                            self.warnings.push(
                                Diagnostic::note(ErrorKind::Domain, op_span, message)
                                    .with_help("compare within rounding with ≈ (typed ~=)"),
                            );
                            undecided = true;
                            None
                        }
                        None => {
                            if !v
                                && let Some(note) =
                                    crate::decide::equality::false_note(a, b, op_span)
                            {
                                self.warnings.push(note);
                            }
                            Some(v)
                        }
                    }
                }
                Ok(Some(v)) => Some(v),
                // (the canonical forms cannot tell, where a phase stands
                // for a number with no exact form: proven by the lifted
                // forms, or a certified difference at a point)
                Ok(None) if op == CmpOp::Eq => {
                    match crate::decide::witness::at_points(a, b, true) {
                        Some(AtPoints::Identity) => Some(true),
                        Some(AtPoints::Differ(_)) => Some(false),
                        _ => {
                            undecided = true;
                            None
                        }
                    }
                }
                Ok(None) => {
                    undecided = true;
                    None
                }
                Err(m) => return Err(Diagnostic::error(ErrorKind::Type, op_span, m)),
            },
            _ => None,
        };
        Ok(Sides {
            l,
            r,
            verdict,
            undecided,
        })
    }

    /// `assert cond`: Ok when the condition holds (or, in `check`, when it
    /// is well typed); an `assert` error showing both sides when it fails.
    pub(super) fn assert(&mut self, cond: &Expr) -> Result<(), Diagnostic> {
        if let ExprKind::Compare {
            op,
            lhs,
            rhs,
            op_span,
        } = &cond.kind
        {
            let s = self.sides(*op, lhs, rhs, *op_span)?;
            // (an assert over free symbols can neither pass nor fail)
            if s.undecided {
                if let (Some(a), Some(b)) = (s.l.value(), s.r.value())
                    && numbers(a, b)
                {
                    return Err(self.too_close(*op, lhs, rhs, *op_span, (a, b)));
                }
                return Err(self.undecided(*op, lhs, rhs, *op_span, true));
            }
            if s.verdict != Some(false) {
                return Ok(());
            }
            let (Some(a), Some(b)) = (s.l.val.as_deref(), s.r.val.as_deref()) else {
                return Ok(());
            };
            return Err(self.assert_failed(cond, *op, (lhs, a), (rhs, b)));
        }
        let t = self.expr(cond)?;
        if !matches!(t.ty.kind, Kind::Bool | Kind::Unknown) {
            return Err(Diagnostic::error(
                ErrorKind::Type,
                cond.span,
                format!("assert needs a condition, not {}", t.ty.kind.a()),
            )
            .with_help("compare two values: assert a == b, or assert a ≈ b (typed ~=)"));
        }
        // (a comparison waiting for numbers can neither pass nor fail)
        if let Some(w) = t.value().and_then(crate::values::waiting::first) {
            return Err(Diagnostic::error(
                ErrorKind::Domain,
                cond.span,
                format!(
                    "cannot decide `{}` without numbers for {}",
                    crate::values::waiting::text(w, 4.into()).unwrap_or_default(),
                    crate::values::waiting::symbols(w)
                ),
            )
            .with_help(
                "an assert checks its condition when it runs: bind numbers to the given names before it",
            ));
        }
        // (a comparison decided over free symbols is its bool)
        let shown = t.value().and_then(super::formula::constant_shown);
        match shown.as_ref().or(t.value()) {
            Some(Value::Bool(false)) => Err(Diagnostic::error(
                ErrorKind::Assert,
                cond.span,
                format!(
                    "assertion failed: `{}` is false",
                    self.text(cond.span).trim()
                ),
            )),
            _ => Ok(()),
        }
    }

    /// The error of a failed comparison: both sides' values under them,
    /// the largest difference, and both values in the help line (which
    /// JSON carries too).
    fn assert_failed(
        &self,
        cond: &Expr,
        op: CmpOp,
        (lhs, a): (&Expr, &Value),
        (rhs, b): (&Expr, &Value),
    ) -> Diagnostic {
        // `==` failing by a rounding error needs every digit to be seen.
        let digits = if op == CmpOp::Eq { 17 } else { 10 };
        let show = |v: &Value| crate::values::format::inline(v, digits);
        let mut message = format!("assertion failed: `{}`", self.text(cond.span).trim());
        if let Some((d, i, j)) = largest_difference(a, b) {
            let d = if d.is_infinite() {
                "NaN or inf".to_string()
            } else if (1e-3..1e6).contains(&d) {
                crate::values::number::fmt_num(d, 4)
            } else {
                format!("{d:.3e}")
            };
            // Where: [i, j] in a matrix, [i] in a vector, nothing for a number.
            let at = match a.as_matrix().map(|m| m.shape()) {
                Some((1, 1)) | None => String::new(),
                Some((_, 1)) => format!(" at [{i}]"),
                Some(_) => format!(" at [{i}, {j}]"),
            };
            message.push_str(&match op {
                CmpOp::Approx => {
                    format!(" (largest difference {d}{at}; ≈ allows {APPROX_TOL:e} relative)")
                }
                _ if op.is_order() => String::new(),
                _ => format!(" (largest difference {d}{at})"),
            });
        }
        // Short values stand under their side; long ones only in the help.
        let label = |side: &str, v: &Value| {
            let text = show(v);
            if text.chars().count() <= 40 {
                format!("{side}: {text}")
            } else {
                side.to_string()
            }
        };
        Diagnostic::error(ErrorKind::Assert, lhs.span, message)
            .with_primary_label(label("left", a))
            .with_label(rhs.span, label("right", b))
            .with_help(format!("left = {}; right = {}", show(a), show(b)))
    }
}

#[cfg(test)]
mod tests {
    use super::super::value::Sym;
    use super::*;
    use crate::decide::equality::symbolic_equal;

    fn v(xs: &[f64]) -> Value {
        Value::vector(Kind::Vector(Some(xs.len())), xs)
    }

    #[test]
    fn exact_and_approximate() {
        let a = v(&[1.0, 2.0]);
        let b = v(&[1.0, 2.0 + 1e-12]);
        assert_eq!(equal(&a, &b, CmpOp::Eq), Ok(Some(false)));
        assert_eq!(equal(&a, &b, CmpOp::Approx), Ok(Some(true)));
        let c = v(&[1.0, 2.0 + 1e-6]);
        assert_eq!(equal(&a, &c, CmpOp::Approx), Ok(Some(false)));
        // Relative to the larger side: 1e12 and 1e12 + 1 agree.
        assert_eq!(
            equal(&v(&[1e12]), &v(&[1e12 + 1.0]), CmpOp::Approx),
            Ok(Some(true))
        );
        assert!(equal(&a, &v(&[1.0, 2.0, 3.0]), CmpOp::Eq).is_err());
        assert_eq!(
            equal(&v(&[f64::NAN]), &v(&[f64::NAN]), CmpOp::Approx),
            Ok(Some(false))
        );
        assert_eq!(
            equal(&v(&[f64::INFINITY]), &v(&[f64::INFINITY]), CmpOp::Approx),
            Ok(Some(true))
        );
    }

    #[test]
    fn largest_difference_says_where() {
        let m = |xs: &[f64]| Value::Num {
            kind: Kind::Matrix(Some(2), Some(2)),
            m: nalgebra::DMatrix::from_row_slice(2, 2, xs).into(),
            exact: Default::default(),
        };
        let (d, i, j) = largest_difference(&m(&[1.0, 2.0, 3.0, 4.0]), &m(&[1.0, 2.0, 3.5, 4.1]))
            .expect("same shape");
        assert_eq!((d, i, j), (0.5, 2, 1));
        let (d, ..) = largest_difference(&m(&[f64::NAN, 0.0, 0.0, 0.0]), &m(&[0.0; 4])).unwrap();
        assert!(d.is_infinite());
        assert!(largest_difference(&v(&[1.0]), &m(&[0.0; 4])).is_none());
    }

    #[test]
    fn symbols_compare_structurally() {
        let t = Sym::Name("t".into());
        assert_eq!(symbolic_equal(&t, &t.clone(), CmpOp::Eq), Some(true));
        assert_eq!(symbolic_equal(&t, &Sym::Name("u".into()), CmpOp::Eq), None);
        // Constants that print alike at 4 digits are still told apart.
        let c = |x: f64| Sym::Const(Box::new(Value::scalar(x)), "1".into());
        assert_eq!(symbolic_equal(&c(1.00001), &c(1.00002), CmpOp::Eq), None);
        assert_eq!(
            symbolic_equal(&c(1.00001), &c(1.00001), CmpOp::Eq),
            Some(true)
        );
    }

    #[test]
    fn rule_needs_one_shape_and_frame() {
        let v3 = Ty::plain(Kind::Vector(Some(3)));
        assert!(compare_rule(&v3, &Ty::plain(Kind::SO3)).is_err());
        assert!(
            compare_rule(
                &Ty::plain(Kind::SO3),
                &Ty::plain(Kind::Matrix(Some(3), Some(3)))
            )
            .is_ok()
        );
        let a = Ty::new(Kind::SE3, crate::check::ty::Frames::pair("a", "b"));
        let c = Ty::new(Kind::SE3, crate::check::ty::Frames::pair("a", "c"));
        let e = compare_rule(&a, &c).unwrap_err();
        assert_eq!(e.kind, Some(ErrorKind::Frame));
        // exp(log(T_ab)) is a displacement in {a}: comparable with T_ab.
        let d = Ty::new(Kind::SE3, Frames::Disp(crate::check::ty::Frame::named("a")));
        assert!(compare_rule(&d, &a).is_ok());
        let d = Ty::new(Kind::SE3, Frames::Disp(crate::check::ty::Frame::named("b")));
        assert!(compare_rule(&d, &a).is_err());
    }
}
