//! Errors and warnings as data, and their rendering.
//!
//! Every stage (parse, check, evaluate) reports a [`Diagnostic`]: a kind from
//! the contract's list (`syntax name type frame domain arity assert`), a message, a
//! primary span, secondary labels (a frame error labels both operands and
//! the operator) and an optional `help:` line. Rendering to text (with
//! carets) and JSON lives in [`render`].

use crate::span::Span;

pub mod escape;
pub mod habits;
pub mod render;
pub mod suggest;
pub mod view;

/// The error kinds of LANGUAGE.md §1, as they appear in JSON and in the
/// `kind error:` header.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// The text does not parse.
    Syntax,
    /// An unknown name (a "did you mean" suggestion may follow).
    Name,
    /// A value of the wrong kind or shape: a rotation where a twist is
    /// wanted, a transform times a free vector (`T * ω`), `.R` of a vector.
    Type,
    /// Frames that do not cancel, `T_ab * T_cb` (LANGUAGE.md §6).
    Frame,
    /// A value outside where an operation is defined: a matrix too far
    /// from SO(3), a singular inverse, division by zero.
    Domain,
    /// A builtin called with the wrong number of arguments.
    Arity,
    /// A failed `assert` (LANGUAGE.md §3).
    Assert,
}

impl ErrorKind {
    /// The word used in `FILE:LINE:COL: kind error:` and in JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            ErrorKind::Syntax => "syntax",
            ErrorKind::Name => "name",
            ErrorKind::Type => "type",
            ErrorKind::Frame => "frame",
            ErrorKind::Domain => "domain",
            ErrorKind::Arity => "arity",
            ErrorKind::Assert => "assert",
        }
    }
}

/// Whether a diagnostic stops the statement or is only reported.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Severity {
    /// The statement stops; nothing is bound.
    Error,
    /// Reported beside the result, which stands (a matrix projected onto
    /// SO(3), gimbal lock).
    Warning,
    /// A remark on a correct result (printed as `note:`).
    Note,
}

/// A secondary label: a span with a short note under it.
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    /// The text the label points at (an operand).
    pub span: Span,
    /// The note, `{b} in {a}`.
    pub message: String,
}

/// One error or warning, pointing into the source: its [`Detail`] behind
/// one pointer, so that a `Result<_, Diagnostic>` (every node of the
/// interpreter returns one, and errors are rare) is no larger than its
/// value and a `Vec` of warnings moves pointers.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostic(Box<Detail>);

impl std::ops::Deref for Diagnostic {
    type Target = Detail;
    #[inline]
    fn deref(&self) -> &Detail {
        &self.0
    }
}

impl std::ops::DerefMut for Diagnostic {
    #[inline]
    fn deref_mut(&mut self) -> &mut Detail {
        &mut self.0
    }
}

/// What a [`Diagnostic`] says and where.
#[derive(Debug, Clone, PartialEq)]
pub struct Detail {
    /// The kind of error, shown as `kind error:` and in JSON.
    pub kind: ErrorKind,
    /// Error, warning or note.
    pub severity: Severity,
    /// The headline.
    pub message: String,
    /// Where the caret goes.
    pub span: Span,
    /// A note under the primary caret (may be empty).
    pub primary_label: String,
    /// Notes under other spans, such as both operands of a frame error.
    pub labels: Vec<Label>,
    /// The `help:` line: a fix to try.
    pub help: Option<String>,
}

impl Diagnostic {
    /// An error of `kind` at `span`.
    pub fn error(kind: ErrorKind, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic(Box::new(Detail {
            kind,
            severity: Severity::Error,
            message: message.into(),
            span,
            primary_label: String::new(),
            labels: Vec::new(),
            help: None,
        }))
    }

    /// A note on a correct result at `span` (printed as `note:`).
    pub fn note(kind: ErrorKind, span: Span, message: impl Into<String>) -> Diagnostic {
        let mut d = Diagnostic::error(kind, span, message);
        d.severity = Severity::Note;
        d
    }

    /// A warning of `kind` at `span` (printed, does not stop the statement).
    pub fn warning(kind: ErrorKind, span: Span, message: impl Into<String>) -> Diagnostic {
        let mut d = Diagnostic::error(kind, span, message);
        d.severity = Severity::Warning;
        d
    }

    /// The message, taken (the rest is dropped).
    pub fn into_message(self) -> String {
        self.0.message
    }

    /// Adds the note under the primary caret.
    pub fn with_primary_label(mut self, text: impl Into<String>) -> Diagnostic {
        self.primary_label = text.into();
        self
    }

    /// Adds a secondary label.
    pub fn with_label(mut self, span: Span, text: impl Into<String>) -> Diagnostic {
        self.labels.push(Label {
            span,
            message: text.into(),
        });
        self
    }

    /// Adds the `help:` line.
    pub fn with_help(mut self, text: impl Into<String>) -> Diagnostic {
        self.help = Some(text.into());
        self
    }
}
