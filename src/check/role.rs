//! What a name says a vector is (LANGUAGE.md §4, §6). The book keeps points
//! apart from free vectors: a point p, q, r has a position and a transform
//! moves it, T p = R p + p_T (3.65); an angular velocity ω (typed `w`), a
//! linear velocity v, a force f, a moment m and a unit axis ω̂, ŝ, x̂ have
//! only a direction and a size, and only rotate (ω_s = R_sb ω_b, (3.35)).
//! The axis names x̂_a, ŷ_a, ẑ_a (typed `x_a`, `xhat_a`, `x̂_a`) are the
//! axes *of* {a} (§3.2.1), written in whatever frame the user wrote them
//! in: their subscript names no frame the value is in.
//!
//! A name says what its vector is the way `V`, `S`, `F` say a 6-vector is a
//! twist, screw or wrench; `given u : free` (or `: point`) says it for any
//! other name ([`given_role`]).

use crate::syntax::ident::base_name;

/// What a name says a vector bound to it is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// A point (p, q, r): a transform moves it (3.65).
    Point,
    /// A free vector (ω, w, v, f, m, ω̂, ŝ): only a rotation acts on it.
    Free,
    /// An axis x̂_a, ŷ_a, ẑ_a of a frame {a}: a free vector whose subscript
    /// names the frame it is an axis of, not the frame it is written in.
    Axis,
}

impl Role {
    /// True for the roles of free vectors (free vectors and axes).
    pub fn is_free(self) -> bool {
        matches!(self, Role::Free | Role::Axis)
    }

    /// What a value of this role is, in words, for error messages.
    pub fn noun(self) -> &'static str {
        match self {
            Role::Point => "a point",
            Role::Free => "a free vector",
            Role::Axis => "an axis (a unit free vector)",
        }
    }
}

/// The role of a vector bound to `name`, read from the book's letters:
/// `p_b`, `q`, `r_s` points; `ω_s`, `w_b`, `v`, `f_a`, `m_b`, `omega`,
/// `ŵ`, `what`, `ŝ`, `shat` free vectors; `x_a`, `ŷ_b`, `zhat_s`, `x̂_a`
/// axes. None for any other name (`u`, `x`, `Sum`).
pub fn of(name: &str) -> Option<Role> {
    let base = base_name(name);
    let subscripted = base.len() < name.len();
    let (letter, hat) = letter_of(base)?;
    match letter {
        'x' | 'y' | 'z' if hat || subscripted => Some(Role::Axis),
        'ω' | 'w' | 'v' | 'f' | 'm' => Some(Role::Free),
        's' if hat => Some(Role::Free),
        'p' | 'q' | 'r' if !hat => Some(Role::Point),
        _ => None,
    }
}

/// The book's letter of a vector name and whether it wears a hat: `ω̂1` is
/// (ω, hat), `w_hat` (w, hat), `what` (w, hat), `omega_2` (ω, no hat),
/// `v1` (v, no hat). None for longer names.
fn letter_of(base: &str) -> Option<(char, bool)> {
    // An index: `ω_1`, `v_2` (the subscript is no frame), or digits `w1`.
    let base = match base.rsplit_once('_') {
        Some((stem, index)) if !index.is_empty() && index.bytes().all(|b| b.is_ascii_digit()) => {
            stem
        }
        _ => base,
    };
    let base = base.trim_end_matches(|c: char| c.is_ascii_digit());
    let (stem, hat) = match base
        .strip_suffix("_hat")
        .or_else(|| base.strip_suffix("hat"))
        .or_else(|| base.strip_suffix('\u{302}'))
    {
        Some(stem) if !stem.is_empty() => (stem, true),
        _ => (base, false),
    };
    let stem = match stem {
        "omega" => "ω",
        s => s,
    };
    let mut chars = stem.chars();
    let c = chars.next()?;
    if chars.next().is_some() {
        return None;
    }
    // Letters with the hat composed in: ŵ, ŝ, ŷ, ẑ.
    Some(match c {
        'ŵ' => ('w', true),
        'ŝ' => ('s', true),
        'ŷ' => ('y', true),
        'ẑ' => ('z', true),
        c => (c, hat),
    })
}

/// What the vector bound to `name` is, in the book's words, for error
/// messages: `ω_b` an angular velocity, `f_a` a force, `x_a` an axis.
pub fn noun(name: &str) -> Option<&'static str> {
    let role = of(name)?;
    let (letter, hat) = letter_of(base_name(name))?;
    Some(match (role, letter) {
        (Role::Free, 'ω' | 'w') if !hat => "an angular velocity",
        (Role::Free, 'v') if !hat => "a linear velocity",
        (Role::Free, 'f') => "a force",
        (Role::Free, 'm') => "a moment",
        (Role::Free, _) | (Role::Axis, _) => "a unit axis",
        (Role::Point, _) => "a point",
    })
}

/// The roles `given` declares (`given u_b : free`, `given c : point`):
/// a free or a point 3-vector, or 2-vector with `free2`, `point2`.
pub fn given_role(ty: &str) -> Option<(Role, usize)> {
    Some(match ty {
        "free" | "free3" => (Role::Free, 3),
        "free2" => (Role::Free, 2),
        "point" | "point3" => (Role::Point, 3),
        "point2" => (Role::Point, 2),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_books_letters_say_point_or_free_vector() {
        for name in [
            "ω_b", "ω", "w_s", "w", "v_b", "v1", "f_a", "m_b", "omega_s", "ω_1", "ŵ", "what",
            "w_hat", "ω̂", "ŝ", "shat", "s_hat", "ω̂_s",
        ] {
            assert_eq!(of(name), Some(Role::Free), "{name}");
        }
        for name in [
            "x_a", "y_b", "z_s", "xhat_a", "x̂_a", "ŷ", "ẑ_b", "x_hat", "zhat",
        ] {
            assert_eq!(of(name), Some(Role::Axis), "{name}");
        }
        for name in ["p_b", "p", "q", "r_s", "p_sb", "q1"] {
            assert_eq!(of(name), Some(Role::Point), "{name}");
        }
        for name in [
            "x", "y", "s", "u", "Sum", "W", "V_s", "F", "x_max", "vel", "mass",
        ] {
            assert_eq!(of(name), None, "{name}");
        }
    }

    #[test]
    fn error_messages_name_the_quantity() {
        assert_eq!(noun("ω_b"), Some("an angular velocity"));
        assert_eq!(noun("w"), Some("an angular velocity"));
        assert_eq!(noun("v_s"), Some("a linear velocity"));
        assert_eq!(noun("f_a"), Some("a force"));
        assert_eq!(noun("m2"), Some("a moment"));
        assert_eq!(noun("ŝ"), Some("a unit axis"));
        assert_eq!(noun("x_a"), Some("a unit axis"));
        assert_eq!(noun("u"), None);
    }

    #[test]
    fn given_declares_free_vectors_and_points() {
        assert_eq!(given_role("free"), Some((Role::Free, 3)));
        assert_eq!(given_role("point2"), Some((Role::Point, 2)));
        assert_eq!(given_role("vec3"), None);
    }
}
