//! Products (`*` and juxtaposition): the kind of `l * r`, its frames by the
//! frame algebra of [`super::algebra`] — composition `X_ab * X_bc = X_ac`,
//! application `X_ab * v_b = v_a`, displacements `exp([S_a] θ) * T_ab` — the
//! adjoint and its transpose (Prop. 3.17), and the help text that names the
//! fix when frames do not cancel. Part of the rule table of [`super::rules`].

use super::algebra::{self, Clash};
use super::error::{Form, Operand, Operands, RuleError, describe};
use super::hints;
use super::ty::{Algebra, Frame, Frames, Kind, Ty};
use crate::syntax::ident::{NameFrames, base_name, name_frames, tagged_name};

pub(super) fn dims_agree(a: Option<usize>, b: Option<usize>) -> bool {
    match (a, b) {
        (Some(x), Some(y)) => x == y,
        _ => true,
    }
}

/// `l * r` (and juxtaposition): kind and frames.
pub fn mul(l: &Ty, r: &Ty, ops: Operands) -> Result<Ty, RuleError> {
    // A tuple is no operand: its parts are (`2 * t` ran into "expected
    // numbers" only with numbers, and passed checking).
    if matches!(l.kind, Kind::Tuple(_)) || matches!(r.kind, Kind::Tuple(_)) {
        return Err(tuple_operand("multiply", &l.kind, &r.kind));
    }
    // Scalars scale anything and leave frames alone.
    if matches!(l.kind, Kind::Scalar) {
        return Ok(r.scaled());
    }
    if matches!(r.kind, Kind::Scalar) {
        return Ok(l.scaled());
    }
    if matches!(
        (&l.kind, &r.kind),
        (Kind::Adjoint { transposed: false }, Kind::Wrench)
    ) {
        return Err(wrench_through_ad(l, r, ops));
    }
    if r.kind.is_vector() && moves_points(&l.kind, &r.kind) {
        if r.free {
            return Err(super::free::through_transform(l, r, ops));
        }
        if r.kind.vec_len() == Some(6) {
            return Err(super::free::six_through_transform(l, r, ops));
        }
    }
    // A row times a column, uᵀv: an inner product (the power V_bᵀF_b is a
    // plain scalar, §3.4: the same in every frame).
    let kind = if matches!(l.kind, Kind::Matrix(Some(1), _)) && r.kind.is_vector() {
        mul_kind(&l.kind, &r.kind, ops)?;
        Kind::Scalar
    } else {
        mul_kind(&l.kind, &r.kind, ops)?
    };
    let (frames, moves) = match algebra::product(l, r, &kind) {
        Ok(f) => f,
        Err(Clash::Inner(x, y)) => {
            // A displacement in {a} is the map {a}←{a'}: name its frame {a}.
            let x = match &l.frames {
                Frames::Disp(a) => *a,
                _ => x,
            };
            return Err(inner_mismatch(l, r, &x, &y, ops));
        }
        Err(Clash::Transposed { left }) => return Err(transposed_factor(l, r, left, ops)),
    };
    let mut out = Ty::new(kind, frames);
    out.moves = moves.map(super::ty::Moves::new);
    // A rotation (or any matrix but a transform) of a free vector is one.
    out.free = r.free && kind.is_vector();
    Ok(conjugation(l, r, out))
}

/// The type error of a tuple in a sum or product: a tuple is no
/// operand, its parts are (§4).
pub fn tuple_operand(what: &str, l: &Kind, r: &Kind) -> RuleError {
    RuleError::typ(format!("cannot {what} {} and {}", l.a(), r.a()))
        .with_help("a tuple is not a vector or matrix: take its parts, t[1] or (a, b) = t")
}

/// True when `l * r` would treat the vector `r` as a point: a transform
/// (or a 4×4, 3×3 planar matrix) times a 3-vector (2-vector) is the
/// homogeneous product T p (3.65); with a 6-vector, no product at all.
fn moves_points(l: &Kind, r: &Kind) -> bool {
    matches!(
        (l, r.vec_len()),
        (Kind::SE3, Some(3 | 6)) | (Kind::Matrix(Some(4), Some(4)), Some(3)) | (Kind::SE2, Some(2))
    )
}

/// What a factor contributes to a product of group elements and one
/// element of their Lie algebra.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Content<'a> {
    Group(&'a Kind),
    Algebra(Algebra),
    Other,
}

fn content(t: &Ty) -> Content<'_> {
    match (&t.kind, t.algebra) {
        (k, _) if k.is_group() => Content::Group(k),
        (Kind::Matrix(..), Some(a)) => Content::Algebra(a),
        (k, _) => Algebra::of(k).map_or(Content::Other, Content::Algebra),
    }
}

/// g·X, X·g and g·X·g⁻¹: a plain matrix that remembers the algebra of X
/// (associative: the content of a product is the one algebra element among
/// group elements of its group). Whether it is back in the algebra — the
/// frames closed on one frame, g·X·g⁻¹ (3.77) — is decided when the value
/// is printed or bound ([`super::rules::settled`]); with numbers, the
/// numbers decide (a displacement's frames close on {b'} whatever its
/// angle, so frames alone do not prove g⁻¹ is the inverse of g).
fn conjugation(l: &Ty, r: &Ty, mut out: Ty) -> Ty {
    if !matches!(out.kind, Kind::Matrix(..)) {
        return out;
    }
    let alg = match (content(l), content(r)) {
        (Content::Group(g), Content::Algebra(a)) | (Content::Algebra(a), Content::Group(g))
            if a.group() == *g =>
        {
            a
        }
        _ => return out,
    };
    out.algebra = Some(alg);
    out
}

/// `T_ab.T` used as a factor: the transpose of a transform is not its
/// inverse (that holds for rotations only, Prop. 3.1).
fn transposed_factor(l: &Ty, r: &Ty, left: bool, ops: Operands) -> RuleError {
    let (t, operand) = if left { (l, ops.lhs) } else { (r, ops.rhs) };
    let text = operand.text().trim();
    let base = match operand.form() {
        Form::Transposed(x) => Some(x),
        _ => None,
    };
    let (name, frames) = match &t.frames {
        // The transpose of {outer}←{inner}; its inverse is {inner}←{outer}.
        Frames::Transposed(outer, inner) => (
            result_name_of(base.map_or(text, |x| x.text().trim()), inner, outer),
            format!("{{{outer}}}←{{{inner}}} is not the map {{{inner}}}←{{{outer}}}"),
        ),
        _ => (String::new(), String::new()),
    };
    let mut e = RuleError::frame(format!(
        "{text} is the transpose of a transform, not a transform: the transpose is the inverse only for rotations"
    ));
    e.lhs = describe(&l.frames);
    e.rhs = describe(&r.frames);
    // The fix names the inverse of what was transposed, when the operand
    // is written as a transpose (`T_ab.T`, `T_ab^T`, `transpose(T_ab)`).
    let fix = match base {
        None => "inv(T) for the inverse of a transform T".to_string(),
        Some(x) => format!("{}{name}", x.inverse_text()),
    };
    e.help = Some(format!(
        "R⁻¹ = Rᵀ for a rotation (Prop. 3.1), but T⁻¹ = [Rᵀ, −Rᵀp; 0, 1] (Prop. 3.10): write {fix}; the transpose of {frames}"
    ));
    e
}

/// ` = T_ba` when `base` is a framed name like `T_ab`, else empty.
fn result_name_of(base: &str, outer: &Frame, inner: &Frame) -> String {
    match framed_base(base) {
        Some(letter) if name_frames(base) != NameFrames::None => format!(
            " = {}",
            tagged_name(letter, &[&outer.to_string(), &inner.to_string()])
        ),
        _ => String::new(),
    }
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
            // (A wrench here is refused by `mul`: `wrench_through_ad`.)
            Adjoint { transposed: false } => match r {
                Screw => Ok(Screw),
                _ if dims_agree(n, Some(6)) => Ok(Twist),
                _ => Err(shape_error(l, r)),
            },
            Adjoint { transposed: true } => match r {
                Twist | Screw => Err(RuleError::frame("[Ad_T]ᵀ acts on wrenches, not on twists")
                    .with_help(format!(
                        "twists change frame with the adjoint itself, V_s = [Ad_T_sb] V_b (3.84); write {} without .T",
                        match ops.lhs.form() {
                            Form::Transposed(x) => x.text().trim(),
                            _ => ops.lhs.text().trim(),
                        }
                    ))),
                _ if dims_agree(n, Some(6)) => Ok(Wrench),
                _ => Err(shape_error(l, r)),
            },
            // T p with a 3-vector p: the point transformed (homogeneous, (3.65)).
            SE3 | Se3 | Matrix(Some(4), Some(4)) if n == Some(3) => Ok(Vector(Some(3))),
            SE3 | Se3 if dims_agree(n, Some(4)) => Ok(Vector(Some(4))),
            Matrix(None, _) | Matrix(_, None) => Ok(Vector(None)),
            SE2 | Se2 if n == Some(2) => Ok(Vector(Some(2))),
            // Two column vectors: the student meant a dot or cross product.
            _ if l.is_vector() && !dims_agree(n, Some(1)) => {
                let (u, v) = (ops.lhs.text().trim(), ops.rhs.text().trim());
                Err(shape_error(l, r).with_help(format!(
                    "for two vectors write dot({u}, {v}) or {u}.T * {v} (a number), or cross({u}, {v}); {u} * {v}.T is the outer product"
                )))
            }
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
        (Adjoint { transposed: a }, Adjoint { transposed: b }) if a == b => Some(*l),
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

/// `Ad(T_ab) * F`: wrenches change frame with the transposed adjoint,
/// F_b = [Ad_T_ab]ᵀ F_a (Prop. 3.17). The help writes the product that
/// expresses the given wrench in the adjoint's outer frame, which is what
/// `Ad(T_ab) * F_b` was reaching for, and the one that goes the other way.
fn wrench_through_ad(l: &Ty, r: &Ty, ops: Operands) -> RuleError {
    let t = match ops.lhs.form() {
        Form::Adjoint(x) => x,
        _ => Operand::of_text("T"),
    };
    let f = ops.rhs.text().trim();
    let rule =
        "Prop. 3.17: wrenches change frame with the transposed adjoint, F_b = [Ad_T_ab]ᵀ F_a";
    let help = match (&l.frames, &r.frames) {
        (Frames::Pair(a, b), Frames::One(c)) if b == c => format!(
            "{rule}; {f} in {{{a}}} is Ad({}).T * {f}, and a wrench in {{{a}}} comes to {{{b}}} by Ad({}).T * F_{a}",
            t.inverse_text(),
            t.text().trim()
        ),
        _ => format!(
            "{rule}; write Ad({t}).T * F for F in the outer frame of {t}",
            t = t.text().trim()
        ),
    };
    RuleError::frame("a wrench does not change frame through [Ad_T]").with_help(help)
}

fn inner_mismatch(l: &Ty, r: &Ty, a_in: &Frame, b_out: &Frame, ops: Operands) -> RuleError {
    let mut e = RuleError::frame("frames do not cancel");
    e.lhs = describe(&l.frames);
    e.rhs = describe(&r.frames);
    e.op = format!("inner frames must agree: {a_in} ≠ {b_out}");
    let plain = [(ops.lhs, l), (ops.rhs, r)]
        .into_iter()
        .filter_map(|(op, t)| plain_name_hint(op, t))
        .collect::<String>();
    let help = product_help(l, r, ops) + &plain + &hints::one_frame_operator(ops, l, r);
    e.help = Some(hints::not_as_typed(help, ops.rhs.text().trim()));
    e
}

/// A plain name (no frame subscript) that carries frames from what it was
/// bound to (`R = R_sb`): the hint to drop them when it is meant as an
/// operator (`R_sa * R`, exercise 3.1(e)).
fn plain_name_hint(op: Operand, t: &Ty) -> Option<String> {
    let Form::Name(op) = op.form() else {
        return None;
    };
    (name_frames(op) == NameFrames::None && t.frames != Frames::None).then(|| {
        format!(
            "; {op} keeps the frames {} of the value bound to it: untag({op}) uses it as a plain operator",
            t.frames
        )
    })
}

/// The letter of a framed name written as an operand, `T` of `T_sb` or
/// `inv(T_sb)`; None for any other expression.
fn operand_base(op: Operand<'_>) -> Option<&str> {
    let name = match op.form() {
        Form::Inverse(x) => x.text(),
        _ => op.text(),
    }
    .trim();
    framed_base(name)
}

/// The letter of a framed name, `T` of `T_sb`.
fn framed_base(name: &str) -> Option<&str> {
    (name_frames(name) != NameFrames::None).then(|| base_name(name))
}

/// The name of a product's result in the help: `T_bc` when both operands
/// are `T_…` names, else the generic `X_bc`.
fn result_name(ops: Operands, outer: &Frame, inner: &Frame) -> String {
    let base = match (operand_base(ops.lhs), operand_base(ops.rhs)) {
        (Some(a), Some(b)) if a == b => a,
        _ => "X",
    };
    tagged_name(base, &[&outer.to_string(), &inner.to_string()])
}

/// The fix for a product whose inner frames differ.
fn product_help(l: &Ty, r: &Ty, ops: Operands) -> String {
    let rule = "X_xy maps coordinates in {y} to {x}";
    match (&l.frames, &r.frames) {
        (Frames::Pair(a, b), Frames::Pair(c, d)) => {
            if b == d && a != c {
                let (inverse, name) = (ops.rhs.inverse_text(), result_name(ops, d, c));
                if inverse == name {
                    format!("{rule}; did you mean {name}?")
                } else {
                    format!("{rule}; did you mean {inverse} = {name}?")
                }
            } else if c == a && b != d {
                // T_sb * T_sc: both from {s}.
                format!(
                    "{rule}; both start in {{{a}}}: the body-frame form is {} * {} = {}{}",
                    ops.lhs.inverse_text(),
                    ops.rhs.text().trim(),
                    result_name(ops, b, d),
                    displacement_hint(ops)
                )
            } else if d == a {
                format!(
                    "{rule}; the other order cancels: {} * {} = {}{}",
                    ops.rhs.text().trim(),
                    ops.lhs.text().trim(),
                    result_name(ops, c, b),
                    displacement_hint(ops)
                )
            } else {
                format!("{rule}; find a transform from {{{b}}} to {{{c}}} (try derive)")
            }
        }
        (Frames::Pair(a, _), Frames::One(c)) if a == c && r.kind.is_vector() => {
            hints::vector_in_outer(l, ops).unwrap_or_else(|| rule.to_string())
        }
        (Frames::Pair(_, b), Frames::One(c)) => format!(
            "{} takes coordinates in {{{b}}}, but {} is in {{{c}}}; express it in {{{b}}} first",
            ops.lhs.text().trim(),
            if r.kind.is_vector() {
                "the vector".to_string()
            } else {
                format!("{} ({})", ops.rhs.text().trim(), r.kind.a())
            }
        ),
        (Frames::Disp(a), Frames::Pair(c, _)) => format!(
            "a displacement in {{{a}}} premultiplies a transform from {{{a}}} (X_{a}?); {} starts in {{{c}}}",
            ops.rhs.text().trim()
        ),
        (Frames::Pair(_, b), Frames::Disp(d)) => format!(
            "a displacement in {{{d}}} postmultiplies a transform into {{{d}}} (X_?{d}); {} ends in {{{b}}}",
            ops.lhs.text().trim()
        ),
        _ => rule.to_string(),
    }
}

/// For `T_sc * inv(T_sb)`: name the space-frame displacement.
fn displacement_hint(ops: Operands) -> String {
    if let Form::Inverse(x) = ops.rhs.form() {
        let inner = x.text();
        format!(
            "; the displacement in the fixed frame taking {inner} to {} is displacement({inner}, {}) = {} * inv({inner})",
            ops.lhs.text().trim(),
            ops.lhs.text().trim(),
            ops.lhs.text().trim()
        )
    } else {
        String::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn t(kind: Kind, frames: Frames) -> Ty {
        Ty::new(kind, frames)
    }

    #[test]
    fn conjugation_is_back_in_the_lie_algebra_under_both_bracketings() {
        let g = t(Kind::SE3, Frames::pair("a", "b"));
        let x = t(Kind::Se3, Frames::one("b"));
        let gi = t(Kind::SE3, Frames::pair("b", "a"));
        let ops = Operands::default();
        let left = mul(&mul(&g, &x, ops).unwrap(), &gi, ops).unwrap();
        let right = mul(&g, &mul(&x, &gi, ops).unwrap(), ops).unwrap();
        assert_eq!(left, right);
        assert_eq!(
            super::super::rules::settled(&left),
            t(Kind::Se3, Frames::one("a"))
        );
        // g·X alone is a plain matrix that remembers its algebra.
        let gx = mul(&g, &x, ops).unwrap();
        assert_eq!(gx.kind, Kind::Matrix(Some(4), Some(4)));
        assert_eq!(gx.algebra, Some(Algebra::Se3));
        // X·X is no longer anything of the algebra.
        let xx = mul(&x, &x, ops).unwrap();
        let gxxg = mul(&mul(&g, &xx, ops).unwrap(), &gi, ops).unwrap();
        assert_eq!(super::super::rules::settled(&gxxg).kind, xx.kind);
        // A rotation does not conjugate se(3), nor SE(2) so(3).
        let se2 = t(Kind::SE2, Frames::pair("a", "b"));
        let w = t(Kind::So3, Frames::one("b"));
        assert_eq!(mul(&se2, &w, ops).unwrap().algebra, None);
    }
}
