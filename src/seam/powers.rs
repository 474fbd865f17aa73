//! Powers with a symbolic exponent over `given` symbols (LANGUAGE.md §7,
//! "symbolic scalars are computed with"): b^e of a number b and a formula
//! e has no canonical form of its own (it is a node of the tree), so the
//! laws of exponents that keep it one power are applied as it is made:
//!
//! - b^e / c = b^(e − k) and b^e · c = b^(e + k) where c = b^(∓k) for an
//!   integer k (`2^(2 + x)/4` is `2^x`, as SymPy's `simplify` gives);
//! - b^e₁ · b^e₂ = b^(e₁ + e₂) (`2^x 2^y` is `2^(x + y)`, `2^x 2^(1 − x)`
//!   is 2), b₁^e · b₂^e = (b₁ b₂)^e (`2^x 3^x` is `6^x`);
//! - b₁^(−e) · b₂^e = (b₂/b₁)^e, one power of one base
//!   (`(1 + cos 1)^(−a) sin(1)^a` is `(sin 1/(1 + cos 1))^a`).
//!
//! Each is an identity for every real e where both sides are defined
//! (b, b₁, b₂ > 0), so the value is the same number once e has one.

use crate::check::ty::Kind;
use crate::sym::Expr;
use crate::sym::coef::Rat;
use crate::values::formula;
use crate::values::value::{Sym, Value};
use num_traits::Zero;

/// The most |k| tried in b^k = c.
const MAX_K: i64 = 64;

/// A positive exact rational constant of the tree.
fn positive_rat(s: &Sym) -> Option<Rat> {
    let Sym::Const(v, _) = s else { return None };
    let r = formula::scalar_of(v)?.as_const()?.as_rat()?;
    (!r.is_negative() && !r.is_zero()).then_some(r)
}

/// The k with b^k = c, |k| ≤ [`MAX_K`], for b ≠ 1.
fn log_of(b: &Rat, c: &Rat) -> Option<i64> {
    if *b == Rat::ONE {
        return None;
    }
    let inv = b.inv()?;
    for (step, sign) in [(b, 1), (&inv, -1)] {
        let mut p = Rat::ONE;
        for k in 0..=MAX_K {
            if p == *c {
                return Some(k * sign);
            }
            p = p.mul(step);
            if p.words() > 64 {
                break;
            }
        }
    }
    None
}

/// A constant of the tree from an exact scalar formula or number.
fn constant(e: Expr) -> Sym {
    let v = formula::make(&Kind::Scalar, crate::sym::Mat::scalar(e));
    let text = crate::values::format::inline(&v, 4);
    Sym::Const(Box::new(v), text)
}

/// b^e with the exponent's formula shifted by k: b^(e + k).
fn shifted(base: &Sym, e: &Value, k: i64) -> Option<Sym> {
    let e = formula::scalar_of(e)?;
    let moved = e.add(&Expr::int(k));
    Some(Sym::Pow(Box::new(base.clone()), Box::new(constant(moved))))
}

/// `a / c` or `a · c` (with `times`) of a power a = b^e by a constant c
/// that is an integer power of b, as one power; None otherwise.
pub(super) fn scaled(a: &Sym, c: &Sym, times: bool) -> Option<Sym> {
    let Sym::Pow(base, e) = a else { return None };
    let Sym::Const(ev, _) = e.as_ref() else {
        return None;
    };
    let b = positive_rat(base)?;
    let k = log_of(&b, &positive_rat(c)?)?;
    shifted(base, ev, if times { k } else { -k })
}

/// A product of two powers of positive constants as one power (module
/// doc): b^e₁ · b^e₂ = b^(e₁ + e₂), b₁^e · b₂^e = (b₁ b₂)^e, b₁^(−e) · b₂^e
/// = (b₂/b₁)^e; None otherwise.
pub(super) fn joined(a: &Sym, b: &Sym) -> Option<Sym> {
    same_base(a, b)
        .or_else(|| same_exponent(a, b))
        .or_else(|| opposite(a, b))
}

/// The constant base and the exponent's formula of a power b^e.
fn parts(a: &Sym) -> Option<(&Sym, &Value, &Sym, Expr)> {
    let Sym::Pow(base, e) = a else { return None };
    let Sym::Const(v, _) = base.as_ref() else {
        return None;
    };
    let Sym::Const(x, _) = e.as_ref() else {
        return None;
    };
    let f = formula::scalar_of(x)?;
    (v.as_scalar()? > 0.0).then_some((base.as_ref(), v.as_ref(), e.as_ref(), f))
}

/// b^e₁ · b^e₂ = b^(e₁ + e₂) for one exact base b > 0; a number where the
/// sum is an integer (2^x 2^(1 − x) is 2).
fn same_base(a: &Sym, b: &Sym) -> Option<Sym> {
    let (base, v1, _, f1) = parts(a)?;
    let (_, v2, _, f2) = parts(b)?;
    let (x1, x2) = (formula::scalar_of(v1)?, formula::scalar_of(v2)?);
    if x1 != x2 || !x1.as_const().is_some_and(|c| c.is_exact()) {
        return None;
    }
    let sum = f1.add(&f2);
    match sum.as_const() {
        Some(k) => {
            let k = k.as_rat()?.as_int().filter(|k| k.abs() <= MAX_K)?;
            x1.powi(k).map(constant)
        }
        None => Some(Sym::Pow(Box::new(base.clone()), Box::new(constant(sum)))),
    }
}

/// b₁^e · b₂^e = (b₁ b₂)^e for positive constants (the product made by
/// the multiplication itself, as [`quotient`]).
fn same_exponent(a: &Sym, b: &Sym) -> Option<Sym> {
    let (_, v1, e, f1) = parts(a)?;
    let (_, v2, _, f2) = parts(b)?;
    if f1 != f2 || f1.as_const().is_some() {
        return None;
    }
    let p = super::apply::Op::Arith(crate::syntax::ast::BinOp::Mul)
        .apply(&[v1, v2], &Kind::Scalar)
        .ok()?;
    Some(Sym::Pow(Box::new(constant_value(p)), Box::new(e.clone())))
}

/// b₁^(−e) · b₂^e (either order) as (b₂/b₁)^e for positive constants b₁, b₂;
/// None otherwise.
fn opposite(a: &Sym, b: &Sym) -> Option<Sym> {
    let (Sym::Pow(b1, e1), Sym::Pow(b2, e2)) = (a, b) else {
        return None;
    };
    let (Sym::Const(v1, _), Sym::Const(v2, _)) = (b1.as_ref(), b2.as_ref()) else {
        return None;
    };
    let (Sym::Const(x1, _), Sym::Const(x2, _)) = (e1.as_ref(), e2.as_ref()) else {
        return None;
    };
    let (f1, f2) = (formula::scalar_of(x1)?, formula::scalar_of(x2)?);
    if f1.as_const().is_some() || !f1.add(&f2).is_zero() {
        return None;
    }
    // (b^(−e) b^e is 1)
    if let (Some(a), Some(b)) = (formula::scalar_of(v1), formula::scalar_of(v2))
        && a == b
        && a.as_const().is_some_and(|c| c.is_exact())
    {
        return Some(constant(Expr::int(1)));
    }
    let (p1, p2) = (v1.as_scalar()?, v2.as_scalar()?);
    if !(p1 > 0.0 && p2 > 0.0) {
        return None;
    }
    // the base of the positive exponent over the other: sign by the
    // exponent's leading coefficient
    let lead_positive = f2.terms.values().next().is_some_and(|c| c.to_c64().0 > 0.0);
    let (num, den, e) = if lead_positive {
        (v2, v1, e2)
    } else {
        (v1, v2, e1)
    };
    let base = quotient(num, den)?;
    Some(Sym::Pow(Box::new(base), e.clone()))
}

/// num/den of two positive constants, made by the division itself (so it
/// keeps the exact form `==` proves with, [`crate::values::recipe`]).
pub(crate) fn quotient(num: &Value, den: &Value) -> Option<Sym> {
    let v = super::apply::Op::Arith(crate::syntax::ast::BinOp::Div)
        .apply(&[num, den], &Kind::Scalar)
        .ok()?;
    v.as_scalar()?;
    Some(constant_value(v))
}

/// A number as a constant of the tree, its text every digit where 4 do
/// not read back as it.
fn constant_value(v: Value) -> Sym {
    let short = crate::values::format::inline(&v, 4);
    let text = match v.as_scalar() {
        Some(x) if short.parse::<f64>().ok() != Some(x) => format!("{x}"),
        _ => short,
    };
    Sym::Const(Box::new(v), text)
}
