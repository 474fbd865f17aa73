//! `solve(lhs == rhs, x)` (LANGUAGE.md §8, Exercises 2.7 and 3.7(b)): the
//! sides are evaluated, not compared, and [`crate::sym::solve`] finds x
//! (of every entry at once when the sides are vectors or matrices).

use super::interp::{Interp, Typed};
use super::value::Value;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::sym::Expr;
use crate::sym::Symbol;
use crate::sym::expr::as_symbol;
use crate::sym::matrix::Mat;
use crate::syntax::ast::{CmpOp, Expr as Ast, ExprKind, Span};
use crate::values::formula;

/// The help of every refusal of `solve`: how it is called.
const HOW: &str = "write solve(lhs == rhs, x) with x declared first: given x : scalar";

impl Interp<'_> {
    /// `solve(eq, x)`: x's value from one equation (or an expression,
    /// taken = 0), a tuple of the real roots of a quadratic; a note names
    /// the coefficient that must not be 0.
    pub(super) fn solve(&mut self, args: &[Ast], span: Span) -> Result<Typed, Diagnostic> {
        let [eq, x] = args else {
            return Err(self
                .domain(span, "solve takes an equation and the unknown")
                .with_help(HOW));
        };
        let (lhs, rhs) = match &eq.kind {
            ExprKind::Compare {
                op: CmpOp::Eq,
                lhs,
                rhs,
                ..
            } => (&**lhs, Some(&**rhs)),
            ExprKind::Compare { op_span, .. } => {
                return Err(self
                    .domain(
                        *op_span,
                        "solve solves an equation: its sides are joined by ==",
                    )
                    .with_help(HOW));
            }
            _ => (eq, None),
        };
        let unknown = self.expr(x)?;
        let sym = unknown
            .value()
            .and_then(formula::scalar_of)
            .and_then(|e| as_symbol(&e))
            .ok_or_else(|| {
                self.domain(
                    x.span,
                    format!(
                        "solve(eq, x) solves for a symbol, and `{}` is not one",
                        self.text(x.span)
                    ),
                )
                .with_help(HOW)
            })?;
        let (left_value, left) = self.side(lhs)?;
        let (right_value, right) = match rhs {
            Some(r) => {
                let (v, m) = self.side(r)?;
                (Some(v), m)
            }
            None => (None, Mat::zeros(left.rows, left.cols)),
        };
        let Some(diff) = left.add(&right, true) else {
            let (r, c) = (right.rows, right.cols);
            return Err(self
                .domain(
                    eq.span,
                    format!(
                        "solve solves scalar equations, or two sides of one size entry by entry, and these sides are {}x{} and {r}x{c}",
                        left.rows, left.cols
                    ),
                )
                .with_help("solve one entry at a time: solve(M[1, 2] == 0, x)"));
        };
        if diff.data.iter().all(|e| e.terms.is_empty()) {
            let sides: Vec<&Value> = std::iter::once(&left_value).chain(&right_value).collect();
            return Err(self
                .domain(
                    eq.span,
                    format!(
                        "cannot solve for {}: {}",
                        sym.name,
                        holds_always(&sides, unknown.value(), &sym)
                    ),
                )
                .with_help(HOW));
        }
        let mut solution = crate::sym::solve::solve_entries(&diff.data, &sym)
            .map_err(|m| {
                self.domain(eq.span, format!("cannot solve for {}: {m}", sym.name))
                    .with_help(
                        "solve finds one unknown of a linear equation, the real roots of a quadratic with exact numbers, or an angle x of a cos x + b sin x = c with exact a, b, c; else give the other symbols numbers first",
                    )
            })?;
        // a root where a side is undefined as typed (its canonical form
        // cancelled the factor: (x − 1)²/(x − 1) is x − 1, but not at 1)
        // is no root: subs there is a division by zero
        let sides: Vec<&Value> = std::iter::once(&left_value).chain(&right_value).collect();
        let mut dropped = Vec::new();
        solution.roots.retain(|r| {
            let at = formula::make(&Kind::Scalar, Mat::scalar(r.clone()));
            let undefined = sides.iter().find_map(|v| {
                let args = [*v, unknown.value()?, &at];
                crate::decide::replay::subs_numbers(&args, &mut Vec::new())?.err()
            });
            if let Some(why) = &undefined {
                dropped.push(format!(
                    "{} = {} ({why})",
                    sym.name,
                    crate::sym::print::expr(r, Default::default())
                ));
            }
            undefined.is_none()
        });
        if solution.roots.is_empty() {
            return Err(self
                .domain(
                    eq.span,
                    format!(
                        "cannot solve for {}: no root is in the domain of the equation as typed: {}",
                        sym.name,
                        dropped.join(", ")
                    ),
                )
                .with_help(HOW));
        }
        if !dropped.is_empty() {
            self.warnings.push(Diagnostic::note(
                ErrorKind::Domain,
                span,
                format!(
                    "not a root: {}, where the equation as typed is undefined",
                    dropped.join(", ")
                ),
            ));
        }
        if let Some(c) = &solution.unless_zero {
            let c = crate::sym::print::expr(c, Default::default());
            self.warnings.push(Diagnostic::note(
                ErrorKind::Domain,
                span,
                format!(
                    "for {c} ≠ 0: where {c} = 0 the equation does not fix {}",
                    sym.name
                ),
            ));
        }
        if let Some(k) = solution.period_of {
            // (2πn/k in lowest terms: 2πn/2 is πn, 2πn/4 is πn/2)
            let step = match (k, k % 2) {
                (1, _) => "2πn".to_string(),
                (2, _) => "πn".to_string(),
                (_, 0) => format!("πn/{}", k / 2),
                _ => format!("2πn/{k}"),
            };
            self.warnings.push(Diagnostic::note(
                ErrorKind::Domain,
                span,
                format!(
                    "the roots in (−π, π]; every {} = root + {step} (n an integer) solves it too",
                    sym.name
                ),
            ));
        }
        let scalar = |e: &Expr| formula::make(&Kind::Scalar, Mat::scalar(e.clone()));
        Ok(match solution.roots.as_slice() {
            [r] => {
                let v = scalar(r);
                Typed::new(Ty::plain(v.kind()), Some(v))
            }
            roots => {
                let vs: Vec<Value> = roots.iter().map(scalar).collect();
                let kinds: Vec<Kind> = vs.iter().map(Value::kind).collect();
                Typed::new(Ty::plain(Kind::tuple(kinds)), Some(Value::Tuple(vs)))
            }
        })
    }

    /// One side of the equation: its value and, a scalar, vector or
    /// matrix, its entries.
    fn side(&mut self, e: &Ast) -> Result<(Value, Mat), Diagnostic> {
        let t = self.expr(e)?;
        let v = t.value().cloned();
        v.and_then(|v| formula::mat_of(&v).map(|m| (v, m))).ok_or_else(|| {
            self.domain(
                e.span,
                format!(
                    "solve solves scalar equations (or vectors and matrices entry by entry), and this side is a {}",
                    t.ty.kind
                ),
            )
            .with_help("solve one entry at a time: solve(M[1, 2] == 0, x)")
        })
    }
}

/// Why an equation whose sides have one canonical form is not solved:
/// it holds for every x where its sides are defined as typed — not
/// at a zero of a divisor the canonical form cancelled (`x/x == 1`
/// holds for every x ≠ 0: [`crate::decide::domain`]), each checked
/// by substituting it as typed where it is a number.
fn holds_always(sides: &[&Value], unknown: Option<&Value>, sym: &Symbol) -> String {
    let mut points: Vec<(Expr, String)> = Vec::new();
    let mut complete = true;
    for v in sides {
        let ex = crate::decide::domain::excluded(v, sym);
        complete &= ex.complete;
        for p in ex.points {
            if points.iter().any(|(q, _)| *q == p) {
                continue;
            }
            let why = if p.as_const().is_some() {
                let at = formula::make(&Kind::Scalar, Mat::scalar(p.clone()));
                let undefined = sides.iter().find_map(|v| {
                    let args = [*v, unknown?, &at];
                    crate::decide::replay::subs_numbers(&args, &mut Vec::new())?.err()
                });
                match undefined {
                    Some(why) => why,
                    // (a zero of a divisor the replay does not
                    // refuse: not claimed either way)
                    None => {
                        complete = false;
                        continue;
                    }
                }
            } else {
                "division by zero".to_string()
            };
            points.push((p, why));
        }
    }
    let x = &sym.name;
    let show = |e: &Expr| crate::sym::print::expr(e, Default::default());
    let why = points
        .iter()
        .map(|(p, why)| format!("{x} = {} ({why})", show(p)))
        .collect::<Vec<_>>()
        .join(" and ");
    match (points.as_slice(), complete) {
        ([], true) => format!("the equation holds for every {x}: both sides are the same"),
        ([(p, one)], true) => format!(
            "the equation holds for every {x} ≠ {}: at {x} = {} a side is undefined as typed ({one}), elsewhere both sides are the same",
            show(p),
            show(p)
        ),
        (_, true) => format!(
            "the equation holds for every {x} except {why}, where a side is undefined as typed; elsewhere both sides are the same"
        ),
        ([], false) => format!(
            "the equation holds for every {x} where both sides are defined as typed: their simplified forms are the same"
        ),
        (_, false) => format!(
            "the equation holds for every {x} where both sides are defined as typed (not at {why}): their simplified forms are the same"
        ),
    }
}
