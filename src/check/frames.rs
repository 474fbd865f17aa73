//! Frame tags: the reference frames a value is expressed in or maps
//! between, as the checker carries them (LANGUAGE.md §6; §3.1's {a}, {b}).

use super::name::Name;

/// One reference frame: a name and how many displacements have moved it
/// (LANGUAGE.md §6). `exp([S_s] θ) * T_sb` is {s}←{b'}: {b} moved once. A
/// name's primes count the same way, so `T_sb'` and `exp([S_s] θ) * T_sb`
/// carry the same frames; a binding may give a moved frame a new name.
///
/// Printing: a frame is written as its name wrote it (`b''` of `T_sb''`),
/// with one more prime once it has moved further; a frame no name wrote is
/// printed with one prime however often it moved ({b'} is "{b} moved").
#[derive(Debug, Clone, Copy, Eq)]
pub struct Frame {
    /// The name without its primes.
    pub name: Name,
    /// The number of displacements applied (primes).
    pub moved: u32,
    /// The primes of the name that wrote it (2 for `b''` of `T_sb''`); 0
    /// when no name with primes wrote it.
    pub written: u32,
}

impl PartialEq for Frame {
    /// Frames are equal when their names and moves are: `T_sb'` names the
    /// frame that `exp([S_s] θ) * T_sb` moved.
    fn eq(&self, other: &Frame) -> bool {
        self.name == other.name && self.moved == other.moved
    }
}

impl std::hash::Hash for Frame {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.name.hash(state);
        self.moved.hash(state);
    }
}

impl Frame {
    /// The frame a name's subscript names: `b''` is {b} moved twice.
    pub fn named(name: &str) -> Frame {
        let base = name.trim_end_matches('\'');
        let moved = (name.len() - base.len()) as u32;
        Frame {
            name: Name::new(base),
            moved,
            written: moved,
        }
    }
    /// {name} moved `moved` times.
    pub fn at(name: impl Into<Name>, moved: u32) -> Frame {
        Frame {
            name: name.into(),
            moved,
            written: 0,
        }
    }
    /// The frame after one more displacement.
    pub fn moved(&self) -> Frame {
        self.lifted(1)
    }
    /// The frame after `k` more displacements.
    pub fn lifted(&self, k: u32) -> Frame {
        Frame {
            moved: self.moved.saturating_add(k),
            ..*self
        }
    }
    /// The frame one displacement earlier (`moved` must be positive).
    pub fn lowered(&self) -> Frame {
        Frame {
            moved: self.moved.saturating_sub(1),
            ..*self
        }
    }
    /// True when this frame has been displaced (printed with a prime).
    pub fn is_moved(&self) -> bool {
        self.moved > 0
    }
}

/// The frame tag of a value (LANGUAGE.md §6).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Frames {
    /// Untagged: matches anything.
    #[default]
    None,
    /// A vector quantity expressed in {a}: point, twist, wrench, `[ω]`…
    One(Frame),
    /// {a}←{b}: R_ab, T_ab, Ad(T_ab) map {b} coordinates to {a}.
    Pair(Frame, Frame),
    /// A displacement expressed in {a}: `exp([S_a] θ)`. Premultiplies
    /// X_a? (moving its inner frame) or postmultiplies X_?a; in the frame
    /// algebra ([`super::algebra`]) it is the map {a}←{a'}.
    Disp(Frame),
    /// The transpose of a map {a}←{b} that is not a rotation (`T_ab.T`):
    /// not a map between frames at all, since the transpose is the inverse
    /// only for rotations (Prop. 3.1). Using it as an operator is an error.
    Transposed(Frame, Frame),
}

impl Frames {
    /// {a}←{b}, the tag of T_ab.
    pub fn pair(a: &str, b: &str) -> Frames {
        Frames::Pair(Frame::named(a), Frame::named(b))
    }
    /// In {a}, the tag of a twist V_a.
    pub fn one(a: &str) -> Frames {
        Frames::One(Frame::named(a))
    }
    /// True for an untagged value.
    pub fn is_none(&self) -> bool {
        matches!(self, Frames::None)
    }
    /// The frame {a} of a displacement in {a}: `Disp(a)`, or a map
    /// {a}←{a''} from a frame to a copy of itself moved more than once
    /// (`exp([S_a] t1) * exp([S_a] t2)`), printed alike.
    pub fn displacement_frame(&self) -> Option<&Frame> {
        match self {
            Frames::Disp(a) => Some(a),
            Frames::Pair(a, b) if a.name == b.name && b.moved > a.moved => Some(a),
            _ => None,
        }
    }
    /// The frames as the JSON list: `[]`, `["a"]`, `["a","b"]`.
    pub fn to_list(&self) -> Vec<String> {
        if let Some(a) = self.displacement_frame() {
            return vec![a.to_string()];
        }
        match self {
            Frames::None => vec![],
            Frames::One(a) | Frames::Disp(a) => vec![a.to_string()],
            Frames::Pair(a, b) => vec![a.to_string(), b.to_string()],
            Frames::Transposed(..) => vec![],
        }
    }
    /// The outer frame: {a} of X_ab, v_a, or the displacement's frame.
    pub fn outer(&self) -> Option<&Frame> {
        match self {
            Frames::None | Frames::Transposed(..) => None,
            Frames::One(a) | Frames::Disp(a) | Frames::Pair(a, _) => Some(a),
        }
    }
    /// `inv(X_ab)` = X_ba; a displacement's inverse is a displacement.
    pub fn swapped(&self) -> Frames {
        match self {
            Frames::Pair(a, b) => Frames::Pair(*b, *a),
            Frames::Transposed(a, b) => Frames::Transposed(*b, *a),
            other => *other,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_frame_prints_as_its_name_wrote_it() {
        let b2 = Frame::named("b''");
        assert_eq!((b2.name.as_str(), b2.moved, b2.written), ("b", 2, 2));
        assert_eq!(b2.to_string(), "b''");
        // Moved further: one more prime; a frame no name wrote: one prime.
        assert_eq!(b2.moved().to_string(), "b'''");
        assert_eq!(Frame::at("b", 2).to_string(), "b'");
        assert_eq!(b2.lowered().to_string(), "b'");
        assert_eq!(Frame::named("world").to_string(), "world");
        // Equal by name and moves, whatever wrote them.
        assert_eq!(b2, Frame::at("b", 2));
        assert_ne!(b2, Frame::at("b", 1));
        let f = Frames::Pair(Frame::named("a"), b2);
        let g = f;
        assert_eq!(f.swapped().to_string(), "{b''}←{a}");
        assert_eq!(g.to_list(), vec!["a".to_string(), "b''".to_string()]);
    }
}
