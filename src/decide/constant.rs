//! `simplify` of a constant (LANGUAGE.md §7, SymPy's `cos(π/9) cos(2π/9)
//! cos(3π/9) cos(4π/9)` = 1/16): the float only proposes candidates, a
//! small fraction p/q or ±√(p/q) within 1e-12 of it, and a candidate is
//! the result only when the proofs of `==` ([`super::equality::equal`]:
//! exact forms, certified balls) prove it equal to the value. Float
//! closeness alone never makes a number exact.

use crate::sym::Expr;
use crate::sym::coef::{Coef, Rat};
use crate::syntax::ast::CmpOp;
use crate::values::formula;
use crate::values::value::Value;

/// The largest denominator of a candidate fraction.
const MAX_DEN: i128 = 10_000;

/// The candidates for a float `x`: p/q, then ±√(p/q) (not a square of a
/// fraction: that is the first).
fn candidates(x: f64) -> Vec<Expr> {
    let mut out = Vec::new();
    if let Some(r) = Rat::approximate(x, MAX_DEN) {
        out.push(Expr::constant(Coef::rat(r)));
    }
    if let Some(r) = Rat::approximate(x * x, MAX_DEN)
        && !r.is_zero()
    {
        let root = Expr::sqrt(&Expr::constant(Coef::rat(r)));
        if root.as_const().is_some_and(|c| c.is_exact()) {
            out.push(if x < 0.0 { root.neg() } else { root });
        }
    }
    out
}

/// The exact short number a scalar constant `v` is proven equal to; None
/// when `v` is no number, already exact, or no candidate is proven.
pub fn simplest(v: &Value) -> Option<Value> {
    let Value::Num { m, .. } = v else { return None };
    if m.shape() != (1, 1) {
        return None;
    }
    let x = m[(0, 0)];
    if let Some(e) = formula::scalar_of(v)
        && e.as_const().is_some_and(|c| c.is_exact())
    {
        return None;
    }
    candidates(x).into_iter().find_map(|c| {
        let cand = formula::scalar(c);
        matches!(super::equality::equal(v, &cand, CmpOp::Eq), Ok(Some(true))).then_some(cand)
    })
}
