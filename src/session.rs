//! A session: the environment plus settings, and the pipeline parse →
//! check → evaluate applied to a whole source text, statement by statement.
//! The CLI, the REPL and the tests all drive chasles through this.

use std::io::Read;

use crate::budget::{self, Budget, Stop};
use crate::diagnostics::{Diagnostic, ErrorKind, render};
use crate::eval::env::{Env, FrameMode, Mode};
use crate::eval::interp::{Interp, Outcome};
use crate::eval::value::Value;
use crate::output::{json, text};
use crate::span::{Anchor, Lines};
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
    /// Symbolic values as text, the book's shorthand (`--short`) or LaTeX
    /// (`--latex`), LANGUAGE.md §7.
    pub sym: crate::sym::print::Mode,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            frames: FrameMode::Strict,
            digits: 4,
            json: false,
            exact: false,
            sym: crate::sym::print::Mode::Text,
        }
    }
}

impl Settings {
    /// How text output prints numbers under these settings.
    pub fn text_style(&self) -> text::Style {
        text::Style {
            digits: self.digits,
            exact: self.exact,
            sym: self.sym,
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
    /// A known line before the statement, to number the lines of its
    /// diagnostics without rescanning the source from its start.
    pub anchor: Anchor,
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
                let (line, col) = render::line_col_from(src, d.span.start, self.anchor);
                json::error(d, line, col).to_string()
            }
            (Err(_), false) => String::new(),
        }
    }

    /// What goes to stderr: rendered warnings, and the error in text mode.
    #[inline]
    pub fn stderr(&self, settings: &Settings, file: &str, src: &str) -> String {
        // Nothing to render (most statements): no call, no loop.
        if self.warnings.is_empty() && (self.result.is_ok() || settings.json) {
            return String::new();
        }
        self.stderr_text(settings, file, src)
    }

    fn stderr_text(&self, settings: &Settings, file: &str, src: &str) -> String {
        let mut out = String::new();
        for w in &self.warnings {
            out.push_str(&render::text_from(w, file, src, self.anchor));
        }
        if let (Err(d), false) = (&self.result, settings.json) {
            out.push_str(&render::text_from(d, file, src, self.anchor));
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
    /// The statements that ran without error, in order, as typed — what
    /// the REPL's `:save` writes and `:history` lists (scripts leave it
    /// empty).
    pub accepted: Vec<String>,
    /// Where pictures printed but not saved are written (§12): `Some(".")`
    /// in the CLI and REPL, or `--draw-dir`. `None` (the default, for
    /// library use and tests) writes no file at all, not even for `save`.
    pub pictures: Option<std::path::PathBuf>,
    /// The file of the last picture written (the REPL's `:open`).
    pub last_picture: Option<String>,
    /// The evaluation budget every statement runs under (`--timeout`,
    /// `--max-memory`, Ctrl-C through its [`Budget::interrupt_handle`]).
    pub budget: Budget,
    /// Whether the last [`Session::run`] was stopped by an interrupt (its
    /// statement bound nothing and was not reported).
    pub interrupted: bool,
}

impl Session {
    pub fn new(settings: Settings) -> Session {
        Session {
            env: Env::default(),
            settings,
            accepted: Vec::new(),
            pictures: None,
            last_picture: None,
            budget: Budget::new(),
            interrupted: false,
        }
    }

    /// A picture that a statement printed: checked and described, and —
    /// when this session writes files — written to the file `save` asked
    /// for, else to `NAME.svg` or `draw-LINE.svg` in the picture folder.
    fn picture(&mut self, o: &mut Outcome, line: usize) -> Result<(), Diagnostic> {
        let Some(Value::Picture(p)) = o.val.as_deref() else {
            return Ok(());
        };
        let fail = |m: String| Diagnostic::error(ErrorKind::Domain, o.span, m);
        let mut p = crate::draw::described(p).map_err(fail)?;
        if let (Some(dir), false, true) = (&self.pictures, p.is_view_only(), o.prints) {
            let path = match (&p.save_to, o.names.as_slice()) {
                (Some(f), _) => std::path::PathBuf::from(f),
                (None, [name]) => dir.join(format!("{}.svg", file_stem(name))),
                _ => dir.join(format!("draw-{line}.svg")),
            };
            crate::draw::file::write(&p, &path).map_err(fail)?;
            let shown = path.to_string_lossy().trim_start_matches("./").to_string();
            std::rc::Rc::make_mut(&mut p).file = Some(shown.clone());
            self.last_picture = Some(shown);
        }
        o.val = Some(Box::new(Value::Picture(p)));
        Ok(())
    }

    /// Runs (or, in [`Mode::Check`], checks) every statement of `src`,
    /// calling `each` with each report in order. Stops after the first
    /// error unless `keep_going`. Returns the number of errors.
    ///
    /// Every statement runs under [`Session::budget`]: a statement that
    /// passes a cap fails with a domain error naming it; a spent time
    /// budget stops the run (even with `keep_going`) after reporting it;
    /// an interrupt stops the run with nothing reported for the statement
    /// it cut short, counted as an error, and sets [`Session::interrupted`].
    pub fn run(
        &mut self,
        src: &str,
        mode: Mode,
        keep_going: bool,
        mut each: impl FnMut(&Report),
    ) -> usize {
        let mut errors = 0;
        let mut lines = Lines::new(src);
        let _budget = self.budget.enter();
        self.interrupted = false;
        for parsed in syntax::statements(src) {
            budget::begin_statement(self.env.held());
            // The report is built in place and changed there: its result
            // (a large value) is written once, not moved through
            // `map_err` and a second struct.
            let mut report;
            match parsed {
                Err(d) => {
                    report = Report {
                        line: lines.line(d.span.start),
                        anchor: lines.anchor(),
                        result: Err(habit_help(d, src)),
                        warnings: Vec::new(),
                    }
                }
                Ok(stmt) => {
                    let line = lines.line(stmt.span.start);
                    let mut interp = Interp::new(&mut self.env, src, mode, self.settings.frames);
                    report = Report {
                        line,
                        anchor: lines.anchor(),
                        result: interp.stmt(&stmt),
                        warnings: Vec::new(),
                    };
                    report.warnings = std::mem::take(&mut interp.warnings);
                    match &mut report.result {
                        Err(d) => add_habit_help(d, src),
                        Ok(o) => {
                            // Only a picture has more to do (checked here,
                            // without the call, for every other value).
                            if matches!(o.val.as_deref(), Some(Value::Picture(_)))
                                && let Err(d) = self.picture(o, line)
                            {
                                report.result = Err(d);
                            } else {
                                report.warnings.extend(not_finite_warning(o));
                            }
                        }
                    }
                }
            }
            // A result cut short by the budget is an error (a loop stopped
            // with what it had); the statement bound nothing.
            let mut fatal = false;
            if let Err(d) = &mut report.result
                && let Err(stop) = budget::check()
            {
                if stop == Stop::Interrupted {
                    self.interrupted = true;
                    errors += 1;
                    break;
                }
                *d = crate::eval::interp::budget_error(stop, d.span);
                fatal = true;
            }
            let failed = report.result.is_err();
            each(&report);
            if failed {
                errors += 1;
                if !keep_going || fatal {
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

/// A syntax or name error on a line typed from MATLAB or Python habit
/// (`syms x`, `format long`, `np.array(..)`) gets the chasles way as its
/// help.
fn habit_help(mut d: Diagnostic, src: &str) -> Diagnostic {
    add_habit_help(&mut d, src);
    d
}

/// [`habit_help`] in place.
fn add_habit_help(d: &mut Diagnostic, src: &str) {
    if !matches!(d.kind, ErrorKind::Syntax | ErrorKind::Name) {
        return;
    }
    let at = d.span.start.min(src.len());
    let start = src[..at].rfind('\n').map_or(0, |i| i + 1);
    let end = src[at..].find('\n').map_or(src.len(), |i| at + i);
    if let Some(h) = crate::diagnostics::habits::statement(&src[start..end]) {
        d.help = Some(h);
    }
}

/// A warning when a result holds NaN (an undefined operation such as
/// inf − inf) or, outside a tuple, ±inf (an overflow such as `2^1e308`, or
/// inf in the input): IEEE values are printed, never silently. Tuples may
/// hold inf by design (`screw_params` gives h = inf for a pure translation).
fn not_finite_warning(o: &crate::eval::interp::Outcome) -> Option<Diagnostic> {
    fn scan(v: &Value, top: bool, nan: &mut bool, inf: &mut bool) {
        match v {
            Value::Num { m, .. } => {
                *nan |= m.iter().any(|x| x.is_nan());
                *inf |= top && m.iter().any(|x| x.is_infinite());
            }
            Value::Tuple(vs) => vs.iter().for_each(|v| scan(v, false, nan, inf)),
            _ => {}
        }
    }
    let (mut nan, mut inf) = (false, false);
    scan(o.val.as_deref()?, true, &mut nan, &mut inf);
    let message = if nan {
        "the result has NaN entries: an undefined operation (inf − inf, 0·inf, an angle of inf)"
    } else if inf {
        "the result is infinite: an overflow (the number exceeds 1.8e308) or inf in the input"
    } else {
        return None;
    };
    Some(Diagnostic::warning(ErrorKind::Domain, o.span, message))
}

/// A binding name as a file name: letters, digits, `_` and `-` kept,
/// anything else (`{`, `,`, `'`) as `_`.
fn file_stem(name: &str) -> String {
    name.chars()
        .map(|c| {
            if c.is_alphanumeric() || c == '_' || c == '-' {
                c
            } else {
                '_'
            }
        })
        .collect()
}

/// Largest script accepted (bytes).
pub const MAX_SOURCE_BYTES: u64 = 100 * 1024 * 1024;

/// Reads a script; Err is the message for exit code 2.
pub fn read_source(path: &str) -> Result<String, String> {
    let bytes = if path == "-" {
        let mut buf = Vec::new();
        std::io::stdin()
            .lock()
            .take(MAX_SOURCE_BYTES + 1)
            .read_to_end(&mut buf)
            .map_err(|e| format!("cannot read standard input: {e}"))?;
        buf
    } else {
        let meta = std::fs::metadata(path)
            .map_err(|e| format!("cannot read '{path}': {}", io_reason(&e)))?;
        if meta.is_dir() {
            return Err(format!("cannot read '{path}': it is a directory"));
        }
        if meta.len() > MAX_SOURCE_BYTES {
            return Err(format!(
                "'{path}' is {} bytes; scripts are limited to {MAX_SOURCE_BYTES} bytes",
                meta.len()
            ));
        }
        std::fs::read(path).map_err(|e| format!("cannot read '{path}': {}", io_reason(&e)))?
    };
    if bytes.len() as u64 > MAX_SOURCE_BYTES {
        return Err(format!("input is larger than {MAX_SOURCE_BYTES} bytes"));
    }
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let what = if path == "-" {
            "standard input".to_string()
        } else {
            format!("'{path}'")
        };
        format!("{what} is not UTF-8 text: invalid byte at offset {at}")
    })
}

pub(crate) fn io_reason(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file".into(),
        std::io::ErrorKind::PermissionDenied => "permission denied".into(),
        _ => e.to_string(),
    }
}
