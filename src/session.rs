//! A session: the environment plus settings, and the pipeline parse →
//! check → evaluate applied to a whole source text, statement by statement.
//! The CLI, the REPL and the tests all drive chasles through this.

use std::io::Read;
use std::ops::ControlFlow;

use crate::budget::{self, Budget, Stop};
use crate::diagnostics::{Diagnostic, ErrorKind, render};
use crate::effects::{Done, Effect, Gate, PictureTo};
use crate::eval::env::{Env, FrameMode, Mode};
use crate::eval::interp::{Interp, Outcome};
use crate::eval::value::Value;
use crate::output::{json, text};
use crate::span::Anchor;
use crate::syntax;

/// Output settings.
#[derive(Debug, Clone, Copy)]
pub struct Settings {
    /// `--frames strict|warn|off` (LANGUAGE.md §6).
    pub frames: FrameMode,
    /// Decimals in text output (LANGUAGE.md §10).
    pub digits: usize,
    /// `--json`: one JSON object per statement (LANGUAGE.md §1), not text.
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
    /// What it produced, or the error that stopped it (nothing bound).
    pub result: Result<Outcome, Diagnostic>,
    /// Its warnings and notes, in order.
    pub warnings: Vec<Diagnostic>,
    /// Where the statement's line starts, and its number: the statement's
    /// line ([`Report::line`]), and where its diagnostics number lines
    /// from without rescanning the source from its start.
    pub anchor: Anchor,
    /// The files the statement asks to write (a picture saved or printed),
    /// performed by the session's gate in [`Session::run`] before the
    /// report is seen, left undone by [`Session::evaluate`].
    pub effects: Vec<Effect>,
}

impl Report {
    /// The 1-based line where the statement starts.
    pub fn line(&self) -> usize {
        self.anchor.line
    }
    /// What goes to stdout: the value text or JSON line (empty if nothing).
    pub fn stdout(&self, settings: &Settings, src: &str) -> String {
        let mut out = String::new();
        self.write_stdout(&mut out, settings, src);
        out
    }

    /// [`Report::stdout`] appended to `out` (a batch run reuses one buffer).
    pub fn write_stdout(&self, out: &mut String, settings: &Settings, src: &str) {
        let json = match (&self.result, settings.json) {
            (Ok(o), false) => return text::write_outcome(out, o, settings.text_style()),
            (Err(_), false) => return,
            (Ok(o), true) => match json::outcome(o, self.line()) {
                Some(mut j) => {
                    json::add_warnings(&mut j, &self.warnings);
                    j
                }
                None => match json::silent(self.line(), &self.warnings) {
                    Some(j) => j,
                    None => return,
                },
            },
            (Err(d), true) => {
                // (an error in the body of a function defined earlier is
                // this statement's: its object is at the call, so that the
                // statement that failed is the one its line names)
                let at = match d.span.start < self.anchor.offset {
                    true => d
                        .labels
                        .iter()
                        .rev()
                        .find(|l| l.span.start >= self.anchor.offset)
                        .map_or(d.span.start, |l| l.span.start),
                    false => d.span.start,
                };
                let (line, col) = render::line_col_from(src, at, self.anchor);
                let mut j = json::error(d, line, col);
                json::add_warnings(&mut j, &self.warnings);
                j
            }
        };
        out.push_str(&json.to_string());
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

    /// Appends what this statement prints to `out` (a line) and `err`, as
    /// [`Session::run_to_strings`] and the REPL's recording runner collect
    /// a run's text.
    pub fn append_to(
        &self,
        settings: &Settings,
        file: &str,
        src: &str,
        out: &mut String,
        err: &mut String,
    ) {
        let o = self.stdout(settings, src);
        if !o.is_empty() {
            out.push_str(&o);
            out.push('\n');
        }
        err.push_str(&self.stderr(settings, file, src));
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
    /// The bindings and user functions so far.
    pub env: Env,
    /// How values print and frames are checked.
    pub settings: Settings,
    /// The statements that ran without error, in order, as typed — what
    /// the REPL's `:save` writes and `:history` lists (scripts leave it
    /// empty).
    pub accepted: Vec<String>,
    /// The front end's decision on every file a statement asks to write
    /// (`save`, printed pictures, `:save`): see [`crate::effects`]. The
    /// default keeps pictures in memory; the CLI and REPL write them (to
    /// `.` or `--draw-dir`), `--no-write` skips (a warning), `--write-dir` confines.
    pub gate: Gate,
    /// The file of the last picture written (the REPL's `:open`).
    pub last_picture: Option<String>,
    /// The evaluation budget every statement runs under (`--timeout`,
    /// `--max-memory`, Ctrl-C through its [`Budget::interrupt_handle`]).
    pub budget: Budget,
    /// Whether the last [`Session::run`] was stopped by an interrupt (its
    /// statement bound nothing and was not reported).
    pub interrupted: bool,
    /// `--quiet` (LANGUAGE.md §1): every statement as if ended by `;` —
    /// no value printed, no printed picture written; errors and warnings
    /// still reported.
    pub quiet: bool,
    /// Whether a long source is read on a second thread while its
    /// statements run ([`syntax::each_statement`]), and a batch run's text
    /// written on another (true; the same results either way). False
    /// keeps a run on one thread: `CHASLES_THREADS=1`, for measurement
    /// and for the tests that compare the two.
    pub read_ahead: bool,
    /// The lines of the session's script before the source being run: 0
    /// for a script; in the REPL, the lines `:save` would write so far
    /// ([`crate::frontend::save::run_recording_each`] sets it). A picture
    /// printed but not saved is `draw-LINE.svg` by its statement's line in
    /// that script, so that two inputs do not write one file, and `:save`
    /// reruns to the same files (LANGUAGE.md §§11, 12).
    pub lines_before: usize,
}

impl Session {
    /// An empty session with `settings`, the default gate (pictures kept
    /// in memory) and a fresh budget.
    pub fn new(settings: Settings) -> Session {
        Session {
            env: Env::default(),
            settings,
            accepted: Vec::new(),
            gate: Gate::default(),
            last_picture: None,
            budget: Budget::new(),
            interrupted: false,
            quiet: false,
            read_ahead: std::env::var_os("CHASLES_THREADS").is_none_or(|n| n != "1"),
            lines_before: 0,
        }
    }

    /// A picture that a statement printed: checked and described, and
    /// the file it asks for as an effect — the name `save` gave, else
    /// `NAME.svg` or `draw-LINE.svg` for the folder of printed pictures.
    /// Nothing is written here.
    fn picture(o: &mut Outcome, line: usize) -> Result<Option<Effect>, Diagnostic> {
        let Some(Value::Picture(p)) = o.val.as_deref() else {
            return Ok(None);
        };
        let fail = |m: String| Diagnostic::error(ErrorKind::Domain, o.span, m);
        let p = crate::draw::described(p).map_err(fail)?;
        // A picture `save` names is written even by a silent statement
        // (`save(pic, "f.svg");`); one only printed is not, when silenced.
        let effect = if !p.is_view_only() && (o.prints || p.save_to.is_some()) {
            let to = match (&p.save_to, o.names.as_slice()) {
                (Some(f), _) => PictureTo::Saved(f.into()),
                (None, [name]) => PictureTo::Printed(format!("{}.svg", file_stem(name))),
                _ => PictureTo::Printed(format!("draw-{line}.svg")),
            };
            Some(Effect::Picture {
                to,
                picture: p.clone(),
            })
        } else {
            None
        };
        o.val = Some(Box::new(Value::Picture(p)));
        Ok(effect)
    }

    /// Performs the report's effects through the gate: a picture written
    /// says where (`→ pic.svg`); a write skipped (`--no-write`) is a
    /// warning naming the file; a write refused or failed makes the
    /// statement's error.
    fn settle(&mut self, report: &mut Report) {
        let Ok(o) = &mut report.result else { return };
        for e in &report.effects {
            match self.gate.perform(e) {
                Ok(Done::InMemory) => {}
                Ok(Done::Skipped(m)) => {
                    report
                        .warnings
                        .push(Diagnostic::warning(ErrorKind::Domain, o.span, m));
                }
                Ok(Done::Written(shown)) => {
                    if let Some(n) = renamed(e, &shown, o.span) {
                        report.warnings.push(n);
                    }
                    if let (Effect::Picture { .. }, Some(Value::Picture(p))) =
                        (e, o.val.as_deref_mut())
                    {
                        std::rc::Rc::make_mut(p).file = Some(shown.clone());
                        self.last_picture = Some(shown);
                    }
                }
                Err(err) => {
                    report.result = Err(Diagnostic::error(
                        ErrorKind::Domain,
                        o.span,
                        err.to_string(),
                    ));
                    return;
                }
            }
        }
    }

    /// Runs (or, in [`Mode::Check`], checks) every statement of `src`,
    /// calling `each` with each report in order, after the gate performed
    /// its effects. Stops after the first error unless `keep_going`.
    /// Returns the number of errors.
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
        each: impl FnMut(&Report),
    ) -> usize {
        self.statements(src, mode, keep_going, true, each)
    }

    /// [`Session::run`] with no effect performed, whatever the gate: each
    /// report carries the files it would write in `effects`, and no file is
    /// touched (the REPL's live preview, LANGUAGE.md §11).
    pub fn evaluate(
        &mut self,
        src: &str,
        mode: Mode,
        keep_going: bool,
        each: impl FnMut(&Report),
    ) -> usize {
        self.statements(src, mode, keep_going, false, each)
    }

    fn statements(
        &mut self,
        src: &str,
        mode: Mode,
        keep_going: bool,
        write: bool,
        mut each: impl FnMut(&Report),
    ) -> usize {
        let mut errors = 0;
        let _budget = self.budget.enter();
        self.interrupted = false;
        // A new text: spans of functions defined before point elsewhere.
        self.env.source = self.env.source.wrapping_add(1);
        syntax::each_statement(src, self.read_ahead, |parsed, anchor| {
            budget::begin_statement(self.env.held());
            // The report is built in place and changed there: its result
            // (a large value) is written once, not moved through
            // `map_err` and a second struct.
            let mut report;
            match parsed {
                Err(d) => {
                    report = Report {
                        anchor,
                        result: Err(habit_help(d.clone(), src)),
                        warnings: Vec::new(),
                        effects: Vec::new(),
                    }
                }
                Ok(stmt) => {
                    let mut interp = Interp::new(&mut self.env, src, mode, self.settings.frames);
                    report = Report {
                        anchor,
                        result: interp.stmt(stmt),
                        warnings: Vec::new(),
                        effects: Vec::new(),
                    };
                    report.warnings = std::mem::take(&mut interp.warnings);
                    match &mut report.result {
                        Err(d) => add_habit_help(d, src),
                        Ok(o) => {
                            o.prints &= !self.quiet;
                            // Only a picture has more to do (checked here,
                            // without the call, for every other value).
                            if matches!(o.val.as_deref(), Some(Value::Picture(_))) {
                                match Session::picture(o, self.lines_before + anchor.line) {
                                    Err(d) => report.result = Err(d),
                                    Ok(e) => report.effects.extend(e),
                                }
                                if write {
                                    self.settle(&mut report);
                                }
                            } else {
                                // (a number silenced by `;` was moved into
                                // its binding and warned there)
                                report.warnings.extend(
                                    o.val
                                        .as_deref()
                                        .and_then(|v| crate::eval::outcome::not_finite(v, o.span)),
                                );
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
                    return ControlFlow::Break(());
                }
                *d = crate::eval::interp::budget_error(stop, d.span);
                fatal = true;
            }
            let failed = report.result.is_err();
            each(&report);
            if failed {
                errors += 1;
                if !keep_going || fatal {
                    return ControlFlow::Break(());
                }
            }
            ControlFlow::Continue(())
        });
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
        self.collect_strings(file, src, mode, keep_going, true)
    }

    /// [`Session::run_to_strings`] without performing any effect (see
    /// [`Session::evaluate`]): the REPL's live preview.
    pub fn evaluate_to_strings(
        &mut self,
        file: &str,
        src: &str,
        mode: Mode,
        keep_going: bool,
    ) -> (String, String, usize) {
        self.collect_strings(file, src, mode, keep_going, false)
    }

    fn collect_strings(
        &mut self,
        file: &str,
        src: &str,
        mode: Mode,
        keep_going: bool,
        write: bool,
    ) -> (String, String, usize) {
        let (mut out, mut err) = (String::new(), String::new());
        let settings = self.settings;
        let n = self.statements(src, mode, keep_going, write, |r| {
            r.append_to(&settings, file, src, &mut out, &mut err);
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

/// The note when a printed picture took another name than it asked for
/// (the name was a file of the user's, kept: `crate::effects`).
fn renamed(e: &Effect, shown: &str, span: crate::span::Span) -> Option<Diagnostic> {
    let Effect::Picture {
        to: PictureTo::Printed(asked),
        ..
    } = e
    else {
        return None;
    };
    let name = |p: &str| std::path::Path::new(p).file_name().map(|n| n.to_owned());
    if name(shown) == name(asked) {
        return None;
    }
    Some(Diagnostic::note(
        ErrorKind::Domain,
        span,
        format!(
            "'{asked}' exists and is not a picture chasles printed: it is kept, and this picture is '{shown}'"
        ),
    ))
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

/// Reads a script (`-` is standard input) under the one size cap
/// [`MAX_SOURCE_BYTES`] — a file is read through the same bounded reader as
/// stdin, so `/dev/zero` or a pipe cannot fill memory — and skips a leading
/// byte-order mark. Err is the message for exit code 2, with the name's
/// control characters and bytes that are not UTF-8 shown escaped.
pub fn read_source(path: impl AsRef<std::path::Path>) -> Result<String, String> {
    let path = path.as_ref();
    let stdin = path.as_os_str() == "-";
    let what = if stdin {
        "standard input".to_string()
    } else {
        format!("'{}'", shown_path(path))
    };
    let mut buf = Vec::new();
    let read = if stdin {
        std::io::stdin()
            .lock()
            .take(MAX_SOURCE_BYTES + 1)
            .read_to_end(&mut buf)
    } else {
        let file = std::fs::File::open(path)
            .map_err(|e| format!("cannot read {what}: {}", io_reason(&e)))?;
        match file.metadata() {
            Ok(m) if m.is_dir() => return Err(format!("cannot read {what}: it is a directory")),
            Ok(m) if m.len() > MAX_SOURCE_BYTES => {
                return Err(format!(
                    "{what} is {} bytes; scripts are limited to {MAX_SOURCE_BYTES} bytes",
                    m.len()
                ));
            }
            // A regular file's text is read into room made for it once
            // (through `take` the reader cannot see the size, and a 2 MB
            // script was read by doubling, copied about 20 times, issue 40).
            Ok(m) if m.is_file() => buf.reserve_exact(m.len() as usize + 1),
            _ => {}
        }
        file.take(MAX_SOURCE_BYTES + 1).read_to_end(&mut buf)
    };
    read.map_err(|e| format!("cannot read {what}: {}", io_reason(&e)))?;
    if buf.len() as u64 > MAX_SOURCE_BYTES {
        return Err(format!(
            "{what} is more than {MAX_SOURCE_BYTES} bytes; scripts are limited to {MAX_SOURCE_BYTES} bytes"
        ));
    }
    let mut text = String::from_utf8(buf).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        format!("{what} is not UTF-8 text: invalid byte at offset {at}")
    })?;
    if text.starts_with('\u{feff}') {
        text.drain(..'\u{feff}'.len_utf8());
    }
    Ok(text)
}

/// A path for a message: bytes that are not UTF-8 as `\xNN`, control
/// characters escaped.
pub fn shown_path(path: &std::path::Path) -> String {
    crate::diagnostics::escape::bytes(path.as_os_str().as_encoded_bytes())
}

pub(crate) fn io_reason(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file".into(),
        std::io::ErrorKind::PermissionDenied => "permission denied".into(),
        _ => e.to_string(),
    }
}
