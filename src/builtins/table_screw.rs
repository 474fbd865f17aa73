//! Builtins for transforms, twists, screws and wrenches (§3.3–3.4): the
//! SE(3) functions of section 3.6 and the constructors of LANGUAGE.md §8.

use super::table_rotations::{screw, se3k, twist, v3, v3val, v6, velocity_rule, wrench};
use super::{Area, ArgError, Args, Builtin, FrameRule, Param, Typing};
use crate::check::ty::{Frames, Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::lie::{LieGroup, SE3, Vec3, se3};
use crate::values::value::Value;

/// (q, ŝ, h) of a screw: frames (Same, Same, none).
fn screw_params_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    if !Param::Vec(6).accepts(&args[0].kind) && !Param::Expc6.accepts(&args[0].kind) {
        return Err(ArgError::type_of(
            0,
            format!(
                "screw_params takes a screw axis or twist, not {}",
                args[0].kind.a()
            ),
        ));
    }
    Ok(Ty::new(
        Kind::tuple(vec![v3(), v3(), Kind::Scalar]),
        args[0].frames,
    ))
}

fn displacement_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    let planar = args
        .iter()
        .all(|t| matches!(t.kind, Kind::SE2 | Kind::Matrix(Some(3), Some(3))));
    for (i, t) in args.iter().enumerate() {
        if !Param::Trans.accepts(&t.kind) && !planar {
            return Err(ArgError::type_of(
                i,
                format!(
                    "displacement takes two transforms (SE(3) or SE(2)), not {}",
                    t.kind.a()
                ),
            ));
        }
    }
    let frames = match (args[0].frames.outer(), args[1].frames.outer()) {
        (Some(a), Some(b)) if a != b => {
            return Err(ArgError {
                arg: Some(1),
                kind: ErrorKind::Frame,
                message: format!(
                    "both transforms must start in the same frame: {{{a}}} and {{{b}}}"
                ),
            });
        }
        (Some(a), _) | (None, Some(a)) => Frames::Disp(*a),
        _ => Frames::None,
    };
    Ok(Ty::new(if planar { Kind::SE2 } else { Kind::SE3 }, frames))
}

/// ScrewToAxis(q, ŝ, h): a direction that is not a unit vector is
/// normalised, with a warning (S must be a unit screw axis, §3.3.2.2).
fn eval_screw_to_axis(a: &mut Args) -> Result<Value, Diagnostic> {
    let (q, s, h) = (a.vec3(0)?, a.vec3(1)?, a.scalar(2)?);
    let n = crate::lie::norm(&s);
    if n == 0.0 || !n.is_finite() {
        return Err(a.error(
            1,
            ErrorKind::Domain,
            "the screw direction ŝ must be a nonzero unit vector",
        ));
    }
    if (n - 1.0).abs() > 1e-12 {
        let shown = |v: &Vec3| crate::values::format::inline(&v3val(v), 4);
        a.warnings.push(
            Diagnostic::warning(
                ErrorKind::Domain,
                a.spans.get(1).unwrap_or(a.call_span),
                format!(
                    "ŝ = {} is not a unit vector (‖ŝ‖ = {}); normalised to {}",
                    shown(&s),
                    crate::values::number::fmt_num(n, 6),
                    shown(&(s / n))
                ),
            )
            .with_help("a screw axis has a unit direction ŝ (§3.3.2.2)"),
        );
    }
    Ok(Value::num(
        Kind::Screw,
        &se3::screw_to_axis(&q, &(s / n), h),
    ))
}

fn eval_displacement(a: &mut Args) -> Result<Value, Diagnostic> {
    if a.mat(0)?.shape() == (3, 3) {
        let (tb, tc) = (a.se2(0)?, a.se2(1)?);
        return Ok(tc.compose(&tb.inverse()).into());
    }
    let (tb, tc) = (a.se3(0)?, a.se3(1)?);
    Ok(tc.compose(&tb.inverse()).into())
}

/// RpToTrans(R_ab, p_ab): {a}←{b}; p must be in {a}.
fn rp_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    // `SE3(M)`: a 4×4 matrix read as a transform, as `SO3(M)` reads a
    // rotation (LANGUAGE.md §5), keeping its frames.
    if let [m] = args
        && matches!(
            m.kind,
            Kind::SE3 | Kind::Se3 | Kind::Matrix(Some(4) | None, Some(4) | None)
        )
        && m.kind != Kind::Matrix(None, None)
    {
        let frames = match m.frames {
            f @ Frames::Pair(..) => f,
            _ => Frames::None,
        };
        return Ok(Ty::new(Kind::SE3, frames));
    }
    if !Param::Rot.accepts(&args[0].kind) {
        return Err(ArgError::type_of(
            0,
            format!("R must be SO(3), not {}", args[0].kind.a()),
        ));
    }
    // `frame(R)`: the rotation as a transform, p = 0 (`frame(I)` is I₄)
    let Some(p) = args.get(1) else {
        let frames = match args[0].frames {
            f @ Frames::Pair(..) => f,
            _ => Frames::None,
        };
        return Ok(Ty::new(Kind::SE3, frames));
    };
    if !Param::Vec(3).accepts(&p.kind) {
        return Err(ArgError::type_of(
            1,
            format!("p must be a 3-vector, not {}", args[1].kind.a()),
        ));
    }
    let frames = match (&args[0].frames, &args[1].frames) {
        (Frames::Pair(a, _), Frames::One(p)) if a != p => {
            return Err(ArgError {
                arg: Some(1),
                kind: ErrorKind::Frame,
                message: format!("R maps into {{{a}}} but p is in {{{p}}}"),
            });
        }
        (Frames::Pair(..), _) => args[0].frames,
        _ => Frames::None,
    };
    Ok(Ty::new(Kind::SE3, frames))
}

fn trans_to_rp_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    if !Param::Trans.accepts(&args[0].kind) {
        return Err(ArgError::type_of(
            0,
            format!("TransToRp takes SE(3), not {}", args[0].kind.a()),
        ));
    }
    Ok(Ty::new(Kind::tuple(vec![Kind::SO3, v3()]), args[0].frames))
}

fn space_twist_rule(a: &[Ty]) -> Result<Ty, ArgError> {
    velocity_rule(true, Kind::Twist)(a)
}

fn body_twist_rule(a: &[Ty]) -> Result<Ty, ArgError> {
    velocity_rule(false, Kind::Twist)(a)
}

pub(super) fn builtins() -> Vec<Builtin> {
    use Area::*;
    use Param::*;
    vec![
        Builtin {
            name: "RpToTrans",
            aliases: &["rp_to_trans", "SE3", "frame"],
            signature: "RpToTrans(R: SO3, p: 3-vector) -> SE3   |   RpToTrans(R) -> SE3 (p = 0)   |   SE3(M: 4×4) -> SE3",
            section: "§3.3.1 (3.62)",
            doc: "the transform T = [R, p; 0, 1] (p = 0 when only R is given: frame(I) is the identity transform); SE3(M) of a 4×4 reads M as a transform (projected within 1e-2, else an error giving its distance)",
            example: "RpToTrans(Rotz(pi/2), (1, 2, 3))",
            area: Transforms,
            typing: Typing::Custom {
                arity: (1, 2),
                rule: rp_rule,
            },
            eval: |a| {
                let p = if a.len() == 2 {
                    a.vec3(1)?
                } else if a.mat(0)?.shape() == (4, 4) {
                    // SE3(M): read as SE(3), projected within 1e-2 (§5)
                    return Ok(a.se3(0)?.into());
                } else {
                    crate::lie::Vec3::zeros()
                };
                Ok(SE3::from_parts(&a.so3(0)?, &p).into())
            },
        },
        Builtin {
            name: "TransToRp",
            aliases: &["trans_to_rp"],
            signature: "TransToRp(T: SE3) -> (R: SO3, p: 3-vector)",
            section: "§3.3.1",
            doc: "the rotation and position of a transform",
            example: "(R, p) = TransToRp(RpToTrans(Rotz(pi/2), (1, 2, 3)))",
            area: Transforms,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: trans_to_rp_rule,
            },
            eval: |a| {
                let (r, p) = a.se3(0)?.parts();
                Ok(Value::Tuple(vec![r.into(), v3val(&p)]))
            },
        },
        Builtin {
            name: "TransInv",
            aliases: &["trans_inv"],
            signature: "TransInv(T: SE3) -> SE3",
            section: "§3.3.1.1 Prop. 3.10 (3.64)",
            doc: "T⁻¹ = [Rᵀ, −Rᵀp; 0, 1]",
            example: "TransInv(RpToTrans(Rotz(pi/2), (1, 2, 3)))",
            area: Transforms,
            typing: Typing::Fixed {
                params: &[Trans],
                ret: se3k,
                frames: FrameRule::Swap(0),
            },
            eval: |a| Ok(a.se3(0)?.inverse().into()),
        },
        super::table_habits::trans(),
        Builtin {
            name: "displacement",
            aliases: &["Displacement"],
            signature: "displacement(T_sb: SE3, T_sc: SE3) -> SE3",
            section: "§3.3.1.2",
            doc: "T_sc T_sb⁻¹: the displacement, expressed in the fixed frame {s}, that takes {b} to {c}",
            example: "displacement(Trans((1, 0, 0)), Trans((1, 2, 0)))",
            area: Transforms,
            typing: Typing::Custom {
                arity: (2, 2),
                rule: displacement_rule,
            },
            eval: eval_displacement,
        },
        Builtin {
            name: "VecTose3",
            aliases: &["vec_to_se3"],
            signature: "VecTose3(V: 6-vector) -> se3",
            section: "§3.3.2 (3.72)",
            doc: "the 4×4 matrix [V] = [[ω], v; 0, 0] of a twist",
            example: "VecTose3((1, 2, 3, 4, 5, 6))",
            area: Twists,
            typing: Typing::Fixed {
                params: &[Vec(6)],
                ret: || Kind::Se3,
                frames: FrameRule::Same(0),
            },
            eval: |a| Ok(Value::num(Kind::Se3, &se3::hat(&a.vec6(0)?))),
        },
        Builtin {
            name: "se3ToVec",
            aliases: &["se3_to_vec"],
            signature: "se3ToVec(se3mat: se3) -> twist",
            section: "§3.3.2 (3.72)",
            doc: "the twist V = (ω, v) of an se(3) matrix",
            example: "se3ToVec([0, -3, 2, 4; 3, 0, -1, 5; -2, 1, 0, 6; 0, 0, 0, 0])",
            area: Twists,
            typing: Typing::Fixed {
                params: &[Expc6],
                ret: twist,
                frames: FrameRule::Same(0),
            },
            eval: |a| Ok(Value::num(Kind::Twist, &a.expc6(0)?)),
        },
        Builtin {
            name: "Adjoint",
            aliases: &["adjoint", "Ad"],
            signature: "Adjoint(T: SE3) -> adjoint",
            section: "§3.3.2 Definition 3.6",
            doc: "the 6×6 [Ad_T] = [R, 0; [p]R, R]: V_a = [Ad_Tab] V_b",
            example: "Ad(RpToTrans(Rotz(pi/2), (1, 0, 0)))",
            area: Twists,
            typing: Typing::Fixed {
                params: &[Trans],
                ret: || Kind::Adjoint { transposed: false },
                frames: FrameRule::Same(0),
            },
            eval: |a| {
                Ok(Value::of(
                    Kind::Adjoint { transposed: false },
                    a.se3(0)?.adjoint(),
                ))
            },
        },
        Builtin {
            name: "ad",
            aliases: &["lie_bracket"],
            signature: "ad(V: 6-vector) -> 6×6 matrix",
            section: "§8.2 (used with twists)",
            doc: "the small adjoint [ad_V] = [[ω], 0; [v], [ω]]",
            example: "ad((0, 0, 1, 1, 0, 0))",
            area: Twists,
            typing: Typing::Fixed {
                params: &[Vec(6)],
                ret: || Kind::Matrix(Some(6), Some(6)),
                frames: FrameRule::None,
            },
            eval: |a| {
                Ok(Value::num(
                    Kind::Matrix(Some(6), Some(6)),
                    &se3::ad(&a.vec6(0)?),
                ))
            },
        },
        Builtin {
            name: "ScrewToAxis",
            aliases: &["screw_to_axis"],
            signature: "ScrewToAxis(q: 3-vector, s: 3-vector, h: scalar) -> screw",
            section: "§3.3.2.2",
            doc: "the screw axis S = (ŝ, −ŝ×q + hŝ) through q along ŝ with pitch h; h = inf gives the pure translation (0, ŝ)",
            example: "ScrewToAxis((3, 0, 0), (0, 0, 1), 2)",
            area: Twists,
            typing: Typing::Fixed {
                params: &[Vec(3), Vec(3), Scalar],
                ret: screw,
                frames: FrameRule::Shared,
            },
            eval: eval_screw_to_axis,
        },
        Builtin {
            name: "screw",
            aliases: &[],
            signature: "screw(q: 3-vector, s: 3-vector, h: scalar) -> screw",
            section: "§3.3.2.2",
            doc: "screw axis through q along s (normalized) with pitch h; h = inf gives the pure translation (0, ŝ)",
            example: "screw((0, 0, 0), (1, 0, 0), inf)",
            area: Twists,
            typing: Typing::Fixed {
                params: &[Vec(3), Vec(3), Scalar],
                ret: screw,
                frames: FrameRule::Shared,
            },
            eval: |a| {
                let (q, s, h) = (a.vec3(0)?, a.vec3(1)?, a.scalar(2)?);
                let n = crate::lie::norm(&s);
                if n == 0.0 || !n.is_finite() {
                    return Err(a.error(
                        1,
                        ErrorKind::Domain,
                        "the screw direction is the zero vector",
                    ));
                }
                // (h = ±inf is the pure translation (0, ±ŝ), §3.3.2.2)
                Ok(Value::num(
                    Kind::Screw,
                    &se3::screw_to_axis(&q, &(s / n), h),
                ))
            },
        },
        Builtin {
            name: "screw_params",
            aliases: &["ScrewParams"],
            signature: "screw_params(S: 6-vector) -> (q: 3-vector, s: 3-vector, h: scalar)",
            section: "§3.3.2.2",
            doc: "point q nearest the origin, unit direction ŝ and pitch h of a screw axis or twist (h = inf for a pure translation)",
            example: "(q, s, h) = screw_params((0, 0, 1, 0, -3, 2))",
            area: Twists,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: screw_params_rule,
            },
            eval: |a| {
                let (q, s, h) = se3::screw_params(&a.expc6(0)?);
                Ok(Value::Tuple(vec![v3val(&q), v3val(&s), Value::scalar(h)]))
            },
        },
        Builtin {
            name: "AxisAng6",
            aliases: &["axis_ang6"],
            signature: "AxisAng6(expc6: 6-vector or se3) -> (S: screw, theta: scalar)",
            section: "§3.3.3.1",
            doc: "screw axis S and distance θ of exponential coordinates Sθ (or of [S]θ: AxisAng6(log(T))); at θ = 0 the axis is undefined: zeros, with a note",
            example: "(S, theta) = AxisAng6((1, 0, 0, 1, 2, 3))",
            area: Twists,
            typing: Typing::Fixed {
                params: &[Expc6],
                ret: || Kind::tuple(vec![Kind::Screw, Kind::Scalar]),
                frames: FrameRule::Same(0),
            },
            eval: |a| {
                let (s, t) = se3::axis_angle(&a.expc6(0)?);
                Ok(Value::Tuple(vec![
                    Value::num(Kind::Screw, &s),
                    Value::scalar(t),
                ]))
            },
        },
        Builtin {
            name: "MatrixExp6",
            aliases: &["matrix_exp6"],
            signature: "MatrixExp6(expc6: 6-vector or se3) -> SE3",
            section: "§3.3.3.1 Proposition 3.16",
            doc: "the transform e^[S]θ of exponential coordinates Sθ",
            example: "MatrixExp6((0, 0, 1, 0, -3, 2) * pi/2)",
            area: Twists,
            typing: Typing::Fixed {
                params: &[Expc6],
                ret: se3k,
                frames: FrameRule::Disp(0),
            },
            eval: |a| Ok(SE3::exp(&a.expc6(0)?).into()),
        },
        Builtin {
            name: "MatrixLog6",
            aliases: &["matrix_log6"],
            signature: "MatrixLog6(T: SE3) -> 6-vector",
            section: "§3.3.3.2",
            doc: "exponential coordinates Sθ of a transform, θ ∈ [0, π] for the rotation",
            example: "MatrixLog6([1, 0, 0, 0; 0, 0, -1, 0; 0, 1, 0, 3; 0, 0, 0, 1])",
            area: Twists,
            typing: Typing::Fixed {
                params: &[Trans],
                ret: v6,
                frames: FrameRule::Outer(0),
            },
            eval: |a| Ok(Value::of(v6(), a.se3_log(0)?)),
        },
        Builtin {
            name: "twist",
            aliases: &["Twist"],
            signature: "twist(w: 3-vector, v: 3-vector) -> twist",
            section: "§3.3.2",
            doc: "the twist V = (ω, v)",
            example: "twist((0, 0, 2), (-2, -4, 0))",
            area: Twists,
            typing: Typing::Fixed {
                params: &[Vec(3), Vec(3)],
                ret: twist,
                frames: FrameRule::Shared,
            },
            eval: |a| Ok(Value::num(Kind::Twist, &stack(&a.vec3(0)?, &a.vec3(1)?))),
        },
        Builtin {
            name: "wrench",
            aliases: &["Wrench"],
            signature: "wrench(m: 3-vector, f: 3-vector) -> wrench",
            section: "§3.4 (3.97)",
            doc: "the wrench F = (m, f): moment and force",
            example: "wrench((0, 0, 0), (0, -5, 0))",
            area: Twists,
            typing: Typing::Fixed {
                params: &[Vec(3), Vec(3)],
                ret: wrench,
                frames: FrameRule::Shared,
            },
            eval: |a| Ok(Value::num(Kind::Wrench, &stack(&a.vec3(0)?, &a.vec3(1)?))),
        },
        Builtin {
            name: "TwistSpace",
            aliases: &["space_twist", "twist_space"],
            signature: "TwistSpace(T: SE3, Tdot: 4×4) -> twist",
            section: "§3.3.2 (3.75)",
            doc: "spatial twist V_s from [V_s] = Ṫ T⁻¹",
            example: "TwistSpace(Trans((1, 0, 0)), [0, -1, 0, 0; 1, 0, 0, 1; 0, 0, 0, 0; 0, 0, 0, 0])",
            area: Twists,
            typing: Typing::Custom {
                arity: (2, 2),
                rule: space_twist_rule,
            },
            eval: |a| {
                let (t, td) = (a.se3(0)?, mat4(a, 1)?);
                Ok(Value::of(Kind::Twist, t.twists(&td).0))
            },
        },
        Builtin {
            name: "TwistBody",
            aliases: &["body_twist", "twist_body"],
            signature: "TwistBody(T: SE3, Tdot: 4×4) -> twist",
            section: "§3.3.2 (3.72)",
            doc: "body twist V_b from [V_b] = T⁻¹ Ṫ",
            example: "TwistBody(Trans((1, 0, 0)), [0, -1, 0, 0; 1, 0, 0, 1; 0, 0, 0, 0; 0, 0, 0, 0])",
            area: Twists,
            typing: Typing::Custom {
                arity: (2, 2),
                rule: body_twist_rule,
            },
            eval: |a| {
                let (t, td) = (a.se3(0)?, mat4(a, 1)?);
                Ok(Value::of(Kind::Twist, t.twists(&td).1))
            },
        },
    ]
}

fn stack(a: &Vec3, b: &Vec3) -> crate::lie::Vec6 {
    crate::lie::Vec6::new(a.x, a.y, a.z, b.x, b.y, b.z)
}

fn mat4(a: &Args, i: usize) -> Result<crate::lie::Mat4, Diagnostic> {
    let m = a.mat(i)?;
    if m.shape() != (4, 4) {
        return Err(a.error(i, ErrorKind::Type, "expected a 4×4 matrix"));
    }
    Ok(crate::lie::Mat4::from_iterator(m.iter().copied()))
}
