//! The rustyline [`Helper`]: a thin layer over [`crate::frontend::complete`] for Tab
//! completion and hints, and colours (only when enabled). Input inside an
//! open bracket continues under the continuation prompt (`super::run_terminal`).

use std::borrow::Cow;

use rustyline::completion::Completer;
use rustyline::highlight::{CmdKind, Highlighter};
use rustyline::hint::Hinter;
use rustyline::validate::{ValidationContext, ValidationResult, Validator};
use rustyline::{CompletionType, Context, Helper};

use crate::frontend::complete;
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
    /// True on a continuation line, where the line alone is no statement
    /// to preview.
    pub continuing: bool,
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
        if self.continuing {
            return None;
        }
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

/// Every line is complete: an open bracket continues on the next line under
/// the continuation prompt `... ` (read by `super::run_terminal`), so a
/// blank Enter inside `[` shows a prompt instead of looking like a hang.
impl Validator for ReplHelper {
    fn validate(&self, _ctx: &mut ValidationContext) -> rustyline::Result<ValidationResult> {
        Ok(ValidationResult::Valid(None))
    }
}

impl Helper for ReplHelper {}
