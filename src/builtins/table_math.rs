//! The mathematical maps `exp` and `log` (§3.2.3, §3.3.3, and e^{At} of
//! exercises 3.33–3.35), linear algebra, and the small helpers of §3.6
//! (NearZero, Normalize). Scalar functions are in `table_scalar`.

use nalgebra::DMatrix;

use super::table_scalar::scalar;
use super::{Area, ArgError, Args, Builtin, FrameRule, Param, Typing};
use crate::check::ty::{Frames, Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::lie::{LieGroup, Mat3, Mat4, SE2, SE3, SO2, SO3, Vec3, matexp, se2, se3, so2, so3};
use crate::values::convert::{self, Group};
use crate::values::num::Num;
use crate::values::ops;
use crate::values::value::Value;

/// `exp`: so(3) → SO(3), se(3) → SE(3), so(2), se(2), any square matrix, a number.
fn exp_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    let t = &args[0];
    let kind = match &t.kind {
        Kind::Scalar => Kind::Scalar,
        Kind::So3 => Kind::SO3,
        Kind::Se3 => Kind::SE3,
        Kind::So2 => Kind::SO2,
        Kind::Se2 => Kind::SE2,
        Kind::Unknown => Kind::Unknown,
        k if k.is_vector() => {
            return Err(ArgError::type_of(
                0,
                format!(
                    "exp takes a matrix such as [ω]θ or [S]θ, not {}; write exp([x]) or MatrixExp3/MatrixExp6(x)",
                    k.a()
                ),
            ));
        }
        k => match k.shape() {
            Some((r, c)) if r == c || r.is_none() || c.is_none() => Kind::Matrix(r, c),
            _ => {
                return Err(ArgError::type_of(
                    0,
                    format!("exp needs a square matrix, not {}", k.a()),
                ));
            }
        },
    };
    let frames = match &t.frames {
        Frames::One(a) | Frames::Disp(a) => Frames::Disp(*a),
        _ => Frames::None,
    };
    Ok(Ty::new(kind, frames))
}

fn eval_exp(a: &mut Args) -> Result<Value, Diagnostic> {
    if let Some(x) = a.value(0).as_scalar() {
        return Ok(Value::scalar(x.exp()));
    }
    let m = a.mat(0)?;
    if !m.all_finite() {
        return Err(a.error(
            0,
            ErrorKind::Domain,
            "exp of a matrix with entries that are not finite",
        ));
    }
    // The common case, [S]θ ∈ se(3) (3.88), on the stack.
    if let Some(f) = m.as_m4()
        && is_se3_fixed(f)
    {
        return Ok(SE3::exp(&se3::vee(f)).into());
    }
    let m = m.to_dmatrix().into_owned();
    let kind = a.value(0).kind();
    let skew3 =
        |m: &DMatrix<f64>| (m + m.transpose()).abs().max() <= 1e-12 * m.abs().max().max(1.0);
    match (kind, m.shape()) {
        (Kind::So3, _) | (_, (3, 3)) if skew3(&m) => {
            let w = so3::vee(&Mat3::from_iterator(m.iter().copied()));
            Ok(SO3::exp(&w).into())
        }
        (_, (4, 4)) if is_se3(&m) => {
            let v = se3::vee(&Mat4::from_iterator(m.iter().copied()));
            Ok(SE3::exp(&v).into())
        }
        (Kind::So2, _) | (_, (2, 2)) if skew3(&m) => Ok(SO2::exp(&m[(1, 0)]).into()),
        (Kind::Se2, _) => {
            let v = se2::vee(&Mat3::from_iterator(m.iter().copied()));
            Ok(SE2::exp(&v).into())
        }
        (_, (r, c)) if r == c => {
            if r > ops::MAX_DIM {
                return Err(a.domain(format!("matrix too large for exp ({r}×{r})")));
            }
            let products = matexp::cost_in_products(&m);
            ops::check_cost(ops::cube(r) * u128::from(products), || {
                format!("exp of a {r}×{r} matrix: about {products} products of its size")
            })
            .map_err(|e| a.domain(e.to_string()))?;
            // The input is finite (checked above): None means overflow.
            let Some(e) = matexp::try_expm(&m) else {
                return Err(a.error(
                    0,
                    ErrorKind::Domain,
                    "exp of this matrix overflows (an entry of the result exceeds 1.8e308)",
                ));
            };
            let e = Num::from_dmatrix(e);
            Ok(Value::Num {
                kind: convert::classify(&e),
                m: e,
                exact: Default::default(),
            })
        }
        _ => Err(a.error(0, ErrorKind::Type, "exp needs a square matrix")),
    }
}

/// [`is_se3`] for a 4×4 matrix on the stack: [ω] skew-symmetric, the
/// last row zero.
fn is_se3_fixed(m: &Mat4) -> bool {
    // (plain loops over the 16 finite entries: nalgebra's `amax` goes
    // through its generic SIMD comparisons, several times the cost)
    let scale = m.iter().fold(1.0f64, |s, x| s.max(x.abs()));
    let mut skew = 0.0f64;
    for i in 0..3 {
        for j in 0..3 {
            skew = skew.max((m[(i, j)] + m[(j, i)]).abs());
        }
    }
    skew <= 1e-12 * scale && (0..4).all(|j| m[(3, j)] == 0.0)
}

fn is_se3(m: &DMatrix<f64>) -> bool {
    let scale = m.abs().max().max(1.0);
    let w = m.view((0, 0), (3, 3));
    (w + w.transpose()).abs().max() <= 1e-12 * scale && m.row(3).abs().max() == 0.0
}

/// `log`: SO(3) → so(3) tagged {a} for R_ab, SE(3) → se(3), SO(2), SE(2), a number.
fn log_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    let t = &args[0];
    let kind = match &t.kind {
        Kind::Scalar => Kind::Scalar,
        Kind::SO3 => Kind::So3,
        Kind::SE3 => Kind::Se3,
        Kind::SO2 => Kind::So2,
        Kind::SE2 => Kind::Se2,
        Kind::Unknown => Kind::Unknown,
        Kind::Matrix(Some(4), Some(4)) => Kind::Se3,
        Kind::Matrix(Some(2), Some(2)) => Kind::So2,
        Kind::Matrix(r, c) if r.is_none_or(|r| r == 3) && c.is_none_or(|c| c == 3) => {
            Kind::Matrix(*r, *c)
        }
        k => {
            return Err(ArgError::type_of(
                0,
                format!(
                    "log takes a rotation or transform (SO(3), SE(3), SO(2), SE(2)), not {}",
                    k.a()
                ),
            ));
        }
    };
    let frames = match t.frames.outer() {
        Some(a) if t.kind != Kind::Scalar => Frames::One(*a),
        _ => Frames::None,
    };
    Ok(Ty::new(kind, frames))
}

fn eval_log(a: &mut Args) -> Result<Value, Diagnostic> {
    if a.value(0).as_scalar().is_some() {
        // (0 and the negatives decided by the exact form when there is one)
        let d = a.decided(0)?;
        let x = d.value();
        if d.order(0.0).map_or(x <= 0.0, std::cmp::Ordering::is_le) {
            return Err(a.error(
                0,
                ErrorKind::Domain,
                format!("log of {x}: the logarithm needs a positive number"),
            ));
        }
        return Ok(Value::scalar(x.ln()));
    }
    let kind = a.value(0).kind();
    let shape = a.mat(0)?.shape();
    match (kind, shape) {
        (Kind::SE2, _) => Ok(Value::of(Kind::Se2, se2::hat(&a.se2(0)?.log()))),
        (_, (3, 3)) => {
            // Read as SO(3) if it is one, else as SE(2); near both, the
            // nearer, and the reading said (§5).
            let (group, both) = convert::read_3x3(a.mat(0)?);
            if let Some((d3, d2)) = both {
                a.warnings
                    .push(crate::builtins::notes::read_as(a.call_span, group, d3, d2));
            }
            match group {
                Group::SE2 => Ok(Value::of(Kind::Se2, se2::hat(&a.se2(0)?.log()))),
                _ => Ok(Value::of(Kind::So3, so3::hat(&a.so3_log(0)?))),
            }
        }
        (_, (4, 4)) => Ok(Value::of(Kind::Se3, se3::hat(&a.se3_log(0)?))),
        (_, (2, 2)) => Ok(Value::num(Kind::So2, &so2::hat(a.so2(0)?.log()))),
        _ => Err(a.error(0, ErrorKind::Type, "log takes SO(3), SE(3), SO(2) or SE(2)")),
    }
}

fn inv_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    crate::check::rules::inverse(&args[0]).map_err(|e| ArgError::type_of(0, e.into_message()))
}

fn transpose_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    crate::check::rules::transpose(&args[0]).map_err(|e| ArgError::type_of(0, e.into_message()))
}

fn pair_rule(what: &'static str, ret: fn(&[Ty]) -> Kind) -> impl Fn(&[Ty]) -> Result<Ty, ArgError> {
    move |args: &[Ty]| {
        for (i, t) in args.iter().enumerate() {
            if !Param::AnyVec.accepts(&t.kind) {
                // (`4·1` as the Grübler line prints it, `R·p` as a product)
                let sign = if what == "dot" { "·" } else { "×" };
                return Err(ArgError::type_of(
                    i,
                    format!(
                        "{what} takes vectors, not {}; {sign} is the {what} product of two vectors: multiply with * or side by side (4*1, R * p)",
                        t.kind.a()
                    ),
                ));
            }
        }
        // the sizes the kinds know, as the numbers will be checked: cross
        // of 3-vectors, dot of two of one length
        if what == "cross"
            && let Some((i, t)) = args
                .iter()
                .enumerate()
                .find(|(_, t)| t.kind.vec_len().is_some_and(|n| n != 3))
        {
            return Err(ArgError::type_of(
                i,
                format!(
                    "argument {} of cross must be a 3-vector, not {}",
                    i + 1,
                    t.kind.a()
                ),
            ));
        }
        if what == "dot"
            && let (Some(m), Some(n)) = (args[0].kind.vec_len(), args[1].kind.vec_len())
            && m != n
        {
            return Err(ArgError::type_of(
                1,
                format!("dot of a {m}-vector and a {n}-vector"),
            ));
        }
        let frames =
            crate::check::rules::vector_pair(what, &args[0], &args[1]).map_err(|e| ArgError {
                arg: Some(1),
                kind: ErrorKind::Frame,
                message: format!("{}: {} and {}", e.message, e.lhs, e.rhs),
            })?;
        let kind = ret(args);
        let frames = if kind == Kind::Scalar {
            Frames::None
        } else {
            frames
        };
        Ok(Ty::new(kind, frames))
    }
}

fn cross_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    pair_rule("cross", |a| match &a[0].kind {
        Kind::Vector(_) => Kind::Vector(Some(3)),
        _ => Kind::Vector(Some(3)),
    })(args)
}

fn dot_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    pair_rule("dot", |_| Kind::Scalar)(args)
}

fn vee_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    let kind = match args[0].kind.shape() {
        Some((Some(4), Some(4))) => Kind::Twist,
        Some((Some(3), Some(3))) => Kind::Vector(Some(3)),
        _ if args[0].kind == Kind::Unknown => Kind::Unknown,
        _ => {
            return Err(ArgError::type_of(
                0,
                format!("vee takes so(3) or se(3), not {}", args[0].kind.a()),
            ));
        }
    };
    Ok(Ty::new(kind, args[0].frames))
}

fn untag_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    Ok(Ty::plain(args[0].kind))
}

fn matrix_ctor_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    for (i, t) in args.iter().enumerate() {
        if !t.kind.maybe_scalar() {
            return Err(ArgError::type_of(
                i,
                format!("sizes are numbers, not {}", t.kind.a()),
            ));
        }
    }
    Ok(Ty::plain(Kind::Matrix(None, None)))
}

fn sized(a: &Args) -> Result<(usize, usize), Diagnostic> {
    let side = |i: usize| -> Result<usize, Diagnostic> {
        let x = a.decided(i)?.value();
        if x.fract() != 0.0 || x < 0.0 || !x.is_finite() {
            return Err(a.error(
                i,
                ErrorKind::Domain,
                format!("a size must be a whole number ≥ 0, got {x}"),
            ));
        }
        if x > ops::MAX_DIM as f64 {
            return Err(a.error(
                i,
                ErrorKind::Domain,
                format!("a side of {x} is too large (at most {})", ops::MAX_DIM),
            ));
        }
        Ok(x as usize)
    };
    let r = side(0)?;
    let c = if a.len() > 1 { side(1)? } else { r };
    if r * c > ops::MAX_ELEMENTS {
        return Err(a.domain(format!(
            "{r}×{c} is too large (at most {} entries)",
            ops::MAX_ELEMENTS
        )));
    }
    crate::budget::room((r * c) as u64).map_err(|stop| a.domain(stop.to_string()))?;
    Ok((r, c))
}

pub(super) fn builtins() -> Vec<Builtin> {
    use Area::*;
    use Param::*;
    vec![
        Builtin {
            name: "exp",
            aliases: &["expm"],
            signature: "exp(X: so3 | se3 | so2 | se2 | square matrix | scalar) -> SO3 | SE3 | SO2 | SE2 | matrix | scalar",
            section: "§3.2.3.2 (3.51), §3.3.3.1 Prop. 3.16, Exercises 3.33–3.35",
            doc: "the matrix exponential: e^[ω]θ ∈ SO(3), e^[S]θ ∈ SE(3), e^{At} for any square A (over a symbol t in closed form, up to 3×3 with exact eigenvalues: eq. 3.41–3.48)",
            example: "exp([(0, 0, 1)] (pi/2))",
            area: LinearAlgebra,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: exp_rule,
            },
            eval: eval_exp,
        },
        Builtin {
            name: "log",
            aliases: &["logm", "ln"],
            signature: "log(X: SO3 | SE3 | SO2 | SE2 | scalar) -> so3 | se3 | so2 | se2 | scalar",
            section: "§3.2.3.3, §3.3.3.2",
            doc: "the matrix logarithm [ω̂]θ or [S]θ with θ ∈ [0, π] (the book's three cases), or ln x",
            example: "log([0, 0, 1; 1, 0, 0; 0, 1, 0])",
            area: LinearAlgebra,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: log_rule,
            },
            eval: eval_log,
        },
        Builtin {
            name: "inv",
            aliases: &["inverse"],
            signature: "inv(X: square matrix | scalar) -> same",
            section: "§3.2.1.1 Prop. 3.1, §3.3.1.1 Prop. 3.10",
            doc: "inverse; X_ab⁻¹ = X_ba (closed forms for SO(3) and SE(3))",
            example: "inv(RpToTrans(Rotz(pi/2), (1, 2, 3)))",
            area: LinearAlgebra,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: inv_rule,
            },
            eval: super::conditioning::eval_inv,
        },
        Builtin {
            name: "transpose",
            aliases: &[],
            signature: "transpose(X: matrix) -> matrix",
            section: "—",
            doc: "the transpose, X.T",
            example: "transpose([1, 2; 3, 4])",
            area: LinearAlgebra,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: transpose_rule,
            },
            eval: |a| Ok(ops::transpose(a.value(0))),
        },
        Builtin {
            name: "det",
            aliases: &[],
            signature: "det(X: square matrix) -> scalar",
            section: "§3.2.1",
            doc: "the determinant (+1 for a rotation)",
            example: "det(Rotz(1))",
            area: LinearAlgebra,
            typing: Typing::Fixed {
                params: &[Square],
                ret: scalar,
                frames: FrameRule::None,
            },
            eval: super::conditioning::eval_det,
        },
        Builtin {
            name: "trace",
            aliases: &["tr"],
            signature: "trace(X: square matrix) -> scalar",
            section: "§3.2.3.3",
            doc: "the sum of the diagonal (tr R = 1 + 2 cos θ)",
            example: "trace(Rotz(1))",
            area: LinearAlgebra,
            typing: Typing::Fixed {
                params: &[Square],
                ret: scalar,
                frames: FrameRule::None,
            },
            eval: |a| Ok(Value::scalar(a.square(0)?.to_dmatrix().trace())),
        },
        Builtin {
            name: "norm",
            aliases: &[],
            signature: "norm(x: vector | matrix) -> scalar",
            section: "—",
            doc: "the Euclidean (Frobenius) norm",
            example: "norm((3, 4, 0))",
            area: LinearAlgebra,
            typing: Typing::Fixed {
                params: &[Mat],
                ret: scalar,
                frames: FrameRule::None,
            },
            eval: |a| Ok(Value::scalar(crate::lie::norm(&a.mat(0)?.to_dmatrix()))),
        },
        Builtin {
            name: "cross",
            aliases: &[],
            signature: "cross(u: 3-vector, v: 3-vector) -> 3-vector",
            section: "§3.2.2",
            doc: "the cross product u × v = [u] v (same frame)",
            example: "cross((1, 0, 0), (0, 1, 0))",
            area: LinearAlgebra,
            typing: Typing::Custom {
                arity: (2, 2),
                rule: cross_rule,
            },
            eval: |a| {
                let (u, v): (Vec3, Vec3) = (a.vec3(0)?, a.vec3(1)?);
                Ok(Value::num(Kind::Vector(Some(3)), &u.cross(&v)))
            },
        },
        Builtin {
            name: "dot",
            aliases: &[],
            signature: "dot(u: vector, v: vector) -> scalar",
            section: "§3.4",
            doc: "the dot product uᵀv (same frame); power is dot(V, F)",
            example: "dot((1, 2, 3), (4, 5, 6))",
            area: LinearAlgebra,
            typing: Typing::Custom {
                arity: (2, 2),
                rule: dot_rule,
            },
            eval: |a| {
                let (u, v) = (a.vec(0)?, a.vec(1)?);
                if u.len() != v.len() {
                    return Err(a.error(
                        1,
                        ErrorKind::Type,
                        format!("dot of a {}-vector and a {}-vector", u.len(), v.len()),
                    ));
                }
                Ok(Value::scalar(u.dot(&v)))
            },
        },
        Builtin {
            name: "vee",
            aliases: &[],
            signature: "vee(X: so3 | se3) -> 3-vector | twist",
            section: "§3.2.2, §3.3.2",
            doc: "so3ToVec for 3×3, se3ToVec for 4×4",
            example: "vee([0, -3, 2; 3, 0, -1; -2, 1, 0])",
            area: Rotations,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: vee_rule,
            },
            eval: |a| match a.mat(0)?.shape() {
                (4, 4) => Ok(Value::num(Kind::Twist, &a.expc6(0)?)),
                _ => Ok(Value::num(Kind::Vector(Some(3)), &a.expc3(0)?)),
            },
        },
        Builtin {
            name: "eye",
            aliases: &["I"],
            signature: "eye(n: scalar) -> n×n identity",
            section: "—",
            doc: "the n×n identity matrix",
            example: "eye(3)",
            area: LinearAlgebra,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: matrix_ctor_rule,
            },
            eval: |a| {
                let (n, _) = sized(a)?;
                let m = Num::identity(n);
                Ok(Value::Num {
                    kind: convert::classify(&m),
                    m,
                    exact: crate::values::exact::Exact::Typed,
                })
            },
        },
        Builtin {
            name: "zeros",
            aliases: &[],
            signature: "zeros(rows: scalar, cols: scalar) -> matrix",
            section: "—",
            doc: "a matrix of zeros (zeros(n) is n×n)",
            example: "zeros(3, 1)",
            area: LinearAlgebra,
            typing: Typing::Custom {
                arity: (1, 2),
                rule: matrix_ctor_rule,
            },
            eval: |a| {
                let (r, c) = sized(a)?;
                let m = Num::zeros(r, c);
                Ok(Value::Num {
                    kind: convert::classify(&m),
                    m,
                    exact: crate::values::exact::Exact::Typed,
                })
            },
        },
        Builtin {
            name: "NearZero",
            aliases: &["near_zero"],
            signature: "NearZero(z: scalar) -> bool",
            section: "§3.6",
            doc: "true if |z| < 1e-6",
            example: "NearZero(1e-7)",
            area: Tests,
            typing: Typing::Fixed {
                params: &[Scalar],
                ret: || Kind::Bool,
                frames: FrameRule::None,
            },
            eval: super::decisions::eval_near_zero,
        },
        Builtin {
            name: "Normalize",
            aliases: &["normalize"],
            signature: "Normalize(V: vector) -> vector",
            section: "§3.6",
            doc: "the unit vector V/‖V‖",
            example: "Normalize((1, 2, 3))",
            area: LinearAlgebra,
            typing: Typing::Fixed {
                params: &[AnyVec],
                ret: || Kind::Vector(None),
                frames: FrameRule::Same(0),
            },
            eval: super::decisions::eval_normalize,
        },
        Builtin {
            name: "untag",
            aliases: &[],
            signature: "untag(x) -> x without frames",
            section: "LANGUAGE §6",
            doc: "the same value with no frames, to use a framed value as a plain operator",
            example: "untag(Rotz(1))",
            area: LinearAlgebra,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: untag_rule,
            },
            eval: |a| Ok(a.value(0).clone()),
        },
    ]
}
