//! `a == b` for numbers with no exact form but made from exact ones
//! (LANGUAGE.md §7, issue 21: never a wrong answer). `cos(1e-9)` and 1
//! are the same float, yet differ by 5·10⁻¹⁹; `cos(π/7) + cos(3π/7) +
//! cos(5π/7)` and 1/2 are different floats, yet equal. A number made by
//! operations over exact numbers keeps how it was made (its recipe,
//! [`crate::values::exact::Exact::with_recipe`]); `==` evaluates both
//! sides' recipes again in certified ball arithmetic ([`super::ball`]) at
//! 128, then 256, then 512 bits: a difference whose ball excludes 0 is
//! certainly nonzero (`false`); sides made by the same operations over the
//! same numbers are equal (`true`); sides still within each other's balls
//! at 512 bits agree far past rounding but are not proven equal — the
//! answer says so ([`Verdict::Agree`]), it is never a bare `true`. A side
//! with no recipe (a numeric matrix exponential, a float read from a
//! file) gets no verdict here: it compares as floats (§7).

use crate::values::exact::deref;
use std::collections::HashMap;

use super::ball::{self, Ball};
use super::balls::{Balls, call, hat, product};
use crate::check::ty::Kind;
use crate::syntax::ast::BinOp;
use crate::values::exact::{Exact, Operation, Pending};
use crate::values::value::Value;

/// What certified arithmetic says of `a == b` on numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Verdict {
    /// Made by the same operations over the same exact numbers.
    Equal,
    /// Certainly different: the largest difference (an entry's, as a
    /// float: 5e-19 for `cos(1e-9) == 1`).
    Differ(f64),
    /// Every entry's difference is within its ball at the highest
    /// precision: the sides agree to this many significant digits and
    /// may or may not be equal.
    Agree(u32),
}

/// The precisions tried, in bits: the first that excludes 0 decides.
pub(crate) const PRECISIONS: [usize; 3] = [128, 256, 512];

/// The verdict of a proof of `a == b` from how the sides were made (their
/// normal forms under exp and log, the lifted forms of their angles, their
/// squares, an inverse function's), the difference a proof finds given at
/// precision `prec`; None when no proof decides.
fn proven(a: &Value, b: &Value, depth: u32, prec: usize) -> Option<Verdict> {
    // (sides made by exp and log: their normal forms)
    if super::transcendental::proven_equal(a, b) {
        return Some(Verdict::Equal);
    }
    match super::lift::verdict(a, b) {
        Some(Ok(())) => return Some(Verdict::Equal),
        Some(Err(d)) => {
            let d = ball::exact(&d, prec).map_or(0.0, |d| ball::floats(&d).0);
            return Some(Verdict::Differ(d));
        }
        None => {}
    }
    if same_sign(a, b) && super::lift::squares_equal(a, b) {
        return Some(Verdict::Equal);
    }
    if super::inverse::proven_equal(a, b, depth) {
        return Some(Verdict::Equal);
    }
    None
}

/// The verdict of certified arithmetic on `a == b` (numbers of one shape,
/// one side at least with no exact form); None when a side has no recipe
/// to evaluate, or its recipe holds an operation not bounded here: the
/// sides then compare as floats.
pub fn equal(a: &Value, b: &Value) -> Option<Verdict> {
    equal_at(a, b, 0)
}

/// [`equal`], asked `depth` times within itself (by
/// [`super::inverse`], which proves f(c) == y to prove asin y == c).
pub(crate) fn equal_at(a: &Value, b: &Value, depth: u32) -> Option<Verdict> {
    let (Value::Num { m: x, .. }, Value::Num { m: y, .. }) = (a, b) else {
        return None;
    };
    if x.shape() != y.shape() || !(a.may_be_exact() && b.may_be_exact()) {
        return None;
    }
    if same(a, b, 0) {
        return Some(Verdict::Equal);
    }
    let mut last = None;
    for (k, prec) in PRECISIONS.into_iter().enumerate() {
        // (the cheapest precision first: most differences show there; an
        // identity is then looked for before working harder)
        if k == 1
            && let Some(v) = proven(a, b, depth, prec)
        {
            return Some(v);
        }
        let mut memo = Memo::default();
        let (Some(p), Some(q)) = (balls(a, prec, &mut memo), balls(b, prec, &mut memo)) else {
            // (a side the balls do not bound, a matrix exponential: an
            // identity may still be proven, `exp([ẑ] 0.1) exp([ẑ] 0.2) ==
            // exp([ẑ] 0.3)`; else the sides compare as floats)
            return match k {
                0 => proven(a, b, depth, PRECISIONS[1]),
                _ => None,
            };
        };
        let mut largest: Option<f64> = None;
        let mut widest = 0f64;
        let mut scale = 0f64;
        for (u, v) in p.data.iter().zip(&q.data) {
            let d = ball::sub(u, v, prec)?;
            let (mid, rad) = ball::floats(&d);
            scale = scale
                .max(ball::floats(u).0.abs())
                .max(ball::floats(v).0.abs());
            if ball::nonzero(&d) {
                largest =
                    Some(largest.map_or(mid, |l: f64| if mid.abs() > l.abs() { mid } else { l }));
            } else {
                widest = widest.max(rad);
            }
        }
        if let Some(d) = largest {
            return Some(Verdict::Differ(d));
        }
        last = Some((widest, scale));
    }
    let (rad, scale) = last?;
    let digits = if rad == 0.0 {
        // (exact balls that hold 0: equal; only a zero radius does that)
        return Some(Verdict::Equal);
    } else {
        (scale.max(1.0) / rad).log10().floor().max(0.0)
    };
    Some(Verdict::Agree(digits as u32))
}

/// True when the numbers `a` and `b` are scalars whose 128-bit balls
/// both exclude 0 on one side of it: with a² = b² proven, then a = b.
fn same_sign(a: &Value, b: &Value) -> bool {
    let mut memo = Memo::default();
    let sign = |v: &Value, memo: &mut Memo| {
        let x = balls(v, PRECISIONS[0], memo)?;
        let x = x.one()?.clone();
        ball::nonzero(&x).then(|| ball::floats(&x).0 > 0.0)
    };
    matches!((sign(a, &mut memo), sign(b, &mut memo)), (Some(p), Some(q)) if p == q)
}

/// True when `a` and `b` are made by the same operations over the same
/// exact numbers (so equal whatever the operations' values): the same
/// number read twice, or recipes alike step by step.
fn same(a: &Value, b: &Value, depth: u32) -> bool {
    let (
        Value::Num {
            m: x,
            exact: e,
            kind: k,
            ..
        },
        Value::Num {
            m: y,
            exact: f,
            kind: l,
            ..
        },
    ) = (a, b)
    else {
        return false;
    };
    if x.shape() != y.shape() || depth > 64 {
        return false;
    }
    if e.identity().is_some() && e.identity() == f.identity() {
        return true;
    }
    if let (Some(p), Some(q)) = (a.exact_form(), b.exact_form()) {
        return p == q;
    }
    if matches!(e, Exact::Typed) || matches!(f, Exact::Typed) {
        return false;
    }
    e.with_recipe(|p| {
        f.with_recipe(|q| {
            k == l
                && format!("{:?}", p.op) == format!("{:?}", q.op)
                && deref(&p.args.refs()).len() == deref(&q.args.refs()).len()
                && deref(&p.args.refs())
                    .iter()
                    .zip(deref(&q.args.refs()))
                    .all(|(u, v)| same(u, v, depth + 1))
        })
        .unwrap_or(false)
    })
    .unwrap_or(false)
}

/// The balls of the values met in one evaluation, by their shared form.
#[derive(Default)]
pub(crate) struct Memo(HashMap<*const (), Option<Balls>>);

/// The balls of a number at `prec` bits: its exact form's, else its
/// recipe's; None for a float, and for a ball that strays from the number's
/// own floats (a recipe read otherwise than it was computed: never trusted).
pub(crate) fn balls(v: &Value, prec: usize, memo: &mut Memo) -> Option<Balls> {
    let Value::Num { m, exact, .. } = v else {
        return None;
    };
    let key = exact.identity();
    if let Some(k) = key
        && let Some(found) = memo.0.get(&k)
    {
        return found.clone();
    }
    let out = stacker::maybe_grow(64 * 1024, 1024 * 1024, || {
        let (r, c) = m.shape();
        // (the size of the operands: the floats of the result may be off
        // by their rounding, (1e16 + sin 1) − 1e16 is 2 as floats)
        let mut scale = 1f64;
        let out = match v.exact_form() {
            Some(form) => Balls {
                rows: r,
                cols: c,
                data: form
                    .data
                    .iter()
                    .map(|e| ball::exact(e, prec))
                    .collect::<Option<_>>()?,
            },
            None => exact.with_recipe(|p| {
                for a in deref(&p.args.refs()) {
                    if let Value::Num { m, .. } = a {
                        scale = m.iter().fold(scale, |s, x| s.max(x.abs()));
                    }
                }
                operation(p, prec, memo)
            })??,
        };
        // (the recipe read as computed: same shape, the floats within reach)
        if (out.rows, out.cols) != (r, c) {
            return None;
        }
        for (k, b) in out.data.iter().enumerate() {
            let (mid, rad) = ball::floats(b);
            let x = m[(k / c, k % c)];
            let within = (mid - x).abs() <= rad + 1e-6 * x.abs().max(scale);
            if !within {
                return None;
            }
        }
        Some(out)
    });
    if let Some(k) = key {
        memo.0.insert(k, out.clone());
    }
    out
}

/// The balls of operation `p` over its operands' balls; None for an
/// operation or a shape not bounded here.
fn operation(p: &Pending, prec: usize, memo: &mut Memo) -> Option<Balls> {
    let args = deref(&p.args.refs())
        .into_iter()
        .map(|v| balls(v, prec, memo))
        .collect::<Option<Vec<Balls>>>()?;
    let one = |i: usize| args.get(i).and_then(Balls::one);
    match &p.op {
        Operation::Neg => args.first()?.map(|x| Some(ball::neg(x))),
        Operation::Degrees => {
            let k = ball::div(&ball::pi(prec), &ball::int(&180.into()), prec)?;
            args.first()?.map(|x| ball::mul(x, &k, prec))
        }
        Operation::Arith(op) => arith(*op, args.first()?, args.get(1)?, prec),
        Operation::Inverse => match p.kind {
            Kind::SO3 | Kind::SO2 => Some(args.first()?.transpose()),
            _ => Some(Balls::scalar(ball::div(
                &ball::int(&1.into()),
                one(0)?,
                prec,
            )?)),
        },
        Operation::Transpose => Some(args.first()?.transpose()),
        Operation::Vector => {
            let xs = (0..args.len())
                .map(|i| one(i).cloned())
                .collect::<Option<_>>()?;
            Some(Balls::column(xs))
        }
        Operation::Block(widths) => block(widths, &args),
        Operation::Index(sels) => index(args.first()?, sels),
        Operation::Member(_) => None,
        Operation::Call(name) => call(name, &args, prec),
    }
}

/// `a op b` on balls: sums entrywise, products by a number or of
/// matrices, quotients by a number, integer powers of a number.
fn arith(op: BinOp, a: &Balls, b: &Balls, prec: usize) -> Option<Balls> {
    let entrywise = |f: &dyn Fn(&Ball, &Ball) -> Option<Ball>| {
        ((a.rows, a.cols) == (b.rows, b.cols)).then(|| {
            Some(Balls {
                rows: a.rows,
                cols: a.cols,
                data: a
                    .data
                    .iter()
                    .zip(&b.data)
                    .map(|(x, y)| f(x, y))
                    .collect::<Option<_>>()?,
            })
        })?
    };
    match op {
        BinOp::Add => entrywise(&|x, y| ball::add(x, y, prec)),
        BinOp::Sub => entrywise(&|x, y| ball::sub(x, y, prec)),
        BinOp::Mul => match (a.one(), b.one()) {
            (Some(x), _) => b.map(|y| ball::mul(x, y, prec)),
            (_, Some(y)) => a.map(|x| ball::mul(x, y, prec)),
            _ => product(a, b, prec),
        },
        BinOp::Div => {
            let y = b.one()?;
            a.map(|x| ball::div(x, y, prec))
        }
        BinOp::Pow => {
            let (x, k) = (a.one()?, b.one()?);
            // (an integer power: an exact exponent that is an integer)
            let (kf, _) = ball::floats(k);
            if !k.rad.is_zero() || kf.fract() != 0.0 || kf.abs() > 1e6 {
                return None;
            }
            Some(Balls::scalar(ball::powi(x, kf as i64, prec)?))
        }
    }
}

/// `[ ... ]`: the bracket of a 3-vector (3.30), one row of numbers as a
/// column (as numbers do), or blocks side by side and row under row.
fn block(widths: &[usize], args: &[Balls]) -> Option<Balls> {
    if let [x] = args
        && widths == [1]
    {
        return match (x.rows, x.cols) {
            (3, 1) => Some(hat(&x.data)),
            (1, 1) => Some(x.clone()),
            _ => None,
        };
    }
    if widths.len() == 1 && args.iter().all(|x| x.data.len() == 1) {
        return Some(Balls::column(
            args.iter().map(|x| x.data[0].clone()).collect(),
        ));
    }
    let mut rows: Vec<Vec<Ball>> = Vec::new();
    let mut at = 0;
    for &w in widths {
        let parts = args.get(at..at + w)?;
        at += w;
        let h = parts.first()?.rows;
        if parts.iter().any(|p| p.rows != h) {
            return None;
        }
        for i in 0..h {
            rows.push(
                parts
                    .iter()
                    .flat_map(|p| (0..p.cols).map(move |j| p.at(i, j).clone()))
                    .collect(),
            );
        }
    }
    let cols = rows.first()?.len();
    if rows.iter().any(|r| r.len() != cols) {
        return None;
    }
    Some(Balls {
        rows: rows.len(),
        cols,
        data: rows.into_iter().flatten().collect(),
    })
}

/// `x[i]`, `M[i, j]` (1-based), as numbers are indexed.
fn index(x: &Balls, sels: &[crate::values::ops::Sel]) -> Option<Balls> {
    use crate::values::ops::Sel;
    let at =
        |i: f64, n: usize| (i.fract() == 0.0 && i >= 1.0 && i <= n as f64).then(|| i as usize - 1);
    let pick = |i, j| Some(Balls::scalar(x.at(i, j).clone()));
    match sels {
        [Sel::At(i)] if x.cols == 1 => pick(at(*i, x.rows)?, 0),
        [Sel::At(i)] if x.rows == 1 => pick(0, at(*i, x.cols)?),
        [Sel::At(i), Sel::At(j)] => pick(at(*i, x.rows)?, at(*j, x.cols)?),
        _ => None,
    }
}
