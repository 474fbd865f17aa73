//! `inv` and `det` of plain matrices judged by conditioning, not by the
//! size of the determinant ([`crate::values::linalg`]): an ill-conditioned
//! inverse and a determinant that underflows come with a warning.

use super::Args;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::values::value::Value;
use crate::values::{linalg, ops};

/// `inv(X)`: a closed form for a group element (Prop. 3.3, (3.64)), else
/// LU with partial pivoting; an ill-conditioned matrix's inverse comes
/// with a warning naming its reciprocal condition number.
pub fn eval_inv(a: &mut Args) -> Result<Value, Diagnostic> {
    let (v, rcond) = ops::inverse_conditioned(a.value(0))
        .map_err(|e| a.error(0, ErrorKind::Domain, e.to_string()))?;
    if let Some(note) = rcond.and_then(linalg::conditioning_note) {
        a.warnings
            .push(Diagnostic::warning(ErrorKind::Domain, a.call_span, note));
    }
    Ok(v)
}

/// `det(X)` by LU; a determinant below the smallest normal number (it
/// prints as 0 although the matrix need not be singular) comes with a
/// warning, as an overflow does.
pub fn eval_det(a: &mut Args) -> Result<Value, Diagnostic> {
    let m = a.square(0)?;
    let n = m.nrows();
    // LU: about n³/3 multiply-adds.
    ops::check_cost(ops::cube(n) / 3, || {
        format!("the determinant of a {n}×{n} matrix")
    })
    .map_err(|e| a.domain(e.to_string()))?;
    let (det, range) = linalg::determinant(&m.to_dmatrix());
    // Overflow is the infinite result's own warning.
    if let Some(r @ linalg::Range::Under(_)) = range {
        a.warnings.push(Diagnostic::warning(
            ErrorKind::Domain,
            a.call_span,
            r.note(),
        ));
    }
    Ok(Value::scalar(det))
}
