//! Comparisons that wait for numbers (LANGUAGE.md §7: "what cannot be
//! decided is said, never guessed"; "binding numbers later makes them
//! numeric"). `given a, b; c = a < b` cannot be decided while `a` and `b`
//! are free, yet typed first (`a = 1; b = 2; c = a < b`) it is `true`: so
//! the statement gives a bool that waits. It is a bool formula whose
//! entries are its two sides stacked (the left side's rows above the
//! right's), made by the comparison's step ([`Step::Compare`]); once every
//! symbol has a number it is decided by replaying that step, exactly as
//! typed first. Shown before, it prints the comparison (`a < b`) and says
//! it cannot be decided yet; where its truth is needed (`assert c`, `c ==
//! true`) it is refused with "cannot decide … without numbers".
//!
//! A range with a bound made from symbols (`0:a:1` over a free `a`) waits
//! the same way ([`range`]): a list formula whose entries are its start,
//! step and end, made by [`Step::Range`]; once they have numbers it is the
//! list typed first gives. It prints as typed (`0:a:1`).
//!
//! A comparison decided over free symbols (`a == 2` is no identity, so
//! false; `a - a < 1`) is a bool formula of one constant entry instead
//! ([`super::recipe::compared`]).

use super::format::Style;
use super::recipe::{Recipe, Step};
use super::value::Value;
use crate::check::ty::Kind;
use crate::sym::Mat;
use crate::sym::print::{self, Mode};
use crate::syntax::ast::CmpOp;

/// The bool of comparison `op` over sides `a`, `b` that cannot be decided
/// while their symbols are free: a waiting bool (see the module), or None
/// when a side is no number or formula (a tree of `given` matrices) or
/// the sides' shapes differ.
pub fn make(op: CmpOp, a: &Value, b: &Value) -> Option<Value> {
    let side = |v: &Value| match v {
        Value::Formula {
            kind: Kind::Bool, ..
        } => None,
        Value::Formula { .. } | Value::Num { .. } => super::formula::mat_of(v),
        _ => None,
    };
    let (x, y) = (side(a)?, side(b)?);
    if (x.rows, x.cols) != (y.rows, y.cols) {
        return None;
    }
    // (only symbols can be waited for: numbers that cannot be ordered
    // stay undecided)
    let mut syms = Vec::new();
    for v in [a, b] {
        if let Value::Formula { m, how, .. } = v {
            m.data.iter().for_each(|e| e.symbols(&mut syms));
            if let Some(r) = how {
                super::recipe::symbols(r, &mut syms);
            }
        }
    }
    if syms.is_empty() {
        return None;
    }
    let how = Recipe::node(
        Step::Compare(op),
        vec![Recipe::of(a), Recipe::of(b)],
        Kind::Bool,
    )?;
    let cols = x.cols;
    let rows = x.rows + y.rows;
    let mut data = x.data;
    data.extend(y.data);
    Some(Value::Formula {
        kind: Kind::Bool,
        m: Mat { rows, cols, data },
        how: Some(how),
    })
}

/// The range `a:h:b` (`stepped`: the step was typed) over bounds of which
/// one at least is a scalar formula: a list that waits for their numbers
/// (see the module). None when a bound is no scalar.
pub fn range(a: &Value, h: &Value, b: &Value, stepped: bool) -> Option<Value> {
    let scalar = |v: &Value| match v {
        Value::Formula {
            kind: Kind::Bool, ..
        } => None,
        Value::Formula { .. } | Value::Num { .. } => {
            super::formula::mat_of(v).filter(|m| m.data.len() == 1)
        }
        _ => None,
    };
    let data: Vec<crate::sym::Expr> = [a, h, b]
        .iter()
        .map(|v| scalar(v).map(|m| m.data[0].clone()))
        .collect::<Option<_>>()?;
    let kind = Kind::list(Kind::Scalar);
    let how = Recipe::node(
        Step::Range(stepped),
        vec![Recipe::of(a), Recipe::of(h), Recipe::of(b)],
        kind,
    )?;
    Some(Value::Formula {
        kind,
        m: Mat::column(data),
        how: Some(how),
    })
}

/// `len`, `sum`, `min` or `max` (builtin `name`, its result of kind
/// `kind`) of a range waiting for numbers: a scalar that waits too. It
/// has no canonical form before the numbers, so it stands for itself, as
/// a symbol named by the call (`len(0:a:1)`, [`stand_in`]) that nothing
/// binds: what it depends on is the range's symbols, through how it was
/// made, and once they have numbers it is the call's value as typed
/// first. None when `range` is not a waiting range.
pub fn of_range(name: &'static str, range: &Value, kind: Kind) -> Option<Value> {
    let text = text(range, 4.into()).filter(|_| is_range(range))?;
    let how = Recipe::node(
        Step::Op(super::operation::Operation::Call(name)),
        vec![Recipe::of(range)],
        kind,
    )?;
    let me = crate::sym::Symbol::new(&format!("{name}({text})"));
    Some(Value::Formula {
        kind,
        m: Mat::scalar(crate::sym::Expr::symbol(me)),
        how: Some(how),
    })
}

/// True for the symbol a value computed from a waiting range stands as
/// ([`of_range`]): no `given` name has a parenthesis, and no binding
/// gives it a number; the value waits for the range's symbols instead.
pub fn stand_in(s: &crate::sym::Symbol) -> bool {
    s.name.contains('(')
}

/// True when `v` is a range waiting for numbers.
pub fn is_range(v: &Value) -> bool {
    matches!(v, Value::Formula { how: Some(r), m, .. }
        if matches!(r.step, Step::Range(_)) && m.data.len() == 3)
}

/// The comparison and its two sides, when `v` is a waiting bool.
pub fn sides(v: &Value) -> Option<(CmpOp, Mat, Mat)> {
    let Value::Formula {
        kind: Kind::Bool,
        m,
        how: Some(r),
    } = v
    else {
        return None;
    };
    let Step::Compare(op) = r.step else {
        return None;
    };
    if m.rows < 2 || m.rows % 2 != 0 {
        return None;
    }
    let half = m.rows / 2;
    Some((
        op,
        m.block(0..half, 0..m.cols),
        m.block(half..m.rows, 0..m.cols),
    ))
}

/// The first waiting bool or range in `v` (itself, or an item of a list
/// or tuple).
pub fn first(v: &Value) -> Option<&Value> {
    match v {
        Value::Formula { .. } if sides(v).is_some() || is_range(v) => Some(v),
        Value::Tuple(vs) => vs.iter().find_map(first),
        Value::List(vs) => vs.iter().find_map(first),
        _ => None,
    }
}

/// A waiting bool on one line: `a < b`, in LaTeX `a \le b`; a waiting
/// range as typed, `0:a:1`.
pub fn text(v: &Value, style: Style) -> Option<String> {
    let latex = style.sym == Mode::Latex;
    if is_range(v)
        && let Value::Formula {
            m, how: Some(r), ..
        } = v
    {
        let bound = |i: usize| {
            let e = Mat::scalar(m.data[i].clone());
            let t = super::format::formula_inline(&e, style);
            // (a bound that is a sum is bracketed, as it must be typed)
            if t.contains(' ') { format!("({t})") } else { t }
        };
        return Some(match r.step {
            Step::Range(true) => format!("{}:{}:{}", bound(0), bound(1), bound(2)),
            _ => format!("{}:{}", bound(0), bound(2)),
        });
    }
    let (op, l, r) = sides(v)?;
    let side = |m: &Mat| {
        if latex {
            super::format::formula_latex(m, style)
        } else {
            super::format::formula_inline(m, style)
        }
    };
    let op = match (op, latex) {
        (CmpOp::Approx, true) => "\\approx",
        (CmpOp::Le, true) => "\\le",
        (CmpOp::Ge, true) => "\\ge",
        (op, _) => op.text(),
    };
    Some(format!("{} {op} {}", side(&l), side(&r)))
}

/// The symbols a waiting bool waits for, as typed (`a, b`).
pub fn symbols(v: &Value) -> String {
    let mut syms = Vec::new();
    if let Value::Formula { m, how, .. } = v {
        m.data.iter().for_each(|e| e.symbols(&mut syms));
        if let Some(r) = how {
            super::recipe::symbols(r, &mut syms);
        }
    }
    let st = print::Style {
        mode: Mode::Text,
        digits: 4,
    };
    let mut names: Vec<String> = syms
        .iter()
        .filter(|s| !stand_in(s))
        .map(|s| print::symbol(s, st))
        .collect();
    names.dedup();
    names.join(", ")
}

/// What a waiting value cannot be yet and when it will be: `cannot
/// decide `a < b` without numbers: it is decided once a, b have numbers`.
pub fn note(v: &Value) -> String {
    let shown = text(v, 4.into()).unwrap_or_default();
    if is_range(v) {
        format!(
            "the range `{shown}` has no items without numbers: they are made once {}",
            once(v)
        )
    } else {
        format!(
            "cannot decide `{shown}` without numbers: it is decided once {}",
            once(v)
        )
    }
}

/// When a waiting bool is decided: `a has a number`, `a, b have numbers`.
pub fn once(v: &Value) -> String {
    let names = symbols(v);
    if names.contains(", ") {
        format!("{names} have numbers")
    } else {
        format!("{names} has a number")
    }
}
