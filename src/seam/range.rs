//! Ranges `a:h:b` (LANGUAGE.md §5): how many items, and the items, the
//! same whether the interpreter makes the list as typed or a range that
//! waited for its numbers is replayed with them ([`crate::decide::replay`]).

use std::rc::Rc;

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

/// The number of items of `a:h:b` (MATLAB's: the end is included when
/// within rounding, so 0:pi/8:pi has 9 items).
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

/// The `n` items of the range from `a` by `h`.
pub(crate) fn items(a: f64, h: f64, n: usize) -> Vec<Value> {
    (0..n).map(|k| Value::scalar(a + k as f64 * h)).collect()
}

/// The list `a:h:b` as typed first, once a range that waited has its
/// numbers ([`crate::decide::replay`]); Err why it has none.
pub(crate) fn range_items(a: f64, h: f64, b: f64) -> Result<Value, RangeFail> {
    let n = range_count(a, h, b)?;
    Ok(Value::List(Rc::new(items(a, h, n))))
}
