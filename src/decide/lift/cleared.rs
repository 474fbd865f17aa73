//! Sides equal once their kept denominators are cleared (issue 35):
//! `sec(2π + 11)` against `sec 11`, `tan(10π/7)` against `tan(3π/7)`,
//! `sin 2/(cos 2 + 1)` against `tan 1` — each a quotient whose lifted
//! form keeps a reciprocal, so equal numbers had different forms.

use super::exact;
use super::field::{reduced, z_of};
use crate::sym::expr::{Expr, Var};

/// True when p = q once both are multiplied by every kept denominator
/// of either ([`crate::sym::together::cleared`]: `sec(2π + 11)` against
/// `sec 11`, `sin 2/(cos 2 + 1)` against `tan 1`), the products reduced in
/// ℚ(e^{iπ/L}) when the angles are split. The denominators are nonzero
/// numbers (each side's certified balls were finite before the lift is
/// asked), and none of them may reduce to zero here, so equal numerators
/// are equal sides.
pub(super) fn cleared_equal(p: &Expr, q: &Expr, split: Option<(i64, i64)>) -> bool {
    let mut dens = Vec::new();
    denominators(p, &mut dens);
    denominators(q, &mut dens);
    let Some((mut p, mut q)) = crate::sym::together::cleared(p, q) else {
        return false;
    };
    if let Some((_, l)) = split {
        let z = z_of([&p, &q].into_iter().chain(&dens));
        if dens.iter().any(|d| reduced(d, l, &z).terms.is_empty()) {
            return false;
        }
        p = reduced(&p, l, &z);
        q = reduced(&q, l, &z);
    }
    exact(&p) && exact(&q) && p == q
}

/// The arguments of the kept reciprocals anywhere in `e`, calls' arguments
/// included.
fn denominators(e: &Expr, out: &mut Vec<Expr>) {
    for (v, _) in e.terms.keys().flatten() {
        if let Var::Call(c) = v {
            if c.f == crate::sym::expr::Func::Recip {
                out.extend(c.args.iter().cloned());
            }
            c.args.iter().for_each(|a| denominators(a, out));
        }
    }
}
