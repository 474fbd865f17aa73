//! Binding a value to a name: the name's frame subscript is a claim about
//! the value's frames (LANGUAGE.md §3, §6), and the book's letters say what
//! the value is (§5). `T_ad = T_ab * T_bc` fails: the value is {c} in {a}.
//! Scalars and bools take no frames from their name (`theta_b`, the power
//! `P_b`, `ok_a`); axis names `x_a` none either (an axis *of* {a});
//! `R_sb`, `T_ab` name group elements ([`named_group`]); only the book's
//! letters `S`, `B`, `V`, `F` make a 6-vector a screw, twist or wrench.

use super::error::{RuleError, describe};
use super::role::{self, Role};
use super::ty::{Frame, Frames, Kind, Ty};
use crate::diagnostics::ErrorKind;
use crate::syntax::ident::{NameFrames, base_name, name_frames, tagged_name};

/// What a binding's name says about its value, read once per name (the
/// environment keeps it): the book's letter (`book_letter`) and the
/// frames of its subscript (LANGUAGE.md §2). `Copy`, so binding a name
/// again reads nothing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Claim {
    /// The book's letter (`T` of `T_sb`, `S` of `S1`), if the name is one
    /// of the book's names.
    pub letter: Option<char>,
    /// The frames of the subscript: none, {a} (`p_a`), or {a}, {b} (`T_ab`).
    /// None for an axis name (`x_a` is an axis *of* {a}, [`Role::Axis`]).
    pub frames: Frames,
    /// What the name says a vector is: a point (`p_b`), a free vector
    /// (`ω_s`, `v_b`) or an axis (`x_a`); `given u : free` says it for
    /// other names ([`super::role`]).
    pub role: Option<Role>,
    /// True when `given name : free` (or `: point`) declared the role: the
    /// user said what the vector is, so no reading of the letter (Fig.
    /// 3.13's literal `v_b` as a point) overrides it.
    pub declared: bool,
}

impl Claim {
    /// The claim of `name`: `T_sb''` is the letter T and the frames {s},
    /// {b''}; `theta_1` has no frames, `Sum` no letter.
    pub fn of(name: &str) -> Claim {
        let role = role::of(name);
        let frames = match name_frames(name) {
            NameFrames::None => Frames::None,
            // x̂_a is an axis of {a}, written in some other frame (§3.2.1).
            NameFrames::One(_) if role == Some(Role::Axis) => Frames::None,
            NameFrames::One(a) => Frames::One(Frame::named(&a)),
            NameFrames::Pair(a, b) => Frames::Pair(Frame::named(&a), Frame::named(&b)),
        };
        Claim {
            letter: book_letter(name),
            frames,
            role,
            declared: false,
        }
    }

    /// The frames the name claims, as a tag for a value of `kind`: `p_sb`
    /// (a vector named with two frames) is the position of {b} in {s},
    /// tagged {s}; a scalar claims none (`theta_b = 30 deg` is a plain angle).
    pub fn frames_for(&self, kind: &Kind) -> Frames {
        match self.frames {
            _ if matches!(kind, Kind::Scalar | Kind::Bool) => Frames::None,
            Frames::Pair(a, _) if kind.is_vector() || kind.is_algebra() => Frames::One(a),
            f => f,
        }
    }

    /// Whether a vector of `kind` bound to this name is a free vector
    /// (ω, v, f, m, an axis, or declared `: free`), which a transform does
    /// not move (§4): Some when the name says (a point's name says no),
    /// None when it says nothing and the value's own flag stands.
    pub fn free_for(&self, kind: &Kind) -> Option<bool> {
        self.role.map(|role| role.is_free() && kind.is_vector())
    }

    /// The type this name gives a value known by its kind only (`given
    /// w_b : vec3`): the frames of its subscript, and a free vector when
    /// its letters say so — as for numbers bound to it
    /// ([`bind_in_place`]), so symbols are checked exactly like numbers
    /// (§7: `T_sb * ω_b` is refused either way).
    pub fn given_ty(&self, kind: Kind) -> Ty {
        let mut ty = Ty::new(kind, self.frames_for(&kind));
        ty.free = self.free_for(&kind).unwrap_or(false);
        ty
    }

    /// The kind a value of `kind` gets under this name: the book's letters
    /// name the kind of a plain 6-vector ([`named_kind`]) and the group of
    /// a square matrix ([`named_group`]).
    pub fn kind_for(&self, kind: Kind) -> Kind {
        let kind = self.vector_kind(kind);
        self.group(&kind).unwrap_or(kind)
    }

    fn vector_kind(&self, kind: Kind) -> Kind {
        if matches!(kind, Kind::Vector(Some(6))) {
            match self.letter {
                Some('V') => Kind::Twist,
                Some('S' | 'B') => Kind::Screw,
                Some('F') => Kind::Wrench,
                _ => kind,
            }
        } else {
            kind
        }
    }

    /// Why a value of `kind` (as [`Claim::kind_for`] makes it) cannot be
    /// bound under this name: a rotation or transform name (`R_sb`,
    /// `T_ab`) requires the group at the binding (LANGUAGE.md §5), so a
    /// scalar, a vector, a matrix of another shape or another group under
    /// it is a type error, whether numbers or symbols. A rotation under a
    /// transform's name stays allowed (a pure rotation, p = 0), and a value
    /// whose kind is not yet known passes (its numbers are checked when
    /// they come).
    #[inline]
    fn group_refusal(&self, name: &str, kind: &Kind) -> Option<RuleError> {
        let unknown = |k: &Kind| {
            matches!(
                k,
                Kind::Unknown | Kind::Function | Kind::Matrix(None, _) | Kind::Matrix(_, None)
            )
        };
        let fits = match (self.letter, self.frames) {
            (Some('R'), Frames::Pair(..)) => matches!(kind, Kind::SO3 | Kind::SO2) || unknown(kind),
            (Some('T'), Frames::Pair(..)) => {
                matches!(kind, Kind::SE3 | Kind::SE2 | Kind::SO3) || unknown(kind)
            }
            _ => true,
        };
        if fits {
            None
        } else {
            Some(self.group_refused(name, kind))
        }
    }

    /// The type error of [`Claim::group_refusal`].
    #[cold]
    #[inline(never)]
    fn group_refused(&self, name: &str, kind: &Kind) -> RuleError {
        let (what, groups, make) = match self.letter {
            Some('R') => (
                "a rotation",
                "SO(3) or SO(2)",
                "a rotation (ProjectToSO3(M) for a near one)",
            ),
            _ => (
                "a transform",
                "SE(3) or SE(2)",
                "a transform (RpToTrans(R, p))",
            ),
        };
        let other = match self.frames {
            Frames::Pair(a, b) => tagged_name("M", &[&a.to_string(), &b.to_string()]),
            _ => "M".into(),
        };
        let mut e = RuleError::from(crate::check::rules::Refusal {
            kind: Some(ErrorKind::Type),
            message: format!(
                "{name} names {what}, in {groups}, but the value is {}",
                kind.a()
            ),
            ..Default::default()
        });
        e.lhs = format!("says {what}");
        e.rhs = kind.a();
        e.help = Some(format!(
            "{name} is the book's name of {what} (§5): give {} another name ({other}), or bind {make}",
            kind.a()
        ));
        e
    }

    fn group(&self, kind: &Kind) -> Option<Kind> {
        let n = match kind {
            Kind::Matrix(Some(r), Some(c)) if r == c => *r,
            Kind::SE2 if self.letter == Some('R') => 3,
            _ => return None,
        };
        if !matches!(self.frames, Frames::Pair(..)) {
            return None;
        }
        match (self.letter?, n) {
            ('R', 3) => Some(Kind::SO3),
            ('R', 2) => Some(Kind::SO2),
            ('T', 4) => Some(Kind::SE3),
            ('T', 3) => Some(Kind::SE2),
            _ => None,
        }
    }
}

/// The book's letter of a name, when the name is one of the book's names
/// for a 6-vector or a group element: one letter, optionally followed by
/// digits, then optionally a frame or index subscript (`S`, `S1`, `S_b`,
/// `S_1`, `B2`, `V_s`, `F_b`, `T3_sb`). `Sum`, `Bq`, `Fk` have none.
fn book_letter(name: &str) -> Option<char> {
    let base = base_name(name);
    let stem = match base.split_once('_') {
        Some((stem, index)) if !index.is_empty() && index.chars().all(|c| c.is_ascii_digit()) => {
            stem
        }
        Some(_) => return None,
        None => base,
    };
    let mut chars = stem.chars();
    let letter = chars.next()?;
    chars.all(|c| c.is_ascii_digit()).then_some(letter)
}

/// The book's letters name the kind of a plain 6-vector: `V` a twist, `S`
/// or `B` a screw axis, `F` a wrench (§3.3.2, §3.4) — for the book's names
/// only (`book_letter`).
pub fn named_kind(name: &str, kind: &Kind) -> Kind {
    Claim::of(name).vector_kind(*kind)
}

/// The group a rotation or transform name asserts for a square matrix of
/// `kind` (LANGUAGE.md §5): `R_sb` a rotation (SO(3), or SO(2) when 2×2),
/// `T_ab` a transform (SE(3) when 4×4, SE(2) when 3×3). None for other
/// names and shapes, and for values that are already group elements (a
/// rotation bound to `T_bc` stays a rotation) — except a planar transform
/// under a rotation's name, which must be a rotation.
pub fn named_group(name: &str, kind: &Kind) -> Option<Kind> {
    Claim::of(name).group(kind)
}

/// A binding that succeeded, with a warning when the name renames a moved
/// frame to its unmoved letter.
#[derive(Debug, Clone)]
pub struct Bound {
    /// The binding's type: the value's, with the kind and frames its name
    /// claims.
    pub ty: Ty,
    /// The renaming warning, if any.
    pub warning: Option<RuleError>,
}

/// The type a binding `name = value` gets, or the frame error.
pub fn bind(name: &str, ty: &Ty) -> Result<Bound, RuleError> {
    bind_claimed(name, &Claim::of(name), *ty).map_err(|r| r.error)
}

/// A binding refused: the frame error, and the type the name gives the
/// value when frames are not checked (its kind, the frames it claims).
#[derive(Debug, Clone)]
pub struct Refused {
    /// Why the name does not fit the value.
    pub error: RuleError,
    /// The type the name gives the value anyway (its kind, the frames it
    /// claims), used when frames are not checked (`--frames warn|off`).
    pub ty: Ty,
}

/// [`bind`] with the name's [`Claim`] already read, taking the type.
pub fn bind_claimed(name: &str, claim: &Claim, ty: Ty) -> Result<Bound, Refused> {
    let mut ty = ty;
    match bind_in_place(name, claim, &mut ty) {
        Ok(warning) => Ok(Bound { ty, warning }),
        Err(error) => Err(Refused { error, ty }),
    }
}

/// [`bind_claimed`] on the type in place (no copy of it): bound, `ty` is
/// the binding's type and the result the warning if there is one; refused,
/// `ty` is the type the name gives the value ([`Refused::ty`]) and the
/// result the frame error.
pub fn bind_in_place(
    name: &str,
    claim: &Claim,
    ty: &mut Ty,
) -> Result<Option<RuleError>, RuleError> {
    let kind = claim.kind_for(ty.kind);
    if let Some(e) = claim.group_refusal(name, &kind) {
        return Err(e);
    }
    // Scalars and bools take no frames from their name (§2, §3).
    if matches!(kind, Kind::Scalar | Kind::Bool) {
        *ty = Ty::new(kind, Frames::None);
        return Ok(None);
    }
    ty.free = match claim.free_for(&kind) {
        Some(free) => free,
        None => ty.free && kind.is_vector(),
    };
    let claim = claim.frames_for(&kind);
    // A tuple written out (`(T_ab, T_cb)`) has no tag of its own: the name
    // claims its parts' frames, which must not say otherwise.
    if let (Kind::Tuple(_), Frames::None) = (kind, ty.frames)
        && let Some(e) = tuple_refusal(name, &claim, ty)
    {
        ty.kind = kind;
        ty.frames = claim;
        return Err(e);
    }
    let mut warning = None;
    let frames = match (claim, ty.frames) {
        (Frames::None, f) => f,
        (c, Frames::None) => c,
        (Frames::Pair(x, y), Frames::Pair(a, b)) if x == a && (y == b || b.is_moved()) => {
            if y.name == b.name && y.moved == 0 && b.moved > 0 {
                warning = Some(renamed_moved_frame(name, &ty.frames, &b, &y));
            }
            claim
        }
        (Frames::Pair(x, y), Frames::Disp(a)) if x == a => {
            if y.name == a.name && y.moved == 0 {
                warning = Some(renamed_moved_frame(name, &ty.frames, &a.moved(), &y));
            }
            claim
        }
        (Frames::One(x), Frames::One(a) | Frames::Disp(a)) if x == a => ty.frames,
        _ => {
            let error = mismatch(name, &claim, &ty.frames);
            let free = ty.free;
            *ty = Ty::new(kind, claim);
            ty.free = free;
            return Err(error);
        }
    };
    // The algebra and moves stay as they were.
    ty.kind = kind;
    ty.frames = frames;
    Ok(warning)
}

/// `q_ab = (T_ab, T_cb)`: the first part of the tuple whose frames are not
/// the name's. Under {a}←{b} a part may be {a}←{b} (or {a}←{b'}, a
/// displacement in {a}), a vector in {a} or {b}, or untagged; under {a},
/// anything whose outer frame is {a}.
fn tuple_refusal(name: &str, claim: &Frames, ty: &Ty) -> Option<RuleError> {
    let Kind::Tuple(kinds) = ty.kind else {
        return None;
    };
    let fits = |part: &Frames| match (claim, part) {
        (Frames::None, _) | (_, Frames::None) => true,
        (Frames::Pair(x, y), Frames::Pair(a, b)) => x == a && (y == b || b.is_moved()),
        (Frames::Pair(x, _), Frames::Disp(a)) => x == a,
        (Frames::Pair(x, y), Frames::One(a)) => x == a || y == a,
        (Frames::One(x), Frames::One(a) | Frames::Disp(a) | Frames::Pair(a, _)) => x == a,
        _ => false,
    };
    let (i, part) = (0..kinds.len())
        .filter_map(|i| ty.part(i).map(|p| (i, p)))
        .find(|(_, p)| !fits(&p.frames))?;
    let mut e = RuleError::from(crate::check::rules::Refusal {
        kind: Some(ErrorKind::Frame),
        message: format!(
            "part {} of the tuple is {}, but the name {name} says {}",
            i + 1,
            describe(&part.frames),
            describe(claim)
        ),
        ..Default::default()
    });
    e.lhs = format!("says {}", describe(claim));
    e.rhs = format!("part {} is {}", i + 1, describe(&part.frames));
    e.help = Some(format!(
        "a name's frames claim every part's: name the tuple without a frame subscript ({} = ...), or give each part its own name",
        base_name(name)
    ));
    Some(e)
}

fn mismatch(name: &str, claim: &Frames, frames: &Frames) -> RuleError {
    let mut e = RuleError::from(crate::check::rules::Refusal {
        kind: Some(ErrorKind::Frame),
        message: format!(
            "the value is {}, but the name {name} says {}",
            describe(frames),
            describe(claim)
        ),
        ..Default::default()
    });
    e.lhs = format!("says {}", describe(claim));
    e.rhs = describe(frames);
    e.help = Some(suggest_name(name, frames));
    // `ω_b = R.T ω_s` with an untagged R: the value stays in {s}.
    if let (Frames::One(want), Frames::One(_)) = (claim, frames) {
        e.help = e.help.take().map(|h| {
            format!(
                "{h}; or, if it is in {{{want}}}, give the matrix its frames: an untagged matrix keeps the frame of the vector it multiplies"
            )
        });
    }
    e
}

/// `Tq_ab = exp([S_a] 0.3) * T_ab`: the value ends in {b'}, and the name
/// calls that frame {b} — the unmoved frame's own name.
fn renamed_moved_frame(name: &str, frames: &Frames, moved: &Frame, named: &Frame) -> RuleError {
    let base = base_name(name);
    let better = match frames {
        Frames::Pair(a, _) | Frames::Disp(a) => {
            tagged_name(base, &[&a.to_string(), &moved.to_string()])
        }
        _ => name.to_string(),
    };
    let mut e = RuleError::from(crate::check::rules::Refusal {
        kind: Some(ErrorKind::Frame),
        message: format!(
            "{name} calls the moved frame {{{moved}}} by the name of the unmoved frame {{{named}}}"
        ),
        ..Default::default()
    });
    e.rhs = describe(frames);
    e.help = Some(format!(
        "a displacement moved {{{named}}} to {{{moved}}}, and {name} now names {{{moved}}} as {{{named}}}: name it {better} to keep them apart"
    ));
    e
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
        Frames::Transposed(..) => {
            "the transpose of a transform is not a transform: write inv(T) for its inverse".into()
        }
        Frames::None => String::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_books_names_make_screws_twists_and_wrenches() {
        let v6 = Kind::Vector(Some(6));
        for (name, want) in [
            ("S", Kind::Screw),
            ("S1", Kind::Screw),
            ("S_b", Kind::Screw),
            ("S_1", Kind::Screw),
            ("B2", Kind::Screw),
            ("V_s", Kind::Twist),
            ("F_b", Kind::Wrench),
            ("Sum", v6),
            ("Bq", v6),
            ("Fk", v6),
            ("Vel_b", v6),
        ] {
            assert_eq!(named_kind(name, &v6), want, "{name}");
        }
    }

    #[test]
    fn rotation_and_transform_names_assert_their_group() {
        let m = |n| Kind::Matrix(Some(n), Some(n));
        assert_eq!(named_group("R_sb", &m(3)), Some(Kind::SO3));
        assert_eq!(named_group("R_sb", &m(2)), Some(Kind::SO2));
        assert_eq!(named_group("T_ab", &m(4)), Some(Kind::SE3));
        assert_eq!(named_group("T3_sb", &m(3)), Some(Kind::SE2));
        assert_eq!(named_group("R", &m(3)), None);
        assert_eq!(named_group("Rq_sb", &m(3)), None);
        assert_eq!(named_group("M_sb", &m(4)), None);
        // A group element keeps its group; a planar transform is no rotation.
        assert_eq!(named_group("T_bc", &Kind::SO3), None);
        assert_eq!(named_group("R_bc", &Kind::SE2), Some(Kind::SO3));
    }

    #[test]
    fn a_claim_is_the_letter_and_the_subscript_frames() {
        let c = Claim::of("T_sb''");
        assert_eq!(c.letter, Some('T'));
        let Frames::Pair(s, b) = c.frames else {
            panic!("{:?}", c.frames)
        };
        assert_eq!((s.to_string(), b.to_string()), ("s".into(), "b''".into()));
        assert_eq!((b.name.as_str(), b.moved, b.written), ("b", 2, 2));
        // A vector named with two frames is in the outer one; a scalar in none.
        assert_eq!(c.frames_for(&Kind::Vector(Some(3))), Frames::one("s"));
        assert_eq!(c.frames_for(&Kind::Scalar), Frames::None);
        assert_eq!(c.kind_for(Kind::Matrix(Some(4), Some(4))), Kind::SE3);
        let c = Claim::of("p_{world}");
        assert_eq!((c.letter, c.frames), (Some('p'), Frames::one("world")));
        assert_eq!(Claim::of("Sum").letter, None);
        assert_eq!(Claim::of("theta_1").frames, Frames::None);
        assert_eq!(
            Claim::of("V_b").kind_for(Kind::Vector(Some(6))),
            Kind::Twist
        );
    }

    #[test]
    fn scalars_take_no_frames_from_their_name() {
        let b = bind("theta_b", &Ty::scalar()).unwrap();
        assert_eq!(b.ty, Ty::scalar());
        assert_eq!(Claim::of("P_b").given_ty(Kind::Scalar), Ty::scalar());
    }

    #[test]
    fn a_given_vector_is_free_or_a_point_as_numbers_bound_to_it_are() {
        let vec3 = Kind::Vector(Some(3));
        for (name, free) in [
            ("ω_b", true),
            ("w_b", true),
            ("v_s", true),
            ("f_a", true),
            ("m", true),
            ("ŝ", true),
            ("x_a", true),
            ("p_b", false),
            ("q", false),
            ("u_b", false),
        ] {
            let given = Claim::of(name).given_ty(vec3);
            assert_eq!(given.free, free, "{name}");
            // the same type as numbers bound to the name (§7)
            assert_eq!(bind(name, &Ty::plain(vec3)).unwrap().ty, given, "{name}");
        }
        let w = Claim::of("w_b").given_ty(vec3);
        assert_eq!(w.frames, Frames::one("b"));
        // only vectors are free: a transform named w is not
        assert!(!Claim::of("w_sb").given_ty(Kind::SE3).free);
        assert!(!Claim::of("ω").given_ty(Kind::Scalar).free);
    }

    #[test]
    fn renaming_a_moved_frame_to_its_own_letter_warns() {
        let moved = Ty::new(
            Kind::SE3,
            Frames::Pair(Frame::named("a"), Frame::named("b'")),
        );
        let b = bind("Tq_ab", &moved).unwrap();
        assert_eq!(b.ty.frames, Frames::pair("a", "b"));
        assert!(
            b.warning
                .unwrap()
                .help
                .as_deref()
                .unwrap()
                .contains("name it Tq_ab'")
        );
        assert!(bind("T_ab'", &moved).unwrap().warning.is_none());
        assert!(bind("T_ab''", &moved).unwrap().warning.is_none());
        assert!(bind("T_ac", &moved).unwrap().warning.is_none());
    }
}
