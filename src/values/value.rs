//! Runtime values: numbers and matrices with their kind, tuples, mechanisms,
//! user functions and symbolic expressions over `given` names.

use std::rc::Rc;

use super::exact::Exact;
use super::num::Num;
use super::symbolic::Tree;
use crate::check::ty::{Kind, Ty};
use crate::lie::{LieGroup, SE2, SE3, SO2, SO3};
use crate::mech::Mechanism;
use crate::syntax::ast::Expr;

/// A symbolic expression over `given` names, with values as constants.
pub type Sym = Tree<Value>;

/// A user function `f(x, y) = body`.
#[derive(Debug, Clone, PartialEq)]
pub struct UserFn {
    /// The name it was defined under, `f`.
    pub name: String,
    /// The parameter names in order, bound to the arguments at each call.
    pub params: Vec<String>,
    /// The right-hand side, evaluated at each call.
    pub body: Expr,
    /// The source text it was defined in ([`crate::eval::env::Env::source`]):
    /// the spans of `body` point into that text only.
    pub source: u64,
}

/// A value. Numbers of every shape are a [`Num`] (small shapes inline)
/// plus a [`Kind`] that says what the book calls it (a scalar is 1×1, a
/// vector n×1).
#[derive(Debug, Clone)]
pub enum Value {
    /// A number, vector or matrix: a scalar, ω, V, R ∈ SO(3), T ∈ SE(3)….
    Num {
        /// What the book calls it (which group or space it belongs to).
        kind: Kind,
        /// The numbers, in a fixed-size shape when small.
        m: Num,
        /// The exact form of the numbers, while they have one (§3, §7).
        exact: Exact,
    },
    /// `true` or `false`: a literal, or the verdict of a comparison.
    Bool(bool),
    /// Several values together, `(w, theta)` of `axis_ang3` (§3.2.3),
    /// read by a destructuring assignment.
    Tuple(Vec<Value>),
    /// A mechanism literal `mech < ... >` (chapter 2), for Grübler's
    /// formula (2.4) and its C-space.
    Mech(Rc<Mechanism>),
    /// An expression over `given` symbols (LANGUAGE.md §7).
    Sym(Sym),
    /// A scalar, vector or matrix whose entries are symbolic scalars in
    /// canonical form (`Rotz(theta)`), with its kind (LANGUAGE.md §7), and
    /// how it was made, replayed with numbers once its symbols have them
    /// ([`super::recipe`]; None for a leaf: a `given` symbol, a derivative).
    Formula {
        /// What the book calls it, as for [`Value::Num`].
        kind: Kind,
        /// The entries as symbolic scalars.
        m: crate::sym::Mat,
        /// How it was made, to replay with numbers.
        how: Option<Rc<super::recipe::Recipe>>,
    },
    /// A list (LANGUAGE.md §12): a range `0:4` or a comprehension.
    List(Rc<Vec<Value>>),
    /// A string literal, `"name.svg"`.
    Str(Rc<str>),
    /// A picture made by `draw` (§12).
    Picture(Rc<Picture>),
}

impl PartialEq for Value {
    /// Structural equality (numbers exactly, symbolic values by their
    /// trees and canonical forms; mechanisms and functions by identity).
    fn eq(&self, other: &Value) -> bool {
        match (self, other) {
            (Value::Num { kind: a, m: x, .. }, Value::Num { kind: b, m: y, .. }) => {
                a == b && x == y
            }
            (Value::Bool(a), Value::Bool(b)) => a == b,
            (Value::Tuple(a), Value::Tuple(b)) => a == b,
            (Value::Mech(a), Value::Mech(b)) => Rc::ptr_eq(a, b),
            (Value::Sym(a), Value::Sym(b)) => a == b,
            // (how a formula was made is no part of what it is)
            (Value::Formula { kind: a, m: x, .. }, Value::Formula { kind: b, m: y, .. }) => {
                a == b && x == y
            }
            (Value::List(a), Value::List(b)) => a == b,
            (Value::Str(a), Value::Str(b)) => a == b,
            (Value::Picture(a), Value::Picture(b)) => Rc::ptr_eq(a, b),
            _ => false,
        }
    }
}

impl Value {
    /// A plain real number (kind scalar, no exact form).
    pub fn scalar(x: f64) -> Value {
        Value::Num {
            kind: Kind::Scalar,
            m: Num::Scalar(x),
            exact: Exact::Float,
        }
    }
    /// A value of `kind` from any nalgebra matrix (held inline when its
    /// shape has a fixed-size [`Num`] variant).
    pub fn num<R: nalgebra::Dim, C: nalgebra::Dim, S>(
        kind: Kind,
        m: &nalgebra::Matrix<f64, R, C, S>,
    ) -> Value
    where
        S: nalgebra::RawStorage<f64, R, C>,
    {
        let (r, c) = m.shape();
        let m = if r * c <= 36 {
            let mut buf = [0.0; 36];
            for (b, x) in buf.iter_mut().zip(m.iter()) {
                *b = *x;
            }
            Num::from_slice(r, c, &buf[..r * c])
        } else {
            Num::Dyn(nalgebra::DMatrix::from_iterator(r, c, m.iter().copied()))
        };
        Value::Num {
            kind,
            m,
            exact: Exact::Float,
        }
    }
    /// A value of `kind` holding `m`.
    pub fn of(kind: Kind, m: impl Into<Num>) -> Value {
        Value::Num {
            kind,
            m: m.into(),
            exact: Exact::Float,
        }
    }
    /// A column vector.
    pub fn vector(kind: Kind, v: &[f64]) -> Value {
        Value::Num {
            kind,
            m: Num::vector(v),
            exact: Exact::Float,
        }
    }
    /// The kind this value has at run time.
    #[inline]
    pub fn kind(&self) -> Kind {
        // (numbers carry theirs: read in place, the rest out of line)
        match self {
            Value::Num { kind, .. } | Value::Formula { kind, .. } => *kind,
            other => other.kind_made(),
        }
    }
    /// [`Value::kind`] of a value that does not carry its kind.
    #[cold]
    fn kind_made(&self) -> Kind {
        match self {
            Value::Num { kind, .. } => *kind,
            Value::Bool(_) => Kind::Bool,
            Value::Tuple(vs) => Kind::tuple(vs.iter().map(Value::kind).collect()),
            Value::Mech(_) => Kind::Mechanism,
            Value::Sym(_) => Kind::Unknown,
            Value::Formula { kind, .. } => *kind,
            Value::List(vs) => Kind::list(common_kind(vs)),
            Value::Str(_) => Kind::Text,
            Value::Picture(_) => Kind::Picture,
        }
    }
    /// The number of a scalar value.
    pub fn as_scalar(&self) -> Option<f64> {
        match self {
            Value::Num { m, .. } if m.len() == 1 => Some(m[0]),
            _ => None,
        }
    }
    /// The numbers of a number, vector or matrix.
    pub fn as_matrix(&self) -> Option<&Num> {
        match self {
            Value::Num { m, .. } => Some(m),
            _ => None,
        }
    }
    /// The same value with the exact form `exact` (numbers only).
    pub fn with_exact(mut self, e: Exact) -> Value {
        self.set_exact(e);
        self
    }
    /// Gives a number the exact form `e` (in place: a value is too large
    /// to move for nothing).
    #[inline]
    pub fn set_exact(&mut self, e: Exact) {
        if let Value::Num { exact, .. } = self {
            *exact = e;
        }
    }
    /// Gives the result of a builtin the exact form `e` of its call,
    /// unless the call has none (a float) and the builtin knows its
    /// numbers exactly: `eye(3)`, `zeros(2)` are 0s and 1s as typed
    /// (`Rotx(2π/3) Rotx(2π/3)ᵀ == eye(3)` was false).
    #[inline]
    pub fn set_call_exact(&mut self, e: Exact) {
        if let Value::Num { exact, .. } = self
            && !(e.is_float() && matches!(exact, Exact::Typed))
        {
            *exact = e;
        }
    }
    /// The exact form of a numeric value, when it has one (§3, §7).
    pub fn exact_form(&self) -> Option<crate::sym::Mat> {
        match self {
            Value::Num { m, exact, .. } => exact.form(m),
            _ => None,
        }
    }
    /// True for a numeric value with an exact form known or to be computed.
    #[inline]
    pub fn may_be_exact(&self) -> bool {
        matches!(self, Value::Num { exact, .. } if !exact.is_float())
    }
    /// True for an expression over `given` symbols ([`Value::Sym`]); a
    /// [`Value::Formula`] is not counted.
    pub fn is_symbolic(&self) -> bool {
        matches!(self, Value::Sym(_))
    }
}

/// A rotation R ∈ SO(3) (§3.2.1) as a value of kind SO(3).
impl From<SO3> for Value {
    fn from(r: SO3) -> Value {
        Value::of(Kind::SO3, *r.matrix())
    }
}

/// A transform T ∈ SE(3) (3.62) as a value of kind SE(3).
impl From<SE3> for Value {
    fn from(t: SE3) -> Value {
        Value::of(Kind::SE3, *t.matrix())
    }
}

/// A planar rotation ∈ SO(2) as a value of kind SO(2) (a general 2×2).
impl From<SO2> for Value {
    fn from(r: SO2) -> Value {
        Value::num(Kind::SO2, r.matrix())
    }
}

/// A planar transform ∈ SE(2) (3.16) as a value of kind SE(2).
impl From<SE2> for Value {
    fn from(t: SE2) -> Value {
        Value::of(Kind::SE2, *t.matrix())
    }
}

/// The kind all elements of a list share, or `Unknown`.
pub fn common_kind(vs: &[Value]) -> Kind {
    let mut it = vs.iter().map(Value::kind);
    let Some(first) = it.next() else {
        return Kind::Unknown;
    };
    if it.all(|k| k == first) {
        first
    } else {
        Kind::Unknown
    }
}

// ---------------------------------------------------------------------------
// Pictures (LANGUAGE.md §12): what `draw` was given — each value with its
// kind and frames — in one or more panels, the view, and where it is to be
// saved. Turning it into marks, projecting and writing SVG or PNG belongs
// to `crate::draw`, which reads these types; nothing here draws.
// ---------------------------------------------------------------------------

/// How one drawn value is shown.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// As the book draws it: a transform or rotation as its frame's axes, a
    /// screw axis or twist as its axis line, a vector as an arrow from the
    /// origin, the 3-vectors of a list as points (a workspace).
    Natural,
    /// `arrow(p, v)`: an arrow from the point p along v.
    Arrow,
    /// `point(p)`: a dot.
    Point,
}

/// One value given to `draw`, with its static type (the frames name the
/// drawn frame: `T_sa` draws {a} in {s}) and a label for untagged values.
#[derive(Debug, Clone)]
pub struct Drawn {
    /// The value drawn.
    pub value: Value,
    /// Its kind and frames as the checker inferred them.
    pub ty: Ty,
    /// The argument as written, for untagged values (`w_hat`).
    pub label: String,
    /// Drawn as the book draws its kind, or as an arrow or a point.
    pub style: Style,
}

/// One drawing with its own reference frame: `draw(..)` makes one,
/// `beside(p1, p2)` puts several side by side.
#[derive(Debug, Clone, Default)]
pub struct Panel {
    /// The values drawn in it, in the order given.
    pub items: Vec<Drawn>,
    /// `view(az, el)` in radians, MATLAB's convention; `None` for the default.
    pub view: Option<(f64, f64)>,
    /// A title written above the panel.
    pub title: Option<String>,
}

/// A picture: panels side by side, where `save` asked it to go, and where it
/// was written (set by the session when it writes the file).
#[derive(Debug, Clone, Default)]
pub struct Picture {
    /// The drawings, left to right.
    pub panels: Vec<Panel>,
    /// `save(pic, "name.svg")`: the file asked for.
    pub save_to: Option<String>,
    /// What the picture shows, for printing: `5 frames and 1 screw axis in {s}`.
    pub summary: String,
    /// The file it was written to.
    pub file: Option<String>,
}

impl Picture {
    /// True for `view(az, el)` alone: a view to pass to `draw`, nothing drawn.
    pub fn is_view_only(&self) -> bool {
        self.panels.iter().all(|p| p.items.is_empty())
    }
}
