//! Help lines for products whose frames do not cancel (LANGUAGE.md §6),
//! beyond the rule itself: the inverse map when the vector is already in
//! the map's outer frame (`Ad(T_sb) V_s` → `Ad(inv(T_sb)) V_s` =
//! `Ad(T_bs) V_s`, (3.83)); a rotation named with one frame subscript
//! (`R_x = Rotx(θ)`: `_x` names a frame {x}, not the axis x̂); and no fix
//! that is what was typed.

use super::error::{Form, Operand, Operands};
use super::ty::{Frame, Frames, Ty};
use crate::syntax::ident::{NameFrames, base_name, name_frames, tagged_name};

/// `X_ab * v_a`: the vector is in {a} already, so the map the other way,
/// X_ba, is meant. `Ad(T_sb) * V_s` → `Ad(inv(T_sb)) * V_s = Ad(T_bs) * V_s`;
/// `R_sb * ω_s` → `inv(R_sb) * ω_s = R_bs * ω_s`.
pub(super) fn vector_in_outer(l: &Ty, ops: Operands) -> Option<String> {
    let Frames::Pair(a, b) = l.frames else {
        return None;
    };
    let v = ops.rhs.text().trim();
    let map = ops.lhs.text().trim();
    let (fix, alias) = match ops.lhs.form() {
        Form::Adjoint(x) => (
            format!("Ad({})", x.inverse_text()),
            renamed(x, &b, &a).map(|n| format!("Ad({n})")),
        ),
        _ => (ops.lhs.inverse_text(), renamed(ops.lhs, &b, &a)),
    };
    let alias = alias.map_or(String::new(), |n| format!(" = {n} * {v}"));
    Some(format!(
        "{map} maps coordinates in {{{b}}} to {{{a}}}, and {v} is in {{{a}}} already: to express it in {{{b}}} use the inverse, {fix} * {v}{alias}"
    ))
}

/// The framed name of the inverse of a framed name `T_sb`, `T_bs`; None
/// for any other operand.
fn renamed(op: Operand<'_>, outer: &Frame, inner: &Frame) -> Option<String> {
    let Form::Name(n) = op.form() else {
        return None;
    };
    matches!(name_frames(n), NameFrames::Pair(..))
        .then(|| tagged_name(base_name(n), &[&outer.to_string(), &inner.to_string()]))
}

/// A rotation, transform or adjoint named with one frame subscript
/// (`R_x = Rotx(θ)`, `R_z R_y R_x`): the subscript names a frame {x}, so the
/// product asks {x} and {y} to cancel. The fix: a name with no subscript.
pub(super) fn one_frame_operator(ops: Operands, l: &Ty, r: &Ty) -> String {
    let mut names: Vec<(&str, String, String)> = Vec::new();
    for (op, t) in [(ops.lhs, l), (ops.rhs, r)] {
        let Form::Name(n) = op.form() else { continue };
        let base = base_name(n);
        let NameFrames::One(f) = name_frames(n) else {
            continue;
        };
        if t.kind.is_group() && matches!(base, "R" | "T") && !names.iter().any(|x| x.0 == n) {
            names.push((n, format!("{base}{f}"), f));
        }
    }
    if names.is_empty() {
        return String::new();
    }
    let join = |pick: &dyn Fn(&(&str, String, String)) -> String| {
        names.iter().map(pick).collect::<Vec<_>>().join(", ")
    };
    let (subject, frames) = (
        join(&|x| x.0.to_string()),
        join(&|x| format!("{{{}}}", x.2)),
    );
    let plain = join(&|x| x.1.clone());
    let (s, verb, axis) = if names.len() > 1 {
        ("s", "name frames", "axes")
    } else {
        ("", "names a frame", "axis")
    };
    format!(
        "; the subscript{s} of {subject} {verb}, {frames}, not the {axis} of a rotation: a rotation's name takes two frames (R_ab); for the rotation{s} about the {axis} write {plain} (no underscore)"
    )
}

/// The help with any "did you mean X?" dropped where X is what was typed
/// (`typed`, spaces and `*` aside): a fix that is the input is no fix.
pub(super) fn not_as_typed(help: String, typed: &str) -> String {
    let squash = |s: &str| {
        s.chars()
            .filter(|c| !c.is_whitespace() && *c != '*')
            .collect::<String>()
    };
    let typed = squash(typed);
    let Some(at) = help.find("did you mean ") else {
        return help;
    };
    let rest = &help[at + "did you mean ".len()..];
    let end = rest.find('?').unwrap_or(rest.len());
    if squash(&rest[..end]) == typed || rest[..end].split(" = ").any(|x| squash(x) == typed) {
        let before = help[..at].trim_end_matches([';', ' ']);
        let after = rest.get(end + 1..).unwrap_or("");
        return format!("{before}{after}");
    }
    help
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fix_that_is_the_input_is_dropped() {
        let h = "X_xy maps coordinates in {y} to {x}; did you mean T_ab * T_bc?".to_string();
        assert_eq!(
            not_as_typed(h.clone(), "T_ab T_bc"),
            "X_xy maps coordinates in {y} to {x}"
        );
        assert_eq!(not_as_typed(h.clone(), "T_ab * T_cb"), h);
        let h = "rule; did you mean inv(T_cb) = T_bc? more".to_string();
        assert_eq!(not_as_typed(h, "T_bc"), "rule more");
    }
}
