//! Where a value made from symbols is defined as typed, in one unknown x
//! (`solve`'s identities, LANGUAGE.md §7: never a wrong answer). The
//! canonical form cancels common factors (`x/x` is 1, `(x² − 1)/(x − 1)`
//! is `1 + x`), yet as typed the value is no number where a divisor is 0:
//! `x/x == 1` holds for every x ≠ 0, not for every x. The recipe
//! (`crate::values::recipe`) still has the divisions: each divisor that
//! mentions x is solved for its zeros; a step whose domain this cannot
//! tell (a square root, an arc sine, a tangent, a matrix inverse) makes
//! the answer partial, said as "where it is defined". Also the refusal
//! of a group element whose numbers are not finite ([`not_finite_group`]).

use std::collections::HashSet;
use std::rc::Rc;

use crate::check::ty::Kind;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::sym::expr::{Func, Var};
use crate::sym::{Expr, Symbol};
use crate::syntax::ast::BinOp;
use crate::values::recipe::{Operation, Recipe, Step};
use crate::values::value::Value;

/// The values of x where a value is undefined as typed.
#[derive(Debug, Default, Clone, PartialEq)]
pub struct Excluded {
    /// The zeros in x of its divisors (numbers, or formulas in the other
    /// symbols: `(x − a)/(x − a)` excludes x = a).
    pub points: Vec<Expr>,
    /// Whether these are all: false when a step's domain in x is not
    /// known here (`sqrt(x)^2`, a divisor whose zeros solve cannot find).
    pub complete: bool,
}

/// The builtins defined for every real argument (of the kinds they take).
const TOTAL: &[&str] = &[
    "sin",
    "cos",
    "atan",
    "abs",
    "exp",
    "Rotx",
    "Roty",
    "Rotz",
    "rotx",
    "roty",
    "rotz",
    "deg2rad",
    "rad2deg",
    "transpose",
    "det",
    "trace",
    "dot",
    "cross",
    "skew",
    "VecToso3",
    "vec_to_so3",
];

/// The points where `v`, a value of symbols, is undefined as typed in `x`
/// (see the module).
pub(crate) fn excluded(v: &Value, x: &Symbol) -> Excluded {
    let mut out = Excluded {
        points: Vec::new(),
        complete: true,
    };
    match v {
        Value::Formula { how: Some(r), .. } => walk(r, x, &mut out, &mut HashSet::new()),
        Value::Formula { m, how: None, .. } => m.data.iter().for_each(|e| leaf(e, x, &mut out)),
        _ => {}
    }
    out
}

/// Whether recipe `r` depends on `x`.
fn mentions(r: &Rc<Recipe>, x: &Symbol) -> bool {
    let mut syms = Vec::new();
    crate::values::recipe::symbols(r, &mut syms);
    syms.contains(x)
}

fn walk(r: &Rc<Recipe>, x: &Symbol, out: &mut Excluded, seen: &mut HashSet<*const Recipe>) {
    if !seen.insert(Rc::as_ptr(r)) || !mentions(r, x) {
        return;
    }
    match &r.step {
        Step::Leaf(Value::Formula { m, .. }) => m.data.iter().for_each(|e| leaf(e, x, out)),
        Step::Leaf(_) => {}
        Step::Op(op) => {
            match op {
                Operation::Arith(BinOp::Div) => zeros_of(&r.args[1], x, out),
                Operation::Inverse if r.kind == Kind::Scalar => zeros_of(&r.args[0], x, out),
                Operation::Arith(BinOp::Pow) => match exponent(&r.args[1]) {
                    Some(k) if k >= 0.0 && k.fract() == 0.0 => {}
                    Some(k) if k.fract() == 0.0 && !mentions(&r.args[1], x) => {
                        zeros_of(&r.args[0], x, out)
                    }
                    _ => out.complete = false,
                },
                Operation::Inverse => out.complete = false,
                Operation::Call(name) if !TOTAL.contains(name) => out.complete = false,
                _ => {}
            }
            r.args.iter().for_each(|a| walk(a, x, out, seen));
        }
        Step::Part(_) | Step::Retag | Step::Closed(_) => {
            r.args.iter().for_each(|a| walk(a, x, out, seen))
        }
        Step::Range(_) | Step::Compare(_) | Step::Guard(_) | Step::LogRate | Step::Rate(..) => {
            out.complete = false
        }
    }
}

/// The exponent of a power, when it is a number.
fn exponent(r: &Rc<Recipe>) -> Option<f64> {
    crate::decide::partly::made_with(r, &|_| None)?.as_scalar()
}

/// A canonical form read at numbers: defined where its calls and its
/// negative powers are; those that mention x make the answer partial.
fn leaf(e: &Expr, x: &Symbol, out: &mut Excluded) {
    for m in e.terms.keys() {
        for (v, k) in m {
            let partial = match v {
                Var::Sym(s) => s == x && *k < 0,
                Var::Pi | Var::Z(_) => false,
                Var::Call(c) => {
                    c.args.iter().any(|a| has(a, x))
                        && (*k < 0
                            || !matches!(
                                c.f,
                                Func::Sin | Func::Cos | Func::Atan | Func::Abs | Func::Exp
                            ))
                }
            };
            if partial {
                out.complete = false;
            }
        }
    }
}

/// The zeros in x of divisor `r`, a scalar: its roots as `solve` finds
/// them; else the answer is partial.
fn zeros_of(r: &Rc<Recipe>, x: &Symbol, out: &mut Excluded) {
    if !mentions(r, x) {
        return;
    }
    let Some(Value::Formula { m, .. }) = crate::decide::partly::made_with(r, &|_| None) else {
        out.complete = false;
        return;
    };
    let [e] = m.data.as_slice() else {
        out.complete = false;
        return;
    };
    // (x² + 1 has no real zero: nothing excluded, and nothing unknown)
    if crate::sym::solve::never_zero(e, x) {
        return;
    }
    match crate::sym::solve::solve(e, x) {
        Ok(s) if s.unless_zero.is_none() && s.period_of.is_none() => {
            for p in s.roots {
                if !out.points.contains(&p) {
                    out.points.push(p);
                }
            }
        }
        _ => out.complete = false,
    }
}

/// Whether `x` occurs in `e`.
fn has(e: &Expr, x: &Symbol) -> bool {
    let mut found = Vec::new();
    e.symbols(&mut found);
    found.contains(x)
}

/// A rotation, transform, Lie-algebra element or adjoint with an inf or NaN
/// entry is not one: a domain error (`Rotz(inf)`), rather than a NaN matrix
/// labelled SO(3).
pub(crate) fn not_finite_group(
    v: &Value,
    name: &str,
    span: crate::span::Span,
) -> Result<(), Diagnostic> {
    if let Value::Num { kind, m, .. } = v
        && matches!(
            kind,
            Kind::SO3
                | Kind::SE3
                | Kind::SO2
                | Kind::SE2
                | Kind::So3
                | Kind::Se3
                | Kind::So2
                | Kind::Se2
                | Kind::Adjoint { .. }
        )
        && !m.all_finite()
    {
        return Err(Diagnostic::error(
            ErrorKind::Domain,
            span,
            format!("{name} gives no finite {kind}: an argument is inf or NaN"),
        ));
    }
    Ok(())
}
