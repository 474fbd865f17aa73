//! Why a rule refuses an operation: [`RuleError`], with the text of each
//! part of the diagnostic, and the words for frame tags that every rule's
//! message uses. The interpreter attaches spans and source text.

use super::ty::{Frames, Ty};
use crate::diagnostics::ErrorKind;
use crate::syntax::ast::{Expr, ExprKind};

/// Why an operation is refused, with the text for each part of the
/// diagnostic. `lhs`/`rhs` label the operands, `op` the operator.
///
/// The [`Refusal`] is behind one pointer: every rule returns a
/// `Result<Ty, RuleError>`, refusals are rare, and a type is smaller than
/// the texts.
#[derive(Debug, Clone, Default)]
pub struct RuleError(Box<Refusal>);

impl std::ops::Deref for RuleError {
    type Target = Refusal;
    #[inline]
    fn deref(&self) -> &Refusal {
        &self.0
    }
}

impl std::ops::DerefMut for RuleError {
    #[inline]
    fn deref_mut(&mut self) -> &mut Refusal {
        &mut self.0
    }
}

impl RuleError {
    /// The message, taken (the rest is dropped).
    pub fn into_message(self) -> String {
        self.0.message
    }
    /// The texts, taken out of their box.
    pub fn into_refusal(self) -> Refusal {
        *self.0
    }
}

impl From<Refusal> for RuleError {
    fn from(r: Refusal) -> RuleError {
        RuleError(Box::new(r))
    }
}

/// What a [`RuleError`] says: the texts of the diagnostic's parts.
#[derive(Debug, Clone, Default)]
pub struct Refusal {
    /// Type, frame, domain…; None: the reader's default (a type error for
    /// an operation, a frame warning for a binding).
    pub kind: Option<ErrorKind>,
    /// The headline: what is wrong.
    pub message: String,
    /// The label under the left operand (`{b} in {a}`), or under the name
    /// of a binding; empty for none.
    pub lhs: String,
    /// The label under the right operand, or the bound value; empty for none.
    pub rhs: String,
    /// The label on the operator (`inner frames must agree: b ≠ c`); empty
    /// for none.
    pub op: String,
    /// A `help:` line suggesting the fix (`did you mean inv(T_cb)?`).
    pub help: Option<String>,
    /// The operand the refusal is about, when it is one argument of a
    /// builtin call (its table row's check); None: the operation. (Small,
    /// so that the error stays as small as it was to move.)
    pub arg: Option<u16>,
}

impl RuleError {
    pub(super) fn typ(message: impl Into<String>) -> RuleError {
        RuleError::from(Refusal {
            kind: Some(ErrorKind::Type),
            message: message.into(),
            ..Default::default()
        })
    }
    pub(super) fn frame(message: impl Into<String>) -> RuleError {
        RuleError::from(Refusal {
            kind: Some(ErrorKind::Frame),
            message: message.into(),
            ..Default::default()
        })
    }
    pub(super) fn with_help(mut self, help: impl Into<String>) -> RuleError {
        self.help = Some(help.into());
        self
    }
}

/// The operands of a binary operation as written, for help lines
/// (`did you mean inv(T_cb)?`).
#[derive(Debug, Clone, Copy, Default)]
pub struct Operands<'a> {
    /// The left operand.
    pub lhs: Operand<'a>,
    /// The right operand.
    pub rhs: Operand<'a>,
}

/// An operand as written: what it is, read from the syntax tree
/// ([`Operand::form`]), and its source text, for printing.
#[derive(Debug, Clone, Copy, Default)]
pub struct Operand<'a> {
    expr: Option<&'a Expr>,
    /// The whole source text (of which the operand's is read only when a
    /// help line needs it), or the operand's own for [`Operand::of_text`].
    src: &'a str,
}

/// What an operand is, as far as help text cares.
#[derive(Debug, Clone, Copy)]
pub enum Form<'a> {
    /// `inv(X)`, with its argument `X`.
    Inverse(Operand<'a>),
    /// `Ad(T)` or `Adjoint(T)`, the adjoint map \[Ad_T\] (Definition 3.20),
    /// with its argument `T`.
    Adjoint(Operand<'a>),
    /// `X.T` (also written `X^T`, `Xᵀ`) or `transpose(X)`, with `X`.
    Transposed(Operand<'a>),
    /// A name, `T_sb` or `R`.
    Name(&'a str),
    /// Anything else.
    Other,
}

impl<'a> Operand<'a> {
    /// The operand `e` of a source text `src`.
    pub fn new(e: &'a Expr, src: &'a str) -> Operand<'a> {
        Operand { expr: Some(e), src }
    }

    /// An operand known only by its text (tests, and the `T` a help line
    /// writes for a transform it has no text for).
    pub fn of_text(text: &'a str) -> Operand<'a> {
        Operand {
            expr: None,
            src: text,
        }
    }

    /// The operand's source text.
    pub fn text(&self) -> &'a str {
        match self.expr {
            Some(e) => self.src.get(e.span.start..e.span.end).unwrap_or(""),
            None => self.src,
        }
    }

    /// What the operand is.
    pub fn form(&self) -> Form<'a> {
        let Some(e) = self.expr else {
            return Form::Other;
        };
        let inner = |x: &'a Expr| Operand::new(x, self.src);
        match &e.kind {
            ExprKind::Var(name) => Form::Name(name),
            ExprKind::Call { func, args } => match (func.name.as_str(), args.as_slice()) {
                ("inv", [x]) => Form::Inverse(inner(x)),
                ("Ad" | "Adjoint", [x]) => Form::Adjoint(inner(x)),
                ("transpose", [x]) => Form::Transposed(inner(x)),
                _ => Form::Other,
            },
            ExprKind::Member { base, member } if member.name == "T" => {
                Form::Transposed(inner(base))
            }
            _ => Form::Other,
        }
    }

    /// The inverse as help lines write it, without a double inverse:
    /// `inv(T_ab)` of `T_ab`, `T_ab` of `inv(T_ab)`.
    pub fn inverse_text(&self) -> String {
        match self.form() {
            Form::Inverse(x) => x.text().trim().to_string(),
            _ => format!("inv({})", self.text().trim()),
        }
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The one expression statement `src` parses to.
    fn expression(src: &str) -> crate::syntax::ast::Expr {
        let stmt = crate::syntax::parse_program(src).remove(0).expect("parses");
        let crate::syntax::ast::StmtKind::Expr(e) = stmt.kind else {
            panic!("not an expression: {src}")
        };
        e
    }

    #[test]
    fn inverse_text_drops_a_double_inverse() {
        let inverse = |src: &str| Operand::new(&expression(src), src).inverse_text();
        assert_eq!(inverse("T_ab"), "inv(T_ab)");
        assert_eq!(inverse("inv(T_ab * T_bc)"), "T_ab * T_bc");
        assert_eq!(inverse("inv( T_ab )"), "T_ab");
        assert_eq!(
            inverse("inv(T_ab) * inv(T_bc)"),
            "inv(inv(T_ab) * inv(T_bc))"
        );
        assert_eq!(Operand::of_text("T_ab").inverse_text(), "inv(T_ab)");
    }

    #[test]
    fn an_operand_says_what_it_is_from_the_syntax_tree() {
        let form = |src: &str| {
            let e = expression(src);
            match Operand::new(&e, src).form() {
                Form::Inverse(x) => format!("inverse of {}", x.text()),
                Form::Adjoint(x) => format!("adjoint of {}", x.text()),
                Form::Transposed(x) => format!("transpose of {}", x.text()),
                Form::Name(n) => format!("name {n}"),
                Form::Other => "other".to_string(),
            }
        };
        assert_eq!(form("Ad(inv(T_ab))"), "adjoint of inv(T_ab)");
        assert_eq!(form("Adjoint(T_ab)"), "adjoint of T_ab");
        assert_eq!(form("T_ab.T"), "transpose of T_ab");
        assert_eq!(form("T_abᵀ"), "transpose of T_ab");
        assert_eq!(form("transpose(R)"), "transpose of R");
        assert_eq!(form("T_sb"), "name T_sb");
        assert_eq!(form("inverse(T_ab)"), "other");
        assert_eq!(form("T_ab * T_bc"), "other");
    }
}
