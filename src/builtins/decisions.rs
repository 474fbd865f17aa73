//! The book's tests whose answer is a branch on a threshold (§3.6),
//! decided by the argument's exact form when it has one (LANGUAGE.md §7;
//! issue 21: never a wrong answer): `NearZero` (|z| < 1e-6) and
//! `Normalize` (V is not the zero vector). A float with no exact form is
//! decided by its float, at no extra cost.

use super::Args;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::lie;
use crate::values::num::Num;
use crate::values::value::Value;

/// `NearZero(z)` (§3.6): |z| < 1e-6, decided by z's exact form when it
/// has one (1e-6 − 1e-30 is below, its float 1e-6 is not); an exact z
/// too near ±1e-6 for 50 decimal places to tell is refused as such.
pub fn eval_near_zero(a: &mut Args) -> Result<Value, Diagnostic> {
    let d = a.decided(0)?;
    let tol = lie::NEAR_ZERO_TOL;
    match (d.order(tol), d.order(-tol)) {
        (Some(hi), Some(lo)) => Ok(Value::Bool(hi.is_lt() && lo.is_gt())),
        _ if d.is_exact() => Err(a.error(
            0,
            ErrorKind::Domain,
            "cannot decide whether |z| < 1e-6: z agrees with ±1e-6 to 50 decimal places",
        )),
        _ => Ok(Value::Bool(lie::near_zero(d.value()))),
    }
}

/// `Normalize(V)` (§3.6): V/‖V‖, refused for the zero vector — zero or
/// not by V's exact form when it has one and its floats are within
/// rounding of 0 (`(0.1 + 0.2, 0) − (0.3, 0)` is zero, though its floats
/// are (5.6e-17, 0); `(1e-200, 0)` is not), the direction then read from
/// the floats nearest its exact entries.
pub fn eval_normalize(a: &mut Args) -> Result<Value, Diagnostic> {
    let v = a.vec(0)?;
    if v.iter().any(|x| !x.is_finite()) {
        return Err(a.error(
            0,
            ErrorKind::Domain,
            "cannot normalize a vector with entries that are not finite (inf or NaN)",
        ));
    }
    // (zero or not by the exact form: `Args::vec`)
    match lie::normalize(&v) {
        Some(u) => Ok(Value::Num {
            kind: a.value(0).kind(),
            m: Num::vector(u.as_slice()),
            exact: Default::default(),
        }),
        None => Err(a.error(
            0,
            ErrorKind::Domain,
            "cannot normalize the zero vector (its norm is 0)",
        )),
    }
}
