//! The one table of builtin functions (LANGUAGE.md §8).
//!
//! Each [`Builtin`] carries its book name and aliases, its signature, the
//! book section, a one-line meaning and a runnable example (for `:help` and
//! completion), the static rule for its result's kind and frames (used by
//! the checker with no numbers), and its implementation on values.

mod args;
mod conditioning;
mod decisions;
pub mod notes;
pub mod parts;
pub mod python;
mod table_calculus;
mod table_draw;
mod table_habits;
mod table_list;
mod table_math;
mod table_repr;
pub use table_repr::gimbal_reading;
mod table_rotations;
mod table_scalar;
mod table_screw;
mod table_sym;
mod table_units;

use std::sync::OnceLock;

pub use args::{ArgError, Args, Spans};
pub use table_calculus::constant_derivative;
pub use table_sym::{branch_note, branch_of, eval_symbolic, known_by_kind};

use crate::check::ty::{Frames, Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
pub use crate::values::symbolic::Role;
use crate::values::value::Value;

/// The topic a builtin belongs to, for `:help`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Area {
    /// Rotations: so(3) and SO(3), `[ω]`, exp and log (§3.2).
    Rotations,
    /// Transforms: SE(3) and SE(2), `RpToTrans`, `TransInv` (§3.1, §3.3.1).
    Transforms,
    /// Twists, screw axes, wrenches and adjoints (§3.3.2–§3.4).
    Twists,
    /// Other orientation representations: Euler angles, quaternions
    /// (Appendix B).
    Representations,
    /// Membership tests and projections onto SO(3)/SE(3) (§3.6).
    Tests,
    /// Linear algebra on any matrix: the matrix exp and log, inv, det,
    /// trace, norm, cross, dot…
    LinearAlgebra,
    /// Scalar functions (sin, atan2, sqrt…) and the calculus on symbols
    /// (diff, subs, simplify, solve).
    Scalars,
    /// Mechanisms: Grübler's formula and C-space (chapter 2).
    Mechanisms,
    /// Lists, ranges and pictures (LANGUAGE.md §12).
    Pictures,
}

impl Area {
    /// Every area, in the order `:help` lists them.
    pub const ALL: [Area; 9] = [
        Area::Rotations,
        Area::Transforms,
        Area::Twists,
        Area::Representations,
        Area::Tests,
        Area::LinearAlgebra,
        Area::Scalars,
        Area::Mechanisms,
        Area::Pictures,
    ];
    /// The heading `:help` shows for the area, with its sections.
    pub fn title(self) -> &'static str {
        match self {
            Area::Rotations => "rotations, so(3) and SO(3) (§3.2)",
            Area::Transforms => "transforms, SE(3) and SE(2) (§3.1, §3.3.1)",
            Area::Twists => "twists, screws, wrenches, adjoints (§3.3.2–3.4)",
            Area::Representations => "other orientation representations (Appendix B)",
            Area::Tests => "membership tests and projections (§3.6)",
            Area::LinearAlgebra => "linear algebra",
            Area::Scalars => "scalar functions",
            Area::Mechanisms => "mechanisms (chapter 2)",
            Area::Pictures => "lists, ranges and pictures",
        }
    }
}

/// What an argument must be, checked without numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Param {
    /// A scalar (an angle θ, a length, a pitch h).
    Scalar,
    /// A vector of this length (a twist, screw or wrench is a 6-vector).
    Vec(usize),
    /// Any vector.
    AnyVec,
    /// A rotation: SO(3) or a 3×3 matrix (checked against SO(3) at run time).
    Rot,
    /// A transform: SE(3) or a 4×4 matrix.
    Trans,
    /// A matrix of any size (vectors and scalars included).
    Mat,
    /// A square matrix.
    Square,
    /// Exponential coordinates: a 3-vector or an so(3) matrix.
    Expc3,
    /// Exponential coordinates: a 6-vector or an se(3) matrix.
    Expc6,
    /// A mechanism.
    Mech,
    /// Anything.
    Any,
}

impl Param {
    /// How the parameter reads in a signature.
    pub fn describe(self) -> &'static str {
        match self {
            Param::Scalar => "scalar",
            Param::Vec(3) => "3-vector",
            Param::Vec(4) => "4-vector",
            Param::Vec(6) => "6-vector",
            Param::Vec(_) => "vector",
            Param::AnyVec => "vector",
            Param::Rot => "SO(3)",
            Param::Trans => "SE(3)",
            Param::Mat => "matrix",
            Param::Square => "square matrix",
            Param::Expc3 => "3-vector or so(3)",
            Param::Expc6 => "6-vector or se(3)",
            Param::Mech => "mechanism",
            Param::Any => "value",
        }
    }

    /// The description with its article: `a 3-vector`, `an SO(3)`.
    pub fn describe_a(self) -> String {
        args::article(self.describe())
    }

    /// Whether a value of kind `k` may be passed (unknown kinds may).
    pub fn accepts(self, k: &Kind) -> bool {
        use Kind::*;
        if *k == Unknown {
            return true;
        }
        let shape = k.shape();
        match self {
            Param::Scalar => *k == Scalar,
            Param::Vec(n) => k.is_vector() && k.vec_len().is_none_or(|m| m == n),
            Param::AnyVec => k.is_vector(),
            Param::Rot => {
                *k == SO3
                    || matches!(k, Matrix(r, c) if r.is_none_or(|r| r == 3) && c.is_none_or(|c| c == 3))
            }
            Param::Trans => {
                *k == SE3
                    || matches!(k, Matrix(r, c) if r.is_none_or(|r| r == 4) && c.is_none_or(|c| c == 4))
            }
            Param::Mat => shape.is_some(),
            Param::Square => matches!(shape, Some((r, c)) if r == c || r.is_none() || c.is_none()),
            Param::Expc3 => {
                (k.is_vector() && k.vec_len().is_none_or(|m| m == 3))
                    || *k == So3
                    || matches!(k, Matrix(r, c) if r.is_none_or(|r| r == 3) && c.is_none_or(|c| c == 3))
            }
            Param::Expc6 => {
                (k.is_vector() && k.vec_len().is_none_or(|m| m == 6))
                    || *k == Se3
                    || matches!(k, Matrix(r, c) if r.is_none_or(|r| r == 4) && c.is_none_or(|c| c == 4))
            }
            Param::Mech => *k == Mechanism,
            Param::Any => true,
        }
    }
}

/// How the result's frames follow from the arguments' (LANGUAGE.md §6).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrameRule {
    /// Untagged.
    None,
    /// The frames of argument i.
    Same(usize),
    /// The frames of argument i swapped (an inverse).
    Swap(usize),
    /// {a}, the outer frame of argument i (`log(T_ab)` is tagged {a}).
    Outer(usize),
    /// `exp` of a quantity tagged {a}: a displacement in {a}.
    Disp(usize),
    /// All (non-scalar) arguments share a frame tag, which the result keeps.
    Shared,
}

/// The static typing of a builtin: fixed parameters or a custom rule.
#[derive(Clone, Copy)]
pub enum Typing {
    /// Fixed parameters, a fixed result kind, a frame rule.
    Fixed {
        /// What each argument must be, in order; their count is the arity.
        params: &'static [Param],
        /// The result's kind, whatever the arguments.
        ret: fn() -> Kind,
        /// How the result's frames follow from the arguments'.
        frames: FrameRule,
    },
    /// Overloaded or shape-dependent: a rule of its own. `arity` is
    /// (min, max) arguments.
    Custom {
        /// The fewest and most arguments accepted.
        arity: (usize, usize),
        /// The result's kind and frames from the arguments', or why the
        /// arguments are refused.
        rule: fn(&[Ty]) -> Result<Ty, ArgError>,
    },
}

/// One builtin function.
pub struct Builtin {
    /// The book's name (section 3.6), e.g. `MatrixLog6`.
    pub name: &'static str,
    /// Other names: snake_case form, short aliases (`Ad`, `skew`).
    pub aliases: &'static [&'static str],
    /// The signature as shown in help and arity errors.
    pub signature: &'static str,
    /// Where the book defines it.
    pub section: &'static str,
    /// One line of meaning.
    pub doc: &'static str,
    /// A runnable example.
    pub example: &'static str,
    /// The `:help` topic it is listed under.
    pub area: Area,
    /// How the checker types a call without numbers.
    pub typing: Typing,
    /// The implementation on evaluated arguments.
    pub eval: fn(&mut Args) -> Result<Value, Diagnostic>,
}

impl Builtin {
    /// (min, max) argument count.
    pub fn arity(&self) -> (usize, usize) {
        match self.typing {
            Typing::Fixed { params, .. } => (params.len(), params.len()),
            Typing::Custom { arity, .. } => arity,
        }
    }

    /// Its role in the algebra of symbols (an inverse, the adjoint map),
    /// by its book name.
    pub fn role(&self) -> Role {
        match self.name {
            "inv" | "RotInv" | "TransInv" => Role::Inverse,
            "Adjoint" => Role::Adjoint,
            _ => Role::Plain,
        }
    }

    /// All names this builtin answers to.
    pub fn names(&self) -> impl Iterator<Item = &'static str> {
        std::iter::once(self.name).chain(self.aliases.iter().copied())
    }

    /// The static type of a call with arguments of types `args`.
    pub fn check(&self, args: &[Ty]) -> Result<Ty, ArgError> {
        let (lo, hi) = self.arity();
        if args.len() < lo || args.len() > hi {
            let want = if lo == hi {
                format!("{lo}")
            } else {
                format!("{lo} to {hi}")
            };
            return Err(ArgError {
                arg: None,
                kind: ErrorKind::Arity,
                message: format!(
                    "{} takes {want} argument{}, got {}",
                    self.name,
                    if hi == 1 { "" } else { "s" },
                    args.len()
                ),
            });
        }
        match self.typing {
            Typing::Custom { rule, .. } => rule(args),
            Typing::Fixed {
                params,
                ret,
                frames,
            } => {
                for (i, (p, a)) in params.iter().zip(args).enumerate() {
                    if !p.accepts(&a.kind) {
                        return Err(ArgError::type_of(
                            i,
                            format!(
                                "argument {} of {} must be {}, not {}",
                                i + 1,
                                self.name,
                                p.describe_a(),
                                a.kind.a()
                            ),
                        ));
                    }
                }
                Ok(Ty::new(ret(), apply_frame_rule(frames, args)?))
            }
        }
    }
}

/// The result frames of a builtin under `rule`.
pub fn apply_frame_rule(rule: FrameRule, args: &[Ty]) -> Result<Frames, ArgError> {
    let outer = |i: usize| match args[i].frames.outer() {
        Some(a) => Frames::One(*a),
        None => Frames::None,
    };
    Ok(match rule {
        FrameRule::None => Frames::None,
        FrameRule::Same(i) => args[i].frames,
        FrameRule::Swap(i) => args[i].frames.swapped(),
        FrameRule::Outer(i) => outer(i),
        FrameRule::Disp(i) => match &args[i].frames {
            Frames::One(a) | Frames::Disp(a) => Frames::Disp(*a),
            _ => Frames::None,
        },
        FrameRule::Shared => {
            let mut acc = Frames::None;
            for (i, a) in args.iter().enumerate() {
                if a.kind == Kind::Scalar {
                    continue;
                }
                match (&acc, &a.frames) {
                    (_, Frames::None) => {}
                    (Frames::None, f) => acc = *f,
                    (x, f) if x == f => {}
                    (x, f) => {
                        return Err(ArgError {
                            arg: Some(i),
                            kind: ErrorKind::Frame,
                            message: format!(
                                "arguments are in different frames: {} and {}",
                                show(x),
                                show(f)
                            ),
                        });
                    }
                }
            }
            acc
        }
    })
}

fn show(f: &Frames) -> String {
    crate::check::rules::describe(f)
}

/// Every builtin, in help order.
pub fn table() -> &'static [Builtin] {
    static TABLE: OnceLock<Vec<Builtin>> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut t = Vec::new();
        t.extend(table_rotations::builtins());
        t.extend(table_screw::builtins());
        t.extend(table_repr::builtins());
        t.extend(table_math::builtins());
        t.extend(table_habits::builtins());
        t.extend(table_scalar::builtins());
        t.extend(table_calculus::builtins());
        t.extend(table_units::builtins());
        t.extend(table_list::builtins());
        t.extend(table_draw::builtins());
        t
    })
}

/// The builtin called `name` (book name or alias); the first in table
/// order when two share a name. The index is built once, hashed with
/// foldhash's fast hash (as the environment's names are), which reads a
/// short name in a few words rather than byte by byte.
pub fn lookup(name: &str) -> Option<&'static Builtin> {
    type Index = std::collections::HashMap<&'static str, usize, foldhash::fast::FixedState>;
    static INDEX: OnceLock<Index> = OnceLock::new();
    let index = INDEX.get_or_init(|| {
        let mut index =
            Index::with_capacity_and_hasher(512, foldhash::fast::FixedState::with_seed(0));
        for (i, b) in table().iter().enumerate() {
            for n in b.names() {
                index.entry(n).or_insert(i);
            }
        }
        index
    });
    index.get(name).map(|&i| &table()[i])
}

/// Every name that can be called, for completion and did-you-mean.
pub fn all_names() -> Vec<&'static str> {
    table().iter().flat_map(|b| b.names()).collect()
}
