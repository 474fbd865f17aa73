//! Notes on a student's common slips in a call that is otherwise correct
//! (issue 36): an angle typed as a whole number of radians beyond a full
//! turn, `Rotz(30)`, is almost always meant in degrees (§2.2: the book
//! writes angles in both; chasles reads a bare number as radians).

use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{Expr, ExprKind, UnOp};

/// Which argument of a rotation builtin is its angle θ (Rotx/Roty/Rotz
/// §3.2.1, Rot §3.2.3.2, SE2 Example 3.4), or None.
fn angle_arg(name: &str, nargs: usize) -> Option<usize> {
    match (name, nargs) {
        ("Rotx" | "Roty" | "Rotz", 1) => Some(0),
        ("Rot", 2) => Some(1),
        ("SE2", 3) => Some(0),
        _ => None,
    }
}

/// A whole number typed as the literal (`30`, `-45`), or None.
fn whole_literal(e: &Expr) -> Option<f64> {
    let x = match &e.kind {
        ExprKind::Number(x) => *x,
        ExprKind::Unary {
            op: UnOp::Neg,
            operand,
        } => match operand.kind {
            ExprKind::Number(x) => -x,
            _ => return None,
        },
        _ => return None,
    };
    (x.fract() == 0.0 && x.is_finite()).then_some(x)
}

/// The note on `name(args)` when its angle is a whole number literal of
/// radians beyond 2π (and within 3600, as degrees are written):
/// "30 rad = 1718.9°; did you mean `30 deg`?". The
/// value is still the rotation by that many radians; `30 rad` (said
/// explicitly) and a computed angle get no note.
pub(super) fn radians_slip(name: &str, args: &[Expr]) -> Option<Diagnostic> {
    let arg = args.get(angle_arg(name, args.len())?)?;
    let x = whole_literal(arg)?;
    // (beyond ten turns in degrees it is no slip for `deg`)
    if x.abs() <= std::f64::consts::TAU || x.abs() > 3600.0 {
        return None;
    }
    let n = crate::values::number::fmt_num(x, 0);
    let deg = crate::values::number::fmt_num(x.to_degrees(), 1);
    Some(
        Diagnostic::note(
            ErrorKind::Domain,
            arg.span,
            format!("{n} rad = {deg}°; did you mean `{n} deg`?"),
        )
        .with_help(format!(
            "a bare number is an angle in radians: write `{n} deg` (or `{n}°`) for degrees, `{n} rad` to keep radians without this note"
        )),
    )
}

/// A number as typed, or arithmetic of numbers (`1.5`, `-2`, `1/2`,
/// `30 deg`).
fn constant(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Number(_) => true,
        ExprKind::Unary { operand, .. } => constant(operand),
        ExprKind::Binary { lhs, rhs, .. } => constant(lhs) && constant(rhs),
        ExprKind::Degrees(x) => constant(x),
        _ => false,
    }
}

/// Whether `name = value` binds a vector typed as numbers (`(0, 0, 1.5)`,
/// `[1; 2; 3]`) to a name whose letter the book uses both for a linear
/// velocity and for a point: v. Fig. 3.13 (§3.3.1.2) writes
/// `v_b = (0, 0, 1.5)` and `v_a = T_ab v_b` with v a point, so such a
/// vector is not made a free vector by its name; a value that *is* a
/// linear velocity (a twist's `.v`) stays one (LANGUAGE.md §4).
///
/// `role` reads the role the session's claim on the name gives
/// ([`crate::check::bind::Claim`], made once per name); it is asked only
/// for a literal, and only a name whose role is a free vector can be a
/// velocity, so other names skip the walk over the name's letters.
pub(super) fn literal_point(
    name: &str,
    role: impl FnOnce() -> Option<crate::check::role::Role>,
    value: &Expr,
) -> bool {
    // The literal first: it is one match, the name's letter a string walk.
    let literal = match &value.kind {
        ExprKind::Paren(xs) => xs.iter().all(constant),
        ExprKind::Brackets(rows) => {
            rows.iter().all(|r| r.len() == 1 && constant(&r[0]))
                || rows.len() == 1 && rows[0].len() > 1 && rows[0].iter().all(constant)
        }
        _ => false,
    };
    literal
        && role() == Some(crate::check::role::Role::Free)
        && crate::check::role::noun(name) == Some("a linear velocity")
}

/// The note on a user function named like a builtin (`trans(n) = n`):
/// allowed, as Python and MATLAB allow it, and said.
pub(super) fn shadowed(name: &str, signature: &str, span: crate::span::Span) -> Diagnostic {
    let builtin = signature.split(" -> ").next().unwrap_or(signature);
    Diagnostic::note(
        ErrorKind::Name,
        span,
        format!("{name} is now your function: it hides the builtin {builtin} in this session"),
    )
    .with_help(format!(
        "choose another name to keep the builtin; `:help {name}` still describes it"
    ))
}

/// The size of `I` written as argument `i` of the builtin `b` where the
/// call fixes it (`frame(I, p)`, `RotInv(I)`: 3; `Ad(I)`, `TransInv(I)`:
/// 4), as `I + W` takes the size of W (LANGUAGE.md §4). None where the call
/// leaves it open (`inv(I)`, `det(I)`).
pub(super) fn identity_size(b: &crate::builtins::Builtin, i: usize) -> Option<usize> {
    use crate::builtins::{Param, Typing};
    match (&b.typing, b.name, i) {
        (_, "RpToTrans", 0) => Some(3),
        (_, "TransToRp", 0) => Some(4),
        (Typing::Fixed { params, .. }, _, _) => match params.get(i)? {
            Param::Rot => Some(3),
            Param::Trans => Some(4),
            _ => None,
        },
        _ => None,
    }
}

/// The help when a function's name is read as a value: call it, or, for
/// `30 degrees`, the unit that was meant (`30 deg`), not the conversion.
pub(super) fn function_as_value(name: &str) -> String {
    match name {
        "degrees" => {
            "degrees are a unit after the number: 30 deg or 30°; degrees(x) converts radians".into()
        }
        _ => format!("call it: {name}(...)"),
    }
}

/// The help for an unknown name with no near spelling: give it a value or
/// declare it with `given` (§7), with the type the name reads as in the
/// book's letters — `R_ab` SO3, `T_ab` SE3, `V_s` twist, `S1`, `B_b` screw,
/// `F_b` wrench, a vector with one frame (`p_b`, `w_s`) or a hat (`ω̂`)
/// vec3, a plain name (`x`, `theta_1`) scalar. The same whatever the mode:
/// `chasles check` (and the editor, which checks) and `chasles run` give
/// one help for one script (it said `given v : SE3` in `check` and
/// `given v : scalar` in `run`, and `given theta_1 : SE3` for any name with
/// an underscore).
pub(super) fn declare_it(name: &str) -> String {
    use crate::syntax::ident::{NameFrames, base_name, name_frames};
    let base = base_name(name);
    let letter = base
        .chars()
        .next()
        .filter(|_| base.chars().skip(1).all(|c| c.is_ascii_digit()));
    let ty = match (name_frames(name), letter) {
        (NameFrames::Pair(..), Some('R')) => "SO3",
        (NameFrames::Pair(..), Some('p')) => "vec3",
        (NameFrames::Pair(..), _) => "SE3",
        (_, Some('V')) => "twist",
        (_, Some('S' | 'B')) => "screw",
        (_, Some('F')) => "wrench",
        (NameFrames::One(_), _) => "vec3",
        (NameFrames::None, _) if name.contains('\u{302}') => "vec3",
        (NameFrames::None, _) => "scalar",
    };
    format!("give it a value first ({name} = ...) or declare it: given {name} : {ty}")
}

#[cfg(test)]
mod declare_it_tests {
    use super::declare_it;

    #[test]
    fn the_type_is_read_from_the_name_alone() {
        let ty = |n: &str| declare_it(n).rsplit(": ").next().unwrap().to_string();
        for (name, want) in [
            ("T_cb", "SE3"),
            ("R_cd", "SO3"),
            ("Ad_sb", "SE3"),
            ("p_sb", "vec3"),
            ("V_s", "twist"),
            ("V", "twist"),
            ("S1", "screw"),
            ("B_b", "screw"),
            ("F_a", "wrench"),
            ("w_b", "vec3"),
            ("p_{cam}", "vec3"),
            ("ω̂", "vec3"),
            ("x", "scalar"),
            ("f", "scalar"),
            ("theta_1", "scalar"),
            ("x_max", "scalar"),
            ("Sum", "scalar"),
        ] {
            assert_eq!(ty(name), want, "{name}");
        }
    }
}

/// A numeric 3×3 argument that the rule refused because its numbers were
/// read as SE(2) (last row (0, 0, 1), an SO(2) block: LANGUAGE.md §5's
/// reading of an untyped 3×3) where the call takes a rotation. Near(i):
/// argument i is within 1e-2 of SO(3), so §5's rotation rule applies to it
/// (accepted, or projected with a warning, as `R_sb = M` does): the call is
/// typed with it as a plain 3×3 matrix. Far(i): a planar transform, and
/// the type error's help names `SO3(M)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Se2Read {
    Near(usize),
    Far(usize),
}

/// [`Se2Read`] of the arguments `tys`/`vals` of a call that `retype`
/// refused, when typing argument i as a plain 3×3 matrix is what it takes
/// to pass (`retype` runs the call's rule on the types given); None when
/// the refusal is of something else.
pub(super) fn se2_for_rotation(
    tys: &[crate::check::ty::Ty],
    vals: &[crate::values::value::Value],
    retype: impl Fn(&[crate::check::ty::Ty]) -> bool,
) -> Option<Se2Read> {
    use crate::check::ty::Kind;
    use crate::values::convert::{self, Group};
    let i = tys.iter().position(|t| t.kind == Kind::SE2)?;
    let crate::values::value::Value::Num { m, .. } = vals.get(i)? else {
        return None;
    };
    let mut plain = tys.to_vec();
    plain[i].kind = Kind::Matrix(Some(3), Some(3));
    if !retype(&plain) {
        return None;
    }
    let d = convert::distance(m, Group::SO3)?;
    Some(if d <= convert::PROJECT_TOL {
        Se2Read::Near(i)
    } else {
        Se2Read::Far(i)
    })
}
