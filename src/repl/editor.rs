//! The rustyline [`Helper`]: a thin layer over [`super::complete`] for Tab
//! completion and hints, the bracket-aware validator that keeps the input
//! open while a bracket is open, and colours (only when enabled).

use std::borrow::Cow;

use rustyline::completion::Completer;
use rustyline::highlight::{CmdKind, Highlighter};
use rustyline::hint::Hinter;
use rustyline::validate::{ValidationContext, ValidationResult, Validator};
use rustyline::{CompletionType, Context, Helper};

use super::complete;
use crate::session::Session;

/// Dim text for hints.
const DIM: &str = "\x1b[2m";
/// Bold green for the prompt.
const PROMPT: &str = "\x1b[1;32m";
/// Back to normal.
const RESET: &str = "\x1b[0m";

/// The editor's helper: a copy of the session (refreshed after every
/// input) for completing names and previewing results.
pub struct ReplHelper {
    /// The session as of the last input.
    pub session: Session,
    /// Whether to colour the prompt, hints and candidates.
    pub colour: bool,
}

impl rustyline::completion::Candidate for complete::Candidate {
    fn display(&self) -> &str {
        &self.display
    }
    fn replacement(&self) -> &str {
        &self.replacement
    }
}

impl Completer for ReplHelper {
    type Candidate = complete::Candidate;

    fn complete(
        &self,
        line: &str,
        pos: usize,
        _ctx: &Context<'_>,
    ) -> rustyline::Result<(usize, Vec<complete::Candidate>)> {
        Ok(complete::complete(&self.session, line, pos))
    }
}

impl Hinter for ReplHelper {
    type Hint = String;

    fn hint(&self, line: &str, pos: usize, _ctx: &Context<'_>) -> Option<String> {
        complete::hint(&self.session, line, pos)
    }
}

impl Highlighter for ReplHelper {
    fn highlight_prompt<'b, 's: 'b, 'p: 'b>(
        &'s self,
        prompt: &'p str,
        default: bool,
    ) -> Cow<'b, str> {
        if self.colour && default {
            Cow::Owned(format!("{PROMPT}{prompt}{RESET}"))
        } else {
            Cow::Borrowed(prompt)
        }
    }

    fn highlight_hint<'h>(&self, hint: &'h str) -> Cow<'h, str> {
        if self.colour {
            Cow::Owned(format!("{DIM}{hint}{RESET}"))
        } else {
            Cow::Borrowed(hint)
        }
    }

    fn highlight_candidate<'c>(
        &self,
        candidate: &'c str,
        _completion: CompletionType,
    ) -> Cow<'c, str> {
        Cow::Borrowed(candidate)
    }

    fn highlight_char(&self, _line: &str, _pos: usize, _kind: CmdKind) -> bool {
        false
    }
}

impl Validator for ReplHelper {
    /// Incomplete while a `(`, `[` or `mech <` is open: Enter then starts
    /// a new row, so a matrix can be typed row by row.
    fn validate(&self, ctx: &mut ValidationContext) -> rustyline::Result<ValidationResult> {
        let input = ctx.input();
        if !super::commands::is_command(input) && crate::syntax::needs_more_input(input) {
            Ok(ValidationResult::Incomplete)
        } else {
            Ok(ValidationResult::Valid(None))
        }
    }
}

impl Helper for ReplHelper {}
