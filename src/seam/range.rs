//! Ranges `a:h:b` (LANGUAGE.md §5): how many items, and the items, the
//! same whether the interpreter makes the list as typed or a range that
//! waited for its numbers is replayed with them ([`crate::decide::replay`]).

use std::rc::Rc;

use crate::check::ty::Kind;
use crate::sym::Mat;
use crate::sym::coef::Coef;
use crate::sym::expr::Expr;
use crate::sym::rat::Rat;
use crate::values::exact::{Exact, Fraction};
use crate::values::num::Num;
use crate::values::value::Value;

/// The longest list made: a range or comprehension with more items is a
/// domain error that gives the count (a list of 10⁷ points is a mistake,
/// not a workspace).
pub const MAX_LIST: usize = 1_000_000;

/// Why a range has no items: its numbers are not finite, its step is 0,
/// or it would be too long.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum RangeFail {
    NotFinite,
    ZeroStep,
    TooLong(f64),
}

impl std::fmt::Display for RangeFail {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RangeFail::NotFinite => write!(f, "a range needs finite numbers (no inf or NaN)"),
            RangeFail::ZeroStep => write!(f, "a range with step 0 never reaches its end"),
            RangeFail::TooLong(n) => {
                let count = if *n < 1e15 {
                    format!("{}", *n as u64)
                } else {
                    format!("{n:.3e}")
                };
                write!(
                    f,
                    "the list would have {count} items; lists are limited to {MAX_LIST}"
                )
            }
        }
    }
}

/// The number of items of `a:h:b` in floats: ⌊s + 1e-10·(1 + |s|)⌋ + 1
/// with s = (b − a)/h (none when s < −1e-10·(1 + |s|)), the end included
/// when within 1e-10 of a step count (so 0:pi/8:pi has 9 items, and an end
/// computed with accumulated rounding is kept). MATLAB's colon includes
/// the end within 2ε·max(|a|, |b|) only; an end off a step count by more
/// than that and less than 1e-10 (relative) is reached here and not there,
/// and [`items`] then makes it the last item, so that none passes it.
pub(crate) fn range_count(a: f64, h: f64, b: f64) -> Result<usize, RangeFail> {
    if !(a.is_finite() && h.is_finite() && b.is_finite()) {
        return Err(RangeFail::NotFinite);
    }
    if h == 0.0 {
        return Err(RangeFail::ZeroStep);
    }
    let steps = (b - a) / h;
    let tol = 1e-10 * (1.0 + steps.abs());
    let n = if steps < -tol {
        0.0
    } else {
        (steps + tol).floor() + 1.0
    };
    if n > MAX_LIST as f64 {
        return Err(RangeFail::TooLong(n));
    }
    Ok(n as usize)
}

/// The number of items of the range `a:h:b` of values: by the exact forms
/// of its bounds when they have them and `(b − a)/h` is a rational number
/// (`1:0.5:1.9999999999` stops at 1.5, its end not reached, where the
/// floats' tolerance would take 2; `0:pi/8:pi` reaches π exactly), else
/// by the floats within rounding ([`range_count`]).
pub(crate) fn count(a: &Value, h: &Value, b: &Value) -> Result<usize, RangeFail> {
    let (Some(x), Some(dx), Some(y)) = (a.as_scalar(), h.as_scalar(), b.as_scalar()) else {
        return Err(RangeFail::NotFinite);
    };
    let floats = range_count(x, dx, y)?;
    let Some(steps) = exact_steps(a, h, b) else {
        return Ok(floats);
    };
    if steps.is_negative() {
        return Ok(0);
    }
    let n = steps.to_big().floor().to_integer() + 1;
    match usize::try_from(n) {
        Ok(n) if n <= MAX_LIST => Ok(n),
        _ => Err(RangeFail::TooLong(steps.to_f64() + 1.0)),
    }
}

/// `(b − a)/h` exactly, when the three have exact forms and the quotient
/// is rational: the difference and the step are one term each over the
/// same power of π (or constants).
fn exact_steps(a: &Value, h: &Value, b: &Value) -> Option<Rat> {
    let (fa, fh, fb) = (scalar_form(a)?, scalar_form(h)?, scalar_form(b)?);
    let d = fb.add(&fa.scale(&Coef::int(-1)));
    if d.terms.is_empty() {
        return Some(Rat::int(0));
    }
    fn one(e: &Expr) -> Option<(&crate::sym::expr::Mono, &Coef)> {
        let mut terms = e.terms.iter();
        let term = terms.next()?;
        terms.next().is_none().then_some(term)
    }
    let ((dm, dc), (hm, hc)) = (one(&d)?, one(&fh)?);
    if dm != hm {
        return None;
    }
    Some(dc.as_rat()?.mul(&hc.as_rat()?.inv()?))
}

/// The `n` items of the range from `a` by `h`: item k is the sum
/// `a + k·h`, in floats as that sum written out gives them and, when `a`
/// and `h` are exact, exact as it is (LANGUAGE.md §7: `(0:0.1:1)[4] ==
/// 0.3` as `0.1·3 == 0.3`, `sqrt(k)` of a `k` of `1:4` as of a `k` typed;
/// `(-0.3:0.1:0.3)[4]` is 0, its floats having cancelled, as
/// `-0.3 + 3·0.1` is). A whole-number range is as typed (no form to keep).
///
/// When the count is by the floats ([`count`]: a bound with no exact
/// form), the end is reached within rounding, and the last item's sum
/// passes it, the last item is the end `b` itself, as MATLAB's colon
/// makes it: no item lies beyond the end (`0:s/7:s` with s = sin(1) ended
/// 1 ulp past s, whose acos was then out of domain).
pub(crate) fn items(a: &Value, h: &Value, b: &Value, n: usize) -> Vec<Value> {
    let mut out = sums(a, h, n);
    let (Some(dx), Some(y)) = (h.as_scalar(), b.as_scalar()) else {
        return out;
    };
    if let Some(last) = out.last_mut()
        && last
            .as_scalar()
            .is_some_and(|x| (x - y) * dx.signum() > 0.0)
        && exact_steps(a, h, b).is_none()
    {
        *last = b.clone();
    }
    out
}

/// The items `a + k·h`, k < n ([`items`] before its end is settled).
fn sums(a: &Value, h: &Value, n: usize) -> Vec<Value> {
    let (Some(x), Some(dx)) = (a.as_scalar(), h.as_scalar()) else {
        return Vec::new();
    };
    let float = |k: usize| x + k as f64 * dx;
    let Some((fa, fh)) = scalar_form(a).zip(scalar_form(h)) else {
        return (0..n).map(|k| Value::scalar(float(k))).collect();
    };
    // (whole numbers below 2⁵³ sum exactly in floats: read as typed)
    let whole = |e: &Expr| {
        e.as_const()
            .and_then(|c| c.as_rat())
            .is_some_and(|r| r.is_integer())
    };
    if whole(&fa) && whole(&fh) && x.abs() + n as f64 * dx.abs() < 9.0e15 {
        return (0..n)
            .map(|k| Value::Num {
                kind: Kind::Scalar,
                m: Num::Scalar(float(k)),
                exact: Exact::Typed,
            })
            .collect();
    }
    // (fractions a and h: each item's a + k·h is a fraction, made at once
    // and held inline, as `Rat` adds and multiplies the coefficients the
    // recipe's sum would; a recipe where it does not fit)
    let rat = |e: &Expr| e.as_const().and_then(|c| c.as_rat());
    let fractions = rat(&fa).zip(rat(&fh));
    let forms = Rc::new((fa, fh));
    (0..n)
        .map(|k| {
            let inline = fractions.as_ref().and_then(|(ra, rh)| {
                let r = ra.add(&rh.mul(&Rat::int(i64::try_from(k).ok()?)));
                Fraction::of(&r)
            });
            let exact = match inline {
                Some(r) => Exact::Ratio(r),
                None => {
                    let f = Rc::clone(&forms);
                    Exact::later(move || {
                        let k = Coef::int(i64::try_from(k).ok()?);
                        Some(Mat::scalar(f.0.add(&f.1.scale(&k))))
                    })
                }
            };
            let mut v = Value::Num {
                kind: Kind::Scalar,
                m: Num::Scalar(float(k)),
                exact,
            };
            let big = x.abs().max(k as f64 * dx.abs());
            if big > 0.0 && float(k).abs() <= big * super::exactness::CANCELLED {
                super::exactness::from_exact_form(&mut v);
            }
            v
        })
        .collect()
}

/// The exact form of a number, as one expression; None for a float.
fn scalar_form(v: &Value) -> Option<Expr> {
    let m = v.exact_form()?;
    let [e] = <[Expr; 1]>::try_from(m.data).ok()?;
    Some(e)
}

/// The list `a:h:b` as typed first, once a range that waited has its
/// numbers ([`crate::decide::replay`]); Err why it has none.
pub(crate) fn range_items(a: &Value, h: &Value, b: &Value) -> Result<Value, RangeFail> {
    let n = count(a, h, b)?;
    Ok(Value::List(Rc::new(items(a, h, b, n))))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::seam::apply::Op;
    use crate::seam::exactness::run;
    use crate::values::exact::Operation;

    /// A sum, difference, product or quotient of fractions at hand is the
    /// fraction the recipe makes, typed mark and all (so `--exact` prints
    /// it alike: 37/100 from integers, 0.37 from a typed 0.37), held
    /// inline; and again of such results.
    #[test]
    fn fractions_at_hand_are_made_at_once_as_the_recipe_makes_them() {
        use crate::sym::coef::Rat;
        use crate::syntax::ast::BinOp::{Add, Div, Mul, Sub};
        let typed = |x: f64| {
            let mut v = Value::scalar(x);
            v.set_exact(Exact::Typed);
            v
        };
        let form_of = |v: &Value| -> (Rat, bool) {
            let m = v.exact_form().expect("exact");
            let r = m.data[0]
                .as_const()
                .and_then(|c| c.as_rat())
                .expect("a fraction");
            let t = r.is_typed();
            (r, t)
        };
        let xs = [0.0, 1.0, -3.0, 100.0, 0.1, 0.37, -2.5, 7.0, 0.125, 1e6];
        let mut inline = 0;
        for &x in &xs {
            for &y in &xs {
                for op in [Add, Sub, Mul, Div] {
                    let (a, b) = (typed(x), typed(y));
                    let recipe = run(&Operation::Arith(op), &[&a, &b], &Kind::Scalar);
                    let Ok(v) = Op::Arith(op).apply_pair(
                        Box::new(a.clone()),
                        Box::new(b.clone()),
                        &Kind::Scalar,
                    ) else {
                        continue;
                    };
                    let Some(recipe) = recipe else {
                        continue;
                    };
                    let want = recipe.data[0]
                        .as_const()
                        .and_then(|c| c.as_rat())
                        .expect("rat");
                    assert_eq!(
                        form_of(&v),
                        (want.clone(), want.is_typed()),
                        "{x} {op:?} {y}"
                    );
                    if let Value::Num {
                        exact: Exact::Ratio(_),
                        ..
                    } = &v
                    {
                        inline += 1;
                        // and once more, of the fraction held inline
                        let again = run(&Operation::Arith(op), &[&v, &b], &Kind::Scalar);
                        let w = Op::Arith(op).apply_pair(
                            Box::new(v.clone()),
                            Box::new(b.clone()),
                            &Kind::Scalar,
                        );
                        if let (Some(again), Ok(w)) = (again, w) {
                            let want = again.data[0].as_const().and_then(|c| c.as_rat());
                            let want = want.expect("rat");
                            assert_eq!(form_of(&w), (want.clone(), want.is_typed()));
                        }
                    }
                }
            }
        }
        assert!(inline > 100, "{inline}");
        // 37/100 of integers is a fraction, not a typed decimal
        let v = Op::Arith(Div)
            .apply_pair(Box::new(typed(37.0)), Box::new(typed(100.0)), &Kind::Scalar)
            .expect("a quotient");
        assert_eq!(form_of(&v), (Rat::new(37, 100).expect("37/100"), false));
        // 0.1 · 3 is 3/10 as typed, its floats 0.30000000000000004: of
        // two numbers typed, a recipe; beside a fraction, inline
        let v = Op::Arith(Mul)
            .apply_pair(Box::new(typed(0.1)), Box::new(typed(3.0)), &Kind::Scalar)
            .expect("a product");
        assert_eq!(form_of(&v), (Rat::new(3, 10).expect("3/10"), true));
        assert_eq!(v.as_scalar(), Some(0.1 * 3.0));
        assert!(matches!(
            v,
            Value::Num {
                exact: Exact::Later(_),
                ..
            }
        ));
        let w = Op::Arith(Div)
            .apply_pair(Box::new(typed(3.0)), Box::new(typed(1.0)), &Kind::Scalar)
            .expect("a quotient");
        let v = Op::Arith(Mul)
            .apply_pair(Box::new(typed(0.1)), Box::new(w), &Kind::Scalar)
            .expect("a product");
        assert_eq!(form_of(&v), (Rat::new(3, 10).expect("3/10"), true));
        assert!(matches!(
            v,
            Value::Num {
                exact: Exact::Ratio(_),
                ..
            }
        ));
        assert_eq!(std::mem::size_of::<Exact>(), 16);
    }

    /// A range of fractions holds its items' fractions inline, each the
    /// a + k·h its recipe made, typed mark and all.
    #[test]
    fn a_range_of_fractions_holds_them_inline_as_its_recipe_made_them() {
        let typed = |x: f64| {
            let mut v = Value::scalar(x);
            v.set_exact(Exact::Typed);
            v
        };
        let third = Op::Arith(crate::syntax::ast::BinOp::Div)
            .apply_pair(Box::new(typed(1.0)), Box::new(typed(3.0)), &Kind::Scalar)
            .expect("1/3");
        for (a, h) in [
            (typed(0.0), typed(0.1)),
            (typed(-0.3), typed(0.1)),
            (typed(2.0), third.clone()),
            (third, typed(0.25)),
            (typed(1.5), typed(-0.001)),
        ] {
            let (fa, fh) = (scalar_form(&a).expect("a"), scalar_form(&h).expect("h"));
            // (an end past the 40th item: none is moved onto it)
            let far = typed(1e9_f64.copysign(h.as_scalar().expect("h")));
            let vs = items(&a, &h, &far, 40);
            assert_eq!(vs.len(), 40);
            for (k, v) in vs.iter().enumerate() {
                assert!(
                    matches!(
                        v,
                        Value::Num {
                            exact: Exact::Ratio(_),
                            ..
                        }
                    ),
                    "{k}"
                );
                let want = fa.add(&fh.scale(&Coef::int(k as i64)));
                let got = scalar_form(v).expect("exact");
                assert_eq!(got, want, "{k}");
                let typed_mark =
                    |e: &Expr| e.as_const().and_then(|c| c.as_rat()).map(|r| r.is_typed());
                assert_eq!(typed_mark(&got), typed_mark(&want), "{k}");
            }
        }
        // (0:0.1:1)[4] is 3/10 exactly, its float 0.30000000000000004
        let v = &items(&typed(0.0), &typed(0.1), &typed(1.0), 11)[3];
        assert_eq!(v.as_scalar(), Some(3.0 * 0.1));
        assert_eq!(
            scalar_form(v),
            Some(Expr::constant(Coef::rat(Rat::new(3, 10).expect("3/10"))))
        );
    }
}
