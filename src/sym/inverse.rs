//! Sines and cosines of inverse trigonometric functions (LANGUAGE.md §7;
//! SymPy's suite of issue 35): sin(asin u) = u, cos(acos u) = u,
//! cos(asin u) = sin(acos u) = √(1 − u²), sin(atan u) = u/√(1 + u²),
//! cos(atan u) = 1/√(1 + u²), on the domain where the inner call is real
//! (asin's and acos's angles lie in [−π/2, π/2] and [0, π], where the
//! cosine and the sine are ≥ 0, so the roots are the positive ones). The
//! tangent and the others follow as quotients: tan(atan x) = x, cot(atan
//! x) = 1/x. Also square roots kept as calls for the proofs of
//! `crate::decide::lift`.

use super::coef::Coef;
use super::expr::{Expr, Func, Var};

/// f(x) in closed form: asin, acos and atan at the book's angles,
/// exactly rπ ([`super::arc::inverse`]), and [`of_inverse`].
pub fn closed(f: Func, x: &Expr) -> Option<Expr> {
    if matches!(f, Func::Asin | Func::Acos | Func::Atan) {
        return super::arc::inverse(f, x);
    }
    of_inverse(f, x)
}

/// f(g(u)) for f sine or cosine and `x` exactly one call g(u) of asin,
/// acos or atan (the module's doc); None otherwise.
pub fn of_inverse(f: Func, x: &Expr) -> Option<Expr> {
    if !matches!(f, Func::Sin | Func::Cos) || x.terms.len() != 1 {
        return None;
    }
    let (mono, c) = x.terms.iter().next()?;
    let [(Var::Call(call), 1)] = mono.as_slice() else {
        return None;
    };
    if !c.is_one() || call.args.len() != 1 {
        return None;
    }
    let u = &call.args[0];
    let square = u.mul(u);
    let root = |e: Expr| Expr::sqrt(&e);
    Some(match (call.f, f) {
        (Func::Asin, Func::Sin) | (Func::Acos, Func::Cos) => u.clone(),
        (Func::Asin, Func::Cos) | (Func::Acos, Func::Sin) => {
            root(Expr::constant(Coef::one()).sub(&square))
        }
        (Func::Atan, Func::Sin) => u.mul(&root(Expr::constant(Coef::one()).add(&square)).recip()?),
        (Func::Atan, Func::Cos) => root(Expr::constant(Coef::one()).add(&square)).recip()?,
        _ => return None,
    })
}

/// u when `e` is exactly exp(u) (one term, coefficient 1): log(exp(u)) =
/// u for a real u.
pub fn exp_arg(e: &Expr) -> Option<Expr> {
    let (mono, c) = e.terms.iter().next()?;
    match (e.terms.len(), mono.as_slice()) {
        (1, [(Var::Call(call), 1)]) if c.is_one() && call.f == Func::Exp => {
            call.args.first().cloned()
        }
        _ => None,
    }
}

impl Expr {
    /// √x kept as a call whatever x is (no float for a root with no exact
    /// form): a proof's square root of a number, whose square is x
    /// exactly (`crate::decide::lift`).
    pub fn sqrt_kept(x: &Expr) -> Expr {
        let e = Expr::sqrt(x);
        if !e.terms.is_empty() && e.terms.values().all(Coef::is_exact) {
            return e;
        }
        Expr::call(Func::Sqrt, vec![x.clone()])
    }
}
