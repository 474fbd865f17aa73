//! `subs` of a call kept over `given` names, with a number (LANGUAGE.md
//! §7): `given c; b = 0.2; subs(MatrixExp3((c, b, 2)), c, 0.5)` is the
//! rotation `MatrixExp3((0.5, 0.2, 2))` gives, as when `b` is given too and
//! bound after.

use super::Bindings;
use super::resolve::{Resolving, plain_symbol};
use crate::diagnostics::Diagnostic;
use crate::seam::apply::to_sym;
use crate::values::value::{Sym, Value};

/// `subs(x, name, by)` of a tree `x` over `given` names (`MatrixExp3((c,
/// 1, 2))` kept as a call) and a number `by`, read as `Resolving::substituted`
/// reads it: the value when that leaves numbers, else None (kept).
pub fn subs_tree(
    x: &Sym,
    name: &Value,
    by: &Value,
    env: &dyn Bindings,
    warnings: &mut Vec<Diagnostic>,
) -> Option<Value> {
    if !matches!(by, Value::Num { .. }) || !plain_symbol(&to_sym(name)) {
        return None;
    }
    let mut own = Vec::new();
    let mut r = Resolving {
        env,
        warnings: &mut own,
        failed: None,
        put: Some([name.clone(), by.clone()]),
    };
    let out = r.go(x);
    match (r.failed, out) {
        (None, Sym::Const(v, _)) if matches!(*v, Value::Num { .. }) => {
            warnings.extend(own);
            Some(*v)
        }
        _ => None,
    }
}
