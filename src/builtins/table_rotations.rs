//! Builtins for rotations (§3.2): the SO(3) functions of section 3.6 and
//! the constructors of LANGUAGE.md §8. Transforms, twists, screws and
//! wrenches are in [`super::table_screw`].

use super::{Area, ArgError, Args, Builtin, FrameRule, Param, Typing};
use crate::check::ty::{Frames, Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::lie::{LieGroup, SO3, Vec3, so3};
use crate::values::value::Value;

pub(super) fn v3() -> Kind {
    Kind::Vector(Some(3))
}
pub(super) fn v6() -> Kind {
    Kind::Vector(Some(6))
}
pub(super) fn so3k() -> Kind {
    Kind::SO3
}
pub(super) fn se3k() -> Kind {
    Kind::SE3
}
pub(super) fn twist() -> Kind {
    Kind::Twist
}
pub(super) fn screw() -> Kind {
    Kind::Screw
}
pub(super) fn wrench() -> Kind {
    Kind::Wrench
}

fn rot_of_axis_tuple() -> Kind {
    Kind::tuple(vec![v3(), Kind::Scalar])
}

/// `Rot(axis, θ)`: the axis is a 3-vector (or `x`, `y`, `z`, resolved by
/// the interpreter before the call).
fn eval_rot(a: &mut Args) -> Result<Value, Diagnostic> {
    // (zero by the exact form when it has one, `Args::vec3`; scaled by its
    // largest entry, so that (1e-200, 0, 0) is x̂ and not a zero norm)
    let axis = a.vec3(0)?;
    let big = axis.amax();
    if big == 0.0 || !axis.iter().all(|x| x.is_finite()) {
        return Err(a.error(0, ErrorKind::Domain, "the rotation axis is the zero vector"));
    }
    Ok(SO3::about(&(axis / big), a.scalar(1)?).into())
}

/// Twist/velocity from a configuration and its derivative, frames of T_sb:
/// body twist in {b}, space twist in {s}.
pub(super) fn velocity_rule(space: bool, kind: Kind) -> impl Fn(&[Ty]) -> Result<Ty, ArgError> {
    move |args: &[Ty]| {
        let f = match &args[0].frames {
            Frames::Pair(s, b) => Frames::One(if space { *s } else { *b }),
            _ => Frames::None,
        };
        Ok(Ty::new(kind, f))
    }
}

fn space_w_rule(a: &[Ty]) -> Result<Ty, ArgError> {
    velocity_rule(true, Kind::Vector(Some(3)))(a)
}
fn body_w_rule(a: &[Ty]) -> Result<Ty, ArgError> {
    velocity_rule(false, Kind::Vector(Some(3)))(a)
}

pub(super) fn v3val(v: &Vec3) -> Value {
    Value::num(v3(), v)
}

/// `SO3(M)` says explicitly that M is a rotation (LANGUAGE.md §5): any 3×3
/// matrix, whatever its numbers were read as (SE(2) for a last row
/// (0, 0, 1), so(3), a plain matrix), is taken, and the builtin reads it as
/// SO(3): as it is within 1e-9, projected with a warning within 1e-2,
/// else a domain error giving the distance. Keeps M's pair of frames.
fn so3_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    let square3 = match args[0].kind.shape() {
        Some((r, c)) => r.is_none_or(|r| r == 3) && c.is_none_or(|c| c == 3),
        None => args[0].kind == Kind::Unknown,
    };
    if !square3 || args[0].kind.is_vector() {
        return Err(ArgError::type_of(
            0,
            format!("SO3 takes a 3×3 matrix, not {}", args[0].kind.a()),
        ));
    }
    let frames = match args[0].frames {
        f @ Frames::Pair(..) => f,
        _ => Frames::None,
    };
    Ok(Ty::new(Kind::SO3, frames))
}

pub(super) fn builtins() -> Vec<Builtin> {
    use Area::*;
    use Param::*;
    vec![
        Builtin {
            name: "RotInv",
            aliases: &["rot_inv"],
            signature: "RotInv(R: SO3) -> SO3",
            section: "§3.2.1.1 Prop. 3.1",
            doc: "inverse of a rotation matrix, R⁻¹ = Rᵀ (Prop. 3.3)",
            example: "RotInv([0, 0, 1; 1, 0, 0; 0, 1, 0])",
            area: Rotations,
            typing: Typing::Fixed {
                params: &[Rot],
                ret: so3k,
                frames: FrameRule::Swap(0),
            },
            eval: |a| Ok(a.so3(0)?.inverse().into()),
        },
        Builtin {
            name: "VecToso3",
            aliases: &["vec_to_so3", "skew"],
            signature: "VecToso3(omg: 3-vector) -> so3",
            section: "§3.2.2 (3.30)",
            doc: "the skew-symmetric matrix [ω] of a 3-vector ω",
            example: "VecToso3((1, 2, 3))",
            area: Rotations,
            typing: Typing::Fixed {
                params: &[Vec(3)],
                ret: || Kind::So3,
                frames: FrameRule::Same(0),
            },
            eval: |a| Ok(Value::num(Kind::So3, &so3::hat(&a.vec3(0)?))),
        },
        Builtin {
            name: "so3ToVec",
            aliases: &["so3_to_vec", "unskew"],
            signature: "so3ToVec(so3mat: so3) -> 3-vector",
            section: "§3.2.2 (3.30)",
            doc: "the 3-vector ω of a skew-symmetric matrix [ω]",
            example: "so3ToVec([0, -3, 2; 3, 0, -1; -2, 1, 0])",
            area: Rotations,
            typing: Typing::Fixed {
                params: &[Expc3],
                ret: v3,
                frames: FrameRule::Same(0),
            },
            eval: |a| Ok(v3val(&a.expc3(0)?)),
        },
        Builtin {
            name: "AxisAng3",
            aliases: &["axis_ang3"],
            signature: "AxisAng3(expc3: 3-vector or so3) -> (omghat: 3-vector, theta: scalar)",
            section: "§3.2.3.2",
            doc: "unit axis ω̂ and angle θ of exponential coordinates ω̂θ (or of [ω̂]θ: AxisAng3(log(R))); at θ = 0 the axis is undefined: zeros, with a note",
            example: "(w, theta) = AxisAng3((1, 2, 3))",
            area: Rotations,
            typing: Typing::Fixed {
                params: &[Expc3],
                ret: rot_of_axis_tuple,
                frames: FrameRule::Same(0),
            },
            eval: |a| {
                let (w, t) = so3::axis_angle(&a.expc3(0)?);
                Ok(Value::Tuple(vec![v3val(&w), Value::scalar(t)]))
            },
        },
        Builtin {
            name: "MatrixExp3",
            aliases: &["matrix_exp3"],
            signature: "MatrixExp3(expc3: 3-vector or so3) -> SO3",
            section: "§3.2.3.2 (3.51)",
            doc: "the rotation e^[ω̂]θ of exponential coordinates (Rodrigues' formula)",
            example: "MatrixExp3((1, 2, 3))",
            area: Rotations,
            typing: Typing::Fixed {
                params: &[Expc3],
                ret: so3k,
                frames: FrameRule::Disp(0),
            },
            eval: |a| Ok(SO3::exp(&a.expc3(0)?).into()),
        },
        Builtin {
            name: "MatrixLog3",
            aliases: &["matrix_log3"],
            signature: "MatrixLog3(R: SO3) -> 3-vector",
            section: "§3.2.3.3",
            doc: "exponential coordinates ω̂θ of a rotation, θ ∈ [0, π]",
            example: "MatrixLog3([0, 0, 1; 1, 0, 0; 0, 1, 0])",
            area: Rotations,
            typing: Typing::Fixed {
                params: &[Rot],
                ret: v3,
                frames: FrameRule::Outer(0),
            },
            eval: |a| Ok(v3val(&a.so3_log(0)?)),
        },
        Builtin {
            name: "Rot",
            aliases: &["rot"],
            signature: "Rot(axis: 3-vector or x|y|z, theta: scalar) -> SO3",
            section: "§3.2.3.2",
            doc: "rotation by θ about an axis (normalized): Rot(ω̂, θ) = e^[ω̂]θ",
            example: "Rot((0, 0.866, 0.5), 30 deg)",
            area: Rotations,
            typing: Typing::Fixed {
                params: &[Vec(3), Scalar],
                ret: so3k,
                frames: FrameRule::None,
            },
            eval: eval_rot,
        },
        Builtin {
            name: "Rotx",
            aliases: &["rotx", "RotX"],
            signature: "Rotx(theta: scalar) -> SO3",
            section: "§3.2.1",
            doc: "rotation by θ about x̂",
            example: "Rotx(90 deg)",
            area: Rotations,
            typing: Typing::Fixed {
                params: &[Scalar],
                ret: so3k,
                frames: FrameRule::None,
            },
            eval: |a| Ok(SO3::rot_x(a.scalar(0)?).into()),
        },
        Builtin {
            name: "Roty",
            aliases: &["roty", "RotY"],
            signature: "Roty(theta: scalar) -> SO3",
            section: "§3.2.1",
            doc: "rotation by θ about ŷ",
            example: "Roty(90 deg)",
            area: Rotations,
            typing: Typing::Fixed {
                params: &[Scalar],
                ret: so3k,
                frames: FrameRule::None,
            },
            eval: |a| Ok(SO3::rot_y(a.scalar(0)?).into()),
        },
        Builtin {
            name: "Rotz",
            aliases: &["rotz", "RotZ"],
            signature: "Rotz(theta: scalar) -> SO3",
            section: "§3.2.1",
            doc: "rotation by θ about ẑ",
            example: "Rotz(90 deg)",
            area: Rotations,
            typing: Typing::Fixed {
                params: &[Scalar],
                ret: so3k,
                frames: FrameRule::None,
            },
            eval: |a| Ok(SO3::rot_z(a.scalar(0)?).into()),
        },
        Builtin {
            name: "SO3",
            aliases: &[],
            signature: "SO3(M: 3×3 matrix) -> SO3",
            section: "§3.2.1",
            doc: "reads a 3×3 matrix as a rotation, whatever it was read as before (projected within 1e-2, else an error giving its distance)",
            example: "SO3([0, -1, 0; 1, 0, 0; 0, 0, 1])",
            area: Rotations,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: so3_rule,
            },
            eval: |a| Ok(a.so3(0)?.into()),
        },
        Builtin {
            name: "AngVelSpace",
            aliases: &["space_angvel", "ang_vel_space"],
            signature: "AngVelSpace(R: SO3, Rdot: 3×3) -> 3-vector",
            section: "§3.2.2 (3.37)",
            doc: "spatial angular velocity ω_s from [ω_s] = Ṙ Rᵀ",
            example: "AngVelSpace(Rotz(0), [0, -1, 0; 1, 0, 0; 0, 0, 0])",
            area: Rotations,
            typing: Typing::Custom {
                arity: (2, 2),
                rule: space_w_rule,
            },
            eval: |a| {
                let (r, rd) = (a.so3(0)?, mat3(a, 1)?);
                Ok(v3val(&r.angular_velocities(&rd).0))
            },
        },
        Builtin {
            name: "AngVelBody",
            aliases: &["body_angvel", "ang_vel_body"],
            signature: "AngVelBody(R: SO3, Rdot: 3×3) -> 3-vector",
            section: "§3.2.2 (3.38)",
            doc: "body angular velocity ω_b from [ω_b] = Rᵀ Ṙ",
            example: "AngVelBody(Rotz(0), [0, -1, 0; 1, 0, 0; 0, 0, 0])",
            area: Rotations,
            typing: Typing::Custom {
                arity: (2, 2),
                rule: body_w_rule,
            },
            eval: |a| {
                let (r, rd) = (a.so3(0)?, mat3(a, 1)?);
                Ok(v3val(&r.angular_velocities(&rd).1))
            },
        },
    ]
}

pub(super) fn mat3(a: &Args, i: usize) -> Result<crate::lie::Mat3, Diagnostic> {
    let m = a.mat(i)?;
    if m.shape() != (3, 3) {
        return Err(a.error(i, ErrorKind::Type, "expected a 3×3 matrix"));
    }
    Ok(crate::lie::Mat3::from_iterator(m.iter().copied()))
}
