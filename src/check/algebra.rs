//! The frame algebra of products (LANGUAGE.md §6), decided in one place: every
//! framed factor is a map from coordinates in one frame to coordinates in
//! another, and a product composes maps. Because composition of maps is
//! associative (Prop. 3.12 for the matrices themselves), every bracketing of a
//! product gets the same frames or the same error.
//!
//! A factor is an [`Arrow`] from its inner end to its outer end. An end is a
//! frame, or the scalar line: a column vector v_a is a map from the scalars
//! into {a}, a row v_aᵀ a map from {a} to the scalars, so vᵀ_b F_b is a
//! plain scalar and u_a v_bᵀ a map {a}←{b}.
//!
//! | factor (tag, shape)                     | arrow                        |
//! |-----------------------------------------|------------------------------|
//! | `X_ab` (R, T, Ad: {a}←{b})              | {a} ← {b}                    |
//! | one-frame operator `[V_a]`, `[ω_a]`     | {a} ← {a}                    |
//! | displacement `exp([S_a] θ)`             | {a} ← {a'}                   |
//! | column vector `v_a` / row `v_aᵀ`        | {a} ← line / line ← {a}      |
//! | untagged operator                       | a displacement of the frame it meets |
//! | untagged so(3)/se(3) matrix `[ω]`       | a quantity in the frame it meets |
//! | product of untagged operators           | as many displacements as theirs |
//! | untagged vector or row                  | line ← any / any ← line      |
//! | transposed transform `T_abᵀ`            | none: an error in a product  |
//!
//! | product (inner ends)                    | result                        |
//! |-----------------------------------------|-------------------------------|
//! | {a}←{b} · {b}←{c}                       | {a}←{c}                       |
//! | {a}←{b'} · {b}←{c}                      | {a}←{c'}: {c} moves with {b}  |
//! | {a}←{b} · {b'}←{c}                      | {a'}←{c}: {a} moves with {b}  |
//! | {a}←{b} · {c}←{d}, b ≠ c                | frame error naming both       |
//! | untagged · {a}←{b}, {a}←{b} · untagged  | {a}←{b'}                      |
//! | line ← {b} · {b} ← line (uᵀv)           | a plain scalar                |
//! | `Tᵀ` · anything, anything · `Tᵀ`         | frame error naming `inv(T)`   |
//!
//! A moved frame counts its displacements ({b} moved twice is printed {b'},
//! like a frame moved once, but the algebra tells them apart). When the
//! inner ends name the same frame moved a different number of times, the
//! less-moved factor is moved to match: frames rigidly attached to a moved
//! frame move with it (`T_ab' T_bc` is T_ac'). Composition thus fails only
//! when the names differ, and the count of the result is the same under
//! every bracketing: the factors are the maps of a category whose objects
//! are (frame, count), each factor standing for all its displaced copies,
//! and a product takes the copies with the fewest displacements that meet.
//!
//! Back to tags ([`to_frames`]): a map {a}←{a} of a group element or adjoint
//! stays the pair (the identity `inv(T_ab) T_ab` is {b}←{b}); of any other
//! kind it is a one-frame quantity in {a}, so conjugation closes:
//! `T_ab [V_b] inv(T_ab)` is `[V_a]` in {a} (3.77) and `R_ab [ω_b] R_abᵀ` is
//! `[ω_a]` (Prop. 3.5). A group element {a}←{a'} prints as a displacement in {a}.
//!
//! Untagged operators carry no frames but count their displacements (an
//! untagged rotation or transform one, an untagged `[ω]` none, a product of
//! them the sum: [`Ty::moves`]), so they too compose alike under every
//! bracketing.

use super::ty::{Frame, Frames, Kind, Moves, Ty};

/// One end of a map.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum End {
    /// Coordinates in a frame.
    At(Frame),
    /// The scalars: the far end of a column vector or a row.
    Line,
    /// Unknown: the frame of an untagged vector or row, matching any.
    Any,
}

impl End {
    fn lifted(&self, k: u32) -> End {
        match self {
            End::At(f) => End::At(f.lifted(k)),
            other => *other,
        }
    }
}

/// A framed factor as a map from coordinates at `inn` to coordinates at `out`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Arrow {
    /// Where its results are expressed: {a} of T_ab.
    pub out: End,
    /// Where its inputs are expressed: {b} of T_ab.
    pub inn: End,
}

impl Arrow {
    fn new(out: End, inn: End) -> Arrow {
        Arrow { out, inn }
    }
    fn lifted(&self, k: u32) -> Arrow {
        Arrow::new(self.out.lifted(k), self.inn.lifted(k))
    }
}

/// How the algebra sees one operand of a product.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Factor {
    /// A map between frames (or the scalar line).
    Map(Arrow),
    /// An untagged operator standing for `k` displacements of whichever
    /// frame it meets: an untagged rotation, transform or matrix is one, an
    /// untagged so(3)/se(3) matrix none — a quantity in the frame it meets
    /// (`R_ab [ω] R_abᵀ` is `[ω_a]` for ω in {b}) — and a product of
    /// untagged operators the sum of theirs.
    Untagged(u32),
    /// The transpose of a transform {a}←{b}: no map between frames.
    Transposed(Frame, Frame),
}

/// The shape of an operand, which decides how a one-frame tag reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// A column vector: point, twist, wrench, 3-vector.
    Column,
    /// A row (a 1×n matrix, `v.T`).
    Row,
    /// A square (or other) matrix acting by `*`.
    Operator,
    /// A Lie-algebra matrix `[ω]`, `[V]`: a one-frame quantity acting by `*`.
    Quantity,
}

impl Shape {
    /// The shape of a value of `kind`.
    pub fn of(kind: &Kind) -> Shape {
        if kind.is_vector() {
            Shape::Column
        } else if matches!(kind, Kind::Matrix(Some(1), _)) {
            Shape::Row
        } else if kind.is_algebra() {
            Shape::Quantity
        } else {
            Shape::Operator
        }
    }
}

/// Why a product has no frames.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Clash {
    /// The inner frames differ: the left factor's inner frame, the right
    /// factor's outer frame.
    Inner(Frame, Frame),
    /// A transposed transform is a factor (`left` says which side).
    Transposed {
        /// True when it is the left factor.
        left: bool,
    },
}

/// The factor of a value, by the first table of the module
/// ([`Ty::moves`] counts the displacements of an untagged product).
pub fn factor_of(t: &Ty) -> Factor {
    let shape = Shape::of(&t.kind);
    match (&t.frames, shape, t.moves.map(Moves::get)) {
        (Frames::None, Shape::Operator | Shape::Quantity, Some(k)) => Factor::Untagged(k),
        _ => factor(&t.frames, shape),
    }
}

/// The factor a tag stands for, by the first table of the module.
pub fn factor(frames: &Frames, shape: Shape) -> Factor {
    use End::*;
    let map = |o, i| Factor::Map(Arrow::new(o, i));
    match (frames, shape) {
        (Frames::Transposed(a, b), _) => Factor::Transposed(*a, *b),
        (Frames::None, Shape::Column) => map(Any, Line),
        (Frames::None, Shape::Row) => map(Line, Any),
        (Frames::None, Shape::Operator) => Factor::Untagged(1),
        (Frames::None, Shape::Quantity) => Factor::Untagged(0),
        (Frames::One(a) | Frames::Pair(a, _) | Frames::Disp(a), Shape::Column) => map(At(*a), Line),
        (Frames::One(a) | Frames::Disp(a), Shape::Row) => map(Line, At(*a)),
        (Frames::Pair(_, b), Shape::Row) => map(Line, At(*b)),
        (Frames::One(a), Shape::Operator | Shape::Quantity) => map(At(*a), At(*a)),
        (Frames::Pair(a, b), Shape::Operator | Shape::Quantity) => map(At(*a), At(*b)),
        (Frames::Disp(a), Shape::Operator | Shape::Quantity) => map(At(*a), At(a.moved())),
    }
}

/// The product `l * r` of two factors, by the second table of the module.
pub fn compose(l: &Factor, r: &Factor) -> Result<Factor, Clash> {
    use Factor::*;
    match (l, r) {
        (Transposed(..), _) => Err(Clash::Transposed { left: true }),
        (_, Transposed(..)) => Err(Clash::Transposed { left: false }),
        (Untagged(j), Untagged(k)) => Ok(Untagged(j.saturating_add(*k))),
        // An untagged operator displaces the frame it meets: on the left of
        // {a'}←{b} it is the step {a}←{a'} (the fewest displacements that
        // make the frames meet), on the left of {a}←{b} it moves {b}.
        (Untagged(k), Map(a)) => Ok(Map(match &a.out {
            End::At(f) => {
                let down = f.moved.min(*k);
                Arrow::new(
                    End::At(Frame {
                        moved: f.moved - down,
                        ..*f
                    }),
                    a.inn.lifted(k - down),
                )
            }
            _ => Arrow::new(a.out, a.inn.lifted(*k)),
        })),
        (Map(a), Untagged(k)) => Ok(Map(Arrow::new(a.out, a.inn.lifted(*k)))),
        (Map(x), Map(y)) => compose_maps(x, y).map(Map),
    }
}

fn compose_maps(x: &Arrow, y: &Arrow) -> Result<Arrow, Clash> {
    match (&x.inn, &y.out) {
        (End::At(b), End::At(c)) => {
            if b.name != c.name {
                return Err(Clash::Inner(*b, *c));
            }
            // The less-moved side moves with the other (rigid attachment).
            // (The result's ends are the first factor's outer end and the
            // last one's inner end, moved alike under every bracketing, so
            // they print alike too.)
            if b.moved >= c.moved {
                Ok(Arrow::new(x.out, y.lifted(b.moved - c.moved).inn))
            } else {
                Ok(Arrow::new(x.lifted(c.moved - b.moved).out, y.inn))
            }
        }
        // The line meets the line (uᵀv, u vᵀ), or a wildcard meets anything.
        _ => Ok(Arrow::new(x.out, y.inn)),
    }
}

/// True for kinds whose map {a}←{a} is a group element (the identity
/// between a frame and itself) rather than a one-frame quantity.
fn group_like(kind: &Kind) -> bool {
    kind.is_group() || matches!(kind, Kind::Adjoint { .. } | Kind::Unknown)
}

/// The tag of a result of `kind` that is the factor `f`.
pub fn to_frames(f: &Factor, kind: &Kind) -> Frames {
    let arrow = match f {
        Factor::Untagged(_) => return Frames::None,
        Factor::Transposed(a, b) => return Frames::Transposed(*a, *b),
        Factor::Map(a) => a,
    };
    match (&arrow.out, &arrow.inn) {
        (End::At(a), End::At(b)) => {
            // (A group element {a}←{a'} prints as a displacement in {a}.)
            if group_like(kind) {
                Frames::Pair(*a, *b)
            } else if a == b {
                Frames::One(*a)
            } else {
                Frames::Pair(*a, *b)
            }
        }
        (End::At(a), _) | (_, End::At(a)) => Frames::One(*a),
        _ => Frames::None,
    }
}

/// The frames of the product of two tagged values: the algebra's answer
/// for `l * r` with the result of `kind`.
/// With the frames, the displacements an untagged operator result stands
/// for when they are not the usual ([`Ty::moves`]).
pub fn product(l: &Ty, r: &Ty, kind: &Kind) -> Result<(Frames, Option<u32>), Clash> {
    let f = compose(&factor_of(l), &factor_of(r))?;
    let moves = match f {
        Factor::Untagged(k) => unusual(k, kind),
        _ => None,
    };
    Ok((to_frames(&f, kind), moves))
}

/// The type `t` with the kind the value turned out to have at run time
/// (a literal that is a rotation is SO(3)): the same frames, and for an
/// untagged operator the same number of displacements; what only the
/// symbols knew (`Ty::algebra`) is left to the numbers.
pub fn with_kind(t: &Ty, kind: Kind) -> Ty {
    let mut out = Ty::new(kind, t.frames);
    out.free = t.free && kind.is_vector();
    if let Factor::Untagged(k) = factor_of(t) {
        out.moves = unusual(k, &out.kind).map(Moves::new);
    }
    out
}

/// For an untagged `X^n` of kind `kind`: the displacements it stands for,
/// n times those of X (as [`product`] counts X·X·…·X), when not the usual.
pub fn untagged_power(x: &Ty, n: Option<i64>, kind: &Kind) -> Option<u32> {
    let (Factor::Untagged(k), Some(n)) = (factor_of(x), n) else {
        return x.moves.map(Moves::get);
    };
    let n = u32::try_from(n.unsigned_abs()).unwrap_or(u32::MAX);
    unusual(k.saturating_mul(n), kind)
}

/// `k` displacements for an untagged operator of `kind`, None when that is
/// the usual number (one for an operator, none for a Lie-algebra matrix)
/// or `kind` is no operator.
fn unusual(k: u32, kind: &Kind) -> Option<u32> {
    let usual = match Shape::of(kind) {
        _ if matches!(kind, Kind::Scalar) => return None,
        Shape::Operator => 1,
        Shape::Quantity => 0,
        Shape::Column | Shape::Row => return None,
    };
    (k != usual).then_some(k)
}

/// The frames of `X^n` (n a whole number, |n| ≥ 2; None when not known
/// before evaluation), as the product X·X·…·X: a map from a frame to a
/// moved copy of itself composes with itself, moving the copy n times
/// (`exp([S_a] θ)^2` is {a}←{a''}); a one-frame quantity stays in its
/// frame; a map between two frames has no power.
pub fn power(frames: &Frames, n: Option<i64>, kind: &Kind) -> Result<Frames, Clash> {
    let (a, b) = match factor(frames, Shape::Operator) {
        Factor::Transposed(..) => return Err(Clash::Transposed { left: true }),
        Factor::Map(Arrow {
            out: End::At(a),
            inn: End::At(b),
        }) => (a, b),
        _ => return Ok(*frames),
    };
    if a.name != b.name {
        return Err(Clash::Inner(b, a));
    }
    let Some(n) = n else {
        return Ok(*frames);
    };
    // X^-n = inv(X)^n.
    let (a, b) = if n < 0 { (b, a) } else { (a, b) };
    let n = u32::try_from(n.unsigned_abs()).unwrap_or(u32::MAX);
    let grow = |base: u32, step: u32| base.saturating_add(step.saturating_mul(n));
    let (out, inn) = if b.moved >= a.moved {
        (a.moved, grow(a.moved, b.moved - a.moved))
    } else {
        (grow(b.moved, a.moved - b.moved), b.moved)
    };
    let at = |k| End::At(Frame::at(a.name, k));
    Ok(to_frames(&Factor::Map(Arrow::new(at(out), at(inn))), kind))
}

#[cfg(test)]
mod tests;
