//! Why a rule refuses an operation: [`RuleError`], with the text of each
//! part of the diagnostic, and the words for frame tags that every rule's
//! message uses. The interpreter attaches spans and source text.

use super::ty::{Frames, Ty};
use crate::diagnostics::ErrorKind;

/// Why an operation is refused, with the text for each part of the
/// diagnostic. `lhs`/`rhs` label the operands, `op` the operator.
#[derive(Debug, Clone, Default)]
pub struct RuleError {
    pub kind: Option<ErrorKind>,
    pub message: String,
    pub lhs: String,
    pub rhs: String,
    pub op: String,
    pub help: Option<String>,
}

impl RuleError {
    pub(super) fn typ(message: impl Into<String>) -> RuleError {
        RuleError {
            kind: Some(ErrorKind::Type),
            message: message.into(),
            ..Default::default()
        }
    }
    pub(super) fn frame(message: impl Into<String>) -> RuleError {
        RuleError {
            kind: Some(ErrorKind::Frame),
            message: message.into(),
            ..Default::default()
        }
    }
    pub(super) fn with_help(mut self, help: impl Into<String>) -> RuleError {
        self.help = Some(help.into());
        self
    }
}

/// The source text of the operands, for help lines (`did you mean inv(T_cb)?`).
#[derive(Debug, Clone, Copy, Default)]
pub struct Operands<'a> {
    pub lhs: &'a str,
    pub rhs: &'a str,
}

/// How a frame tag reads in a label: `{b} in {a}`, `in {a}`.
pub fn describe(frames: &Frames) -> String {
    if let Some(a) = frames.displacement_frame() {
        return format!("displacement in {{{a}}}");
    }
    match frames {
        Frames::None => "untagged".to_string(),
        Frames::One(a) => format!("in {{{a}}}"),
        Frames::Pair(a, b) => format!("{{{b}}} in {{{a}}}"),
        Frames::Disp(a) => format!("displacement in {{{a}}}"),
        Frames::Transposed(a, b) => format!("transpose of {{{b}}} in {{{a}}}: no frames"),
    }
}

/// Sums, `cross` and `dot` of quantities in different frames.
pub(super) fn same_frame_error(what: &str, l: &Ty, r: &Ty) -> RuleError {
    let mut e = RuleError::frame(format!("cannot {what} quantities in different frames"));
    e.lhs = describe(&l.frames);
    e.rhs = describe(&r.frames);
    e.help = Some(
        "express both in one frame first (an adjoint for twists, a rotation for vectors)".into(),
    );
    e
}

/// `inv(X)` as text, without a double inverse: `inv(inv(T_ab))` is `T_ab`
/// (help lines write the inverse of what the user typed).
pub fn inverse_text(x: &str) -> String {
    let x = x.trim();
    match x.strip_prefix("inv(").and_then(|s| s.strip_suffix(')')) {
        Some(inner) if balanced(inner) => inner.trim().to_string(),
        _ => format!("inv({x})"),
    }
}

/// True when every bracket in `s` closes inside it (so `inv(a) * inv(b)`
/// is not read as `inv( a) * inv(b )`).
fn balanced(s: &str) -> bool {
    let mut depth = 0i32;
    for c in s.chars() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => {
                depth -= 1;
                if depth < 0 {
                    return false;
                }
            }
            _ => {}
        }
    }
    depth == 0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_text_drops_a_double_inverse() {
        assert_eq!(inverse_text("T_ab"), "inv(T_ab)");
        assert_eq!(inverse_text("inv(T_ab * T_bc)"), "T_ab * T_bc");
        assert_eq!(inverse_text(" inv(T_ab) "), "T_ab");
        assert_eq!(
            inverse_text("inv(T_ab) * inv(T_bc)"),
            "inv(inv(T_ab) * inv(T_bc))"
        );
    }
}
