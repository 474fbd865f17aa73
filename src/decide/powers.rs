//! `==` of powers with a symbolic exponent (LANGUAGE.md §7; SymPy's
//! `(1 + cos 1)^(−a) sin(1)^a == tan(1/2)^a`): b₁^e and b₂^(±e) of positive
//! numbers are one function of e exactly when b₁ = b₂ (or b₁ b₂ = 1), which
//! the proofs of `==` between numbers decide ([`super::equality::equal`],
//! exact forms and certified balls, never float closeness alone).

use crate::check::ty::Kind;
use crate::seam::apply::Op;
use crate::syntax::ast::{BinOp, CmpOp};
use crate::values::formula;
use crate::values::value::{Sym, Value};
use num_traits::Zero;

/// A positive number's value, the base of a power.
fn positive(s: &Sym) -> Option<&Value> {
    let Sym::Const(v, _) = s else { return None };
    matches!(v.as_ref(), Value::Num { .. })
        .then_some(v.as_ref())
        .filter(|v| v.as_scalar().is_some_and(|x| x > 0.0))
}

/// Some(true) when `a` and `b` are powers b₁^e, b₂^e with b₁ = b₂ proven,
/// or b₁^e, b₂^(−e) with b₁ b₂ = 1 proven; None otherwise (never false:
/// the bases being unequal numbers is left to the caller's undecided).
pub fn equal(a: &Sym, b: &Sym) -> Option<bool> {
    let (Sym::Pow(b1, e1), Sym::Pow(b2, e2)) = (a, b) else {
        return None;
    };
    let (x1, x2) = (positive(b1)?, positive(b2)?);
    let exponent = |e: &Sym| match e {
        Sym::Const(v, _) => formula::scalar_of(v),
        _ => None,
    };
    let (f1, f2) = (exponent(e1)?, exponent(e2)?);
    if f1.as_const().is_some() {
        return None;
    }
    let proven =
        |p: &Value, q: &Value| matches!(super::equality::equal(p, q, CmpOp::Eq), Ok(Some(true)));
    if f1 == f2 {
        return proven(x1, x2).then_some(true);
    }
    if f1.add(&f2).is_zero() {
        let product = Op::Arith(BinOp::Mul).apply(&[x1, x2], &Kind::Scalar).ok()?;
        return proven(&product, &formula::scalar(crate::sym::Expr::int(1))).then_some(true);
    }
    None
}
