//! Decisions on matrices and vectors by their exact forms (LANGUAGE.md
//! §5, §7; issue 21: never a wrong answer), as [`super::domain`] decides
//! on scalars: whether a vector is zero (`Normalize`), whether a matrix is
//! in SO(3) or SE(3) (RᵀR = I and det R = 1, §3.2.1; the last row of T
//! (0, 0, 0, 1), (3.62)), and whether a rotation is a half turn (tr R = −1,
//! case (ii) of the logarithm, §3.2.3.3). A matrix with an exact form is
//! decided by it; a float with none, by its floats.
//!
//! The floats of an exact matrix may fall on the other side of a
//! threshold: `(0.1 + 0.2, 0) − (0.3, 0)` is (5.6e-17, 0) in floats and
//! the zero vector exactly; a rotation by π − 1e-20 about −ẑ typed exactly
//! has a skew part of −1e-20, 0 in floats, so read as a half turn its log
//! was +ẑπ. Exact forms are asked for only where the floats are within
//! rounding of the threshold, so a float input costs nothing, and an
//! exact one away from every threshold nothing more than its floats.

use super::convert::{self, ACCEPT_TOL, Group, Membership, PROJECT_TOL};
use super::domain::{nearest, sign};
use super::exact::{Exact, Operation};
use super::num::Num;
use super::value::Value;
use crate::lie::{Vec3, so3::HalfTurn};
use crate::sym::Mat;
use crate::sym::coef::{Coef, Rat};
use crate::sym::expr::Expr;
use crate::values::exact::deref;

/// The exact form of a numeric value that may have one (None at once for
/// a float: nothing is computed).
pub fn form(v: &Value) -> Option<Mat> {
    match v {
        Value::Num { m, exact, .. } => form_of(m, exact),
        _ => None,
    }
}

/// The exact form of numbers `m` carrying `exact`.
fn form_of(m: &Num, exact: &Exact) -> Option<Mat> {
    if exact.is_float() {
        None
    } else {
        exact.form(m)
    }
}

/// The floats nearest the entries of an exact matrix, row by row (the
/// float of each entry's exact value, not of the floats that made it).
pub fn nearest_floats(m: &Mat) -> Option<Vec<f64>> {
    m.data.iter().map(nearest).collect()
}

/// ‖x‖₂ of floats with no overflow or underflow on the way: scaled by the
/// largest entry (‖(1e-200, 0)‖ is 1e-200, not 0; ‖(3e200, 4e200)‖ is
/// 5e200, not ∞).
pub fn norm(xs: &[f64]) -> f64 {
    let big = xs.iter().fold(0f64, |s, x| s.max(x.abs()));
    if big == 0.0 || !big.is_finite() {
        return big;
    }
    big * xs.iter().map(|x| (x / big).powi(2)).sum::<f64>().sqrt()
}

/// The entries of a numeric value whose floats are all within rounding of
/// 0 (below 1e-6), as the floats nearest their exact values (all 0 for
/// an exact zero: `(0.1 + 0.2, 0) − (0.3, 0)` is (5.6e-17, 0) in floats);
/// None for a float, or where a float is larger (an exact form cannot
/// make it 0).
pub fn small_entries(v: &Value) -> Option<Vec<f64>> {
    let Value::Num { m, .. } = v else { return None };
    if m.iter().any(|x| x.is_nan() || x.abs() > 1e-6) {
        return None;
    }
    nearest_floats(&form(v)?)
}

/// How far an exact matrix is from a group, decided exactly.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gap {
    /// The book's DistanceToSO3/DistanceToSE3 measure (§3.6) of the exact
    /// matrix, to the float nearest each entry of RᵀR − I: 1e9 when det R
    /// is not positive.
    pub distance: f64,
    /// RᵀR = I, det R = 1 (and the last row (0, …, 0, 1)) exactly.
    pub exactly_in: bool,
}

/// The [`Gap`] of an exact matrix of `group`'s shape; None when a sign
/// cannot be decided (a determinant within 1e-45 of 0 and not 0).
pub fn group_gap(m: &Mat, group: Group) -> Option<Gap> {
    let (off, det) = off_group(m, group)?;
    let exactly_in = det > 0 && off.iter().all(|e| e.terms.is_empty());
    let distance = if det > 0 {
        norm(&off.iter().map(nearest).collect::<Option<Vec<f64>>>()?)
    } else {
        crate::lie::project::FAR
    };
    Some(Gap {
        distance,
        exactly_in,
    })
}

/// The entries of the book's measure of distance from `group` (§3.6) of
/// an exact matrix — RᵀR − I of its rotation block R, and for a transform
/// its last row minus (0, …, 0, 1) — and the sign of det R; None for the
/// wrong shape or a sign within 1e-45 of 0.
fn off_group(m: &Mat, group: Group) -> Option<(Vec<Expr>, i32)> {
    let n = group.size();
    if (m.rows, m.cols) != (n, n) {
        return None;
    }
    let k = rotation_size(group);
    let r = m.block(0..k, 0..k);
    let mut off = r.transpose().mul(&r)?.add(&Mat::identity(k), true)?.data;
    if n > k {
        // (the last row of a transform: (0, …, 0, 1))
        for j in 0..n {
            let want = if j == n - 1 {
                Expr::int(1)
            } else {
                Expr::int(0)
            };
            off.push(m.get(n - 1, j).sub(&want));
        }
    }
    Some((off, sign(&r.det()?)?))
}

/// The size of a group's rotation block.
fn rotation_size(group: Group) -> usize {
    match group {
        Group::SO3 | Group::SE3 => 3,
        Group::SO2 | Group::SE2 => 2,
    }
}

/// Whether the book's distance of the numeric value `v` from `group` is
/// below `tol` (`TestIfSO3`, `TestIfSE3`: below 1e-3, §3.6), decided by its
/// exact form where its float `float` is within 1e-9 of `tol`: the sum of
/// the squares of RᵀR − I against tol² (a distance of exactly 1e-3 is
/// 0.000999… in floats, and not below 1e-3). None where the floats decide
/// (a float, far from `tol`, or a sign within 1e-45 of 0).
pub fn distance_below(v: &Value, group: Group, float: f64, tol: f64) -> Option<bool> {
    if (float - tol).abs() > 1e-9 * tol {
        return None;
    }
    let (off, det) = off_group(&form(v)?, group)?;
    if det <= 0 {
        return Some(false);
    }
    let squares = off.iter().fold(Expr::int(0), |s, e| s.add(&e.mul(e)));
    let t = Expr::constant(Coef::rat(Rat::typed(tol)?));
    Some(sign(&squares.sub(&t.mul(&t)))? < 0)
}

/// [`convert::membership`] of numbers `m` carrying `exact` (LANGUAGE.md
/// §5), with the tolerances measured on the exact matrix when it has one
/// and its floats are off the group: a matrix exactly within 1e-9 of it
/// (exactly in it, however far its floats have strayed: `[1,
/// cos(3π/2)/1e-17, 0; 0, 1, 0; 0, 0, 1]` is the identity, its floats
/// 18.4 off) is taken as it is, at the floats nearest its entries; within
/// 1e-2 it is projected, with its own distance; farther is refused with
/// it. Within 1e-9 in floats is within 1e-9 (the contract's tolerance for
/// rounded book values and printed values read back, §10), so a matrix
/// the floats accept costs nothing more.
pub fn membership(m: &Num, exact: &Exact, group: Group) -> Membership {
    let float = convert::membership(m, group);
    if matches!(float, Membership::Exact(_)) {
        return float;
    }
    let Some(e) = form_of(m, exact) else {
        return float;
    };
    let (Some(gap), Some(xs)) = (group_gap(&e, group), nearest_floats(&e)) else {
        return float;
    };
    // (row by row to column by column)
    let (r, c) = (e.rows, e.cols);
    let cols: Vec<f64> = (0..r * c).map(|k| xs[(k % r) * c + k / r]).collect();
    let near = Num::from_slice(r, c, &cols);
    match gap.distance {
        d if d <= ACCEPT_TOL => Membership::Exact(near),
        d if d <= PROJECT_TOL => Membership::Projected(convert::project(&near, group), d),
        distance => {
            let k = rotation_size(group);
            let det = near.to_dmatrix().view((0, 0), (k, k)).determinant();
            Membership::Outside { distance, det }
        }
    }
}

/// Whether the floats of `v`, a 3×3 or 4×4 made from exact numbers, put
/// the angle θ of its rotation block within rounding of π (cosθ < 0 and
/// ‖sinθ ω̂‖ ≤ 1e-12): where the floats cannot tell the log's branch, and
/// its exact form ([`half_turn`]) or certified balls (`decide::turn`) must.
pub fn near_half_turn(v: &Value) -> bool {
    let Value::Num { m, exact, .. } = v else {
        return false;
    };
    let n = match m.shape() {
        (3, 3) => 3,
        (4, 4) => 4,
        _ => return false,
    };
    if exact.is_float() {
        return false;
    }
    // (the entries read from one slice: indexing `m` asks its shape anew
    // at every entry)
    let xs = m.as_slice();
    let f = |i: usize, j: usize| xs[j * n + i];
    let skew = Vec3::new(f(2, 1) - f(1, 2), f(0, 2) - f(2, 0), f(1, 0) - f(0, 1)) * 0.5;
    let cos = 0.5 * (f(0, 0) + f(1, 1) + f(2, 2) - 1.0);
    cos < 0.0 && skew.norm() <= 1e-12
}

/// The branch of the logarithm of the rotation block R of a numeric value
/// `v` (3×3 or 4×4), decided by its exact form where its floats put θ
/// within rounding of π (cosθ < 0, ‖sinθ ω̂‖ ≤ 1e-12): θ = π when tr R = −1
/// exactly, else sinθ ω̂ and cosθ to the floats nearest their exact values.
/// None where the floats decide (a float, θ away from π, R not exactly a
/// rotation, or a sign within 1e-45 of 0).
pub fn half_turn(v: &Value) -> Option<HalfTurn> {
    let Value::Num { m, exact, .. } = v else {
        return None;
    };
    if !near_half_turn(v) {
        return None;
    }
    let e = form_of(m, exact)?;
    let r = e.block(0..3, 0..3);
    if !group_gap(&r, Group::SO3)?.exactly_in {
        return None;
    }
    let half = Expr::constant(Coef::rat(Rat::new(1, 2)?));
    let g = |i: usize, j: usize| r.get(i, j);
    let skew = [
        g(2, 1).sub(g(1, 2)).mul(&half),
        g(0, 2).sub(g(2, 0)).mul(&half),
        g(1, 0).sub(g(0, 1)).mul(&half),
    ];
    let cos = r.trace().sub(&Expr::int(1)).mul(&half);
    let half_turn = skew.iter().all(|s| s.terms.is_empty());
    let floats: Option<Vec<f64>> = skew.iter().map(nearest).collect();
    let floats = floats?;
    Some(HalfTurn {
        skew: Vec3::new(floats[0], floats[1], floats[2]),
        cos: if half_turn { -1.0 } else { nearest(&cos)? },
        half_turn,
    })
}

/// The exact forms of a vector's or matrix's entries one by one, row by
/// row: all of them when it has an exact form; else, for one written
/// entry by entry of exact and float numbers (`(1, exp(0))`, `[1, exp(0);
/// 0, 1]`), each entry's own (None for an entry with none). None for a
/// float, or a value made otherwise.
pub fn entry_forms(v: &Value) -> Option<Vec<Option<Expr>>> {
    let Value::Num { m, exact, .. } = v else {
        return None;
    };
    if exact.is_float() {
        return None;
    }
    if let Some(f) = exact.form(m) {
        return Some(f.data.into_iter().map(Some).collect());
    }
    exact
        .with_recipe(|p| {
            let entries = deref(&p.args.refs())
                .iter()
                .all(|a| a.as_scalar().is_some());
            (entries && matches!(p.op, Operation::Vector | Operation::Block(_))).then(|| {
                deref(&p.args.refs())
                    .into_iter()
                    .map(|a| form(a).and_then(|f| f.data.into_iter().next()))
                    .collect()
            })
        })
        .flatten()
}

/// True when an entry of `a` and the same entry of `b` both have exact
/// forms and they differ ([`entry_forms`]): the two are not equal, and not
/// by rounding, whatever the other entries' floats say.
pub fn entries_differ(a: &Value, b: &Value) -> bool {
    if !(a.may_be_exact() && b.may_be_exact()) {
        return false;
    }
    match (entry_forms(a), entry_forms(b)) {
        (Some(x), Some(y)) => x
            .iter()
            .zip(&y)
            .any(|(p, q)| matches!((p, q), (Some(p), Some(q)) if p != q)),
        _ => false,
    }
}

/// The entries of a matrix as decisions read them, row by row: floats
/// nearer their values than the matrix's own (the floats nearest an exact
/// form, or the midpoints of certified balls) and, for each, whether it is
/// exactly 0 (Some(true)), certainly not (Some(false)), or undecided.
#[derive(Debug, Clone, PartialEq)]
pub struct Entries {
    /// The floats, row by row.
    pub floats: Vec<f64>,
    /// Whether each entry is 0.
    pub zero: Vec<Option<bool>>,
}

/// The [`Entries`] of a numeric value with an exact form.
pub fn exact_entries(v: &Value) -> Option<Entries> {
    let e = form(v)?;
    Some(Entries {
        floats: nearest_floats(&e)?,
        zero: e.data.iter().map(|x| Some(x.terms.is_empty())).collect(),
    })
}
