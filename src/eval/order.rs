//! Orders of scalars (LANGUAGE.md §3): `a < b`, `a <= b` (`≤`), `a > b`,
//! `a >= b` (`≥`) give a bool, in an expression or an `assert`. Only
//! scalars are ordered: a vector or a matrix is a type error that says to
//! compare a norm or an entry.

use super::value::Value;
use crate::check::rules::RuleError;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::ErrorKind;
use crate::syntax::ast::CmpOp;

/// The static rule of an order: both sides scalars (or not known yet);
/// the result is a bool with no frames.
pub fn order_rule(l: &Ty, r: &Ty) -> Result<Ty, RuleError> {
    for side in [l, r] {
        if !side.kind.maybe_scalar() && !matches!(side.kind, Kind::Unknown) {
            return Err(RuleError {
                kind: Some(ErrorKind::Type),
                message: format!("only numbers are ordered, not {}", side.kind.a()),
                help: Some(
                    "compare a number made from it: norm(v) < 1, R[1, 1] > 0, dof(m) >= 1".into(),
                ),
                ..RuleError::default()
            });
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
            return Ok(None);
        }
        return Err(format!(
            "only numbers are ordered: cannot compare {} with {}",
            a.kind().a(),
            b.kind().a()
        ));
    };
    Ok(Some(match op {
        CmpOp::Lt => x < y,
        CmpOp::Le => x <= y,
        CmpOp::Gt => x > y,
        CmpOp::Ge => x >= y,
        // Equalities are decided by `equal`; as numbers they are these.
        CmpOp::Eq | CmpOp::Approx => x == y,
    }))
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
