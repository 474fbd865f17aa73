//! The frame and type rules of LANGUAGE.md §6, in one place: for each
//! operation, the resulting kind and frames, or the error with its text.
//!
//! | expression            | result                  | else                       |
//! |-----------------------|-------------------------|----------------------------|
//! | `X_ab * X_bc`         | `X_ac`                  | frame error, both frames   |
//! | `X_ab * v_b`          | `v_a`                   | frame error                |
//! | `inv(X_ab)`, `X_ab.T` | `X_ba`                  |                            |
//! | `Ad(T_ab) * V_b`      | `V_a`                   | a wrench: cite Prop. 3.17  |
//! | `Ad(T_ab).T * F_a`    | `F_b` (Prop. 3.17)      |                            |
//! | `exp([S_a] θ) * T_ab` | {a}←{b'} (moved)        | `T_cb`: frame error        |
//! | `T_ba * exp([S_a] θ)` | {b}←{a'}                |                            |
//! | `u_a + v_a`, `cross`  | same frame              | frame error                |
//! | untagged operand      | matches anything        |                            |
//!
//! The functions here know only [`Ty`]s; the interpreter attaches spans and
//! source text to the [`RuleError`]s they return.

use super::ty::{Frame, Frames, Kind, Ty};
use crate::diagnostics::ErrorKind;

/// Why an operation is refused, with the text for each part of the
/// diagnostic. `lhs`/`rhs` label the operands, `op` the operator.
#[derive(Debug, Clone, Default)]
pub struct RuleError {
    pub kind: Option<ErrorKind>,
    pub message: String,
    pub lhs: String,
    pub rhs: String,
    pub op: String,
    pub help: Option<String>,
}

impl RuleError {
    fn typ(message: impl Into<String>) -> RuleError {
        RuleError {
            kind: Some(ErrorKind::Type),
            message: message.into(),
            ..Default::default()
        }
    }
    fn frame(message: impl Into<String>) -> RuleError {
        RuleError {
            kind: Some(ErrorKind::Frame),
            message: message.into(),
            ..Default::default()
        }
    }
    fn with_help(mut self, help: impl Into<String>) -> RuleError {
        self.help = Some(help.into());
        self
    }
}

/// The source text of the operands, for help lines (`did you mean inv(T_cb)?`).
#[derive(Debug, Clone, Copy, Default)]
pub struct Operands<'a> {
    pub lhs: &'a str,
    pub rhs: &'a str,
}

/// How a frame tag reads in a label: `{b} in {a}`, `in {a}`.
pub fn describe(frames: &Frames) -> String {
    match frames {
        Frames::None => "untagged".to_string(),
        Frames::One(a) => format!("in {{{a}}}"),
        Frames::Pair(a, b) => format!("{{{b}}} in {{{a}}}"),
        Frames::Disp(a) => format!("displacement in {{{a}}}"),
    }
}

/// What multiplying by a scalar does to a kind: group elements stop being
/// group elements, a screw axis times θ is a twist (exponential coordinates).
pub fn scaled_kind(kind: &Kind) -> Kind {
    match kind {
        Kind::SO3 | Kind::SE2 => Kind::Matrix(Some(3), Some(3)),
        Kind::SE3 => Kind::Matrix(Some(4), Some(4)),
        Kind::SO2 => Kind::Matrix(Some(2), Some(2)),
        Kind::Screw => Kind::Twist,
        other => other.clone(),
    }
}

fn dims_agree(a: Option<usize>, b: Option<usize>) -> bool {
    match (a, b) {
        (Some(x), Some(y)) => x == y,
        _ => true,
    }
}

/// `l * r` (and juxtaposition): kind and frames.
pub fn mul(l: &Ty, r: &Ty, ops: Operands) -> Result<Ty, RuleError> {
    // Scalars scale anything and leave frames alone.
    if l.kind == Kind::Scalar {
        return Ok(Ty::new(scaled_kind(&r.kind), r.frames.clone()));
    }
    if r.kind == Kind::Scalar {
        return Ok(Ty::new(scaled_kind(&l.kind), l.frames.clone()));
    }
    let kind = mul_kind(&l.kind, &r.kind, ops)?;
    let frames = if kind.is_vector() || matches!(kind, Kind::Vector(_)) {
        apply_frames(l, r, ops)?
    } else {
        compose_frames(l, r, ops)?
    };
    Ok(Ty::new(kind, frames))
}

fn shape_error(l: &Kind, r: &Kind) -> RuleError {
    RuleError::typ(format!("cannot multiply {} by {}", l.a(), r.a()))
}

/// The kind of a product of two non-scalars.
fn mul_kind(l: &Kind, r: &Kind, ops: Operands) -> Result<Kind, RuleError> {
    use Kind::*;
    if r.is_vector() {
        let n = r.vec_len();
        return match l {
            Adjoint { transposed: false } => match r {
                Wrench => Err(wrench_through_ad(ops)),
                Screw => Ok(Screw),
                _ if dims_agree(n, Some(6)) => Ok(Twist),
                _ => Err(shape_error(l, r)),
            },
            Adjoint { transposed: true } => match r {
                Twist | Screw => Err(RuleError::typ("[Ad_T]ᵀ acts on wrenches, not on twists")
                    .with_help(format!(
                        "twists change frame with the adjoint itself: write {} without .T",
                        ops.lhs.trim_end_matches(".T")
                    ))),
                _ if dims_agree(n, Some(6)) => Ok(Wrench),
                _ => Err(shape_error(l, r)),
            },
            // T p with a 3-vector p: the point transformed (homogeneous, (3.59)).
            SE3 | Se3 | Matrix(Some(4), Some(4)) if n == Some(3) => Ok(Vector(Some(3))),
            SE3 | Se3 if dims_agree(n, Some(4)) => Ok(Vector(Some(4))),
            Matrix(None, _) | Matrix(_, None) => Ok(Vector(None)),
            SE2 | Se2 if n == Some(2) => Ok(Vector(Some(2))),
            _ => {
                let (rows, cols) = l.shape().ok_or_else(|| shape_error(l, r))?;
                if !dims_agree(cols, n) {
                    return Err(shape_error(l, r).with_help(format!(
                        "a {}-column matrix needs a {}-vector",
                        cols.unwrap_or(0),
                        cols.unwrap_or(0)
                    )));
                }
                Ok(match (l, rows) {
                    (Unknown, _) => Unknown,
                    (_, rows) => Vector(rows),
                })
            }
        };
    }
    if l.is_vector() {
        // A column vector times a matrix: only a 1-row matrix makes sense.
        return match r.shape() {
            Some((Some(1), c)) => Ok(Matrix(l.vec_len(), c)),
            _ if *r == Unknown => Ok(Unknown),
            _ => Err(shape_error(l, r)
                .with_help("for vectors use dot(u, v) or cross(u, v); a row is v.T")),
        };
    }
    let same_group = match (l, r) {
        (SO3, SO3) => Some(SO3),
        (SE3, SE3) => Some(SE3),
        (SO2, SO2) => Some(SO2),
        (SE2, SE2) => Some(SE2),
        (Adjoint { transposed: a }, Adjoint { transposed: b }) if a == b => Some(l.clone()),
        _ => None,
    };
    if let Some(k) = same_group {
        return Ok(k);
    }
    match (l.shape(), r.shape()) {
        (Some((lr, lc)), Some((rr, rc))) => {
            if !dims_agree(lc, rr) {
                return Err(shape_error(l, r).with_help(format!(
                    "inner dimensions differ: {}×{} times {}×{}",
                    dim(lr),
                    dim(lc),
                    dim(rr),
                    dim(rc)
                )));
            }
            if *l == Unknown || *r == Unknown {
                Ok(Unknown)
            } else if lr == Some(1) && rc == Some(1) {
                Ok(Scalar)
            } else if rc == Some(1) {
                Ok(Vector(lr))
            } else {
                Ok(Matrix(lr, rc))
            }
        }
        _ => Err(shape_error(l, r)),
    }
}

fn dim(d: Option<usize>) -> String {
    d.map_or("n".into(), |n| n.to_string())
}

fn wrench_through_ad(ops: Operands) -> RuleError {
    let t = ops
        .lhs
        .strip_prefix("Ad(")
        .or_else(|| ops.lhs.strip_prefix("Adjoint("))
        .and_then(|s| s.strip_suffix(')'))
        .unwrap_or("T");
    RuleError::frame("a wrench does not change frame through [Ad_T]")
        .with_help(format!(
            "Prop. 3.17: wrenches change frame with the transpose, F_b = [Ad_T_ab]ᵀ F_a; write Ad({t}).T * F"
        ))
}

fn inner_mismatch(l: &Ty, r: &Ty, a_in: &Frame, b_out: &Frame, ops: Operands) -> RuleError {
    let mut e = RuleError::frame("frames do not cancel");
    e.lhs = describe(&l.frames);
    e.rhs = describe(&r.frames);
    e.op = format!("inner frames must agree: {a_in} ≠ {b_out}");
    e.help = Some(product_help(l, r, ops));
    e
}

/// The fix for a product whose inner frames differ.
fn product_help(l: &Ty, r: &Ty, ops: Operands) -> String {
    let rule = "X_xy maps coordinates in {y} to {x}";
    match (&l.frames, &r.frames) {
        (Frames::Pair(a, b), Frames::Pair(c, d)) => {
            if b == d && a != c {
                format!(
                    "{rule}; did you mean inv({}) = X_{}{}?",
                    ops.rhs.trim(),
                    d,
                    c
                )
            } else if c == a && b != d {
                // T_sc * inv(T_sb): both from {s}.
                let hint = displacement_hint(ops);
                format!(
                    "{rule}; both start in {{{a}}}: the body-frame form is inv({}) * {} = X_{}{}{}",
                    ops.lhs.trim(),
                    ops.rhs.trim(),
                    b,
                    d,
                    hint
                )
            } else if d == a {
                format!(
                    "{rule}; the other order cancels: {} * {} = X_{}{}{}",
                    ops.rhs.trim(),
                    ops.lhs.trim(),
                    c,
                    b,
                    displacement_hint(ops)
                )
            } else {
                format!("{rule}; find a transform from {{{b}}} to {{{c}}} (try derive)")
            }
        }
        (Frames::Pair(_, b), Frames::One(c)) => format!(
            "{} takes coordinates in {{{b}}}, but the vector is in {{{c}}}; express it in {{{b}}} first",
            ops.lhs.trim()
        ),
        (Frames::Disp(a), Frames::Pair(c, _)) => format!(
            "a displacement in {{{a}}} premultiplies a transform from {{{a}}} (X_{a}?); {} starts in {{{c}}}",
            ops.rhs.trim()
        ),
        (Frames::Pair(_, b), Frames::Disp(d)) => format!(
            "a displacement in {{{d}}} postmultiplies a transform into {{{d}}} (X_?{d}); {} ends in {{{b}}}",
            ops.lhs.trim()
        ),
        _ => rule.to_string(),
    }
}

/// For `T_sc * inv(T_sb)`: name the space-frame displacement.
fn displacement_hint(ops: Operands) -> String {
    let r = ops.rhs.trim();
    if let Some(inner) = r.strip_prefix("inv(").and_then(|s| s.strip_suffix(')')) {
        format!(
            "; the displacement in the fixed frame taking {inner} to {} is displacement({inner}, {}) = {} * inv({inner})",
            ops.lhs.trim(),
            ops.lhs.trim(),
            ops.lhs.trim()
        )
    } else {
        String::new()
    }
}

/// Frames of `operator * operator`.
fn compose_frames(l: &Ty, r: &Ty, ops: Operands) -> Result<Frames, RuleError> {
    use Frames::*;
    Ok(match (&l.frames, &r.frames) {
        (None, None) => None,
        (Pair(a, b), Pair(c, d)) => {
            if b != c {
                return Err(inner_mismatch(l, r, b, c, ops));
            }
            Pair(a.clone(), d.clone())
        }
        // An untagged operator is a displacement: R * R_sb = {s}←{b'}.
        (None, Pair(a, b)) | (Pair(a, b), None) => Pair(a.clone(), b.moved()),
        (None, One(a)) | (One(a), None) => One(a.clone()),
        (None, Disp(a)) | (Disp(a), None) => Disp(a.clone()),
        (Disp(a), Pair(c, d)) => {
            if a != c {
                return Err(inner_mismatch(l, r, a, c, ops));
            }
            Pair(c.clone(), d.moved())
        }
        (Pair(a, b), Disp(d)) => {
            if b != d {
                return Err(inner_mismatch(l, r, b, d, ops));
            }
            Pair(a.clone(), b.moved())
        }
        (Disp(a), Disp(b)) | (One(a), One(b)) | (Disp(a), One(b)) | (One(a), Disp(b)) => {
            if a != b {
                return Err(same_frame_error("multiply", l, r));
            }
            l.frames.clone()
        }
        // [V_s] T_sb = Ṫ_sb ; T_sb [V_b] = Ṫ_sb.
        (One(a), Pair(c, _)) => {
            if a != c {
                return Err(inner_mismatch(l, r, a, c, ops));
            }
            r.frames.clone()
        }
        (Pair(_, b), One(c)) => {
            if b != c {
                return Err(inner_mismatch(l, r, b, c, ops));
            }
            l.frames.clone()
        }
    })
}

/// Frames of `operator * vector`.
fn apply_frames(l: &Ty, r: &Ty, ops: Operands) -> Result<Frames, RuleError> {
    use Frames::*;
    Ok(match (&l.frames, &r.frames) {
        (_, _) if l.kind.is_vector() => None,
        (None, f) => f.clone(),
        (Pair(a, _), None) => One(a.clone()),
        (Pair(a, b), One(c)) => {
            if b != c {
                return Err(inner_mismatch(l, r, b, c, ops));
            }
            One(a.clone())
        }
        (One(a) | Disp(a), One(c)) => {
            if a != c {
                let mut e = inner_mismatch(l, r, a, c, ops);
                e.help = Some(format!(
                    "{} is in {{{a}}}; the vector must be expressed in {{{a}}} too",
                    ops.lhs.trim()
                ));
                return Err(e);
            }
            One(a.clone())
        }
        (One(a) | Disp(a), None) => One(a.clone()),
        (_, Pair(..) | Disp(_)) => r.frames.clone(),
    })
}

fn same_frame_error(what: &str, l: &Ty, r: &Ty) -> RuleError {
    let mut e = RuleError::frame(format!("cannot {what} quantities in different frames"));
    e.lhs = describe(&l.frames);
    e.rhs = describe(&r.frames);
    e.help = Some(
        "express both in one frame first (an adjoint for twists, a rotation for vectors)".into(),
    );
    e
}

/// Frames shared by a sum, `cross` or `dot`: same frame, or one untagged.
pub fn same_frames(what: &str, l: &Ty, r: &Ty) -> Result<Frames, RuleError> {
    match (&l.frames, &r.frames) {
        (Frames::None, f) | (f, Frames::None) => Ok(f.clone()),
        (a, b) if a == b => Ok(a.clone()),
        _ => Err(same_frame_error(what, l, r)),
    }
}

/// `l + r`, `l - r`: same shape, same frames.
pub fn add(l: &Ty, r: &Ty) -> Result<Ty, RuleError> {
    let kind = add_kind(&l.kind, &r.kind)?;
    let frames = same_frames("add", l, r)?;
    Ok(Ty::new(kind, frames))
}

fn add_kind(l: &Kind, r: &Kind) -> Result<Kind, RuleError> {
    use Kind::*;
    if l == r {
        return Ok(scaled_kind(l));
    }
    match (l, r) {
        (Unknown, k) | (k, Unknown) => Ok(scaled_kind(k)),
        (Twist | Screw, Twist | Screw | Vector(_)) | (Vector(_), Twist | Screw) => {
            if r.vec_len().is_some_and(|n| n != 6) || l.vec_len().is_some_and(|n| n != 6) {
                Err(RuleError::typ(format!(
                    "cannot add {} and {}",
                    l.a(),
                    r.a()
                )))
            } else {
                Ok(Twist)
            }
        }
        (Wrench, Vector(n)) | (Vector(n), Wrench) if dims_agree(*n, Some(6)) => Ok(Wrench),
        _ => {
            let (a, b) = (l.shape(), r.shape());
            match (a, b) {
                (Some((lr, lc)), Some((rr, rc))) if dims_agree(lr, rr) && dims_agree(lc, rc) => {
                    if l.is_vector() || r.is_vector() {
                        Ok(Vector(lr.or(rr)))
                    } else if l.is_algebra() && l == r {
                        Ok(l.clone())
                    } else {
                        Ok(Matrix(lr.or(rr), lc.or(rc)))
                    }
                }
                _ => Err(
                    RuleError::typ(format!("cannot add {} and {}", l.a(), r.a()))
                        .with_help("sums need operands of the same size"),
                ),
            }
        }
    }
}

/// `-x`.
pub fn neg(t: &Ty) -> Result<Ty, RuleError> {
    match t.kind {
        Kind::Mechanism | Kind::Tuple(_) | Kind::Bool | Kind::Function => {
            Err(RuleError::typ(format!("cannot negate {}", t.kind.a())))
        }
        _ => Ok(Ty::new(scaled_kind(&t.kind), t.frames.clone())),
    }
}

/// `l / r`: only division by a scalar.
pub fn div(l: &Ty, r: &Ty) -> Result<Ty, RuleError> {
    if !r.kind.maybe_scalar() {
        return Err(RuleError::typ(format!("cannot divide by {}", r.kind.a()))
            .with_help("to undo a matrix, multiply by inv(M)"));
    }
    if !r.frames.is_none() {
        return Err(RuleError::frame("cannot divide by a framed quantity"));
    }
    neg(l).map(|_| Ty::new(scaled_kind(&l.kind), l.frames.clone()))
}

/// `inv(X_ab)` = X_ba.
pub fn inverse(t: &Ty) -> Result<Ty, RuleError> {
    match &t.kind {
        Kind::Scalar => Ok(t.clone()),
        k if k.is_group() || matches!(k, Kind::Adjoint { .. }) => {
            Ok(Ty::new(k.clone(), t.frames.swapped()))
        }
        Kind::Matrix(r, c) if dims_agree(*r, *c) => {
            Ok(Ty::new(Kind::Matrix(*r, *c), t.frames.swapped()))
        }
        Kind::Unknown => Ok(Ty::new(Kind::Unknown, t.frames.swapped())),
        k => Err(RuleError::typ(format!("cannot invert {}", k.a()))
            .with_help("only square matrices have inverses")),
    }
}

/// `x.T` — transposes swap frames; [Ad_T]ᵀ acts on wrenches.
pub fn transpose(t: &Ty) -> Result<Ty, RuleError> {
    let kind = match &t.kind {
        Kind::SO3 | Kind::SO2 => t.kind.clone(),
        Kind::Adjoint { transposed } => Kind::Adjoint {
            transposed: !transposed,
        },
        k if k.is_vector() => Kind::Matrix(Some(1), k.vec_len()),
        Kind::Scalar => Kind::Scalar,
        Kind::Unknown => Kind::Unknown,
        k => match k.shape() {
            Some((r, c)) => {
                if c == Some(1) && r != Some(1) {
                    Kind::Vector(r)
                } else {
                    Kind::Matrix(c, r)
                }
            }
            None => return Err(RuleError::typ(format!("cannot transpose {}", k.a()))),
        },
    };
    let frames = if t.kind.is_vector() {
        t.frames.clone()
    } else {
        t.frames.swapped()
    };
    Ok(Ty::new(kind, frames))
}

/// `X ^ n` with a literal integer exponent when known.
pub fn pow(base: &Ty, exp: &Ty, literal: Option<f64>) -> Result<Ty, RuleError> {
    if !exp.kind.maybe_scalar() {
        return Err(RuleError::typ(format!(
            "the exponent must be a number, not {}",
            exp.kind.a()
        )));
    }
    if base.kind.maybe_scalar() && base.kind == Kind::Scalar {
        return Ok(Ty::new(Kind::Scalar, base.frames.clone()));
    }
    let square = match base.kind.shape() {
        Some((r, c)) => dims_agree(r, c),
        None => false,
    };
    if !square {
        return Err(
            RuleError::typ(format!("cannot raise {} to a power", base.kind.a()))
                .with_help("powers need a square matrix"),
        );
    }
    match literal {
        Some(-1.0) => inverse(base),
        Some(0.0) => Ok(Ty::new(identity_kind(&base.kind), Frames::None)),
        Some(1.0) => Ok(base.clone()),
        _ => {
            let frames = match &base.frames {
                Frames::Pair(a, b) if a != b => {
                    let mut e = RuleError::frame("frames do not cancel in a power");
                    e.lhs = describe(&base.frames);
                    e.help = Some(format!(
                        "X_{a}{b} * X_{a}{b} needs {{{b}}} = {{{a}}}; powers are for displacements (X_{a}{a}) or untagged matrices"
                    ));
                    return Err(e);
                }
                f => f.clone(),
            };
            let kind = if base.kind.is_group() || matches!(base.kind, Kind::Adjoint { .. }) {
                base.kind.clone()
            } else {
                scaled_kind(&base.kind)
            };
            Ok(Ty::new(kind, frames))
        }
    }
}

fn identity_kind(k: &Kind) -> Kind {
    if k.is_group() {
        k.clone()
    } else {
        scaled_kind(k)
    }
}

/// `x.member` (LANGUAGE.md §4): `.T .R .p .w .v .m .f`.
pub fn member(t: &Ty, name: &str) -> Result<Ty, RuleError> {
    use Kind::*;
    let outer = || match t.frames.outer() {
        Some(a) => Frames::One(a.clone()),
        None => Frames::None,
    };
    let v3 = Vector(Some(3));
    let is6 = |k: &Kind| matches!(k, Twist | Screw | Wrench | Unknown) || k.vec_len() == Some(6);
    match (name, &t.kind) {
        ("T", _) => transpose(t),
        ("R", SE3 | Matrix(Some(4), Some(4))) => Ok(Ty::new(SO3, t.frames.clone())),
        ("R", Matrix(None, _) | Matrix(_, None)) => Ok(Ty::new(Unknown, t.frames.clone())),
        ("p", Matrix(Some(4), Some(4))) => Ok(Ty::new(v3.clone(), outer())),
        ("p", Matrix(None, _) | Matrix(_, None)) => Ok(Ty::new(Unknown, outer())),
        ("R", SE2) => Ok(Ty::new(SO2, t.frames.clone())),
        ("R", Unknown) => Ok(Ty::new(Unknown, t.frames.clone())),
        ("p", SE3) => Ok(Ty::new(v3, outer())),
        ("p", SE2) => Ok(Ty::new(Vector(Some(2)), outer())),
        ("p", Unknown) => Ok(Ty::new(Unknown, outer())),
        ("w" | "v", Se3) => Ok(Ty::new(v3, t.frames.clone())),
        ("w" | "v", k) if is6(k) && *k != Wrench => Ok(Ty::new(v3, t.frames.clone())),
        ("m" | "f", k) if is6(k) && !matches!(k, Twist | Screw) => {
            Ok(Ty::new(v3, t.frames.clone()))
        }
        _ => {
            let known = match &t.kind {
                SE3 | SE2 => ".R .p .T",
                Twist | Screw => ".w .v .T",
                Wrench => ".m .f .T",
                k if k.is_vector() && k.vec_len() == Some(6) => ".w .v (twist), .m .f (wrench), .T",
                k if k.shape().is_some() => ".T",
                _ => "none",
            };
            Err(
                RuleError::typ(format!("{} has no member .{name}", t.kind.a()))
                    .with_help(format!("members of {}: {known}", t.kind.a())),
            )
        }
    }
}

/// `cross(u, v)`, `dot(u, v)`: frames must agree.
pub fn vector_pair(what: &str, l: &Ty, r: &Ty) -> Result<Frames, RuleError> {
    same_frames(what, l, r)
}
