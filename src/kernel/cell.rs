//! One notebook session (LANGUAGE.md §13): the REPL's session and
//! commands driven cell by cell, with nothing of the wire protocol. A cell
//! is statements and `:` commands (`:exact`, `:latex`, `:digits N`, …, one
//! per line, run by the command code every front end shares,
//! [`crate::frontend`]); each statement's value becomes a MIME bundle
//! ([`super::rich`]), each error an error output with the terminal's caret
//! diagnostic. A failing statement binds nothing and ends the cell; every
//! earlier binding stays.

use serde_json::{Map, Value as J, json};

use std::time::Duration;

use crate::budget::{Budget, Interrupt};
use crate::diagnostics::render;
use crate::effects::Gate;
use crate::frontend::commands::{Piece, pieces};
use crate::frontend::{commands, complete, help, save};
use crate::session::{Session, Settings};
use crate::syntax::needs_more_input;

/// One output of a cell, in order.
#[derive(Debug, Clone, PartialEq)]
pub enum Output {
    /// Text on stdout (a command's answer) or stderr (warnings).
    Stream {
        /// True for stderr (warnings), false for stdout.
        stderr: bool,
        /// The text, newlines included.
        text: String,
    },
    /// A value: its MIME bundle (`text/plain`, `text/latex`, …).
    Data(Map<String, J>),
    /// The error that ended the cell.
    Error(Failure),
}

/// An error as Jupyter shows it: `ename` the error kind (`frame`,
/// `syntax`, …), `evalue` the message, the traceback the terminal's
/// diagnostic (header, source line, carets, help), one line per entry.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Failure {
    /// The error kind, `frame`.
    pub ename: String,
    /// The message.
    pub evalue: String,
    /// The rendered diagnostic, one line per entry.
    pub traceback: Vec<String>,
}

/// A kernel's session: the bindings and settings, the cells stored in
/// history and the execution count.
#[derive(Debug, Default)]
pub struct Notebook {
    /// The bindings and settings every cell runs in.
    pub session: Session,
    /// The cells run with `store_history`, in order; cell `i` is
    /// execution count `i + 1`.
    pub history: Vec<String>,
    /// The time each cell may take (`--timeout`), if limited.
    timeout: Option<Duration>,
}

/// What `chasles kernel`'s flags set for its session (LANGUAGE.md §§1,
/// 13), as for a script: the settings (`--frames`, `--digits`, …), the
/// effects gate (`--no-write`, `--write-dir`; printed pictures stay in
/// memory, shown inline), the budget (`--max-memory`, the interrupt flag)
/// and `--timeout`, which a kernel applies to each cell: a notebook has
/// no end, so the time of one run is the time of one cell.
#[derive(Debug, Clone)]
pub struct Options {
    /// `--frames`, `--digits`, … as for a script.
    pub settings: Settings,
    /// Where `save` may write (`--no-write`, `--write-dir`).
    pub gate: Gate,
    /// `--max-memory` and the interrupt flag.
    pub budget: Budget,
    /// `--timeout`, applied to each cell; None: no limit.
    pub timeout: Option<Duration>,
}

/// The default settings, `save` writing where asked, no time limit.
impl Default for Options {
    fn default() -> Options {
        Options {
            settings: Settings::default(),
            gate: Gate::anywhere(None),
            budget: Budget::new(),
            timeout: None,
        }
    }
}

impl Notebook {
    /// A fresh session with the default settings. Its effects gate writes
    /// what `save` asks for and keeps printed pictures in memory: a
    /// notebook shows them inline and writes no file for them (§13).
    pub fn new() -> Notebook {
        Notebook::with(Options::default())
    }

    /// A fresh session under the command line's `options`.
    pub fn with(options: Options) -> Notebook {
        let mut session = Session::new(Settings {
            json: false,
            ..options.settings
        });
        session.gate = options.gate.printed_in_memory();
        session.budget = options.budget;
        Notebook {
            session,
            history: Vec::new(),
            timeout: options.timeout,
        }
    }

    /// What stops a running statement from another thread (the socket
    /// side's `interrupt_request`, SIGINT): the session budget's flag, the
    /// REPL's Ctrl-C mechanism.
    pub fn interrupter(&self) -> Interrupt {
        self.session.budget.interrupt_handle()
    }

    /// The execution count of the next stored cell.
    pub fn next_count(&self) -> usize {
        self.history.len() + 1
    }

    /// Runs one cell, passing each output to `emit` as it is produced.
    /// Err is the error that ended the cell (also emitted). A stored cell
    /// joins the history (and takes the next execution count).
    pub fn execute(
        &mut self,
        code: &str,
        store_history: bool,
        emit: &mut dyn FnMut(Output),
    ) -> Result<(), Failure> {
        let file = format!("In[{}]", self.next_count());
        if store_history {
            self.history.push(code.to_string());
        }
        // An interrupt that came while no cell ran stops nothing.
        self.interrupter().clear();
        if let Some(t) = self.timeout {
            self.session.budget = self.session.budget.clone().with_timeout(t);
        }
        let r = self.pieces(&file, code, emit);
        self.interrupter().clear();
        r
    }

    /// The pieces of a cell in order, until an error or an interrupt.
    fn pieces(
        &mut self,
        file: &str,
        code: &str,
        emit: &mut dyn FnMut(Output),
    ) -> Result<(), Failure> {
        for piece in pieces(code) {
            match piece {
                Piece::Command(line) => self.command(line, emit),
                Piece::Statements(first, src) => {
                    if let Some(cmd) = commands::bare_command(&self.session, &src) {
                        self.command(&cmd, emit);
                    } else {
                        self.statements(file, first, &src, emit)?;
                    }
                }
            }
            if self.session.interrupted {
                // The statement it stopped bound nothing; the session is
                // as it was before it.
                self.session.interrupted = false;
                let f = Failure {
                    ename: "interrupted".into(),
                    evalue: "interrupted: the statement was stopped; earlier bindings are kept"
                        .into(),
                    traceback: vec!["interrupted".into()],
                };
                emit(Output::Error(f.clone()));
                return Err(f);
            }
        }
        Ok(())
    }

    /// A `:` command, answered as the REPL answers it.
    fn command(&mut self, line: &str, emit: &mut dyn FnMut(Output)) {
        let reply = commands::command(&mut self.session, line);
        if reply.quit {
            emit(Output::Stream {
                stderr: false,
                text: "the kernel keeps running: shut it down from the notebook's Kernel menu\n"
                    .into(),
            });
        }
        if !reply.out.is_empty() {
            emit(Output::Stream {
                stderr: false,
                text: reply.out,
            });
        }
        if !reply.err.is_empty() {
            emit(Output::Stream {
                stderr: true,
                text: reply.err,
            });
        }
    }

    /// Statements starting at line `first` of the cell: each value as a
    /// bundle, warnings on stderr, the first error as the cell's failure.
    fn statements(
        &mut self,
        file: &str,
        first: usize,
        chunk: &str,
        emit: &mut dyn FnMut(Output),
    ) -> Result<(), Failure> {
        // Blank lines before the chunk number its lines as in the cell.
        let src = format!("{}{chunk}", "\n".repeat(first.saturating_sub(1)));
        let settings = self.session.settings;
        let mut failure = None;
        save::run_recording_each(&mut self.session, &src, |r| {
            for w in &r.warnings {
                emit(Output::Stream {
                    stderr: true,
                    text: render::text_from(w, file, &src, r.anchor),
                });
            }
            match &r.result {
                Ok(o) => {
                    if let Some(mut b) = super::rich::bundle(o, r.line(), &settings) {
                        // the statement's notes ride with its JSON, as in `--json`
                        if let Some(j) = b.get_mut("application/json") {
                            crate::output::json::add_warnings(j, &r.warnings);
                        }
                        emit(Output::Data(b));
                    }
                }
                Err(d) => {
                    let shown = render::text_from(d, file, &src, r.anchor);
                    let f = Failure {
                        ename: d.kind.as_str().to_string(),
                        // as the traceback's header: control characters escaped
                        evalue: crate::diagnostics::escape::controls(&d.message).into_owned(),
                        traceback: shown.trim_end().lines().map(str::to_string).collect(),
                    };
                    emit(Output::Error(f.clone()));
                    failure = Some(f);
                }
            }
        });
        failure.map_or(Ok(()), Err)
    }

    /// Completions at `cursor` (in characters, as Jupyter counts): the
    /// REPL's completion of the cursor's line. Returns the replacements,
    /// the characters they replace and each one's type and signature.
    pub fn complete(&self, code: &str, cursor: usize) -> (Vec<String>, usize, usize, J) {
        let pos = byte_offset(code, cursor);
        let line_start = code[..pos].rfind('\n').map_or(0, |i| i + 1);
        let line_end = code[pos..].find('\n').map_or(code.len(), |i| pos + i);
        let (start, cands) =
            complete::complete(&self.session, &code[line_start..line_end], pos - line_start);
        let start = char_offset(code, line_start + start);
        let end = char_offset(code, pos);
        let types: Vec<J> = cands
            .iter()
            .map(|c| {
                json!({
                    "start": start,
                    "end": end,
                    "text": c.replacement,
                    "type": if c.replacement.starts_with(':') { "magic" } else { "function" },
                    "signature": c.display,
                })
            })
            .collect();
        let matches = cands.into_iter().map(|c| c.replacement).collect();
        (
            matches,
            start,
            end,
            json!({ "_jupyter_types_experimental": types }),
        )
    }

    /// The `:help` text of the name under the cursor (or of the function
    /// whose call the cursor is in), None when there is no help for it.
    pub fn inspect(&self, code: &str, cursor: usize) -> Option<String> {
        let pos = byte_offset(code, cursor);
        let settings = &self.session.settings;
        word_at(code, pos)
            .and_then(|w| help::help(&w, settings).ok())
            .or_else(|| help::help(&call_at(code, pos)?, settings).ok())
    }

    /// Whether a cell can run as it is: false while a bracket is open (the
    /// notebook's console then continues the cell on the next line). Only
    /// the statements after the last `:` command can be open: a bracket in
    /// a command line (`:help (`) opens nothing, as the cell runs it.
    pub fn is_complete(code: &str) -> bool {
        match pieces(code).last() {
            Some(Piece::Statements(_, src)) => !needs_more_input(src),
            _ => true,
        }
    }
}

/// The byte offset of character `chars` of `s` (its end when beyond).
fn byte_offset(s: &str, chars: usize) -> usize {
    s.char_indices().nth(chars).map_or(s.len(), |(i, _)| i)
}

/// The number of characters before byte `at` of `s`.
fn char_offset(s: &str, at: usize) -> usize {
    s[..at.min(s.len())].chars().count()
}

/// Whether `c` may be part of a name (as completion reads names), or
/// begins a command.
fn name_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_' || c == '\''
}

/// The name at byte `pos` (touching it on either side), or a `:command`.
fn word_at(code: &str, pos: usize) -> Option<String> {
    let before = &code[..pos];
    let after = &code[pos..];
    let start = before
        .char_indices()
        .rev()
        .take_while(|(_, c)| name_char(*c))
        .last()
        .map_or(pos, |(i, _)| i);
    let end = pos + after.find(|c: char| !name_char(c)).unwrap_or(after.len());
    let word = &code[start..end];
    if word.is_empty() {
        None
    } else if code[..start].ends_with(':') {
        Some(format!(":{word}"))
    } else {
        Some(word.to_string())
    }
}

/// The name before the innermost `(` still open at byte `pos` (on its line).
fn call_at(code: &str, pos: usize) -> Option<String> {
    let before = &code[..pos];
    let mut depth = 0usize;
    for (i, c) in before.char_indices().rev() {
        match c {
            ')' | ']' => depth += 1,
            '[' => depth = depth.saturating_sub(1),
            '(' if depth > 0 => depth -= 1,
            '(' => {
                let head = &before[..i];
                let s = head
                    .char_indices()
                    .rev()
                    .take_while(|(_, c)| name_char(*c))
                    .last()
                    .map(|(j, _)| j)?;
                return Some(head[s..].to_string());
            }
            '\n' => return None,
            _ => {}
        }
    }
    None
}

#[cfg(test)]
mod tests;
