//! Builtins for other representations of orientation (Appendix B, with the
//! conventions of LANGUAGE.md §8), planar motions (§3.1, Example 3.4), the
//! membership tests and projections of §3.6, and mechanisms (chapter 2).

use super::{Area, ArgError, Args, Builtin, FrameRule, Param, Typing};
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::lie::{LieGroup, Mat3, Mat4, SE2, SE3, SO3, Vec3, project, repr, se2};
use crate::values::convert::{self, Group};
use crate::values::value::Value;

fn so3k() -> Kind {
    Kind::SO3
}
fn v3() -> Kind {
    Kind::Vector(Some(3))
}
fn v4() -> Kind {
    Kind::Vector(Some(4))
}
fn boolk() -> Kind {
    Kind::Bool
}
fn scalar() -> Kind {
    Kind::Scalar
}

/// How Euler-type angles are extracted: from the floats, or with gimbal
/// lock decided by the caller; and the two entries that are 0 exactly at
/// gimbal lock (r₁₁, r₂₁ for ZYX and roll–pitch–yaw; r₁₃, r₂₃ for ZXZ).
type Extract = (
    fn(&Mat3) -> repr::Angles,
    fn(&Mat3, bool) -> repr::Angles,
    [(usize, usize); 2],
);

/// Angles from a rotation; a gimbal-lock note becomes a warning. Near
/// gimbal lock (the two entries below 1e-12 in floats) the lock is decided
/// by the rotation's exact form or certified entries when it has them
/// (`Args::entries`), and the angles read from those entries.
fn angles(a: &mut Args, (f, decided, pair): Extract) -> Result<Value, Diagnostic> {
    let r = a.so3(0)?;
    let m = r.matrix();
    let refined = gimbal_reading(m, pair, || a.entries(0)).map(|(x, lock)| decided(&x, lock));
    let out = refined.unwrap_or_else(|| f(m));
    if let Some(note) = out.note {
        a.warnings
            .push(Diagnostic::warning(ErrorKind::Domain, a.call_span, note));
    }
    Ok(Value::num(v3(), &out.angles))
}

/// Gimbal lock of the Euler-type angles of `m` (App. B: cos b = 0 for ZYX
/// and roll–pitch–yaw, sin b = 0 for ZXZ, the two entries `pair` both 0)
/// as the builtins decide it: near the lock (the two entries below 1e-12
/// in floats) by the rotation's `entries` (exact form or certified),
/// giving the entries' floats and the decision; None where the floats
/// decide (away from the lock, or the entries do not settle it). `explain`
/// takes the same branch through this.
pub fn gimbal_reading(
    m: &Mat3,
    [p, q]: [(usize, usize); 2],
    entries: impl FnOnce() -> Option<crate::values::exact_mat::Entries>,
) -> Option<(Mat3, bool)> {
    if m[p].hypot(m[q]) >= 1e-12 {
        return None;
    }
    let e = entries()?;
    let x = Mat3::from_row_slice(&e.floats);
    let at = |(i, j): (usize, usize)| e.zero[i * 3 + j];
    // (the entries of the matrix as read, not of one projected)
    let lock = match (at(p), at(q)) {
        (Some(true), Some(true)) => true,
        (Some(false), _) | (_, Some(false)) => false,
        _ => return None,
    };
    ((x - m).amax() <= 1e-12).then_some((x, lock))
}

fn se2_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    match args.len() {
        1 => {
            if !Param::Square.accepts(&args[0].kind) {
                return Err(ArgError::type_of(
                    0,
                    format!("SE2 takes a 3×3 matrix, not {}", args[0].kind.a()),
                ));
            }
            Ok(Ty::new(Kind::SE2, args[0].frames))
        }
        _ => {
            for (i, t) in args.iter().enumerate() {
                if !Param::Scalar.accepts(&t.kind) {
                    return Err(ArgError::type_of(
                        i,
                        format!("SE2(theta, x, y) takes numbers, not {}", t.kind.a()),
                    ));
                }
            }
            Ok(Ty::plain(Kind::SE2))
        }
    }
}

fn dof_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    if args[0].kind != Kind::Mechanism && args[0].kind != Kind::Unknown {
        return Err(ArgError::type_of(
            0,
            format!("dof takes a mechanism, not {}", args[0].kind.a()),
        ));
    }
    Ok(Ty::scalar())
}

fn distance_value(a: &Args, g: Group) -> Result<Value, Diagnostic> {
    let m = a.mat(0)?;
    if m.shape() != (g.size(), g.size()) {
        return Err(a.error(
            0,
            ErrorKind::Type,
            format!("expected a {0}×{0} matrix", g.size()),
        ));
    }
    let d = convert::distance(m, g).unwrap_or(f64::INFINITY);
    // (near the group RᵀR − I cancels: summed again with its roundings
    // kept, so that a small distance has all its digits)
    let d = if d < 1e-4 {
        let n = g.size();
        let k = if matches!(g, Group::SE3 | Group::SE2) {
            n - 1
        } else {
            n
        };
        project::gram_distance(m.as_slice(), n, k)
    } else {
        d
    };
    // (within rounding of 0: the exact matrix's own distance when it has
    // one — 1.41e-20 for [1, 1e-20, 0; 0, 1, 0; 0, 0, 1], 0 for an exact
    // rotation — where the floats' is rounding noise)
    let exact = (d <= convert::ACCEPT_TOL)
        .then(|| crate::values::exact_mat::form(a.value(0)))
        .flatten()
        .and_then(|e| crate::values::exact_mat::group_gap(&e, g));
    Ok(Value::scalar(exact.map_or(d, |gap| gap.distance)))
}

/// `TestIfSO3`/`TestIfSE3` (§3.6): the book's distance `d` (a float) below
/// 1e-3, decided by the exact form of `v` when `d` is within rounding of
/// 1e-3 (a distance of exactly 1e-3 is not below it).
fn test_below(v: &Value, g: Group, d: f64) -> bool {
    crate::values::exact_mat::distance_below(v, g, d, project::TEST_TOL)
        .unwrap_or(d.abs() < project::TEST_TOL)
}

fn projection(a: &mut Args, g: Group) -> Result<Value, Diagnostic> {
    let m = a.mat(0)?;
    if m.shape() != (g.size(), g.size()) || m.iter().any(|x| !x.is_finite()) {
        return Err(a.error(
            0,
            ErrorKind::Type,
            format!("expected a {0}×{0} matrix of finite numbers", g.size()),
        ));
    }
    let m = m.clone();
    // (a rotation block with many nearest rotations: one of them, said)
    let block = Mat3::from_fn(|i, j| m.to_dmatrix()[(i, j)]);
    if let Some(tie) = project::so3_tie(&block) {
        let span = a.call_span;
        a.warnings.push(super::notes::projection_tie(span, g, tie));
    }
    Ok(Value::Num {
        kind: g.kind(),
        m: convert::project(&m, g),
        exact: Default::default(),
    })
}

pub(super) fn builtins() -> Vec<Builtin> {
    use Area::*;
    use Param::*;
    vec![
        Builtin {
            name: "rot_zyx",
            aliases: &["RotZYX"],
            signature: "rot_zyx(a: scalar, b: scalar, c: scalar) -> SO3",
            section: "Appendix B",
            doc: "ZYX Euler angles: Rotz(a) Roty(b) Rotx(c)",
            example: "rot_zyx(10 deg, 20 deg, 30 deg)",
            area: Representations,
            typing: Typing::Fixed {
                params: &[Scalar, Scalar, Scalar],
                ret: so3k,
                frames: FrameRule::None,
            },
            eval: |a| {
                Ok(Value::num(
                    Kind::SO3,
                    &repr::rot_zyx(a.scalar(0)?, a.scalar(1)?, a.scalar(2)?),
                ))
            },
        },
        Builtin {
            name: "euler_zyx",
            aliases: &["EulerZYX"],
            signature: "euler_zyx(R: SO3) -> (a, b, c) with b ∈ [−π/2, π/2]",
            section: "Appendix B",
            doc: "ZYX Euler angles of a rotation (at gimbal lock a = 0 is chosen and a warning says so)",
            example: "euler_zyx(rot_zyx(10 deg, 20 deg, 30 deg))",
            area: Representations,
            typing: Typing::Fixed {
                params: &[Rot],
                ret: v3,
                frames: FrameRule::None,
            },
            eval: |a| {
                angles(
                    a,
                    (repr::euler_zyx, repr::euler_zyx_decided, [(0, 0), (1, 0)]),
                )
            },
        },
        Builtin {
            name: "rot_zxz",
            aliases: &["RotZXZ"],
            signature: "rot_zxz(a: scalar, b: scalar, c: scalar) -> SO3",
            section: "Appendix B",
            doc: "ZXZ Euler angles: Rotz(a) Rotx(b) Rotz(c)",
            example: "rot_zxz(10 deg, 20 deg, 30 deg)",
            area: Representations,
            typing: Typing::Fixed {
                params: &[Scalar, Scalar, Scalar],
                ret: so3k,
                frames: FrameRule::None,
            },
            eval: |a| {
                Ok(Value::num(
                    Kind::SO3,
                    &repr::rot_zxz(a.scalar(0)?, a.scalar(1)?, a.scalar(2)?),
                ))
            },
        },
        Builtin {
            name: "euler_zxz",
            aliases: &["EulerZXZ"],
            signature: "euler_zxz(R: SO3) -> (a, b, c) with b ∈ [0, π]",
            section: "Appendix B",
            doc: "ZXZ Euler angles of a rotation",
            example: "euler_zxz(rot_zxz(10 deg, 20 deg, 30 deg))",
            area: Representations,
            typing: Typing::Fixed {
                params: &[Rot],
                ret: v3,
                frames: FrameRule::None,
            },
            eval: |a| {
                angles(
                    a,
                    (repr::euler_zxz, repr::euler_zxz_decided, [(0, 2), (1, 2)]),
                )
            },
        },
        Builtin {
            name: "rot_rpy",
            aliases: &["RotRPY"],
            signature: "rot_rpy(roll: scalar, pitch: scalar, yaw: scalar) -> SO3",
            section: "Appendix B",
            doc: "roll-pitch-yaw: Rotz(yaw) Roty(pitch) Rotx(roll)",
            example: "rot_rpy(30 deg, 20 deg, 10 deg)",
            area: Representations,
            typing: Typing::Fixed {
                params: &[Scalar, Scalar, Scalar],
                ret: so3k,
                frames: FrameRule::None,
            },
            eval: |a| {
                Ok(Value::num(
                    Kind::SO3,
                    &repr::rot_rpy(a.scalar(0)?, a.scalar(1)?, a.scalar(2)?),
                ))
            },
        },
        Builtin {
            name: "rpy",
            aliases: &["RPY"],
            signature: "rpy(R: SO3) -> (roll, pitch, yaw) with pitch ∈ [−π/2, π/2]",
            section: "Appendix B",
            doc: "roll, pitch and yaw of a rotation",
            example: "rpy(rot_rpy(30 deg, 20 deg, 10 deg))",
            area: Representations,
            typing: Typing::Fixed {
                params: &[Rot],
                ret: v3,
                frames: FrameRule::None,
            },
            eval: |a| angles(a, (repr::rpy, repr::rpy_decided, [(0, 0), (1, 0)])),
        },
        Builtin {
            name: "quat",
            aliases: &["Quat", "quaternion"],
            signature: "quat(R: SO3) -> (w, x, y, z)",
            section: "Appendix B",
            doc: "unit quaternion (cos θ/2, ω̂ sin θ/2) of a rotation, with w ≥ 0",
            example: "quat(Rotz(90 deg))",
            area: Representations,
            typing: Typing::Fixed {
                params: &[Rot],
                ret: v4,
                frames: FrameRule::None,
            },
            eval: |a| Ok(Value::num(v4(), &repr::quat(a.so3(0)?.matrix()))),
        },
        Builtin {
            name: "rot_quat",
            aliases: &["RotQuat"],
            signature: "rot_quat(q: 4-vector) -> SO3",
            section: "Appendix B",
            doc: "the rotation of a quaternion (w, x, y, z) (normalized first)",
            example: "rot_quat((0.7071, 0, 0, 0.7071))",
            area: Representations,
            typing: Typing::Fixed {
                params: &[Vec(4)],
                ret: so3k,
                frames: FrameRule::None,
            },
            eval: |a| match repr::rot_quat(&a.vec4(0)?) {
                Some(r) => Ok(Value::num(Kind::SO3, &r)),
                None => Err(a.error(
                    0,
                    ErrorKind::Domain,
                    "the zero quaternion is not a rotation",
                )),
            },
        },
        Builtin {
            name: "quat_mul",
            aliases: &["QuatMul"],
            signature: "quat_mul(q: 4-vector, p: 4-vector) -> 4-vector",
            section: "Appendix B",
            doc: "Hamilton product: rot_quat(quat_mul(q, p)) = rot_quat(q) rot_quat(p)",
            example: "quat_mul(quat(Rotz(30 deg)), quat(Rotx(20 deg)))",
            area: Representations,
            typing: Typing::Fixed {
                params: &[Vec(4), Vec(4)],
                ret: v4,
                frames: FrameRule::None,
            },
            eval: |a| Ok(Value::num(v4(), &repr::quat_mul(&a.vec4(0)?, &a.vec4(1)?))),
        },
        Builtin {
            name: "cayley",
            aliases: &["Cayley"],
            signature: "cayley(R: SO3) -> 3-vector",
            section: "Appendix B",
            doc: "Cayley–Rodrigues parameters r = ω̂ tan(θ/2) (undefined at θ = π)",
            example: "cayley(Rotz(90 deg))",
            area: Representations,
            typing: Typing::Fixed {
                params: &[Rot],
                ret: v3,
                frames: FrameRule::None,
            },
            eval: |a| {
                let r = a.so3(0)?;
                repr::cayley(r.matrix())
                    .map(|v| Value::num(v3(), &v))
                    .map_err(|e| a.error(0, ErrorKind::Domain, e))
            },
        },
        Builtin {
            name: "rot_cayley",
            aliases: &["RotCayley"],
            signature: "rot_cayley(r: 3-vector) -> SO3",
            section: "Appendix B",
            doc: "the rotation of Cayley–Rodrigues parameters r",
            example: "rot_cayley((0, 0, 1))",
            area: Representations,
            typing: Typing::Fixed {
                params: &[Vec(3)],
                ret: so3k,
                frames: FrameRule::None,
            },
            eval: |a| Ok(Value::num(Kind::SO3, &repr::rot_cayley(&a.vec3(0)?))),
        },
        // ---- planar ----
        Builtin {
            name: "SE2",
            aliases: &["se2_from"],
            signature: "SE2(theta: scalar, x: scalar, y: scalar) -> SE2   |   SE2(M: 3×3) -> SE2",
            section: "§3.1 (3.16)",
            doc: "a planar transform [cos θ, −sin θ, x; sin θ, cos θ, y; 0, 0, 1], or a 3×3 matrix read as SE(2)",
            example: "SE2(90 deg, 2, 1)",
            area: Transforms,
            typing: Typing::Custom {
                arity: (1, 3),
                rule: se2_rule,
            },
            eval: |a| match a.len() {
                1 => Ok(a.se2(0)?.into()),
                3 => Ok(SE2::from_angle(a.scalar(0)?, a.scalar(1)?, a.scalar(2)?).into()),
                _ => Err(a.domain("SE2 takes one matrix or (theta, x, y)")),
            },
        },
        Builtin {
            name: "se2",
            aliases: &[],
            signature: "se2(w: scalar, vx: scalar, vy: scalar) -> se2",
            section: "§3.1, Example 3.4",
            doc: "the planar twist matrix [0, −ω, vx; ω, 0, vy; 0, 0, 0]",
            example: "se2(1, 2, 0)",
            area: Twists,
            typing: Typing::Fixed {
                params: &[Scalar, Scalar, Scalar],
                ret: || Kind::Se2,
                frames: FrameRule::None,
            },
            eval: |a| {
                Ok(Value::num(
                    Kind::Se2,
                    &se2::hat(&Vec3::new(a.scalar(0)?, a.scalar(1)?, a.scalar(2)?)),
                ))
            },
        },
        // ---- tests and projections ----
        Builtin {
            name: "ProjectToSO3",
            aliases: &["project_to_so3"],
            signature: "ProjectToSO3(mat: 3×3) -> SO3",
            section: "§3.6",
            doc: "the rotation nearest a 3×3 matrix (SVD); where many are as near (0, −I, rank 1: singular values σ₂ + sσ₃ = 0, s the sign of det) one of them, with a warning",
            example: "ProjectToSO3([0.675, 0.150, 0.720; 0.370, 0.771, -0.511; -0.630, 0.619, 0.472])",
            area: Tests,
            typing: Typing::Fixed {
                params: &[Square],
                ret: so3k,
                frames: FrameRule::Same(0),
            },
            eval: |a| projection(a, Group::SO3),
        },
        Builtin {
            name: "ProjectToSE3",
            aliases: &["project_to_se3"],
            signature: "ProjectToSE3(mat: 4×4) -> SE3",
            section: "§3.6",
            doc: "the transform nearest a 4×4 matrix (rotation block by SVD)",
            example: "ProjectToSE3([0.675, 0.150, 0.720, 1.2; 0.370, 0.771, -0.511, 5.4; -0.630, 0.619, 0.472, 3.6; 0.003, 0.002, 0.010, 0.9])",
            area: Tests,
            typing: Typing::Fixed {
                params: &[Square],
                ret: || Kind::SE3,
                frames: FrameRule::Same(0),
            },
            eval: |a| projection(a, Group::SE3),
        },
        Builtin {
            name: "DistanceToSO3",
            aliases: &["distance_to_so3"],
            signature: "DistanceToSO3(mat: 3×3) -> scalar",
            section: "§3.6",
            doc: "‖MᵀM − I‖_F if det M > 0, else 1e9: how far M is from SO(3) (of the exact M when it has one)",
            example: "DistanceToSO3([1, 0, 0; 0, 0.1, -0.95; 0, 1, 0.1])",
            area: Tests,
            typing: Typing::Fixed {
                params: &[Square],
                ret: scalar,
                frames: FrameRule::None,
            },
            eval: |a| distance_value(a, Group::SO3),
        },
        Builtin {
            name: "DistanceToSE3",
            aliases: &["distance_to_se3"],
            signature: "DistanceToSE3(mat: 4×4) -> scalar",
            section: "§3.6",
            doc: "how far a 4×4 matrix is from SE(3) (the book's measure)",
            example: "DistanceToSE3([1, 0, 0, 1.2; 0, 0.1, -0.95, 1.5; 0, 1, 0.1, -0.9; 0, 0, 0.1, 0.98])",
            area: Tests,
            typing: Typing::Fixed {
                params: &[Square],
                ret: scalar,
                frames: FrameRule::None,
            },
            eval: |a| distance_value(a, Group::SE3),
        },
        Builtin {
            name: "TestIfSO3",
            aliases: &["test_if_so3"],
            signature: "TestIfSO3(mat: 3×3) -> bool",
            section: "§3.6",
            doc: "true if DistanceToSO3(mat) < 1e-3",
            example: "TestIfSO3(Rotz(1))",
            area: Tests,
            typing: Typing::Fixed {
                params: &[Square],
                ret: boolk,
                frames: FrameRule::None,
            },
            eval: |a| {
                let m = a.mat(0)?;
                if m.shape() != (3, 3) {
                    return Ok(Value::Bool(false));
                }
                let d = SO3::distance(&Mat3::from_iterator(m.iter().copied()));
                Ok(Value::Bool(test_below(a.value(0), Group::SO3, d)))
            },
        },
        Builtin {
            name: "TestIfSE3",
            aliases: &["test_if_se3"],
            signature: "TestIfSE3(mat: 4×4) -> bool",
            section: "§3.6",
            doc: "true if DistanceToSE3(mat) < 1e-3",
            example: "TestIfSE3(Trans((1, 2, 3)))",
            area: Tests,
            typing: Typing::Fixed {
                params: &[Square],
                ret: boolk,
                frames: FrameRule::None,
            },
            eval: |a| {
                let m = a.mat(0)?;
                if m.shape() != (4, 4) {
                    return Ok(Value::Bool(false));
                }
                let d = SE3::distance(&Mat4::from_iterator(m.iter().copied()));
                Ok(Value::Bool(test_below(a.value(0), Group::SE3, d)))
            },
        },
        // ---- mechanisms ----
        Builtin {
            name: "dof",
            aliases: &["DOF", "grubler"],
            signature: "dof(m: mechanism) -> scalar",
            section: "§2.2.2 (2.4)",
            doc: "degrees of freedom by Grübler's formula, m(N − 1 − J) + Σ fᵢ",
            example: "dof(mech < links 4; joints R R R R; planar >)",
            area: Mechanisms,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: dof_rule,
            },
            eval: |a| Ok(Value::scalar(a.mech(0)?.dof() as f64)),
        },
    ]
}
