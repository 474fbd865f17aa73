//! Whether two values are equal, or in order (LANGUAGE.md §3, §7): the one
//! place that decides `a == b` (exact: by exact forms when both sides have
//! them, else float by float, with a note when they differ by rounding
//! only), `a ≈ b` (within 1e-9 relative) and `a < b`, for numbers typed
//! first and for numbers bound later alike (a comparison over symbols is
//! decided again with their numbers, `super::replay`). Symbolic sides ask
//! the canonical forms ([`crate::values::formula::equal`]) or the trees
//! ([`symbolic_equal`]).

use super::certify::Verdict;
use crate::check::ty::Kind;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::seam::apply::to_sym;
use crate::syntax::ast::{CmpOp, Span};
use crate::values::num::Num;
use crate::values::value::{Sym, Value};

/// The tolerance of `a ≈ b`: every entry within 1e-9 · max(1, |a|∞, |b|∞).
pub const APPROX_TOL: f64 = 1e-9;

/// Whether `a op b` holds: `Ok(Some(..))` decided, `Ok(None)` undecided
/// (symbolic sides the canonical form cannot settle), `Err` a message when
/// the two cannot be compared (different shapes, mechanisms).
pub fn equal(a: &Value, b: &Value, op: CmpOp) -> Result<Option<bool>, String> {
    // (a bool decided over symbols is that bool)
    let shown = |v: &Value| match v {
        Value::Formula {
            kind: Kind::Bool, ..
        } => crate::values::formula::constant_shown(v),
        _ => None,
    };
    // (a comparison still waiting for numbers is neither true nor false)
    if crate::values::waiting::sides(a).is_some() || crate::values::waiting::sides(b).is_some() {
        return Ok(None);
    }
    if let Some(x) = shown(a) {
        return equal(&x, b, op);
    }
    if let Some(y) = shown(b) {
        return equal(a, &y, op);
    }
    if op.is_order() {
        return super::order::holds(a, b, op);
    }
    match (a, b) {
        (Value::Sym(_), _) | (_, Value::Sym(_)) => Ok(symbolic_equal(&to_sym(a), &to_sym(b), op)),
        // Symbolic scalars and matrices: by their canonical forms (§7).
        (Value::Formula { .. }, _) | (_, Value::Formula { .. }) => {
            crate::values::formula::equal(a, b, op == CmpOp::Approx)
        }
        (Value::Num { m: x, .. }, Value::Num { m: y, .. }) => {
            if x.shape() != y.shape() {
                return Err(format!(
                    "cannot compare {} with {}",
                    a.kind().a(),
                    b.kind().a()
                ));
            }
            Ok(match op {
                CmpOp::Approx => Some(approx(x, y)),
                _ => exactly_equal(a, b),
            })
        }
        (Value::Bool(x), Value::Bool(y)) => Ok(Some(x == y)),
        (Value::Tuple(xs), Value::Tuple(ys)) if xs.len() == ys.len() => {
            let mut all = Some(true);
            for (x, y) in xs.iter().zip(ys) {
                match equal(x, y, op)? {
                    Some(false) => return Ok(Some(false)),
                    Some(true) => {}
                    None => all = None,
                }
            }
            Ok(all)
        }
        _ => Err(format!(
            "cannot compare {} with {}",
            a.kind().a(),
            b.kind().a()
        )),
    }
}

/// The note on `a == b` false by rounding only (LANGUAGE.md §3).
pub fn rounding_note(span: Span) -> Diagnostic {
    Diagnostic::note(
        ErrorKind::Domain,
        span,
        "the two sides differ by rounding only: floats with no exact form are equal only when every digit is",
    )
    .with_help("compare within rounding with ≈ (typed ~=)")
}

/// Equality of symbolic expressions (LANGUAGE.md §7). Today it is
/// structural: equal trees are equal, and anything else is undecided
/// (`None`). A canonical form decides more pairs by extending this one
/// function. `Sym`'s own `==` compares constants by their 4-digit text, so
/// the trees are also compared in full (their `Debug` form holds every
/// constant's exact value): `t + 1.00001` is not `t + 1.00002`.
pub fn symbolic_equal(a: &Sym, b: &Sym, _op: CmpOp) -> Option<bool> {
    // What cancelled products leave (`inv(T) * T`, `A^0`) is the identity `I`.
    let identity = |s: &Sym| match s {
        Sym::Identity(_) => true,
        Sym::Const(v, _) => v
            .as_matrix()
            .is_some_and(|m| m.is_square() && m.nrows() > 1 && m.is_identity(0.0)),
        _ => false,
    };
    if identity(a) && identity(b) {
        return Some(true);
    }
    // Trees compare structurally, constants by value (not printed text),
    // with the adjoint of an inverse written one way: (Ad_T)⁻¹ = Ad_{T⁻¹}
    // (Proposition 3.20), so inv(Ad(T)) == Ad(inv(T)) is true (issue 35),
    // and an integer power written as the product it is (`A^2 == A A`).
    if let Some(t) = super::powers::equal(a, b) {
        return Some(t);
    }
    if a == b {
        return Some(true);
    }
    let (x, y) = (adjoint_inverses(a), adjoint_inverses(b));
    (x == y || identity(&x) && identity(&y)).then_some(true)
}

/// The largest integer power written out as a product for `==`
/// ([`adjoint_inverses`]): `A^8` is eight factors.
const POWER_FACTORS: u32 = 8;

/// `x^n` as the product it is, for an integer `n` with |n| at most
/// [`POWER_FACTORS`]: `x x … x`, `inv(x) … inv(x)` for a negative power,
/// the identity for `x^0` (of a square matrix or a scalar alike, the
/// product of no factors). None for any other exponent.
fn power_product(x: &Sym, e: &Sym) -> Option<Sym> {
    let Sym::Const(v, _) = e else { return None };
    let n = v.as_scalar()?;
    if n.fract() != 0.0 || n.abs() > f64::from(POWER_FACTORS) {
        return None;
    }
    let factor = if n < 0.0 {
        x.clone().inverse()
    } else {
        x.clone()
    };
    Some(Sym::product(vec![factor; n.abs() as usize]))
}

/// `s` with every inverse of an adjoint written as the adjoint of the
/// inverse, and the adjoint of a product as the product of the adjoints
/// (Ad is a homomorphism: `Ad(T1 T2) == Ad(T1) Ad(T2)` is true),
/// `dot(a, M y)` as `dot(Mᵀ a, y)`, and a small integer power as its
/// product ([`power_product`]: `A^3 == A A A`, `A^-2 == inv(A) inv(A)`).
fn adjoint_inverses(s: &Sym) -> Sym {
    use crate::values::symbolic::Role;
    let go = |x: &Sym| Box::new(adjoint_inverses(x));
    match s {
        // (the inverse of an adjoint of a product: of the inverse, split)
        Sym::Inv(x) if matches!(&**x, Sym::Call(f, args) if f.role == Role::Adjoint && args.len() == 1 && matches!(args[0], Sym::Product(_))) =>
        {
            let Sym::Call(f, args) = &**x else {
                return s.clone();
            };
            adjoint_inverses(&Sym::Call(*f, vec![args[0].clone().inverse()]))
        }
        Sym::Inv(x) => match adjoint_inverses(x) {
            // (a block [R, p; 0, 1] where Ad is defined is a transform:
            // its inverse in closed form, 3.64, as `inv` gives it)
            Sym::Call(f, args) if f.role == Role::Adjoint && args.len() == 1 => {
                let inv = crate::seam::transform::inverse_of(&args[0])
                    .unwrap_or_else(|| args[0].clone().inverse());
                Sym::Call(f, vec![inv])
            }
            x => x.inverse(),
        },
        // (Ad_{T₁T₂} = Ad_{T₁} Ad_{T₂}: the checker typed the argument a
        // transform, so each factor of the product is one)
        Sym::Call(f, args) if f.role == Role::Adjoint && args.len() == 1 => {
            match adjoint_inverses(&args[0]) {
                Sym::Product(xs) => {
                    Sym::product(xs.into_iter().map(|x| Sym::Call(*f, vec![x])).collect())
                }
                x => Sym::Call(*f, vec![x]),
            }
        }
        // (dot(a, M y) = dot(Mᵀ a, y): the matrices moved to the left, so
        // the power of a wrench on a twist reads alike in either frame, 3.99)
        Sym::Call(f, args) if f.name == "dot" && args.len() == 2 => {
            let (a, b) = (adjoint_inverses(&args[0]), adjoint_inverses(&args[1]));
            match b {
                Sym::Product(mut fs) if fs.len() > 1 => {
                    let y = fs.pop().unwrap_or_else(Sym::identity);
                    let moved = Sym::times(Sym::product(fs).transpose(), a);
                    Sym::Call(*f, vec![moved, y])
                }
                b => Sym::Call(*f, vec![a, b]),
            }
        }
        Sym::Call(f, args) => Sym::Call(*f, args.iter().map(adjoint_inverses).collect()),
        Sym::Product(xs) => Sym::product(xs.iter().map(adjoint_inverses).collect()),
        Sym::Pow(x, e) => {
            power_product(&adjoint_inverses(x), e).unwrap_or_else(|| Sym::Pow(go(x), e.clone()))
        }
        Sym::Transpose(x) => Sym::Transpose(go(x)),
        Sym::Neg(x) => Sym::Neg(go(x)),
        Sym::Add(x, y) => Sym::Add(go(x), go(y)),
        Sym::Sub(x, y) => Sym::Sub(go(x), go(y)),
        other => other.clone(),
    }
}

/// `a == b` on numbers (LANGUAGE.md §3, §7): by their exact forms when
/// both have one (`0.1 + 0.2 == 0.3`, `sqrt(2)*sqrt(3) == sqrt(6)`); else,
/// when both were made from exact numbers, by certified arithmetic on how
/// they were made ([`super::certify`]: `cos(1e-9) == 1` is false, and
/// sides that agree far past rounding but are not proven equal are
/// undecided, None); else as floats, equal only when every entry is the
/// same float.
fn exactly_equal(a: &Value, b: &Value) -> Option<bool> {
    if a.may_be_exact()
        && b.may_be_exact()
        && let (Some(x), Some(y)) = (a.exact_form(), b.exact_form())
    {
        return Some(x == y);
    }
    // (entry by entry where only some entries are exact)
    if crate::values::exact_mat::entries_differ(a, b) {
        return Some(false);
    }
    match super::certify::equal(a, b) {
        Some(Verdict::Equal) => return Some(true),
        Some(Verdict::Differ(_)) => return Some(false),
        Some(Verdict::Agree(_)) => return None,
        None => {}
    }
    Some(match (a, b) {
        (Value::Num { m: x, .. }, Value::Num { m: y, .. }) => x == y,
        _ => false,
    })
}

/// The note on `a == b` found false, if any: "differ by 5e-19, below
/// double precision" when certified arithmetic found a difference the
/// floats cannot show; the rounding note ([`rounding_note`]) when the
/// sides are floats with no recipe that differ by rounding only.
pub fn false_note(a: &Value, b: &Value, span: Span) -> Option<Diagnostic> {
    match super::certify::equal(a, b) {
        Some(Verdict::Differ(d)) => {
            let same_floats =
                matches!((a, b), (Value::Num { m: x, .. }, Value::Num { m: y, .. }) if x == y);
            same_floats.then(|| {
                Diagnostic::note(
                    ErrorKind::Domain,
                    span,
                    format!(
                        "the two sides differ by {}, below double precision: their floats are equal, their exact values are not",
                        format!("{:.1e}", d.abs()).replace(".0e", "e")
                    ),
                )
            })
        }
        Some(_) => None,
        None => rounding_only(a, b).then(|| rounding_note(span)),
    }
}

/// How many digits the two sides of an undecided `a == b` on numbers
/// agree to ([`super::certify`]), if that is why it is undecided.
pub fn agreement(a: &Value, b: &Value) -> Option<u32> {
    match super::certify::equal(a, b) {
        Some(Verdict::Agree(n)) => Some(n),
        _ => None,
    }
}

/// True when `a == b` is false by rounding only: the sides are floats (one
/// at least has no exact form) within 1e-12 of the larger side (of its
/// largest entry for a matrix), so `≈` is meant. Relative to the sides
/// themselves, not to 1: `exp(-40) == exp(-41)` differ by far more than
/// rounding, though by less than 1e-12.
pub fn rounding_only(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Num { m: x, .. }, Value::Num { m: y, .. }) => {
            x.shape() == y.shape()
                && !(a.may_be_exact()
                    && b.may_be_exact()
                    && a.exact_form().is_some()
                    && b.exact_form().is_some())
                && within_sides(x, y, ROUNDING_TOL)
                && !crate::values::exact_mat::entries_differ(a, b)
        }
        (Value::Formula { .. }, _) | (_, Value::Formula { .. }) => {
            crate::values::formula::rounding_only(a, b)
        }
        (Value::Tuple(xs), Value::Tuple(ys)) if xs.len() == ys.len() => {
            xs.iter()
                .zip(ys)
                .all(|(x, y)| exactly_equal(x, y) == Some(true) || rounding_only(x, y))
                && xs.iter().zip(ys).any(|(x, y)| rounding_only(x, y))
        }
        _ => false,
    }
}

/// How far apart floats may be, relative to the larger side, for a
/// false `==` to say they differ by rounding only.
const ROUNDING_TOL: f64 = 1e-12;

/// Entrywise within [`APPROX_TOL`] relative to the larger side (absolute
/// near zero); infinite entries must agree exactly, NaN never does.
fn approx(x: &Num, y: &Num) -> bool {
    within(x, y, APPROX_TOL, 1.0)
}

/// Entrywise within `tol` of the larger side's largest entry, however
/// small it is (no absolute floor).
fn within_sides(x: &Num, y: &Num, tol: f64) -> bool {
    within(x, y, tol, 0.0)
}

/// Entrywise within `tol` times the largest entry of either side (at
/// least `floor`: with 1, absolute near zero); infinite entries must
/// agree exactly, NaN never does.
fn within(x: &Num, y: &Num, tol: f64, floor: f64) -> bool {
    let scale = x
        .iter()
        .chain(y.iter())
        .filter(|v| v.is_finite())
        .fold(floor, |s, v| s.max(v.abs()));
    x.iter().zip(y.iter()).all(|(a, b)| {
        if a.is_finite() && b.is_finite() {
            (a - b).abs() <= tol * scale
        } else {
            a == b
        }
    })
}

/// The largest entrywise difference of two numeric values of one shape,
/// and where it is: the 1-based (row, column) of the first such entry
/// (NaN counts as the largest).
pub fn largest_difference(a: &Value, b: &Value) -> Option<(f64, usize, usize)> {
    let (Value::Num { m: x, .. }, Value::Num { m: y, .. }) = (a, b) else {
        return None;
    };
    if x.shape() != y.shape() {
        return None;
    }
    let mut best = (0.0f64, 1, 1);
    for j in 0..x.ncols() {
        for i in 0..x.nrows() {
            let e = (x[(i, j)] - y[(i, j)]).abs();
            let e = if e.is_nan() { f64::INFINITY } else { e };
            if e > best.0 {
                best = (e, i + 1, j + 1);
            }
        }
    }
    Some(best)
}

/// `s` with what the kinds of its `given` names say written out
/// (LANGUAGE.md §7), for `==` over trees the structure alone cannot
/// settle: the transpose of a rotation is its inverse (Rᵀ = R⁻¹, Prop. 3.3,
/// so products cancel it: `inv(R) == R^T`, `R^T R R^T == R^T`), and the
/// transpose of an so(3) or so(2) matrix its negative (`W^T == -W`),
/// and a bracket of a rotated vector or a moved twist the conjugate of
/// the bracket: \[Rω\] = R\[ω\]Rᵀ (3.30), \[Ad_T V\] = T\[V\]T⁻¹
/// (Definition 3.6). `kind_of` gives the kind of a `given` name, None for
/// any other.
pub fn with_kinds(s: &Sym, kind_of: &dyn Fn(&str) -> Option<Kind>) -> Sym {
    let go = |x: &Sym| with_kinds(x, kind_of);
    match s {
        Sym::Transpose(x) => match &**x {
            Sym::Name(n) if matches!(kind_of(n), Some(Kind::SO3 | Kind::SO2)) => {
                Sym::Name(n.clone()).inverse()
            }
            Sym::Name(n) if matches!(kind_of(n), Some(Kind::So3 | Kind::So2)) => {
                Sym::Neg(Box::new(Sym::Name(n.clone())))
            }
            _ => go(x).transpose(),
        },
        Sym::Product(xs) => Sym::product(xs.iter().map(go).collect()),
        Sym::Bracket(x) => bracket(go(x), kind_of),
        // (dot(a, M y) = dot(Mᵀ a, y), then Rᵀ R cancels: dot(R u, R v)
        // is dot(u, v))
        Sym::Call(f, args) if f.name == "dot" && args.len() == 2 => {
            match (go(&args[0]), go(&args[1])) {
                (a, Sym::Product(mut fs)) if fs.len() > 1 => {
                    let y = fs.pop().unwrap_or_else(Sym::identity);
                    let moved = go(&Sym::times(Sym::product(fs).transpose(), a));
                    Sym::Call(*f, vec![moved, y])
                }
                (a, b) => Sym::Call(*f, vec![a, b]),
            }
        }
        Sym::Inv(x) => go(x).inverse(),
        Sym::Neg(x) => match go(x) {
            Sym::Neg(y) => *y,
            y => Sym::Neg(Box::new(y)),
        },
        Sym::Add(x, y) => Sym::Add(Box::new(go(x)), Box::new(go(y))),
        Sym::Sub(x, y) => Sym::Sub(Box::new(go(x)), Box::new(go(y))),
        Sym::Call(f, args) => Sym::Call(*f, args.iter().map(go).collect()),
        other => other.clone(),
    }
}

/// \[x\] of `x` (already with the kinds written out, [`with_kinds`]):
/// \[R y\] = R\[y\]R⁻¹ for a rotation R (a `given` SO(3) or its
/// inverse, 3.30) and \[Ad_T y\] = T\[y\]T⁻¹ (Definition 3.6), factor by
/// factor; else the bracket as it is.
fn bracket(x: Sym, kind_of: &dyn Fn(&str) -> Option<Kind>) -> Sym {
    use crate::values::symbolic::Role;
    let rotation = |s: &Sym| match s {
        Sym::Name(n) => matches!(kind_of(n), Some(Kind::SO3)),
        Sym::Inv(y) => matches!(&**y, Sym::Name(n) if matches!(kind_of(n), Some(Kind::SO3))),
        _ => false,
    };
    let Sym::Product(fs) = &x else {
        return Sym::Bracket(Box::new(x));
    };
    let by = match fs.first() {
        Some(Sym::Call(f, a)) if f.role == Role::Adjoint && a.len() == 1 => a[0].clone(),
        Some(r) if rotation(r) => r.clone(),
        _ => return Sym::Bracket(Box::new(x)),
    };
    let rest = bracket(Sym::product(fs[1..].to_vec()), kind_of);
    Sym::product(vec![by.clone(), rest, by.inverse()])
}
