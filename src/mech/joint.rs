//! Joints (§2.2.1, Table 2.1) and the space a mechanism moves in (§2.2.2).

use std::fmt;

/// The space the links of a mechanism move in, which fixes `m`, the number
/// of degrees of freedom of one rigid body (Proposition 2.1, Grübler's
/// formula (2.4)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Space {
    /// Links move in a common plane: a planar rigid body has `m = 3`
    /// freedoms `(x, y, θ)` (§2.1).
    Planar,
    /// Links move in three-dimensional space: a spatial rigid body has
    /// `m = 6` freedoms (§2.1).
    Spatial,
    /// All joint axes pass through one common point, so every link only
    /// rotates about that point: `m = 3` (the spherical four-bar of
    /// Exercise 13, §2.7).
    Spherical,
}

impl Space {
    /// Reads `planar`, `spatial` or `spherical` (any case, surrounding
    /// blanks ignored); anything else is `None`.
    pub fn parse(word: &str) -> Option<Space> {
        match word.trim().to_ascii_lowercase().as_str() {
            "planar" => Some(Space::Planar),
            "spatial" => Some(Space::Spatial),
            "spherical" => Some(Space::Spherical),
            _ => None,
        }
    }

    /// `m`, the degrees of freedom of one rigid body in this space
    /// (Proposition 2.1): 3 planar, 6 spatial, 3 spherical.
    pub fn m(self) -> i64 {
        match self {
            Space::Planar | Space::Spherical => 3,
            Space::Spatial => 6,
        }
    }

    /// The word as written in a `mech < … >` spec.
    pub fn name(self) -> &'static str {
        match self {
            Space::Planar => "planar",
            Space::Spatial => "spatial",
            Space::Spherical => "spherical",
        }
    }
}

impl fmt::Display for Space {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One of the basic joints of Figure 2.3 and Table 2.1 (§2.2.1), named by
/// the book's letter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum JointType {
    /// Revolute (hinge) joint: rotation about the joint axis, `f = 1`.
    R,
    /// Prismatic (sliding, linear) joint: translation along the axis, `f = 1`.
    P,
    /// Screw (helical) joint: rotation and translation coupled about a screw
    /// axis, `f = 1`; not a planar joint (Table 2.1: N/A).
    H,
    /// Cylindrical joint: independent rotation and translation about one
    /// axis, `f = 2`; not a planar joint.
    C,
    /// Universal joint: two revolute joints with orthogonal axes, `f = 2`;
    /// not a planar joint.
    U,
    /// Spherical (ball-and-socket) joint, `f = 3`; not a planar joint.
    S,
    /// A point contact that rolls without slipping (Exercise 2.17(c) "a
    /// point contact with no slip", 2.19(c)–(d)): `f = 3` between spatial
    /// bodies (the rotations about the contact point), `f = 1` between
    /// planar ones (the rolling angle). Written `rolling`.
    Rolling,
    /// A frictionless point contact that may slide (Exercise 2.18(b) "a
    /// frictionless point contact", 2.19(a) "sliding point contact"):
    /// `f = 5` between spatial bodies (two slides, three rotations),
    /// `f = 2` between planar ones (a slide and a rotation). Written
    /// `sliding`.
    Sliding,
}

impl JointType {
    /// The six joints of Table 2.1, in the table's order.
    pub const ALL: [JointType; 6] = [
        JointType::R,
        JointType::P,
        JointType::H,
        JointType::C,
        JointType::U,
        JointType::S,
    ];

    /// The joint named by the book's letter `R P H C U S` (lower case is
    /// accepted too); `None` for any other character.
    pub fn from_letter(c: char) -> Option<JointType> {
        match c.to_ascii_uppercase() {
            'R' => Some(JointType::R),
            'P' => Some(JointType::P),
            'H' => Some(JointType::H),
            'C' => Some(JointType::C),
            'U' => Some(JointType::U),
            'S' => Some(JointType::S),
            _ => None,
        }
    }

    /// The contact joint named by `word` (Exercises 2.17–2.19): `rolling`
    /// (also `noslip`, a point contact with no slip) or `sliding` (also
    /// `frictionless`, a frictionless point contact); any case.
    pub fn contact(word: &str) -> Option<JointType> {
        match word.to_ascii_lowercase().as_str() {
            "rolling" | "noslip" => Some(JointType::Rolling),
            "sliding" | "frictionless" => Some(JointType::Sliding),
            _ => None,
        }
    }

    /// How the joint is written: its letter, or the contact's name.
    pub fn symbol(self) -> &'static str {
        match self {
            JointType::R => "R",
            JointType::P => "P",
            JointType::H => "H",
            JointType::C => "C",
            JointType::U => "U",
            JointType::S => "S",
            JointType::Rolling => "rolling",
            JointType::Sliding => "sliding",
        }
    }

    /// The book's letter for the joint (a contact's initial, lower case).
    pub fn letter(self) -> char {
        match self {
            JointType::R => 'R',
            JointType::P => 'P',
            JointType::H => 'H',
            JointType::C => 'C',
            JointType::U => 'U',
            JointType::S => 'S',
            JointType::Rolling => 'r',
            JointType::Sliding => 's',
        }
    }

    /// The joint's name in Table 2.1 (`revolute`, `prismatic`, `screw`,
    /// `cylindrical`, `universal`, `spherical`).
    pub fn name(self) -> &'static str {
        match self {
            JointType::R => "revolute",
            JointType::P => "prismatic",
            JointType::H => "screw",
            JointType::C => "cylindrical",
            JointType::U => "universal",
            JointType::S => "spherical",
            JointType::Rolling => "rolling point contact",
            JointType::Sliding => "sliding point contact",
        }
    }

    /// `f`, the degrees of freedom the joint provides (Table 2.1):
    /// R, P, H 1; C, U 2; S 3; between spatial bodies a rolling contact 3
    /// and a sliding one 5 ([`JointType::freedoms_in`] for planar ones).
    pub fn freedoms(self) -> i64 {
        match self {
            JointType::R | JointType::P | JointType::H => 1,
            JointType::C | JointType::U => 2,
            JointType::S | JointType::Rolling => 3,
            JointType::Sliding => 5,
        }
    }

    /// `f` in a mechanism of `space`: a planar rolling contact 1, a planar
    /// sliding contact 2 (Exercise 2.18); the rest as [`JointType::freedoms`].
    pub fn freedoms_in(self, space: Space) -> i64 {
        match (self, space) {
            (JointType::Rolling, Space::Planar) => 1,
            (JointType::Sliding, Space::Planar) => 2,
            _ => self.freedoms(),
        }
    }

    /// Whether the joint exists in a mechanism of this space. Table 2.1
    /// gives only R and P between planar bodies (H C U S are N/A); in a
    /// spherical mechanism every joint is a rotation about the common
    /// point, so only R is allowed.
    pub fn allowed_in(self, space: Space) -> bool {
        match space {
            Space::Spatial => true,
            Space::Planar => matches!(
                self,
                JointType::R | JointType::P | JointType::Rolling | JointType::Sliding
            ),
            Space::Spherical => self == JointType::R,
        }
    }

    /// `c`, the constraints the joint places between two rigid bodies of
    /// the space (Table 2.1), `c = m − f`; `None` where the table says N/A.
    pub fn constraints(self, space: Space) -> Option<i64> {
        self.allowed_in(space)
            .then(|| space.m() - self.freedoms_in(space))
    }

    /// The joint's own C-space as factors (§2.3.1): R a circle `S^1`; P and
    /// H a line `R^1`; C `S^1 × R^1`; U `T^2`; S the rotations `SO(3)`.
    pub(crate) fn factors(self) -> &'static [Factor] {
        match self {
            JointType::R => &[Factor::Circle],
            JointType::P | JointType::H => &[Factor::Line],
            JointType::C => &[Factor::Circle, Factor::Line],
            JointType::U => &[Factor::Circle, Factor::Circle],
            JointType::S => &[Factor::Rotations],
            // A contact closes a loop: no C-space factor of its own.
            JointType::Rolling | JointType::Sliding => &[],
        }
    }
}

impl fmt::Display for JointType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.symbol())
    }
}

/// One factor of a C-space written as a product (§2.3.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Factor {
    /// `S^1`; several collect into a torus `T^n`.
    Circle,
    /// `R^1`; several collect into `R^n`.
    Line,
    /// `SO(3)`, the rotations of a spherical joint (Chapter 3).
    Rotations,
}

/// A joint between two links (§2.2.1: every joint connects exactly two
/// links). Usually one basic joint; several letters make a compound joint
/// such as the RP (revolute-prismatic) pair of Examples 2.1 and 2.3, which
/// counts as ONE joint whose `f` is the sum of its parts.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Joint {
    /// The basic joints it is made of, in the order written.
    pub kinds: Vec<JointType>,
}

impl Joint {
    /// A joint of one basic type.
    pub fn single(kind: JointType) -> Joint {
        Joint { kinds: vec![kind] }
    }

    /// `f_i`, the freedoms the joint provides: the sum over its parts
    /// (Table 2.1; an RP pair has `f = 2`, Example 2.1(ii)).
    pub fn freedoms(&self) -> i64 {
        self.kinds.iter().map(|k| k.freedoms()).sum()
    }

    /// `f_i` in a mechanism of `space` (a contact's freedoms depend on it).
    pub fn freedoms_in(&self, space: Space) -> i64 {
        self.kinds.iter().map(|k| k.freedoms_in(space)).sum()
    }

    /// Whether the joint is a point contact (`rolling`, `sliding`).
    pub fn is_contact(&self) -> bool {
        self.kinds
            .iter()
            .any(|k| matches!(k, JointType::Rolling | JointType::Sliding))
    }

    /// `c_i = m − f_i` (Proposition 2.1), or `None` if a part does not exist
    /// in this space or the joint would provide more than `m` freedoms.
    pub fn constraints(&self, space: Space) -> Option<i64> {
        let ok = self.kinds.iter().all(|k| k.allowed_in(space));
        let c = space.m() - self.freedoms_in(space);
        (ok && c >= 0).then_some(c)
    }

    /// The letters as written, e.g. `RP` (a contact by its name).
    pub fn letters(&self) -> String {
        self.kinds.iter().map(|k| k.symbol()).collect()
    }
}

impl fmt::Display for Joint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.letters())
    }
}
