//! The rules (LANGUAGE.md §6) of the operations that take shapes apart
//! or build them: indexing `x[i]`, the book's bracket `[x]` (3.30, 3.70)
//! and block matrices `[a, b; c, d]`. [`super::apply::Op::rule`] uses them.
//! With values: the zero blocks a lone `0` of `[R, p; 0, 1]` stands for,
//! and a vector's entries as indexing gives them.

use crate::check::rules::RuleError;
use crate::check::ty::{Frames, Kind, Ty};
use crate::values::error::OpError;
use crate::values::ops::{Sel, position};
use crate::values::value::Value;

/// The rule of `x[i]`, `M[i, j]`, `M[:, j]`: a tuple's part, a column
/// in the outer frame of the matrix, a row, or an entry.
pub(crate) fn index_type(t: &Ty, sels: &[Sel]) -> Result<Ty, RuleError> {
    let outer = match t.frames.outer() {
        Some(a) => Frames::One(*a),
        None => Frames::None,
    };
    Ok(match (&t.kind, sels) {
        // part i, with its own frames (a literal's) or its part of the
        // tuple's tag (a builtin's)
        (Kind::Tuple(ks), [Sel::At(i)])
            if i.fract() == 0.0 && *i >= 1.0 && (*i as usize) <= ks.len() =>
        {
            t.part(*i as usize - 1)
                .unwrap_or(Ty::plain(ks[*i as usize - 1]))
        }
        // which part is not known (checking, an index that is no literal):
        // the parts' one type when they share it, else nothing certain
        (Kind::Tuple(_), _) => t.any_part().unwrap_or(Ty::plain(Kind::Unknown)),
        (k, _) if k.shape().is_none() => {
            return Err(RuleError::from(crate::check::rules::Refusal {
                kind: Some(crate::diagnostics::ErrorKind::Type),
                message: format!("cannot index a {k}"),
                ..Default::default()
            }));
        }
        // (as long as the kind's columns and rows are: R[:, 2] of a
        // rotation is a 3-vector, with symbols too)
        (k, [Sel::All, Sel::At(_)]) => Ty::new(Kind::Vector(k.shape().and_then(|s| s.0)), outer),
        (k, [Sel::At(_), Sel::All]) => {
            Ty::plain(Kind::Matrix(Some(1), k.shape().and_then(|s| s.1)))
        }
        _ => Ty::scalar(),
    })
}

/// The error `x[i]`, `M[i, j]` would stop with, known from the kind's
/// sizes and the indices known without numbers (`L[1]` of a 4×8 matrix,
/// `t[3]` of a pair, `x[1.5]`): what [`crate::values::ops::index`] says of
/// the value, so that checking refuses what running refuses. An index
/// that is NaN is not known.
pub(crate) fn index_refusal(kind: &Kind, sels: &[Sel]) -> Option<OpError> {
    let at = |x: f64, n: Option<usize>| -> Option<OpError> {
        if x.is_nan() {
            return None;
        }
        if x.fract() != 0.0 || !x.is_finite() {
            return Some(OpError::IndexNotWhole(x));
        }
        position(x, n?).err()
    };
    if let Kind::Tuple(ks) = kind {
        return match sels {
            [Sel::At(i)] => at(*i, Some(ks.len())),
            _ => Some(OpError::TupleIndex),
        };
    }
    let (rows, cols) = kind.shape()?;
    match sels {
        [Sel::At(i)] => match (rows, cols) {
            (_, Some(1)) => at(*i, rows),
            (Some(1), _) => at(*i, cols),
            (Some(_), Some(_)) => Some(OpError::MatrixIndex),
            _ => at(*i, None),
        },
        [Sel::At(i), Sel::At(j)] => at(*i, rows).or_else(|| at(*j, cols)),
        [Sel::At(i), Sel::All] => at(*i, rows),
        [Sel::All, Sel::At(j)] => at(*j, cols),
        [Sel::All, Sel::All] | [Sel::All] => None,
        _ => Some(OpError::TooManyIndices),
    }
}

/// The error a block matrix `[a, b; c, d]` of entries of these kinds
/// would stop with, as far as the kinds know, in the order running finds
/// them (`crate::values::ops::brackets`): a row whose blocks have different
/// heights (`[T_ab, v]`, `[1, v]`), then a row of another width than the
/// first (`[R, 0; 1, 1]`). Each entry is its kind and whether it is a lone
/// `0`, which stands for the zero block its row's height and its column's
/// width need (`zero_blocks_where`); any other scalar is 1×1. A row with an
/// entry of unknown height is judged by the heights known.
pub(crate) fn block_refusal(rows: &[Vec<(Kind, bool)>]) -> Option<OpError> {
    // (all 1×1: a vector or a matrix of numbers, no blocks to fill)
    let blocks = rows
        .iter()
        .flatten()
        .any(|(k, _)| k.shape() != Some((Some(1), Some(1))));
    let lone = |i: usize, j: usize| blocks && rows[i][j].1;
    let dims = |k: &Kind| k.shape().unwrap_or((None, None));
    let mut filled: Vec<Vec<(Option<usize>, Option<usize>)>> = Vec::with_capacity(rows.len());
    for (i, row) in rows.iter().enumerate() {
        let known: Vec<Option<usize>> = (0..row.len())
            .filter(|&j| !lone(i, j))
            .map(|j| dims(&row[j].0).0)
            .collect();
        let height = match known.iter().all(Option::is_some) {
            true => Some(known.iter().flatten().copied().max().unwrap_or(1)),
            false => None,
        };
        let mut cells = Vec::with_capacity(row.len());
        for (j, (k, _)) in row.iter().enumerate() {
            if !lone(i, j) {
                cells.push(dims(k));
                continue;
            }
            let mut width = Some(1);
            for (r, other) in rows.iter().enumerate() {
                if other.len() == row.len() && !lone(r, j) {
                    width = width.zip(dims(&other[j].0).1).map(|(a, b)| a.max(b));
                }
            }
            cells.push((height, width));
        }
        // (running compares each block with the row's first)
        let heights: Vec<usize> = match height {
            Some(_) => cells.iter().filter_map(|c| c.0).collect(),
            None => (0..row.len())
                .filter(|&j| !lone(i, j))
                .filter_map(|j| cells[j].0)
                .collect(),
        };
        if let Some((first, rest)) = heights.split_first()
            && let Some(other) = rest.iter().find(|&&h| h != *first)
        {
            return Some(OpError::RowHeights(i + 1, *first, *other));
        }
        filled.push(cells);
    }
    let widths: Vec<Option<usize>> = filled
        .iter()
        .map(|cells| cells.iter().try_fold(0, |w, c| c.1.map(|x| w + x)))
        .collect();
    let first = *widths.first()?;
    let first = first?;
    widths.iter().enumerate().find_map(|(i, w)| {
        w.filter(|&w| w != first)
            .map(|w| OpError::RowWidths(first, w, i + 1))
    })
}

/// The rule of `[x]`, one entry in brackets: the book's bracket of a 3-
/// or 6-vector is in so(3) or se(3) (3.30, 3.70), in the vector's frame;
/// anything else is itself.
#[inline(always)]
pub(crate) fn bracket_type(t: &Ty) -> Ty {
    match t.kind.vec_len() {
        Some(3) => Ty::new(Kind::So3, t.frames),
        Some(6) => Ty::new(Kind::Se3, t.frames),
        _ => *t,
    }
}

/// The rule of [`super::apply::Op::Block`], `[ ... ]`, its entries row by row with
/// `widths` entries in each: the book's bracket of one vector, a column
/// vector of one row of numbers, else a block matrix whose frames are the
/// one pair tag inside it (`[R_sb, p_sb; 0, 0, 0, 1]` is {s}←{b}).
pub(crate) fn block_type(widths: &[usize], args: &[&Ty]) -> Ty {
    if let [t] = args {
        return bracket_type(t);
    }
    let all_scalar = args.iter().all(|t| matches!(t.kind, Kind::Scalar));
    if all_scalar && widths.len() == 1 {
        return Ty::plain(Kind::Vector(Some(args.len())));
    }
    let mut frames = Frames::None;
    for t in args {
        if let Frames::Pair(..) = t.frames {
            if frames.is_none() {
                frames = t.frames;
            } else if frames != t.frames {
                frames = Frames::None;
                break;
            }
        }
    }
    // Shape: a row is as tall as its tallest entry and a column as wide as
    // its widest (among rows with as many entries as the first), as
    // `zero_blocks_where` makes the values: a scalar may be a lone `0`
    // standing for a zero block, so it only says "at least 1"
    // (`[1, 0; 0, R]` is 4×4, `[R, 0; 0, R]` 6×6). An entry of unknown
    // shape leaves its row's height or its column's width unknown.
    let dims = |t: &&Ty| t.kind.shape().unwrap_or((None, None));
    let widest = |a: Option<usize>, b: Option<usize>| a.zip(b).map(|(a, b)| a.max(b));
    let first = widths.first().map_or(0, |&n| n.min(args.len()));
    let mut columns: Vec<Option<usize>> = vec![Some(1); first];
    let mut height = Some(0);
    let mut start = 0;
    for &n in widths {
        let row = &args[start.min(args.len())..(start + n).min(args.len())];
        let tall = row.iter().map(|t| dims(t).0).fold(Some(1), widest);
        height = height.zip(tall).map(|(a, b)| a + b);
        if n == first {
            for (c, t) in columns.iter_mut().zip(row) {
                *c = widest(*c, dims(t).1);
            }
        }
        start += n;
    }
    let width: Option<usize> = columns.into_iter().sum();
    // (one column is a vector, as the numbers are classified: `[p_a; p_b]`
    // is a 6-vector)
    match width {
        Some(1) => Ty::new(Kind::Vector(height), frames),
        _ => Ty::new(Kind::Matrix(height, width), frames),
    }
}

/// `[R, p; 0, 1]` with its values: each entry that `lone(i, j)` says was
/// written as a lone `0` becomes the zero block as wide as its column
/// (from rows with as many entries) and as tall as its row: at a block
/// literal, and when a block kept over symbols gets its numbers
/// (LANGUAGE.md §7: as if they had been typed first).
pub(crate) fn zero_blocks_where(lone: impl Fn(usize, usize) -> bool, vals: &mut [Vec<Value>]) {
    let shape = |v: &Value| match v {
        Value::Num { m, .. } => Some(m.shape()),
        Value::Formula { m, .. } => Some((m.rows, m.cols)),
        _ => None,
    };
    let blocks = vals
        .iter()
        .flatten()
        .any(|v| shape(v).is_some_and(|s| s != (1, 1)));
    if !blocks {
        return;
    }
    let mut fills = Vec::new();
    for (i, row) in vals.iter().enumerate() {
        let height = row
            .iter()
            .enumerate()
            .filter(|&(j, _)| !lone(i, j))
            .filter_map(|(_, v)| shape(v).map(|s| s.0))
            .max()
            .unwrap_or(1);
        for j in 0..row.len() {
            if !lone(i, j) {
                continue;
            }
            let width = vals
                .iter()
                .enumerate()
                .filter(|(k, r)| r.len() == row.len() && !lone(*k, j))
                .filter_map(|(_, vs)| shape(&vs[j]).map(|s| s.1))
                .max()
                .unwrap_or(1);
            fills.push((i, j, height, width));
        }
    }
    for (i, j, h, w) in fills {
        vals[i][j] = Value::Num {
            kind: Kind::Matrix(Some(h), Some(w)),
            m: crate::values::num::Num::zeros(h, w),
            exact: crate::values::exact::Exact::Typed,
        };
    }
}

/// The entries of a vector of numbers (a column, or a row as MATLAB
/// writes one), each as `v[i]` gives it: with its exact form when the
/// vector has one (`[x^2 for x in (sqrt(2), 1)]`, `(x, y) = (sqrt(2), 1)`
/// and `min([sqrt(2), 2])` keep √2 exact, as `v[1]` does; §7). Any other
/// matrix gives its floats, column by column.
pub(crate) fn entries(v: &Value) -> Vec<Value> {
    let Value::Num { m, .. } = v else {
        return Vec::new();
    };
    let (rows, cols) = (m.nrows(), m.ncols());
    if cols != 1 && rows != 1 {
        return m.iter().map(|x| Value::scalar(*x)).collect();
    }
    (1..=rows.max(cols))
        .map(|i| {
            let at = Sel::At(i as f64);
            let sel = if cols == 1 {
                vec![at]
            } else {
                vec![Sel::At(1.0), at]
            };
            super::apply::Op::Index(&sel)
                .apply(&[v], &Kind::Scalar)
                .unwrap_or_else(|_| Value::scalar(f64::NAN))
        })
        .collect()
}

/// The entries of `[ ... ]` ([`super::apply::Op::Block`]) row by row,
/// `widths` giving each row's length.
pub(super) fn rows_of(widths: &[usize], args: &[&Value]) -> Vec<Vec<Value>> {
    let mut rest = args;
    widths
        .iter()
        .map(|&n| {
            let (row, tail) = rest.split_at(n.min(rest.len()));
            rest = tail;
            row.iter().map(|v| (*v).clone()).collect()
        })
        .collect()
}
