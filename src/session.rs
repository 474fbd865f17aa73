//! A session: the environment plus settings, and the pipeline parse →
//! check → evaluate applied to a whole source text, statement by statement.
//! The CLI, the REPL and the tests all drive chasles through this.

use crate::diagnostics::{Diagnostic, render};
use crate::eval::env::{Env, FrameMode, Mode};
use crate::eval::interp::{Interp, Outcome};
use crate::output::{json, text};
use crate::syntax;

/// Output settings.
#[derive(Debug, Clone, Copy)]
pub struct Settings {
    pub frames: FrameMode,
    /// Decimals in text output (LANGUAGE.md §10).
    pub digits: usize,
    pub json: bool,
    /// Print values near simple closed forms as `1/√2`, `π/6` (the REPL's
    /// `:exact`; text output only).
    pub exact: bool,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            frames: FrameMode::Strict,
            digits: 4,
            json: false,
            exact: false,
        }
    }
}

impl Settings {
    /// How text output prints numbers under these settings.
    pub fn text_style(&self) -> text::Style {
        text::Style {
            digits: self.digits,
            exact: self.exact,
        }
    }
}

/// The result of one statement.
#[derive(Debug, Clone)]
pub struct Report {
    /// 1-based line where the statement starts.
    pub line: usize,
    pub result: Result<Outcome, Diagnostic>,
    pub warnings: Vec<Diagnostic>,
}

impl Report {
    /// What goes to stdout: the value text or JSON line (empty if nothing).
    pub fn stdout(&self, settings: &Settings, src: &str) -> String {
        match (&self.result, settings.json) {
            (Ok(o), false) => text::show_outcome(o, settings.text_style()),
            (Ok(o), true) => json::outcome(o, self.line)
                .map(|j| j.to_string())
                .unwrap_or_default(),
            (Err(d), true) => {
                let (line, col) = render::line_col(src, d.span.start);
                json::error(d, line, col).to_string()
            }
            (Err(_), false) => String::new(),
        }
    }

    /// What goes to stderr: rendered warnings, and the error in text mode.
    pub fn stderr(&self, settings: &Settings, file: &str, src: &str) -> String {
        let mut out = String::new();
        for w in &self.warnings {
            out.push_str(&render::text(w, file, src));
        }
        if let (Err(d), false) = (&self.result, settings.json) {
            out.push_str(&render::text(d, file, src));
        }
        out
    }
}

/// A calculator session: bindings survive errors (a failing statement
/// binds nothing).
#[derive(Debug, Clone, Default)]
pub struct Session {
    pub env: Env,
    pub settings: Settings,
}

impl Session {
    pub fn new(settings: Settings) -> Session {
        Session {
            env: Env::default(),
            settings,
        }
    }

    /// Runs (or, in [`Mode::Check`], checks) every statement of `src`,
    /// calling `each` with each report in order. Stops after the first
    /// error unless `keep_going`. Returns the number of errors.
    pub fn run(
        &mut self,
        src: &str,
        mode: Mode,
        keep_going: bool,
        mut each: impl FnMut(&Report),
    ) -> usize {
        let mut errors = 0;
        let index = render::LineIndex::new(src);
        for parsed in syntax::parse_program(src) {
            let line = |d: &Diagnostic| index.line(d.span.start);
            let report = match parsed {
                Err(d) => Report {
                    line: line(&d),
                    result: Err(d),
                    warnings: Vec::new(),
                },
                Ok(stmt) => {
                    let mut interp = Interp::new(&mut self.env, src, mode, self.settings.frames);
                    let result = interp.stmt(&stmt);
                    let warnings = std::mem::take(&mut interp.warnings);
                    Report {
                        line: index.line(stmt.span.start),
                        result,
                        warnings,
                    }
                }
            };
            let failed = report.result.is_err();
            each(&report);
            if failed {
                errors += 1;
                if !keep_going {
                    break;
                }
            }
        }
        errors
    }

    /// Runs `src` and collects stdout and stderr text (used by tests and `-e`).
    pub fn run_to_strings(
        &mut self,
        file: &str,
        src: &str,
        mode: Mode,
        keep_going: bool,
    ) -> (String, String, usize) {
        let (mut out, mut err) = (String::new(), String::new());
        let settings = self.settings;
        let n = self.run(src, mode, keep_going, |r| {
            let o = r.stdout(&settings, src);
            if !o.is_empty() {
                out.push_str(&o);
                out.push('\n');
            }
            err.push_str(&r.stderr(&settings, file, src));
        });
        (out, err, n)
    }
}
