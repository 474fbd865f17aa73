//! Static types and frame tags: what the checker knows about an expression
//! without its numbers (LANGUAGE.md §5–6).

use std::fmt;

pub use super::frames::{Frame, Frames};
pub use super::name::Name;

/// What kind of mathematical object a value is (LANGUAGE.md §5). `None`
/// dimensions are unknown until evaluation (e.g. `zeros(n, m)`). Compared
/// and hashed as written out in `check::kind_eq` (inlined: kinds compare at
/// every node).
#[derive(Debug, Clone, Copy, Eq)]
pub enum Kind {
    /// A real number: an angle θ, a length, a pitch h.
    Scalar,
    /// `true` or `false`: a literal, or the verdict of a comparison.
    Bool,
    /// A column n-vector.
    Vector(Option<usize>),
    /// An r×c matrix that is not (known to be) a group element.
    Matrix(Option<usize>, Option<usize>),
    /// A rotation matrix R ∈ SO(3) (§3.2.1).
    SO3,
    /// A homogeneous transform T ∈ SE(3) (§3.3.1).
    SE3,
    /// A skew-symmetric `[ω]` ∈ so(3) (§3.2.2).
    So3,
    /// A twist matrix `[V]` ∈ se(3) (§3.3.2).
    Se3,
    /// A planar rotation R ∈ SO(2) (Definition 3.2).
    SO2,
    /// A planar transform T ∈ SE(2) (Definition 3.5).
    SE2,
    /// A 2×2 skew-symmetric matrix ∈ so(2), the algebra of SO(2).
    So2,
    /// A 3×3 planar twist matrix ∈ se(2), the algebra of SE(2).
    Se2,
    /// A twist V = (ω, v) (§3.3.2).
    Twist,
    /// A screw axis S: a unit twist (§3.3.2.2).
    Screw,
    /// A wrench F = (m, f) (§3.4).
    Wrench,
    /// The 6×6 adjoint `[Ad_T]` (Definition 3.6).
    Adjoint {
        /// `[Ad_T]ᵀ`, which acts on wrenches (Prop. 3.17).
        transposed: bool,
    },
    /// A mechanism (chapter 2).
    Mechanism,
    /// A tuple of values of these kinds (interned: [`Kind::tuple`]).
    Tuple(&'static [Kind]),
    /// A user function.
    Function,
    /// A list of values of one kind (LANGUAGE.md §12): `0:4`,
    /// `[f(k) for k in 0:4]`; `Unknown` elements when they differ.
    /// The element kind is interned ([`Kind::list`]); then the number of
    /// items when known without numbers (`0:4` has 5: [`Kind::list_len`]),
    /// so that `check` refuses `(0:4)[9]` as `run` does. Not part of the
    /// kind: lists of any length compare equal (`check::kind_eq`).
    List(&'static Kind, Option<u32>),
    /// A picture made by `draw` (§12).
    Picture,
    /// A string, `"name.svg"`: file names for `save` and picture titles.
    Text,
    /// Not known statically (e.g. the element of a tuple of unknown shape).
    Unknown,
}

/// Every tuple kind made so far (a list's element kind is a tuple of one),
/// stored once for the whole process so that [`Kind`] is `Copy`.
static KINDS: std::sync::LazyLock<
    std::sync::Mutex<std::collections::HashSet<&'static [Kind], foldhash::fast::FixedState>>,
> = std::sync::LazyLock::new(Default::default);

/// The interned copy of `kinds` (the same kinds, the same slice).
fn intern(kinds: Vec<Kind>) -> &'static [Kind] {
    // The set is only added to, so it is whole even after a panic.
    let mut set = KINDS.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(&k) = set.get(kinds.as_slice()) {
        return k;
    }
    let k: &'static [Kind] = Box::leak(kinds.into_boxed_slice());
    set.insert(k);
    k
}

impl Kind {
    /// The kind of a tuple whose parts have these kinds.
    pub fn tuple(kinds: Vec<Kind>) -> Kind {
        Kind::Tuple(intern(kinds))
    }
    /// The kind of a list whose elements have kind `elem` (LANGUAGE.md §12).
    pub fn list(elem: Kind) -> Kind {
        Kind::List(&intern(vec![elem])[0], None)
    }
    /// The type name of the JSON schema (LANGUAGE.md §1).
    pub fn json_name(&self) -> &'static str {
        match self {
            Kind::Scalar => "scalar",
            Kind::Bool => "bool",
            Kind::Vector(_) => "vector",
            Kind::Matrix(..) | Kind::Unknown | Kind::Function => "matrix",
            Kind::SO3 => "SO3",
            Kind::SE3 => "SE3",
            Kind::So3 => "so3",
            Kind::Se3 => "se3",
            Kind::SO2 => "SO2",
            Kind::SE2 => "SE2",
            Kind::So2 => "so2",
            Kind::Se2 => "se2",
            Kind::Twist => "twist",
            Kind::Screw => "screw",
            Kind::Wrench => "wrench",
            Kind::Adjoint { .. } => "adjoint",
            Kind::Mechanism => "mechanism",
            Kind::Tuple(_) => "tuple",
            Kind::List(..) => "list",
            Kind::Picture => "picture",
            Kind::Text => "string",
        }
    }

    /// Rows and columns when the kind is matrix-shaped and known.
    pub fn shape(&self) -> Option<(Option<usize>, Option<usize>)> {
        Some(match self {
            Kind::Scalar => (Some(1), Some(1)),
            Kind::Vector(n) => (*n, Some(1)),
            Kind::Matrix(r, c) => (*r, *c),
            Kind::SO3 | Kind::So3 | Kind::SE2 | Kind::Se2 => (Some(3), Some(3)),
            Kind::SE3 | Kind::Se3 => (Some(4), Some(4)),
            Kind::SO2 | Kind::So2 => (Some(2), Some(2)),
            Kind::Twist | Kind::Screw | Kind::Wrench => (Some(6), Some(1)),
            Kind::Adjoint { .. } => (Some(6), Some(6)),
            Kind::Unknown => (None, None),
            _ => return None,
        })
    }

    /// True for column vectors of any flavour (plain, twist, screw, wrench).
    pub fn is_vector(&self) -> bool {
        matches!(
            self,
            Kind::Vector(_) | Kind::Twist | Kind::Screw | Kind::Wrench
        )
    }

    /// Length of a vector kind, if known.
    pub fn vec_len(&self) -> Option<usize> {
        match self {
            Kind::Vector(n) => *n,
            Kind::Twist | Kind::Screw | Kind::Wrench => Some(6),
            _ => None,
        }
    }

    /// True for square matrix-like kinds that act on vectors by `*`
    /// (operators: rotations, transforms, adjoints, plain square matrices).
    pub fn is_operator(&self) -> bool {
        matches!(
            self,
            Kind::SO3
                | Kind::SE3
                | Kind::SO2
                | Kind::SE2
                | Kind::Adjoint { .. }
                | Kind::So3
                | Kind::Se3
                | Kind::So2
                | Kind::Se2
                | Kind::Matrix(..)
                | Kind::Unknown
        )
    }

    /// True for group elements (SO(n), SE(n)).
    pub fn is_group(&self) -> bool {
        matches!(self, Kind::SO3 | Kind::SE3 | Kind::SO2 | Kind::SE2)
    }

    /// True for Lie-algebra matrices (so(n), se(n)).
    pub fn is_algebra(&self) -> bool {
        matches!(self, Kind::So3 | Kind::Se3 | Kind::So2 | Kind::Se2)
    }

    /// What multiplying by a scalar does to a kind: group elements stop
    /// being group elements, a screw axis times θ is a twist (exponential
    /// coordinates, §3.3.3.2).
    pub fn scaled(&self) -> Kind {
        match self {
            Kind::SO3 | Kind::SE2 => Kind::Matrix(Some(3), Some(3)),
            Kind::SE3 => Kind::Matrix(Some(4), Some(4)),
            Kind::SO2 => Kind::Matrix(Some(2), Some(2)),
            Kind::Screw => Kind::Twist,
            other => *other,
        }
    }

    /// True when the kind may stand where a number is needed.
    pub fn maybe_scalar(&self) -> bool {
        matches!(self, Kind::Scalar | Kind::Unknown)
    }
}

impl Kind {
    /// The kind with its article: `a 3-vector`, `an SO(3)`, `an adjoint`.
    pub fn a(&self) -> String {
        let name = self.to_string();
        let vowel = name.starts_with(['a', 'e', 'i', 'o', 'u', 'S', 's'])
            && !name.starts_with("screw")
            && !name.starts_with("scalar")
            && !name.starts_with("string");
        // (an n-vector, an n×3 matrix: a size checking does not know)
        let vowel = vowel
            || ["8-", "11-", "18-", "n-", "n×"]
                .iter()
                .any(|p| name.starts_with(p));
        format!("{} {name}", if vowel { "an" } else { "a" })
    }
}

impl fmt::Display for Kind {
    /// The book's names: `SE(3)`, `so(3)`, `twist`, `3-vector`, `4×4 matrix`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let dim = |d: &Option<usize>| d.map_or("n".to_string(), |n| n.to_string());
        match self {
            Kind::Scalar => write!(f, "scalar"),
            Kind::Bool => write!(f, "bool"),
            Kind::Vector(n) => write!(f, "{}-vector", dim(n)),
            Kind::Matrix(r, c) => write!(f, "{}×{} matrix", dim(r), dim(c)),
            Kind::SO3 => write!(f, "SO(3)"),
            Kind::SE3 => write!(f, "SE(3)"),
            Kind::So3 => write!(f, "so(3)"),
            Kind::Se3 => write!(f, "se(3)"),
            Kind::SO2 => write!(f, "SO(2)"),
            Kind::SE2 => write!(f, "SE(2)"),
            Kind::So2 => write!(f, "so(2)"),
            Kind::Se2 => write!(f, "se(2)"),
            Kind::Twist => write!(f, "twist"),
            Kind::Screw => write!(f, "screw axis"),
            Kind::Wrench => write!(f, "wrench"),
            Kind::Adjoint { transposed: false } => write!(f, "adjoint"),
            Kind::Adjoint { transposed: true } => write!(f, "adjoint transpose"),
            Kind::Mechanism => write!(f, "mechanism"),
            Kind::Tuple(ks) => {
                write!(f, "(")?;
                for (i, k) in ks.iter().enumerate() {
                    if i > 0 {
                        write!(f, ", ")?;
                    }
                    write!(f, "{k}")?;
                }
                write!(f, ")")
            }
            Kind::Function => write!(f, "function"),
            Kind::List(k, _) => match **k {
                Kind::Unknown => write!(f, "list"),
                Kind::Scalar => write!(f, "list of numbers"),
                Kind::Screw => write!(f, "list of screw axes"),
                Kind::List(..) => write!(f, "list of lists"),
                Kind::Vector(_)
                | Kind::Matrix(..)
                | Kind::Twist
                | Kind::Wrench
                | Kind::Picture
                | Kind::Tuple(_) => {
                    write!(f, "list of {k}s")
                }
                _ => write!(f, "list of {k}"),
            },
            Kind::Picture => write!(f, "picture"),
            Kind::Text => write!(f, "string"),
            Kind::Unknown => write!(f, "value"),
        }
    }
}

/// What a frame tag says of a value's parts: it needs the kinds, so it
/// lives with them ([`super::frames`] knows no kinds).
impl Frames {
    /// The frames of one part of a tuple tagged `self`: none for a scalar
    /// (θ of `AxisAng3`), the outer frame for a vector part of a
    /// pair-tagged tuple (p of `TransToRp(T_ab)` is in {a}), else the same
    /// (ω̂ of coordinates in {s} is in {s}; R of T_ab is {a}←{b}).
    pub fn part(&self, k: &Kind) -> Frames {
        match (self, k) {
            (_, Kind::Scalar) => Frames::None,
            (Frames::Pair(a, _), k) if k.is_vector() => Frames::One(*a),
            (f, _) => *f,
        }
    }
}

/// A Lie algebra (§3.2.3, §3.3.2): the content a product g·X of a group
/// element and an element X of its algebra remembers ([`Ty::algebra`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Algebra {
    /// so(3): skew-symmetric `[ω]` (§3.2.3.1).
    So3,
    /// se(3): twist matrices `[V]` (§3.3.2).
    Se3,
    /// so(2): the planar `[ω]`.
    So2,
    /// se(2): the planar `[V]`.
    Se2,
}

impl Algebra {
    /// The algebra a kind is an element of: so(3) of [`Kind::So3`].
    pub fn of(kind: &Kind) -> Option<Algebra> {
        Some(match kind {
            Kind::So3 => Algebra::So3,
            Kind::Se3 => Algebra::Se3,
            Kind::So2 => Algebra::So2,
            Kind::Se2 => Algebra::Se2,
            _ => return None,
        })
    }
    /// The kind of the algebra's elements.
    pub fn kind(self) -> Kind {
        match self {
            Algebra::So3 => Kind::So3,
            Algebra::Se3 => Kind::Se3,
            Algebra::So2 => Kind::So2,
            Algebra::Se2 => Kind::Se2,
        }
    }
    /// The group whose Lie algebra this is: SO(3) for so(3).
    pub fn group(self) -> Kind {
        match self {
            Algebra::So3 => Kind::SO3,
            Algebra::Se3 => Kind::SE3,
            Algebra::So2 => Kind::SO2,
            Algebra::Se2 => Kind::SE2,
        }
    }
}

/// How many displacements an untagged product stands for ([`Ty::moves`]),
/// in four bytes with its `None` (a type moves through every node of every
/// statement, issue 40): kept as k + 1, saturating, as the count itself
/// saturates in [`super::algebra`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Moves(std::num::NonZeroU32);

impl Moves {
    /// `k` displacements (at most `u32::MAX - 1`: a product longer than
    /// that is counted as that long).
    pub fn new(k: u32) -> Moves {
        Moves(std::num::NonZeroU32::MIN.saturating_add(k))
    }
    /// The number of displacements.
    pub fn get(self) -> u32 {
        self.0.get() - 1
    }
}

/// The checker's knowledge of an expression: kind and frames.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Ty {
    /// What it is (SO(3), a twist, a scalar…).
    pub kind: Kind,
    /// Its frame tag: {a}←{b}, in {a}, or none.
    pub frames: Frames,
    /// For a plain matrix that is a group element times an element of its
    /// Lie algebra, g·X or X·g (`T_sb [V_b]` = Ṫ_sb, (3.75)), the algebra:
    /// conjugation g·X·g⁻¹ lands back in it when the frames close on one
    /// (`[V_s] = T [V_b] T⁻¹`, (3.77); Prop. 3.5). Known without numbers only.
    pub algebra: Option<Algebra>,
    /// For an untagged operator that is a product of untagged operators,
    /// how many displacements it stands for when not the usual one (an
    /// untagged rotation or transform is one displacement of the frame it
    /// meets, an untagged [`Kind::So3`]/[`Kind::Se3`] matrix none), so that
    /// `A * B * T_sb` moves {b} alike under every bracketing.
    pub moves: Option<Moves>,
    /// For a vector: a free vector (ω, v, f, m, an axis; [`super::role`]),
    /// which only rotates: a transform moves points, so `T * ω` is refused.
    pub free: bool,
    /// For a tuple whose parts have types of their own (the literal
    /// `(T_ab, T_cb)`, whose one tag is none): each part's type, so that
    /// `t[1]` and `(A, B) = t` keep part 1's frames ([`super::parts`]).
    /// None when the tuple's tag says its parts' ([`Frames::part`]).
    pub parts: Option<super::part_list::Parts>,
}

impl Ty {
    /// A value of `kind` tagged `frames`, nothing more known.
    pub fn new(kind: Kind, frames: Frames) -> Ty {
        Ty {
            kind,
            frames,
            algebra: None,
            moves: None,
            free: false,
            parts: None,
        }
    }
    /// An untagged value of `kind`.
    pub fn plain(kind: Kind) -> Ty {
        Ty::new(kind, Frames::None)
    }
    /// An untagged scalar.
    pub fn scalar() -> Ty {
        Ty::plain(Kind::Scalar)
    }
    /// The type of a multiple `c x` or `-x` ([`Kind::scaled`]): the same
    /// frames, and a g·X stays one.
    pub fn scaled(&self) -> Ty {
        Ty {
            kind: self.kind.scaled(),
            frames: self.frames,
            algebra: self.algebra,
            moves: self.moves,
            free: self.free,
            parts: self.parts,
        }
    }
}

impl fmt::Display for Ty {
    /// `SE(3) {a}←{c}`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.frames.is_none() {
            write!(f, "{}", self.kind)
        } else {
            write!(f, "{} {}", self.kind, self.frames)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tuple_and_list_kinds_are_stored_once() {
        let t = Kind::tuple(vec![Kind::SO3, Kind::Vector(Some(3))]);
        let u = Kind::tuple(vec![Kind::SO3, Kind::Vector(Some(3))]);
        let (Kind::Tuple(a), Kind::Tuple(b)) = (t, u) else {
            panic!("not tuples")
        };
        assert!(std::ptr::eq(a, b));
        assert_eq!(t.to_string(), "(SO(3), 3-vector)");
        assert_ne!(t, Kind::tuple(vec![Kind::SO3]));
        assert_eq!(Kind::list(Kind::Screw).to_string(), "list of screw axes");
        assert_eq!(Kind::list(Kind::Scalar), Kind::list(Kind::Scalar));
    }
}
