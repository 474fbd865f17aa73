//! Notes that a correct result deserves, added after a builtin has run:
//! at θ = π the logarithms' axis is one of two equally valid answers
//! (§3.2.3.3, case (ii)); chasles gives the book's, and says so. At θ = 0
//! `AxisAng3` and `AxisAng6` have no axis to give (§3.2.3.3, case (i));
//! the zero vector stands in for it, and the note says so.

use super::Args;
use crate::check::ty::Kind;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::lie::{LieGroup, Mat3, SO3, Vec3};
use crate::values::convert::Group;
use crate::values::value::Value;

/// Notes on the call `a` (its arguments still in place) that returned `v`.
/// (One match on the name: every builtin call passes here, and most have
/// no note.)
pub fn after_call(a: &mut Args, v: &Value) {
    let note = match a.name {
        "log" | "MatrixLog3" | "MatrixLog6" => half_turn(a, v),
        "AxisAng3" => no_axis(a, v),
        "AxisAng6" => no_axis(a, v).or_else(|| slow_turn(a)),
        "screw_params" => slow_turn(a),
        "exp" | "MatrixExp3" | "MatrixExp6" => far_turn(a, v),
        _ => None,
    };
    if let Some(n) = note {
        a.warnings.push(n);
    }
}

/// `AxisAng6` or `screw_params` of a twist whose ω is not zero but below
/// the book's `NearZero` tolerance (1e-6): a turn about an axis far from
/// the origin, close to a pure translation. `AxisAng6` reads it as the
/// book's software does (θ = ‖v‖, so S is no unit screw axis), and
/// `screw_params` as the mathematics does (ŝ = ω/‖ω‖, a far q); the note
/// gives the other reading, so that neither passes for the only one.
fn slow_turn(a: &Args) -> Option<Diagnostic> {
    let s = a.expc6(0).ok()?;
    let w = crate::lie::norm(&s.fixed_rows::<3>(0));
    let v = crate::lie::norm(&s.fixed_rows::<3>(3));
    if !(w > 0.0 && crate::lie::near_zero(w) && v > 0.0) {
        return None;
    }
    let text = if a.name == "AxisAng6" {
        let (q, _, h) = crate::lie::se3::screw_params(&s);
        let n = |x: f64| crate::values::number::fmt_num(x, 4);
        format!(
            "‖ω‖ = {w:.3e} is below NearZero's 1e-6, so, as the book's AxisAng6, θ = ‖v‖ and S is \
             not a unit screw axis (ω ≠ 0); exactly, it is θ = ‖ω‖ = {w:.3e} about the axis of \
             pitch {} through q = ({}, {}, {}) (screw_params)",
            n(h),
            n(q.x),
            n(q.y),
            n(q.z)
        )
    } else {
        format!(
            "ω ≠ 0, so this is a turn about an axis, not a pure translation (§3.3.2.2); \
             ‖ω‖ = {w:.3e} is below NearZero's 1e-6, so it is nearly one: if ω is a rounding \
             of 0, it is the pure translation ŝ = v/‖v‖, h = ∞"
        )
    };
    Some(Diagnostic::note(ErrorKind::Domain, a.call_span, text))
}

/// The first operand's entries, column by column, and its size, when it is
/// a 3×3 or 4×4 matrix (a rotation or transform, or its Lie algebra's).
fn square_operand<'a>(a: &'a Args) -> Option<(&'a [f64], usize)> {
    let m = a.vals.first()?.as_matrix()?;
    match m.shape() {
        (3, 3) => Some((m.as_slice(), 3)),
        (4, 4) => Some((m.as_slice(), 4)),
        _ => None,
    }
}

/// θ·2⁻⁵³ above which [`far_turn`] warns: the rotation then moves by more
/// than 1e-9, the contract's `≈` tolerance (θ above about 9·10⁶ rad).
const FAR_TURN: f64 = 1e-9 * 9_007_199_254_740_992.0;

/// `exp`, `MatrixExp3`, `MatrixExp6` of exponential coordinates ω̂θ whose
/// angle θ = ‖ω̂θ‖ (§3.2.3.3, (3.51); §3.3.3.2) is so large that its
/// rounding to the nearest float moves the result: the angle is known to
/// θ·2⁻⁵³ only, and so is the rotation (at ω̂θ = (1, 2, 3)·10²⁰ not one
/// digit is left; modern_robotics' MatrixExp3 does the same). Exact when
/// one component of ω̂θ alone is nonzero (the norm is then that component).
fn far_turn(a: &Args, v: &Value) -> Option<Diagnostic> {
    let (xs, n) = square_operand(a)?;
    // ([ω] column by column: ω₁ = m₃₂, ω₂ = m₁₃, ω₃ = m₂₁; no component
    // near the bound, the common case, is the first test: θ ≤ √3 max|ωᵢ|)
    let w = [xs[n + 2], xs[2 * n], xs[1]];
    if w.iter().all(|x| x.abs() <= FAR_TURN / 2.0) || !matches!(v.kind(), Kind::SO3 | Kind::SE3) {
        return None;
    }
    let theta = crate::lie::norm(&Vec3::from(w));
    if theta <= FAR_TURN || w.iter().filter(|x| **x != 0.0).count() < 2 {
        return None;
    }
    let moved = theta / 9_007_199_254_740_992.0;
    Some(Diagnostic::warning(
        ErrorKind::Domain,
        a.call_span,
        format!(
            "θ = ‖ω̂θ‖ = {theta:.3e} rad is rounded to the nearest float: the angle, and so the rotation, is known only to about {moved:.1e}"
        ),
    )
    .with_help("give the angle apart and below 2π: Rot(ω̂, θ) or exp([ω̂] θ) with θ reduced mod 2π"))
}

/// `AxisAng3` or `AxisAng6` of the zero vector: θ = 0, and the axis is
/// undefined (§3.2.3.3, case (i): "If R = I, then θ = 0 and ω̂ is
/// undefined"); the zero vector it returns is a stand-in, not a unit axis
/// (the book's Python divides by ‖0‖ and returns NaN).
fn no_axis(a: &Args, v: &Value) -> Option<Diagnostic> {
    let what = match a.name {
        "AxisAng3" => "no rotation, so the axis ω̂ is undefined (§3.2.3.3, case (i))",
        "AxisAng6" => "no motion, so the screw axis S is undefined (§3.3.3.1)",
        _ => return None,
    };
    let Value::Tuple(parts) = v else {
        return None;
    };
    (parts.get(1)?.as_scalar()? == 0.0).then(|| {
        Diagnostic::note(
            ErrorKind::Domain,
            a.call_span,
            format!("θ = 0: {what}; the zero vector stands in for it"),
        )
    })
}

/// `log`, `MatrixLog3`, `MatrixLog6` of a rotation or transform with
/// θ = π: which of the book's formulas gave ω̂, and that −ω̂ is as valid.
fn half_turn(a: &Args, v: &Value) -> Option<Diagnostic> {
    // `log` of a 3×3 matrix may be the SE(2) log: only so(3) and se(3)
    // results qualify.
    let applies = match (a.name, v.kind()) {
        ("log", Kind::So3 | Kind::Se3) => true,
        ("MatrixLog3" | "MatrixLog6", k) => k.is_vector(),
        _ => false,
    };
    // (asked before the operand is read as a matrix: that is a copy)
    if !applies {
        return None;
    }
    // (the rotation block read from one slice, column by column: indexing
    // the matrix asks its shape anew at every entry)
    let (xs, n) = square_operand(a)?;
    let r = Mat3::from_fn(|i, j| xs[j * n + i]);
    // (by the exact form where it decides: `Args::so3_log`)
    let half_turn = match a.half_turn(0) {
        Some(d) => d.half_turn,
        None => SO3::assume(r).is_half_turn(),
    };
    if !half_turn {
        return None;
    }
    let eq = if 1.0 + r[(2, 2)] >= 1e-6 {
        "(3.58)"
    } else if 1.0 + r[(1, 1)] >= 1e-6 {
        "(3.59)"
    } else {
        "(3.60)"
    };
    Some(Diagnostic::note(
        ErrorKind::Domain,
        a.call_span,
        format!("θ = π: ω̂ is the book's, from {eq} (§3.2.3.3); −ω̂ is an equally valid answer"),
    ))
}

/// An untyped 3×3 within 1e-2 of both SO(3) and SE(2) and in neither
/// (LANGUAGE.md §5): which reading `log` took, the nearer, and how to
/// choose the other.
pub fn read_as(span: crate::span::Span, group: Group, d3: f64, d2: f64) -> Diagnostic {
    let other = match group {
        Group::SE2 => "SO3(M) reads it as a rotation",
        _ => "SE2(M) reads it as a planar transform",
    };
    Diagnostic::note(
        ErrorKind::Domain,
        span,
        format!(
            "this 3×3 is {d3:.2e} from SO(3) and {d2:.2e} from SE(2): read as {}, the nearer",
            group.name()
        ),
    )
    .with_help(format!("{other}; a name R_ab or T_ab also chooses"))
}

/// `ProjectToSO3`/`ProjectToSE3` of a matrix whose rotation block has many
/// nearest rotations ([`crate::lie::project::so3_tie`]): the answer is one.
pub fn projection_tie(
    span: crate::span::Span,
    g: Group,
    tie: crate::lie::project::Tie,
) -> Diagnostic {
    use crate::lie::project::Tie;
    let fmt = |x: f64| crate::values::number::fmt_num(x, 4);
    let block = match g {
        Group::SE3 => "the rotation block",
        _ => "the matrix",
    };
    let why = match tie {
        Tie::Zero => format!("{block} is 0, and every rotation is as near"),
        Tie::RankOne { sigma } => format!(
            "{block} has rank 1 (singular values {}, 0, 0): every rotation taking its row space's direction to its column space's is as near",
            fmt(sigma)
        ),
        Tie::Reflection { sigma } => format!(
            "det < 0 and the two smallest singular values of {block} are equal (σ₂ = σ₃ = {}): the reflection is undone along any direction of their plane, each as near",
            fmt(sigma)
        ),
    };
    Diagnostic::warning(
        ErrorKind::Domain,
        span,
        format!("the nearest rotation is not unique: {why}; this is one of them"),
    )
    .with_help("ProjectToSO3 (§3.6) is meaningful for matrices near SO(3); another equally near answer is as right")
}
