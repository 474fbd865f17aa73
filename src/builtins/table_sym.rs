//! Builtins on symbolic values (LANGUAGE.md §7): the closed form of every
//! builtin that §7 lists when an argument has symbolic entries — Rot and
//! Rotx/y/z and exp of so(3) by Rodrigues (3.51), exp of se(3) by
//! Proposition 3.16, inverses by transpose, the adjoint (Definition 3.20),
//! [x], cross, dot, det, trace, the Euler/RPY/quaternion maps — and of
//! the builtins of symbols themselves ([`super::table_calculus`]); tan,
//! cot, sec and csc of a symbol as quotients of sin and cos.

use crate::check::ty::Kind;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::span::Span;
use crate::sym::Expr;
use crate::sym::branch::{self, Branch};
use crate::sym::expr::Func;
use crate::sym::matrix::{self as sm, Mat};
use crate::values::formula::{self, make, mat_of, scalar, scalar_of};
use crate::values::value::Value;
use num_traits::{One, Zero};

type Out = Option<Result<Value, String>>;

fn ok(v: Value) -> Out {
    Some(Ok(v))
}

/// A constant vector's unit direction as expressions: ω/‖ω‖, exact when
/// ‖ω‖ is a closed form.
fn unit(v: &Mat) -> Option<Vec<Expr>> {
    let n2 = v
        .data
        .iter()
        .fold(Expr::zero(), |acc, x| acc.add(&x.mul(x)));
    n2.as_const()?;
    let inv = Expr::sqrt(&n2).recip()?;
    Some(v.data.iter().map(|x| x.mul(&inv)).collect())
}

fn vec3(e: &[Expr]) -> Value {
    make(&Kind::Vector(Some(3)), Mat::column(e.to_vec()))
}

fn cross(a: &[Expr], b: &[Expr]) -> Vec<Expr> {
    let c = |i: usize, j: usize| a[i].mul(&b[j]).sub(&a[j].mul(&b[i]));
    vec![c(1, 2), c(2, 0), c(0, 1)]
}

fn dot(a: &[Expr], b: &[Expr]) -> Expr {
    a.iter()
        .zip(b)
        .fold(Expr::zero(), |acc, (x, y)| acc.add(&x.mul(y)))
}

/// Rotz(a) Roty(b) Rotx(c) and the like: a product of axis rotations.
fn rot_chain(axes: [usize; 3], angles: [&Expr; 3]) -> Option<Mat> {
    let r = sm::rot_axis(axes[0], angles[0]).mul(&sm::rot_axis(axes[1], angles[1]))?;
    r.mul(&sm::rot_axis(axes[2], angles[2]))
}

/// The most terms of ‖q‖² that `rot_quat` of a symbolic q divides by.
const MAX_QUAT_NORM: usize = 24;

/// The rotation of a quaternion (w, x, y, z), normalized first as the
/// numeric `rot_quat` does (Appendix B): R = I + 2(w[v] + [v]²)/‖q‖².
/// None when ‖q‖² has no reciprocal (zero).
fn rot_quat(q: &[Expr]) -> Option<Mat> {
    let norm2 = q.iter().fold(Expr::zero(), |acc, x| acc.add(&x.mul(x)));
    // (a unit quaternion as typed needs no quotient; a quotient by a long
    // sum is kept as the call, computed once its symbols have numbers)
    let two = if norm2 == Expr::one() {
        Expr::int(2)
    } else if norm2.size() > MAX_QUAT_NORM {
        return None;
    } else {
        norm2.recip()?.mul(&Expr::int(2))
    };
    let p = |i: usize, j: usize| q[i].mul(&q[j]).mul(&two);
    let one = Expr::one();
    let rows = vec![
        vec![
            one.sub(&p(2, 2)).sub(&p(3, 3)),
            p(1, 2).sub(&p(0, 3)),
            p(1, 3).add(&p(0, 2)),
        ],
        vec![
            p(1, 2).add(&p(0, 3)),
            one.sub(&p(1, 1)).sub(&p(3, 3)),
            p(2, 3).sub(&p(0, 1)),
        ],
        vec![
            p(1, 3).sub(&p(0, 2)),
            p(2, 3).add(&p(0, 1)),
            one.sub(&p(1, 1)).sub(&p(2, 2)),
        ],
    ];
    Mat::from_rows(rows)
}

/// The unit quaternion (w, x, y, z) of R, w = √(1 + tr R)/2 ≥ 0 (Appendix B).
fn quat(r: &Mat) -> Option<Vec<Expr>> {
    let g = |i: usize, j: usize| r.get(i, j).clone();
    let w = Expr::sqrt(&Expr::one().add(&r.trace())).mul(&Expr::num(0.5));
    let k = w.scale(&crate::sym::coef::Coef::int(4)).recip()?;
    Some(vec![
        w,
        g(2, 1).sub(&g(1, 2)).mul(&k),
        g(0, 2).sub(&g(2, 0)).mul(&k),
        g(1, 0).sub(&g(0, 1)).mul(&k),
    ])
}

fn tuple(parts: Vec<Value>) -> Value {
    Value::Tuple(parts)
}

/// The symbolic path of builtin `name`: None when it has none (the call is
/// then kept as a call over the symbols).
pub fn eval_symbolic(name: &str, vals: &[Value], kind: &Kind) -> Out {
    let ms: Vec<Mat> = vals.iter().map(mat_of).collect::<Option<_>>()?;
    let shape = |i: usize| (ms[i].rows, ms[i].cols);
    let s = |i: usize| scalar_of(&vals[i]);
    match (name, ms.len()) {
        ("Rotx" | "Roty" | "Rotz", 1) => {
            let axis = ["Rotx", "Roty", "Rotz"].iter().position(|n| *n == name)?;
            ok(make(&Kind::SO3, sm::rot_axis(axis, &s(0)?)))
        }
        ("Rot", 2) if shape(0) == (3, 1) => {
            let axis = unit(&ms[0]).or_else(|| crate::sym::axis::unit_direction(&ms[0].data))?;
            ok(make(&Kind::SO3, sm::rodrigues(&axis, &s(1)?)))
        }
        ("exp" | "MatrixExp3" | "MatrixExp6", 1) => exp(&ms[0], kind),
        ("inv", 1) => match formula::fits_inverse(&vals[0].kind(), &ms[0]) {
            Err(e) => Some(Err(e)),
            Ok(()) => ok(make(kind, formula::inverse(&vals[0].kind(), &ms[0])?)),
        },
        ("RotInv", 1) if shape(0) == (3, 3) => ok(make(&Kind::SO3, ms[0].transpose())),
        ("TransInv", 1) if shape(0) == (4, 4) => ok(make(&Kind::SE3, sm::trans_inv(&ms[0])?)),
        ("Adjoint", 1) if shape(0) == (4, 4) => {
            // [p] R's work and terms counted before it is formed, its size
            // after (issue 21)
            let (r, p) = (ms[0].block(0..3, 0..3), ms[0].block(0..3, 3..4));
            if let Err(e) = formula::fits(&sm::skew(&p.data), &r, "adjoint") {
                return Some(Err(e));
            }
            let a = sm::adjoint(&ms[0])?;
            let limit = crate::values::symbolic::MAX_SYM_NODES;
            if a.size() > limit {
                return Some(Err(format!(
                    "symbolic expression too large: the adjoint has {} terms (more than {limit})",
                    a.size()
                )));
            }
            ok(make(kind, a))
        }
        ("ad" | "lie_bracket", 1) if shape(0) == (6, 1) => ok(make(
            &Kind::Matrix(Some(6), Some(6)),
            sm::small_adjoint(&ms[0].data),
        )),
        ("VecToso3", 1) if shape(0) == (3, 1) => ok(make(&Kind::So3, sm::skew(&ms[0].data))),
        ("VecTose3", 1) if shape(0) == (6, 1) => {
            ok(make(&Kind::Se3, sm::twist_matrix(&ms[0].data)))
        }
        ("so3ToVec" | "vee", 1) if shape(0) == (3, 3) => ok(vec3(&sm::unskew(&ms[0]))),
        // (exponential coordinates already, as with numbers: `so3ToVec`
        // and `se3ToVec` take the vector or its matrix, §3.6)
        ("so3ToVec", 1) if shape(0) == (3, 1) => ok(vec3(&ms[0].data)),
        ("se3ToVec", 1) if shape(0) == (6, 1) => ok(make(&Kind::Twist, ms[0].clone())),
        ("se3ToVec" | "vee", 1) if shape(0) == (4, 4) => {
            let mut v = sm::unskew(&ms[0].block(0..3, 0..3));
            v.extend(ms[0].block(0..3, 3..4).data);
            ok(make(&Kind::Twist, Mat::column(v)))
        }
        ("cross", 2) if shape(0) == (3, 1) && shape(1) == (3, 1) => {
            ok(vec3(&cross(&ms[0].data, &ms[1].data)))
        }
        ("dot", 2) if shape(0) == shape(1) => ok(scalar(dot(&ms[0].data, &ms[1].data))),
        ("norm", 1) if ms[0].cols == 1 => ok(scalar(Expr::sqrt(&dot(&ms[0].data, &ms[0].data)))),
        ("det", 1) => ok(scalar(ms[0].det()?)),
        ("trace", 1) => ok(scalar(ms[0].trace())),
        ("transpose", 1) => ok(make(&Kind::Unknown, ms[0].transpose())),
        ("RpToTrans", 2) if shape(0) == (3, 3) && shape(1) == (3, 1) => {
            ok(make(&Kind::SE3, sm::rp_to_trans(&ms[0], &ms[1])))
        }
        // frame(R): [R, 0; 0, 1]
        ("RpToTrans", 1) if shape(0) == (3, 3) => ok(make(
            &Kind::SE3,
            sm::rp_to_trans(&ms[0], &sm::Mat::zeros(3, 1)),
        )),
        ("TransToRp", 1) if shape(0) == (4, 4) => ok(tuple(vec![
            make(&Kind::SO3, ms[0].block(0..3, 0..3)),
            make(&Kind::Vector(Some(3)), ms[0].block(0..3, 3..4)),
        ])),
        ("SE2", 3) => {
            // (3.16): [cos θ, −sin θ, x; sin θ, cos θ, y; 0, 0, 1]
            let (c, sn) = (Expr::cos(&s(0)?), Expr::sin(&s(0)?));
            let rows = vec![
                vec![c.clone(), sn.neg(), s(1)?],
                vec![sn, c, s(2)?],
                vec![Expr::zero(), Expr::zero(), Expr::one()],
            ];
            ok(make(&Kind::SE2, Mat::from_rows(rows)?))
        }
        ("Trans", 1) if shape(0) == (3, 1) => {
            ok(make(&Kind::SE3, sm::rp_to_trans(&Mat::identity(3), &ms[0])))
        }
        ("displacement", 2) if shape(0) == (4, 4) && shape(1) == (4, 4) => {
            let inv = sm::trans_inv(&ms[0])?;
            ok(make(&Kind::SE3, ms[1].mul(&inv)?))
        }
        ("twist" | "wrench", 2) if shape(0) == (3, 1) && shape(1) == (3, 1) => {
            let mut v = ms[0].data.clone();
            v.extend(ms[1].data.clone());
            ok(make(kind, Mat::column(v)))
        }
        ("screw" | "ScrewToAxis", 3) if shape(0) == (3, 1) && shape(1) == (3, 1) => {
            // S = (ŝ, −ŝ × q + h ŝ) (§3.3.2.2), ŝ normalized as with numbers
            let (q, h) = (&ms[0].data, s(2)?);
            // (a closed form with ŝ as given is another axis where ‖ŝ‖ ≠ 1)
            let sh = &match unit(&ms[1]).or_else(|| crate::sym::axis::unit_direction(&ms[1].data)) {
                Some(sh) => sh,
                None if ms[1].data.iter().all(|e| e.as_const().is_some()) => {
                    return Some(Err(
                        "the screw direction ŝ must be a nonzero unit vector".into()
                    ));
                }
                None => return None,
            };
            // (an infinite pitch is a pure translation (0, ±ŝ), as with numbers)
            if let Some(inf) = h.as_f64().filter(|x| x.is_infinite()) {
                let mut out = vec![Expr::zero(); 3];
                out.extend(
                    sh.iter()
                        .map(|e| if inf < 0.0 { e.neg() } else { e.clone() }),
                );
                return ok(make(kind, Mat::column(out)));
            }
            let v = cross(sh, q);
            let mut out = sh.clone();
            out.extend(v.iter().zip(sh).map(|(a, b)| a.neg().add(&b.mul(&h))));
            ok(make(kind, Mat::column(out)))
        }
        ("rot_zyx", 3) => ok(make(
            &Kind::SO3,
            rot_chain([2, 1, 0], [&s(0)?, &s(1)?, &s(2)?])?,
        )),
        ("rot_zxz", 3) => ok(make(
            &Kind::SO3,
            rot_chain([2, 0, 2], [&s(0)?, &s(1)?, &s(2)?])?,
        )),
        ("rot_rpy", 3) => ok(make(
            &Kind::SO3,
            rot_chain([2, 1, 0], [&s(2)?, &s(1)?, &s(0)?])?,
        )),
        ("rot_quat", 1) if shape(0) == (4, 1) => ok(make(&Kind::SO3, rot_quat(&ms[0].data)?)),
        ("quat_mul", 2) if shape(0) == (4, 1) && shape(1) == (4, 1) => {
            let (a, b) = (&ms[0].data, &ms[1].data);
            let w = a[0].mul(&b[0]).sub(&dot(&a[1..], &b[1..]));
            let c = cross(&a[1..], &b[1..]);
            let mut out = vec![w];
            for i in 0..3 {
                out.push(a[0].mul(&b[i + 1]).add(&b[0].mul(&a[i + 1])).add(&c[i]));
            }
            ok(make(&Kind::Vector(Some(4)), Mat::column(out)))
        }
        ("euler_zyx" | "euler_zxz" | "rpy" | "quat" | "cayley" | "log" | "MatrixLog3", 1)
            if shape(0) == (3, 3) =>
        {
            inverse_map(name, &ms[0])
        }
        ("log" | "MatrixLog6", 1) if shape(0) == (4, 4) => inverse_map(name, &ms[0]),
        // (log(exp(u)) = u for a real u)
        ("log", 1)
            if shape(0) == (1, 1) && crate::sym::inverse::exp_arg(&ms[0].data[0]).is_some() =>
        {
            ok(scalar(crate::sym::inverse::exp_arg(&ms[0].data[0])?))
        }
        ("sin", 1) => ok(scalar(Expr::sin(&s(0)?))),
        ("cos", 1) => ok(scalar(Expr::cos(&s(0)?))),
        ("tan" | "cot" | "sec" | "csc", 1) => ok(scalar(ratio(name, &s(0)?)?)),
        ("sqrt", 1) => ok(scalar(Expr::sqrt(&s(0)?))),
        ("atan2", 2) => {
            let (y, x) = (s(0)?, s(1)?);
            ok(scalar(
                branch::atan2(&y, &x).map_or_else(|| Expr::atan2(&y, &x), |(t, _)| t),
            ))
        }
        ("abs", 1) => ok(scalar(Expr::abs(&s(0)?))),
        ("asin" | "acos" | "atan", 1) => {
            let (f, g): (Func, fn(f64) -> f64) = match name {
                "asin" => (Func::Asin, f64::asin),
                "acos" => (Func::Acos, f64::acos),
                _ => (Func::Atan, f64::atan),
            };
            ok(scalar(Expr::apply(f, &s(0)?, g)))
        }
        ("diff", 2) => Some(super::table_calculus::diff(&vals[0], &ms[0], &ms[1], kind)),
        ("simplify", 1) => ok(make(
            &vals[0].kind(),
            ms[0].map(crate::sym::together::simplest),
        )),
        ("expand", 1) => ok(make(&vals[0].kind(), ms[0].map(Expr::cancel))),
        ("subs", 3) => Some(super::table_calculus::subs(
            &vals[0], &ms[0], &ms[1], &ms[2],
        )),
        _ => None,
    }
}

/// The closed form of an inverse map of a symbolic rotation on its branch
/// ([`branch`]), and that branch; None where there is none.
fn on_branch(name: &str, r: &Mat) -> Option<(Value, Branch)> {
    let scalars = |v: Vec<Expr>| vec3(&v);
    Some(match name {
        "euler_zyx" | "rpy" => {
            let (mut v, b) = branch::euler(r, true)?;
            if name == "rpy" {
                v.reverse();
            }
            (scalars(v), b)
        }
        "euler_zxz" => {
            let (v, b) = branch::euler(r, false)?;
            (scalars(v), b)
        }
        "quat" => {
            let (v, b) = branch::quat(r)?;
            (make(&Kind::Vector(Some(4)), Mat::column(v)), b)
        }
        "cayley" => {
            let (v, b) = branch::cayley(r)?;
            (make(&Kind::Vector(Some(3)), Mat::column(v)), b)
        }
        "log" if r.rows == 4 => {
            let (m, b) = branch::log6(r)?;
            (make(&Kind::Se3, m), b)
        }
        "MatrixLog6" => {
            let (m, b) = branch::log6(r)?;
            let mut v = sm::unskew(&m.block(0..3, 0..3));
            v.extend(m.block(0..3, 3..4).data);
            (make(&Kind::Vector(Some(6)), Mat::column(v)), b)
        }
        "log" => {
            let (m, b) = branch::log3(r)?;
            (make(&Kind::So3, m), b)
        }
        "MatrixLog3" => {
            let (m, b) = branch::log3(r)?;
            (vec3(&sm::unskew(&m)), b)
        }
        _ => return None,
    })
}

/// euler_zyx, euler_zxz, rpy, quat, cayley and the logs of a symbolic
/// rotation: the closed form on its branch, else the general form (atan2
/// and sqrt, right on every branch), else None (the call is kept).
fn inverse_map(name: &str, r: &Mat) -> Out {
    if let Some((v, _)) = on_branch(name, r) {
        return ok(v);
    }
    match name {
        "quat" => ok(make(&Kind::Vector(Some(4)), Mat::column(quat(r)?))),
        _ => None,
    }
}

/// The note a closed form on a branch is printed with (LANGUAGE.md §7:
/// say which branch was assumed): `assumed cos(b) > 0 and a, b, c in
/// (−π, π]`. None when the call has no such form.
pub fn branch_note(name: &str, vals: &[Value], span: Span) -> Option<Diagnostic> {
    let (_, text) = branch_of(name, vals)?;
    Some(Diagnostic::note(ErrorKind::Domain, span, text))
}

/// The branch the closed form of `name` over `vals` holds on
/// ([`branch`]), with the note's text; None when the call has no such form.
pub fn branch_of(name: &str, vals: &[Value]) -> Option<(Branch, String)> {
    let (b, what) = match vals {
        [y, x] if name == "atan2" => {
            let (y, x) = (scalar_of(y)?, scalar_of(x)?);
            (branch::atan2(&y, &x)?.1, "symbolic arguments")
        }
        [v] => {
            let r = mat_of(v)?;
            let transform = (r.rows, r.cols) == (4, 4) && matches!(name, "log" | "MatrixLog6");
            if ((r.rows, r.cols) != (3, 3) && !transform) || r.as_f64().is_some() {
                return None;
            }
            let what = if transform {
                "a symbolic transform"
            } else {
                "a symbolic rotation"
            };
            (on_branch(name, &r)?.1, what)
        }
        _ => return None,
    };
    let show = |es: &[Expr]| {
        es.iter()
            .map(|e| crate::sym::print::expr(e, Default::default()))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut parts = Vec::new();
    if !b.positive.is_empty() {
        parts.push(format!("{} > 0", show(&b.positive)));
    }
    // −θ in (−π, π) is θ in (−π, π): each angle with its sign taken out
    // (θ in (−π, π] read so is −θ in [−π, π))
    let open = matches!(
        name,
        "log" | "MatrixLog3" | "MatrixLog6" | "quat" | "cayley"
    );
    let leads_minus = |e: &Expr| crate::sym::print::expr(e, Default::default()).starts_with('-');
    let (minus, plus): (Vec<Expr>, Vec<Expr>) = b.angles.iter().cloned().partition(leads_minus);
    let minus: Vec<Expr> = minus.iter().map(Expr::neg).collect();
    let (plus, minus) = if open {
        ([plus, minus].concat(), Vec::new())
    } else {
        (plus, minus)
    };
    let range = if open { "(−π, π)" } else { "(−π, π]" };
    if !plus.is_empty() {
        parts.push(format!("{} in {range}", show(&plus)));
    }
    if !minus.is_empty() {
        parts.push(format!("{} in [−π, π)", show(&minus)));
    }
    if parts.is_empty() {
        return None;
    }
    let text = format!(
        "{name} of {what}: the closed form on the branch {}",
        parts.join(" and ")
    );
    Some((b, text))
}

/// tan, cot, sec and csc as quotients of sin and cos (a kept reciprocal
/// that prints `tan(t)`); None at a pole (a zero denominator).
fn ratio(name: &str, x: &Expr) -> Option<Expr> {
    let (s, c) = (Expr::sin(x), Expr::cos(x));
    let (num, den) = match name {
        "tan" => (s, c),
        "cot" => (c, s),
        "sec" => (Expr::one(), c),
        _ => (Expr::one(), s),
    };
    Some(num.mul(&den.recip()?).cancel())
}

/// exp of a symbolic so(3) or se(3) matrix (or of a 3- or 6-vector of
/// exponential coordinates, as MatrixExp3/6 take), or of a scalar.
fn exp(m: &Mat, kind: &Kind) -> Out {
    match (m.rows, m.cols) {
        (1, 1) => ok(scalar(Expr::apply(Func::Exp, &m.data[0], f64::exp))),
        (3, 1) => ok(make(&Kind::SO3, sm::exp3(&sm::skew(&m.data))?)),
        (6, 1) => ok(make(&Kind::SE3, sm::exp6(&sm::twist_matrix(&m.data))?)),
        (3, 3) if m.add(&m.transpose(), false) == Some(Mat::zeros(3, 3)) => {
            ok(make(&Kind::SO3, sm::exp3(m)?))
        }
        (4, 4) if m.block(3..4, 0..4) == Mat::zeros(1, 4) => ok(make(&Kind::SE3, sm::exp6(m)?)),
        (r, c) if r == c => ok(make(kind, crate::sym::matexp::exp_square(m)?)),
        _ => None,
    }
}

/// A call on a `given` matrix whose value its kind decides (LANGUAGE.md
/// §7): `det` of a rotation or transform is 1 (Prop. 3.2; the SE(3)
/// determinant is its rotation's), `trace` of an so(3) or so(2) matrix is
/// 0 (skew-symmetric), `trace(I)` is n for the n×n identity a product of
/// inverses leaves (`trace(R^T R)` printed `trace(I)`). Given the
/// builtin's name, its arguments and their kinds; None for anything else.
pub fn known_by_kind(name: &str, args: &[Value], tys: &[crate::check::ty::Ty]) -> Option<Value> {
    let ([Value::Sym(s)], [ty]) = (args, tys) else {
        return None;
    };
    let k = &ty.kind;
    use crate::values::symbolic::Tree;
    let x = match (name, k, s) {
        ("det", Kind::SO3 | Kind::SO2 | Kind::SE3 | Kind::SE2, _) => 1.0,
        ("trace", Kind::So3 | Kind::So2, _) => 0.0,
        ("trace", _, Tree::Identity(_)) => match k.shape()? {
            (Some(n), Some(m)) if n == m => n as f64,
            _ => return None,
        },
        _ => return None,
    };
    Some(Value::Num {
        kind: Kind::Scalar,
        m: crate::values::num::Num::Scalar(x),
        exact: crate::values::exact::Exact::Typed,
    })
}
