//! Binding a value to a name: the name's frame subscript is a claim about
//! the value's frames (LANGUAGE.md §3, §6). `T_ad = T_ab * T_bc` fails: the
//! value is {c} in {a}.

use super::rules::{RuleError, describe};
use super::ty::{Frame, Frames, Kind, Ty};
use crate::diagnostics::ErrorKind;
use crate::syntax::ident::{NameFrames, base_name, name_frames, tagged_name};

/// The frames a name claims, as a tag for a value of `kind`: `p_sb` (a
/// vector named with two frames) is the position of {b} in {s}, tagged {s}.
pub fn claimed_frames(name: &str, kind: &Kind) -> Frames {
    match name_frames(name) {
        NameFrames::None => Frames::None,
        NameFrames::One(a) => Frames::One(Frame::named(a)),
        NameFrames::Pair(a, b) => {
            if kind.is_vector() || kind.is_algebra() {
                Frames::One(Frame::named(a))
            } else {
                Frames::Pair(Frame::named(a), Frame::named(b))
            }
        }
    }
}

/// The book's letters name the kind of a plain 6-vector: `V` a twist, `S`
/// or `B` a screw axis, `F` a wrench.
pub fn named_kind(name: &str, kind: &Kind) -> Kind {
    if kind.vec_len() == Some(6) && *kind == Kind::Vector(Some(6)) {
        match base_name(name).chars().next() {
            Some('V') => Kind::Twist,
            Some('S' | 'B') => Kind::Screw,
            Some('F') => Kind::Wrench,
            _ => kind.clone(),
        }
    } else {
        kind.clone()
    }
}

/// The type a binding `name = value` gets, or the frame error.
pub fn bind(name: &str, ty: &Ty) -> Result<Ty, RuleError> {
    let kind = named_kind(name, &ty.kind);
    let claim = claimed_frames(name, &kind);
    let frames = match (&claim, &ty.frames) {
        (Frames::None, f) => f.clone(),
        (c, Frames::None) => c.clone(),
        (Frames::Pair(x, y), Frames::Pair(a, b)) if x == a && (y == b || b.moved) => claim.clone(),
        (Frames::Pair(x, _), Frames::Disp(a)) if x == a => claim.clone(),
        (Frames::One(x), Frames::One(a) | Frames::Disp(a)) if x == a => ty.frames.clone(),
        _ => {
            let mut e = RuleError {
                kind: Some(ErrorKind::Frame),
                message: format!(
                    "the value is {}, but the name {name} says {}",
                    describe(&ty.frames),
                    describe(&claim)
                ),
                ..Default::default()
            };
            e.lhs = format!("says {}", describe(&claim));
            e.rhs = describe(&ty.frames);
            e.help = Some(suggest_name(name, &ty.frames));
            return Err(e);
        }
    };
    Ok(Ty::new(kind, frames))
}

fn suggest_name(name: &str, frames: &Frames) -> String {
    let base = base_name(name);
    match frames {
        Frames::Pair(a, b) => format!(
            "name it {}, or check the product's order",
            tagged_name(base, &[&a.to_string(), &b.to_string()])
        ),
        Frames::One(a) => format!("name it {}", tagged_name(base, &[&a.to_string()])),
        Frames::Disp(a) => format!(
            "a displacement in {{{a}}}: name it {}…",
            tagged_name(base, &[&a.to_string()])
        ),
        Frames::None => String::new(),
    }
}
