//! `a == b` where a side is an inverse trigonometric function of a number
//! (LANGUAGE.md §7; SymPy's suite of issue 35): `asin(sin(7/2)) == π −
//! 7/2`, `atan(√(5 − 2√5)) == π/5`, `atan(cot(1/4)) == π/2 − 1/4`. The
//! inverse is the one angle of its principal range with the given sine,
//! cosine or tangent: asin y = c exactly when c lies in [−π/2, π/2] and
//! sin c = y (acos: [0, π] and cos c = y; atan: (−π/2, π/2) and tan c = y).
//! Here c must lie strictly inside the range by its certified ball, and
//! sin c = y must be proven as any other `==` of numbers is
//! ([`super::certify`]): then the two sides are equal, proven; anything
//! else proves nothing.

use super::ball::{self, Ball};
use super::certify::{Memo, PRECISIONS, Verdict, balls};
use crate::check::ty::Kind;
use crate::seam::apply::Op;
use crate::values::exact::Operation;
use crate::values::exact::deref;
use crate::values::value::Value;

/// True when `a == b` is proven by the principal range of an inverse
/// trigonometric side (the module's doc), either side.
pub(crate) fn proven_equal(a: &Value, b: &Value, depth: u32) -> bool {
    depth < 4 && (one_way(a, b, depth) || one_way(b, a, depth))
}

/// True when `inv` is asin, acos or atan of a number y, `c` is a number
/// strictly inside that function's range, and f(c) == y is proven.
fn one_way(inv: &Value, c: &Value, depth: u32) -> bool {
    let Value::Num { exact, .. } = inv else {
        return false;
    };
    if c.as_scalar().is_none() {
        return false;
    }
    let found = exact
        .with_recipe(|p| match (&p.op, deref(&p.args.refs()).as_slice()) {
            (Operation::Call(name), [y]) => {
                Some((crate::builtins::lookup(name)?.name, (*y).clone()))
            }
            _ => None,
        })
        .flatten();
    let Some((name, y)) = found else {
        return false;
    };
    // (the range as multiples of π/2: asin [−1, 1], acos [0, 2], atan (−1, 1))
    let (forward, lo, hi) = match name {
        "asin" => ("sin", -1, 1),
        "acos" => ("cos", 0, 2),
        "atan" => ("tan", -1, 1),
        _ => return false,
    };
    if !strictly_inside(c, lo, hi) {
        return false;
    }
    let Some(f) = crate::builtins::lookup(forward) else {
        return false;
    };
    let Ok(fc) = Op::Call(f, forward).apply(&[c], &Kind::Scalar) else {
        return false;
    };
    proven(&fc, &y, depth + 1)
}

/// True when `a == b` is proven: equal exact forms, or certified
/// arithmetic's proof ([`super::certify::equal`], its lift included).
fn proven(a: &Value, b: &Value, depth: u32) -> bool {
    if let (Some(x), Some(y)) = (a.exact_form(), b.exact_form()) {
        return x == y;
    }
    matches!(super::certify::equal_at(a, b, depth), Some(Verdict::Equal))
}

/// True when the number `c`'s certified ball lies strictly between
/// `lo`·π/2 and `hi`·π/2.
fn strictly_inside(c: &Value, lo: i64, hi: i64) -> bool {
    let prec = PRECISIONS[0];
    let Some(x) = balls(c, prec, &mut Memo::default()) else {
        return false;
    };
    let Some(x) = x.one() else { return false };
    let half_pi = |k: i64| -> Option<Ball> {
        let p = ball::div(&ball::pi(prec), &ball::int(&2.into()), prec)?;
        ball::mul(&p, &ball::int(&k.into()), prec)
    };
    let positive =
        |d: Option<Ball>| d.is_some_and(|d| ball::nonzero(&d) && ball::floats(&d).0 > 0.0);
    let (Some(l), Some(h)) = (half_pi(lo), half_pi(hi)) else {
        return false;
    };
    positive(ball::sub(x, &l, prec)) && positive(ball::sub(&h, x, prec))
}
