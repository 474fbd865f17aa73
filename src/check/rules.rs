//! The frame and type rules of LANGUAGE.md §6, in one place: for each
//! operation, the resulting kind and frames, or the error with its text.
//! The frames of products and powers come from the frame algebra of
//! [`super::algebra`] (its tables are the detail of the first rows here).
//!
//! | expression              | result                    | else                          |
//! |-------------------------|---------------------------|-------------------------------|
//! | `X_ab * X_bc`           | `X_ac`                    | frame error, both frames      |
//! | `X_ab * v_b`            | `v_a`                     | frame error                   |
//! | `T_ab [V_b] inv(T_ab)`  | `[V_a]` in {a} (3.77)     |                               |
//! | `inv(X_ab)`, `R_ab.T`   | `X_ba`                    |                               |
//! | `T_ab.T`                | no frames (transposed)    | as a factor: frame error      |
//! | `Ad(T_ab) * V_b`        | `V_a`                     | a wrench: cite Prop. 3.17     |
//! | `Ad(T_ab).T * F_a`      | `F_b` (Prop. 3.17)        | a twist: frame error          |
//! | `exp([S_a] θ) * T_ab`   | {a}←{b'} (moved)          | `T_cb`: frame error           |
//! | `T_ba * exp([S_a] θ)`   | {b}←{a'}                  |                               |
//! | `X_ab' * X_bc`          | `X_ac'` ({c} moves with {b}) |                            |
//! | `X^n`                   | `X * … * X`               | `X_ab`, a ≠ b: frame error    |
//! | `u_a + v_a`, `cross`    | same frame                | frame error                   |
//! | untagged operand        | matches anything          |                               |
//!
//! Products (`*`) live in `super::product` and are re-exported here as
//! [`mul`]. The functions know only [`Ty`]s; the interpreter attaches spans and
//! source text to the [`RuleError`]s they return.

use super::algebra::{self, Clash};
use super::error::same_frame_error;
pub use super::error::{Operands, Refusal, RuleError, describe};
use super::product::dims_agree;
pub use super::product::mul;
use super::ty::{Frame, Frames, Kind, Ty};

/// What multiplying by a scalar does to a kind ([`Kind::scaled`]).
pub fn scaled_kind(kind: &Kind) -> Kind {
    kind.scaled()
}

/// Frames shared by a sum, `cross` or `dot`: same frame, or one untagged.
pub fn same_frames(what: &str, l: &Ty, r: &Ty) -> Result<Frames, RuleError> {
    match (&l.frames, &r.frames) {
        (Frames::None, f) | (f, Frames::None) => Ok(*f),
        (a, b) if a == b => Ok(*a),
        _ => Err(same_frame_error(what, l, r)),
    }
}

/// `l + r`, `l - r`: same shape, same frames.
pub fn add(l: &Ty, r: &Ty) -> Result<Ty, RuleError> {
    let kind = add_kind(&l.kind, &r.kind)?;
    let frames = same_frames("add", l, r)?;
    let mut out = Ty::new(kind, frames);
    // ω_1 + ω_2 is an angular velocity; p + v is a point again.
    out.free = l.free && r.free;
    Ok(out)
}

/// The kind of `l + r`: the group kinds are not closed under addition
/// (Rotz(0) + Rotz(1) is a plain 3×3 matrix, and a sum of adjoints is the
/// adjoint of no transform), the algebras, twists, wrenches and vectors are.
pub fn add_kind(l: &Kind, r: &Kind) -> Result<Kind, RuleError> {
    use Kind::*;
    if matches!(l, Tuple(_)) || matches!(r, Tuple(_)) {
        return Err(super::product::tuple_operand("add", l, r));
    }
    if let (Adjoint { .. }, Adjoint { .. }) = (l, r) {
        return Ok(Matrix(Some(6), Some(6)));
    }
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
                        Ok(*l)
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
        Kind::Mechanism
        | Kind::Tuple(_)
        | Kind::Bool
        | Kind::Function
        | Kind::List(..)
        | Kind::Picture
        | Kind::Text => Err(RuleError::typ(format!("cannot negate {}", t.kind.a()))),
        _ => Ok(t.scaled()),
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
    neg(l)
}

/// `inv(X_ab)` = X_ba.
pub fn inverse(t: &Ty) -> Result<Ty, RuleError> {
    let kind = match &t.kind {
        Kind::Scalar => return Ok(*t),
        k if k.is_group() || matches!(k, Kind::Adjoint { .. }) => *k,
        Kind::Matrix(r, c) if dims_agree(*r, *c) => Kind::Matrix(*r, *c),
        Kind::Unknown => Kind::Unknown,
        k => {
            return Err(RuleError::typ(format!("cannot invert {}", k.a()))
                .with_help("only square matrices have inverses"));
        }
    };
    // The inverse of an untagged product of displacements is as many.
    let mut out = Ty::new(kind, t.frames.swapped());
    out.moves = t.moves;
    Ok(out)
}

/// `x.T` — the transpose of a rotation is its inverse (Prop. 3.1), so
/// `R_ab.T` is R_ba; `[Ad_T]ᵀ` acts on wrenches (Prop. 3.17) and maps them
/// the other way; a vector's transpose is a row in the same frame, a
/// one-frame matrix's transpose stays in its frame. The transpose of any
/// other map {a}←{b} (a transform, a product) maps no frame to another: it
/// is tagged [`Frames::Transposed`], and a product with it is refused.
pub fn transpose(t: &Ty) -> Result<Ty, RuleError> {
    let kind = match &t.kind {
        // [ω]ᵀ = −[ω] is skew-symmetric too: still so(3) (§3.2.3.1).
        Kind::SO3 | Kind::SO2 | Kind::So3 | Kind::So2 => t.kind,
        Kind::Adjoint { transposed } => Kind::Adjoint {
            transposed: !transposed,
        },
        k if k.is_vector() => Kind::Matrix(Some(1), k.vec_len()),
        Kind::Scalar => Kind::Scalar,
        Kind::Unknown => Kind::Unknown,
        k => match k.shape() {
            // (a row's transpose is a column: a vector, as the numbers
            // are classified; `v.T.T` is v again)
            Some((r, c)) => {
                if r == Some(1) && c != Some(1) {
                    Kind::Vector(c)
                } else {
                    Kind::Matrix(c, r)
                }
            }
            None => return Err(RuleError::typ(format!("cannot transpose {}", k.a()))),
        },
    };
    let inverse_is_transpose = matches!(
        t.kind,
        Kind::SO3 | Kind::SO2 | Kind::Adjoint { .. } | Kind::Unknown
    );
    let frames = match &t.frames {
        _ if t.kind.is_vector() => t.frames,
        Frames::Pair(a, b)
            if !inverse_is_transpose && !matches!(kind, Kind::Matrix(Some(1), _)) =>
        {
            Frames::Transposed(*a, *b)
        }
        Frames::Disp(a) if !inverse_is_transpose => Frames::Transposed(*a, a.moved()),
        Frames::Transposed(a, b) => Frames::Pair(*a, *b),
        f => f.swapped(),
    };
    let mut out = Ty::new(kind, frames);
    out.moves = t.moves;
    Ok(out)
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
        return Ok(Ty::new(Kind::Scalar, base.frames));
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
        Some(1.0) => Ok(*base),
        _ => {
            let n = literal
                .filter(|x| x.fract() == 0.0 && x.abs() < 1e15)
                .map(|x| x as i64);
            let frames = match algebra::power(&base.frames, n, &base.kind) {
                Ok(f) => f,
                Err(Clash::Inner(..)) => {
                    let mut e = RuleError::frame("frames do not cancel in a power");
                    e.lhs = describe(&base.frames);
                    if let Frames::Pair(a, b) = &base.frames {
                        e.help = Some(format!(
                            "X_{a}{b} * X_{a}{b} needs {{{b}}} = {{{a}}}; powers are for displacements (X_{a}{a}) or untagged matrices"
                        ));
                    }
                    // (an exponent with no number yet — a name, in `check` —
                    // may be the −1, 0 or 1 for which they do cancel)
                    if literal.is_none() {
                        e.message = "frames do not cancel in a power unless its exponent is −1, 0 or 1, and this exponent's number is not known here".into();
                        if let Frames::Pair(a, b) = &base.frames {
                            e.help = Some(format!(
                                "X_{a}{b}^n is a map between frames only for n = −1 (inv(X_{a}{b}), {{{a}}} in {{{b}}}), 0 (I) or 1; write inv(X_{a}{b}) for the inverse"
                            ));
                        }
                    }
                    return Err(e);
                }
                Err(Clash::Transposed { .. }) => {
                    return Err(RuleError::frame(
                        "the transpose of a transform is not a transform: the transpose is the inverse only for rotations",
                    )
                    .with_help("write inv(T) for the inverse of a transform (Prop. 3.10)"));
                }
            };
            // Powers of group elements stay in the group; a power of an
            // so(3)/se(3) matrix is not in the algebra in general ([ω]² is
            // symmetric), so it is a plain matrix.
            let kind = if base.kind.is_group() || matches!(base.kind, Kind::Adjoint { .. }) {
                base.kind
            } else if base.kind.is_algebra() {
                plain_matrix(&base.kind)
            } else {
                scaled_kind(&base.kind)
            };
            let moves = algebra::untagged_power(base, n, &kind);
            let mut out = Ty::new(kind, frames);
            out.moves = moves.map(super::ty::Moves::new);
            Ok(out)
        }
    }
}

/// `X^0`: the identity in X's group, else a plain matrix (`[1, 2; 3, 4]^0`
/// is the 2×2 identity, not labelled SO(2)).
fn identity_kind(k: &Kind) -> Kind {
    if k.is_group() { *k } else { plain_matrix(k) }
}

/// The plain matrix of the shape of `k`.
fn plain_matrix(k: &Kind) -> Kind {
    match k.shape() {
        Some((r, c)) => Kind::Matrix(r, c),
        None => k.scaled(),
    }
}

/// `x.member` (LANGUAGE.md §4): `.T .R .p .w .v .m .f`.
pub fn member(t: &Ty, name: &str) -> Result<Ty, RuleError> {
    use Kind::*;
    let outer = || match t.frames.outer() {
        Some(a) => Frames::One(*a),
        None => Frames::None,
    };
    let v3 = Vector(Some(3));
    let is6 = |k: &Kind| matches!(k, Twist | Screw | Wrench | Unknown) || k.vec_len() == Some(6);
    match (name, &t.kind) {
        ("T", _) => transpose(t),
        ("R", SE3) => Ok(Ty::new(SO3, t.frames)),
        // (of a 4×4 not known to be a transform, a 3×3 block: a symbolic
        // `[2 R, p; 0, 1].R` is no rotation; numbers say theirs, SO(3)
        // when they are one)
        ("R", Matrix(Some(4), Some(4))) => Ok(Ty::new(Matrix(Some(3), Some(3)), t.frames)),
        ("R", Matrix(None, _) | Matrix(_, None)) => Ok(Ty::new(Unknown, t.frames)),
        ("p", Matrix(Some(4), Some(4))) => Ok(Ty::new(v3, outer())),
        ("p", Matrix(None, _) | Matrix(_, None)) => Ok(Ty::new(Unknown, outer())),
        ("R", SE2) => Ok(Ty::new(SO2, t.frames)),
        ("R", Unknown) => Ok(Ty::new(Unknown, t.frames)),
        ("p", SE3) => Ok(Ty::new(v3, outer())),
        ("p", SE2) => Ok(Ty::new(Vector(Some(2)), outer())),
        ("p", Unknown) => Ok(Ty::new(Unknown, outer())),
        // The parts of a twist and a wrench are free vectors (§4).
        ("w" | "v", Se3) => Ok(free(v3, t.frames)),
        ("w" | "v", k) if is6(k) && *k != Wrench => Ok(free(v3, t.frames)),
        ("m" | "f", k) if is6(k) && !matches!(k, Twist | Screw) => Ok(free(v3, t.frames)),
        _ => {
            let known = match &t.kind {
                SE3 | SE2 => ".R .p .T",
                Twist | Screw => ".w .v .T",
                Wrench => ".m .f .T",
                k if k.is_vector() && k.vec_len() == Some(6) => ".w .v (twist), .m .f (wrench), .T",
                k if k.shape().is_some() => ".T",
                _ => "none",
            };
            // (the member a student tries first, and what does it)
            let instead = match name {
                "inv" | "inverse" | "I" | "Inv" => "; the inverse is inv(x)",
                "x" | "y" | "z" if t.kind.is_vector() => "; an entry is v[1], v[2], v[3] (1-based)",
                "det" | "trace" | "norm" => "; call it as a function: det(x), trace(x), norm(x)",
                "transpose" | "t" => "; the transpose is x.T or x^T",
                _ => "",
            };
            Err(
                RuleError::typ(format!("{} has no member .{name}", t.kind.a()))
                    .with_help(format!("members of {}: {known}{instead}", t.kind.a())),
            )
        }
    }
}

/// A free vector of `kind` in `frames` ([`Ty::free`]).
fn free(kind: Kind, frames: Frames) -> Ty {
    let mut t = Ty::new(kind, frames);
    t.free = true;
    t
}

/// The tag a result of a builtin `name` may carry for its kind (§6): a
/// scalar none, a vector or so(3)/se(3) matrix one frame ([`settled`]); a
/// vector of a map between two frames (`se3ToVec(T_ab * [V_b])`) is a frame
/// error.
#[inline]
pub fn settle(t: Ty, name: &str) -> Result<Ty, RuleError> {
    let mut settled = t;
    settle_in_place(&mut settled);
    // Frames still a pair after settling are the type's own (settling only
    // ever makes them one frame or none), and so is its kind.
    if let (true, Frames::Pair(a, b)) = (one_frame_kind(&settled.kind), &settled.frames) {
        return Err(unsettled(&settled.kind, &settled.frames, *a, *b, name));
    }
    Ok(settled)
}

/// [`settle`]'s refusal: a one-frame `kind` of a map from {b} to {a}.
#[cold]
#[inline(never)]
fn unsettled(kind: &Kind, frames: &Frames, a: Frame, b: Frame, name: &str) -> RuleError {
    let mut e = RuleError::frame(format!(
        "{name} gives {}, a quantity in one frame, but its argument maps {{{b}}} to {{{a}}}",
        kind.a()
    ));
    e.lhs = describe(frames);
    e.help = Some(format!(
        "a twist [V_{a}] in {{{a}}} is T [V_{b}] T⁻¹ (3.77), not T [V_{b}]; a transform's own coordinates are log(T_{a}{b}) (in {{{a}}})"
    ));
    e
}

fn one_frame_kind(k: &Kind) -> bool {
    k.is_vector() || k.is_algebra()
}

/// A value's tag made consistent with its kind, as it is printed or bound:
/// a scalar has no frames; a vector or so(3)/se(3) matrix tagged with a
/// frame and a moved copy of it (`exp([S_a] θ) [V_a] exp(−[S_a] θ)`, whose
/// two displacements chasles cannot tell apart) is a quantity in that frame.
pub fn settled(t: &Ty) -> Ty {
    let mut t = *t;
    settle_in_place(&mut t);
    t
}

/// [`settled`], in place (no copy of the type).
pub fn settle_in_place(t: &mut Ty) {
    // g·X·g⁻¹ whose frames close on one frame is back in the Lie algebra
    // (3.77, Prop. 3.5): known from the symbols (with numbers, they decide).
    if let (Some(alg), Frames::One(_), Kind::Matrix(..)) = (t.algebra, &t.frames, &t.kind) {
        t.kind = alg.kind();
        t.algebra = None;
        return;
    }
    if matches!(t.kind, Kind::Scalar | Kind::Bool) {
        t.frames = Frames::None;
        return;
    }
    if !one_frame_kind(&t.kind) {
        return;
    }
    if let Some(a) = t.frames.displacement_frame() {
        t.frames = Frames::One(*a);
    } else if let Frames::Pair(a, b) = t.frames
        && a == b
    {
        t.frames = Frames::One(a);
    }
}

/// `cross(u, v)`, `dot(u, v)`: frames must agree.
pub fn vector_pair(what: &str, l: &Ty, r: &Ty) -> Result<Frames, RuleError> {
    same_frames(what, l, r)
}
