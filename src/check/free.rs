//! A transform applied to what is not a point (LANGUAGE.md §4): `T * p`
//! with a 3-vector p is the homogeneous product R p + p_T (3.65), right for
//! a point and wrong for a free vector — an angular velocity ω_s = R_sb ω_b
//! (3.35), a linear velocity, a force, a moment, an axis only rotate. A
//! twist changes frame with the adjoint, V_a = [Ad_T_ab] V_b (3.83), and a
//! wrench with its transpose (Prop. 3.17); a transform times a 6-vector is
//! no product at all. The errors name the product that is meant.

use super::error::{Form, Operands, RuleError, describe};
use super::role;
use super::ty::{Frames, Kind, Ty};
use crate::syntax::ident::{NameFrames, base_name, name_frames, tagged_name};

/// `T_sb * ω_b`: a transform times a free vector.
pub(super) fn through_transform(l: &Ty, r: &Ty, ops: Operands) -> RuleError {
    let t = ops.lhs.text().trim();
    let v = ops.rhs.text().trim();
    let (what, named) = match ops.rhs.form() {
        Form::Name(n) => match role::noun(n) {
            Some(what) => (what, Some(n)),
            None => ("a free vector", None),
        },
        _ => ("a free vector", None),
    };
    let (rotation, book) = rotation_of(ops, &l.frames);
    let book = book.map_or(String::new(), |r| format!(" (the book's {r} {v})"));
    let mut e = RuleError::typ(format!(
        "{t} * {v} applies a transform to a free vector: {v} is {what}, not a point"
    ));
    e.lhs = describe(&l.frames);
    e.rhs = format!("{what} {}", describe(&r.frames));
    let planar = matches!(l.kind, Kind::SE2);
    let ad = if planar {
        String::new()
    } else {
        format!("; a twist V = (ω, v) changes frame by Ad({t}) * V (3.83)")
    };
    // The book also names a point v (Figure 3.13): how to say so.
    let point = match named {
        Some(n) if what == "a linear velocity" => {
            format!("; if {n} is a point, say so first: given {n} : point")
        }
        _ => String::new(),
    };
    e.help = Some(format!(
        "a transform moves points, T p = R p + p (3.65); a free vector only rotates: write {rotation} * {v}{book}{ad}{point}"
    ));
    e
}

/// `T_sb * V_b`: a transform times a twist, screw or wrench (or a plain
/// 6-vector): the adjoint is meant.
pub(super) fn six_through_transform(_l: &Ty, r: &Ty, ops: Operands) -> RuleError {
    let t = ops.lhs.text().trim();
    let v = ops.rhs.text().trim();
    let mut e = RuleError::typ(format!(
        "a transform does not act on {}: {t} is 4×4 and {v} has six coordinates",
        r.kind.a()
    ));
    e.lhs = "SE(3)".into();
    e.rhs = r.kind.to_string();
    e.help = Some(match r.kind {
        Kind::Wrench => format!(
            "a wrench changes frame with the transposed adjoint (Prop. 3.17): F_b = Ad(T_ab).T * F_a, so Ad(inv({t})).T * {v} moves {v} the way {t} moves points"
        ),
        _ => format!("a twist changes frame with the adjoint (3.83): write Ad({t}) * {v}"),
    });
    e
}

/// How to write the rotation of the transform operand, `T_sb.R`
/// (`(T_sb * T_bc).R`), and the book's name for it, `R_sb`, when the
/// operand is a transform's name.
fn rotation_of(ops: Operands, frames: &Frames) -> (String, Option<String>) {
    let text = ops.lhs.text().trim();
    match ops.lhs.form() {
        Form::Name(n) => {
            let book = match (base_name(n), name_frames(n), frames) {
                ("T", NameFrames::Pair(..), Frames::Pair(a, b)) => {
                    Some(tagged_name("R", &[&a.to_string(), &b.to_string()]))
                }
                _ => None,
            };
            (format!("{text}.R"), book)
        }
        _ => (format!("({text}).R"), None),
    }
}
