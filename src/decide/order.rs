//! Orders of scalars (LANGUAGE.md §3): `a < b`, `a <= b` (`≤`), `a > b`,
//! `a >= b` (`≥`) give a bool, in an expression or an `assert`. Only
//! scalars are ordered: a vector or a matrix is a type error that says to
//! compare a norm or an entry.

use crate::check::rules::RuleError;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::ErrorKind;
use crate::syntax::ast::CmpOp;
use crate::values::value::Value;

/// The static rule of an order: both sides scalars (or not known yet);
/// the result is a bool with no frames.
pub fn order_rule(l: &Ty, r: &Ty) -> Result<Ty, RuleError> {
    for side in [l, r] {
        if !side.kind.maybe_scalar() && !matches!(side.kind, Kind::Unknown) {
            return Err(RuleError::from(crate::check::rules::Refusal {
                kind: Some(ErrorKind::Type),
                message: format!("only numbers are ordered, not {}", side.kind.a()),
                help: Some(
                    "compare a number made from it: norm(v) < 1, R[1, 1] > 0, dof(m) >= 1".into(),
                ),
                ..Default::default()
            }));
        }
    }
    Ok(Ty::plain(Kind::Bool))
}

/// The number of a scalar value: plain, or an exact or symbolic one with
/// no symbols left.
fn number(v: &Value) -> Option<f64> {
    match v {
        Value::Formula { m, .. } if m.rows == 1 && m.cols == 1 => m.get(0, 0).as_f64(),
        _ => v.as_scalar(),
    }
}

/// Whether `a op b` holds: `Ok(None)` when a side still has symbols.
pub fn holds(a: &Value, b: &Value, op: CmpOp) -> Result<Option<bool>, String> {
    let (Some(x), Some(y)) = (number(a), number(b)) else {
        if matches!(a, Value::Formula { .. } | Value::Sym(_))
            || matches!(b, Value::Formula { .. } | Value::Sym(_))
        {
            return Ok(proven(a, b, op));
        }
        return Err(format!(
            "only numbers are ordered: cannot compare {} with {}",
            a.kind().a(),
            b.kind().a()
        ));
    };
    // Exact numbers compare exactly (§3, §7): `sqrt(2)*sqrt(3) <= sqrt(6)`
    // is true though the floats may differ in the last bit.
    // (always by the exact forms when both sides have one: floats of
    // exact numbers can be far from them, tan(2π) is −2.4e-16 and
    // (0.1 − 10¹³) + 10¹³ is 0.0996)
    let order = match exact_order(a, b) {
        Some(Some(o)) => Some(o),
        // (exact sides closer than the bounds of π can tell: honest)
        Some(None) => return Ok(None),
        // (made from exact numbers: by the certified sign of the
        // difference, `cos(1e-9) < 1` though the floats are equal; sides
        // that agree far past rounding compare as floats, as the same
        // sides over symbols bound later do: `sqrt(a) sqrt(a) <= a`)
        None => match super::certify::equal(a, b) {
            Some(super::certify::Verdict::Equal) => Some(std::cmp::Ordering::Equal),
            Some(super::certify::Verdict::Differ(d)) => d.partial_cmp(&0.0),
            _ => x.partial_cmp(&y),
        },
    };
    use std::cmp::Ordering::{Equal, Greater, Less};
    Ok(Some(match (op, order) {
        // (NaN is in no order: every comparison with it is false)
        (_, None) => false,
        (CmpOp::Lt, Some(o)) => o == Less,
        (CmpOp::Le, Some(o)) => o != Greater,
        (CmpOp::Gt, Some(o)) => o == Greater,
        (CmpOp::Ge, Some(o)) => o != Less,
        // Equalities are decided by `equal`; as numbers they are these.
        (CmpOp::Eq | CmpOp::Approx, Some(o)) => o == Equal,
    }))
}

/// `a op b` over free symbols when it holds (or fails) for every real
/// number they may take, proven from the canonical form of `a − b`: a sum
/// of positive multiples of even powers of symbols (and of π) is ≥ 0, and
/// positive with a positive constant term (`a^2 + 1 > 0`). None when not
/// proven: the comparison then waits for the numbers (§7: "what cannot be
/// decided is said, never guessed").
fn proven(a: &Value, b: &Value, op: CmpOp) -> Option<bool> {
    let side = |v: &Value| match v {
        Value::Formula { kind, .. } if *kind == crate::check::ty::Kind::Bool => None,
        Value::Formula { .. } | Value::Num { .. } => crate::values::formula::scalar_of(v),
        _ => None,
    };
    let d = side(a)?.sub(&side(b)?);
    let (up, down) = (sign(&d), sign(&d.neg()));
    // (`Some(true)`: > 0 for every number; `Some(false)`: ≥ 0)
    match op {
        CmpOp::Gt => match (up, down) {
            (Some(true), _) => Some(true),
            (_, Some(_)) => Some(false),
            _ => None,
        },
        CmpOp::Ge => match (up, down) {
            (Some(_), _) => Some(true),
            (_, Some(true)) => Some(false),
            _ => None,
        },
        CmpOp::Lt => match (down, up) {
            (Some(true), _) => Some(true),
            (_, Some(_)) => Some(false),
            _ => None,
        },
        CmpOp::Le => match (down, up) {
            (Some(_), _) => Some(true),
            (_, Some(true)) => Some(false),
            _ => None,
        },
        CmpOp::Eq | CmpOp::Approx => None,
    }
}

/// Some(true) when `e` > 0 for every real value of its symbols, Some(false)
/// when only `e` ≥ 0 is proven, None when neither: each term a positive
/// real coefficient times π and even powers of real symbols.
fn sign(e: &crate::sym::Expr) -> Option<bool> {
    use crate::sym::coef::Coef;
    use crate::sym::expr::Var;
    let mut strict = false;
    for (mono, c) in &e.terms {
        let positive = match c {
            Coef::Exact { re, im } => im.is_zero() && re.signum() > 0.0,
            Coef::Approx { re, im } => *im == 0.0 && *re > 0.0,
        };
        if !positive {
            return None;
        }
        let mut constant = true;
        for (v, k) in mono {
            match v {
                Var::Pi => {}
                Var::Sym(_) if *k > 0 && k % 2 == 0 => constant = false,
                _ => return None,
            }
        }
        strict |= constant;
    }
    Some(strict)
}

/// The order of two scalars that both have exact forms (a number typed
/// or made exactly, or a formula with no symbols left): by the sign of
/// their exact difference, exactly when it is a sum of square roots,
/// else (π in it) between bounds of 50 decimal places
/// ([`crate::sym::sign::sign_with_pi`]: `pi > 3.141592653589793` was
/// false, the float of the difference being 0). None when a side has no
/// exact form; `Some(None)` when the bounds cannot tell.
fn exact_order(a: &Value, b: &Value) -> Option<Option<std::cmp::Ordering>> {
    let form = |v: &Value| -> Option<crate::sym::Expr> {
        let m = match v {
            Value::Formula { m, .. } => m.clone(),
            v if v.may_be_exact() => v.exact_form()?,
            _ => return None,
        };
        if m.data.len() != 1 || !crate::values::exact::is_exact(&m) {
            return None;
        }
        m.data.into_iter().next()
    };
    let (x, y) = (form(a)?, form(b)?);
    if x == y {
        return Some(Some(std::cmp::Ordering::Equal));
    }
    let d = x.sub(&y);
    let sign = match d.as_const() {
        Some(crate::sym::coef::Coef::Exact { re, im }) if im.is_zero() => re.signum(),
        _ => match crate::sym::sign::sign_with_pi(&d) {
            Some(s) => f64::from(s),
            None => return Some(None),
        },
    };
    Some(sign.partial_cmp(&0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn num(x: f64) -> Value {
        Value::scalar(x)
    }

    #[test]
    fn scalars_are_ordered() {
        assert_eq!(holds(&num(1.0), &num(2.0), CmpOp::Lt), Ok(Some(true)));
        assert_eq!(holds(&num(2.0), &num(2.0), CmpOp::Le), Ok(Some(true)));
        assert_eq!(holds(&num(2.0), &num(2.0), CmpOp::Gt), Ok(Some(false)));
        assert_eq!(holds(&num(3.0), &num(2.0), CmpOp::Ge), Ok(Some(true)));
        assert_eq!(holds(&num(f64::NAN), &num(2.0), CmpOp::Lt), Ok(Some(false)));
    }

    #[test]
    fn only_scalars_are_ordered() {
        assert!(order_rule(&Ty::scalar(), &Ty::scalar()).is_ok());
        let v = Ty::plain(Kind::Vector(Some(3)));
        let e = order_rule(&v, &Ty::scalar()).unwrap_err();
        assert!(
            e.message.contains("only numbers are ordered"),
            "{}",
            e.message
        );
    }
}
