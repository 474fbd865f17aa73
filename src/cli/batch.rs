//! Running scripts (LANGUAGE.md §1): `chasles run FILE...`, `chasles
//! FILE...`, `chasles check FILE...`, `-e` and stdin. Each file runs in a
//! fresh session (after `--prelude FILE`, if given), under its own
//! `--timeout` and `--max-memory`; a file that cannot be read is reported
//! and the others still run. `--report` collects every assert as a test
//! case of [`crate::grade`].

use std::io::Write;
use std::path::PathBuf;
use std::time::Instant;

use super::{Opts, emit, emit_err, gate, writer};
use crate::diagnostics::render;
use crate::effects::Gate;
use crate::eval::env::Mode;
use crate::grade::{Suite, Verdict};
use crate::session::{Report, Session, read_source, shown_path};
use crate::syntax::AHEAD_FROM;

/// A script to run: its name in messages and its text, or why it could
/// not be read (with the bytes, when there were any, for the report).
pub(super) struct Source {
    /// The file as messages name it (`<stdin>`, `<-e>`).
    pub name: String,
    /// The text, or the message and the bytes read.
    pub text: Result<String, (String, Option<Vec<u8>>)>,
}

impl Source {
    /// Text given on the command line (`-e`).
    pub fn given(name: &str, text: String) -> Source {
        Source {
            name: name.into(),
            text: Ok(text),
        }
    }
}

/// Reads every file (`-` is stdin), keeping a failure as the file's own.
pub(super) fn load(files: &[PathBuf]) -> Vec<Source> {
    files
        .iter()
        .map(|f| {
            let stdin = f.as_os_str() == "-";
            Source {
                name: if stdin {
                    "<stdin>".to_string()
                } else {
                    shown_path(f)
                },
                text: read_source(f).map_err(|m| (m, (!stdin).then(|| bytes_of(f)).flatten())),
            }
        })
        .collect()
}

/// The bytes of a script that is not text, for the report to find its
/// asserts in: only a regular file under the size cap (never `/dev/zero`
/// or a pipe).
fn bytes_of(f: &std::path::Path) -> Option<Vec<u8>> {
    let meta = std::fs::metadata(f).ok()?;
    if !meta.is_file() || meta.len() > crate::session::MAX_SOURCE_BYTES {
        return None;
    }
    std::fs::read(f).ok()
}

/// What a run of many files shares: the flags, the gate, the prelude.
struct Batch<'a> {
    opts: &'a Opts,
    mode: Mode,
    gate: Gate,
    prelude: Option<(String, String)>,
    /// Whether each JSON object names its file (`run` and `check`).
    file_key: bool,
    /// Whether `--report` asks for the asserts as test cases: only then
    /// is each script read once more for its asserts (`Suite::new`).
    report: bool,
}

/// Runs (or checks) each source in a fresh session; returns the exit code:
/// 130 when interrupted, else 2 when a file could not be read (or the
/// report not written), else 1 when a script failed, else 0.
pub(super) fn run(sources: &[Source], mode: Mode, opts: &Opts, file_key: bool) -> i32 {
    let gate = match mode {
        Mode::Run => match gate(opts) {
            Ok(g) => g,
            Err(code) => return code,
        },
        _ => Gate::default(),
    };
    let prelude = match &opts.prelude {
        None => None,
        Some(p) => match read_source(p) {
            Ok(text) => Some((shown_path(p), text)),
            Err(m) => {
                emit_err(&format!("chasles: --prelude: {m}\n"));
                return 2;
            }
        },
    };
    let report = match opts.report() {
        // `check` evaluates no assert: it has no verdict to report.
        Ok(Some(_)) if mode == Mode::Check => {
            emit_err("chasles: --report is for `run` (check evaluates no assert)\n");
            return 2;
        }
        Ok(r) => r,
        Err(m) => {
            emit_err(&format!("chasles: {m}\n"));
            return 2;
        }
    };
    let batch = Batch {
        opts,
        mode,
        gate,
        prelude,
        file_key,
        report: report.is_some(),
    };
    // One Ctrl-C handler for the whole run; each file's clock starts anew.
    let base = opts.budget();
    // Not locked for the run: a long script's text is written by a thread
    // of its own (`writer`); the buffer locks stdout only when it writes.
    let mut out = std::io::BufWriter::new(std::io::stdout());
    let mut suites = Vec::new();
    let mut code = 0;
    for source in sources {
        let started = Instant::now();
        let (suite, file_code) = match &source.text {
            Err((message, bytes)) => {
                let _ = out.flush();
                emit_err(&format!("chasles: {message}\n"));
                if mode == Mode::Check && !opts.json {
                    emit(
                        &mut out,
                        &format!("{}: not checked: {message}", source.name),
                    );
                }
                let suite = Suite::unreadable(&source.name, bytes.as_deref(), message);
                (suite, 2)
            }
            Ok(text) => {
                let mut budget = base.clone();
                if let Some(t) = opts.timeout {
                    budget = budget.with_timeout(t);
                }
                batch.file(&source.name, text, budget, &mut out)
            }
        };
        if file_code == 130 {
            let _ = out.flush();
            emit_err("chasles: interrupted\n");
            return 130;
        }
        code = code.max(file_code);
        if report.is_some() {
            let mut suite = suite;
            suite.finish(started.elapsed().as_secs_f64());
            suites.push(suite);
        }
    }
    if out.flush().is_err() {
        return 0;
    }
    if let Some((format, path)) = &report {
        let text = format.write(&suites);
        if let Err(e) = crate::effects::atomic::write(path, text.as_bytes(), true) {
            emit_err(&format!(
                "chasles: cannot write the report '{}': {}\n",
                shown_path(path),
                crate::effects::atomic::reason(&e)
            ));
            return 2;
        }
    }
    code
}

impl Batch<'_> {
    /// One file in a fresh session: the prelude, then the script. Returns
    /// its asserts and its exit code (130 when interrupted).
    fn file(
        &self,
        name: &str,
        src: &str,
        budget: crate::budget::Budget,
        out: &mut impl Write,
    ) -> (Suite, i32) {
        let settings = self.opts.settings();
        let mut session = Session::new(settings);
        session.gate = self.gate.clone();
        session.budget = budget;
        session.quiet = self.opts.quiet;
        let keep_going = self.keep_going();
        // Without `--report` the suite is empty: no second parse of the
        // script for asserts nobody reports.
        let mut suite = Suite::new(name, if self.report { src } else { "" });
        let mut last_error = None;
        let mut errors = 0;
        if let Some((pname, psrc)) = &self.prelude {
            // The prelude's values are not printed; its errors are.
            errors += session.run(psrc, self.mode, keep_going, |r| {
                self.diagnostics(r, pname, psrc, out, &mut last_error);
            });
            if session.interrupted {
                return (suite, 130);
            }
            if errors > 0 && !keep_going {
                let why = format!("the prelude failed: {}", last_error.unwrap_or_default());
                suite.stop(why);
                return (suite, 1);
            }
        }
        let (script_errors, statements) =
            self.script(&mut session, name, src, &mut suite, &mut last_error, out);
        errors += script_errors;
        if session.interrupted {
            return (suite, 130);
        }
        let pending = suite
            .cases
            .iter()
            .any(|c| c.verdict == Verdict::NotRun(String::new()));
        if errors > 0 && (!keep_going || pending) {
            suite.stop(last_error.unwrap_or_default());
        }
        if self.mode == Mode::Check && !settings.json {
            let summary = if errors == 0 {
                format!(
                    "{name}: {statements} statement{} checked, frames consistent",
                    if statements == 1 { "" } else { "s" }
                )
            } else {
                format!(
                    "{name}: {errors} error{}",
                    if errors == 1 { "" } else { "s" }
                )
            };
            emit(out, &summary);
        }
        (suite, i32::from(errors > 0))
    }

    /// The script's statements in `session`, each one's text written as
    /// it is reported. Returns the errors and the statements run.
    fn script(
        &self,
        session: &mut Session,
        name: &str,
        src: &str,
        suite: &mut Suite,
        last_error: &mut Option<String>,
        out: &mut impl Write,
    ) -> (usize, usize) {
        let settings = self.opts.settings();
        let keep_going = self.keep_going();
        let mut statements = 0;
        // A long script's text is written by a second thread while the
        // next statements are evaluated ([`writer`]; the text of `run`
        // only: JSON lines and `check`'s errors are written here).
        if self.mode == Mode::Run && !settings.json && session.read_ahead && src.len() >= AHEAD_FROM
        {
            let _ = out.flush();
            let style = settings.text_style();
            let errors = writer::beside(style, |w| {
                session.run(src, self.mode, keep_going, |r| {
                    statements += 1;
                    let job = w.next();
                    if let Ok(o) = &r.result {
                        job.out.write(o, style);
                    }
                    suite.observe(r, src);
                    if !says_nothing(r) {
                        job.err = self.diagnostics_text(r, name, src, last_error);
                    }
                    w.done();
                })
            });
            return (errors, statements);
        }
        // One buffer for every statement's printed text.
        let mut text = String::with_capacity(192);
        let errors = session.run(src, self.mode, keep_going, |r| {
            statements += 1;
            // `check` prints only errors and its summary (or JSON lines).
            if self.mode == Mode::Run || settings.json {
                text.clear();
                r.write_stdout(&mut text, &settings, src);
                if !text.is_empty() {
                    if self.file_key {
                        emit(out, &with_file(&text, name));
                    } else {
                        emit(out, &text);
                    }
                }
            }
            suite.observe(r, src);
            self.diagnostics(r, name, src, out, last_error);
        });
        (errors, statements)
    }

    /// Whether a file runs on after an error (`--keep-going`, and always
    /// in `check`).
    fn keep_going(&self) -> bool {
        self.opts.keep_going || self.mode == Mode::Check
    }

    /// A report's warnings and error on stderr — the error under `--json`
    /// too, so that a grader's `NAME.err` holds it — remembering the
    /// error's first line.
    fn diagnostics(
        &self,
        r: &Report,
        file: &str,
        src: &str,
        out: &mut impl Write,
        last_error: &mut Option<String>,
    ) {
        // (most statements: nothing to say, answered without a call)
        if says_nothing(r) {
            return;
        }
        let err = self.diagnostics_text(r, file, src, last_error);
        if !err.is_empty() {
            let _ = out.flush();
            emit_err(&err);
        }
    }

    /// What [`Batch::diagnostics`] writes on stderr (empty when nothing;
    /// callers ask [`says_nothing`] first, without a call).
    #[inline(never)]
    fn diagnostics_text(
        &self,
        r: &Report,
        file: &str,
        src: &str,
        last_error: &mut Option<String>,
    ) -> String {
        let settings = self.opts.settings();
        let mut err = r.stderr(&settings, file, src);
        if let Err(d) = &r.result {
            let text = render::text_from(d, file, src, r.anchor);
            *last_error = Some(text.lines().next().unwrap_or_default().to_string());
            if settings.json {
                err.push_str(&text);
            }
        }
        err
    }
}

/// True for a report with no warning and no error: nothing for stderr
/// (most statements).
#[inline]
fn says_nothing(r: &Report) -> bool {
    r.warnings.is_empty() && r.result.is_ok()
}

/// A JSON line with `"file"` first (LANGUAGE.md §1: with `run`, every
/// object carries it).
fn with_file(line: &str, file: &str) -> String {
    match line.strip_prefix('{') {
        Some(rest) => {
            let key = serde_json::Value::from(file).to_string();
            let sep = if rest.starts_with('}') { "" } else { "," };
            format!("{{\"file\":{key}{sep}{rest}")
        }
        None => line.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::with_file;

    #[test]
    fn the_file_key_leads_each_json_line() {
        let line = with_file("{\"line\":1,\"value\":2}", "hw \"1\".chs");
        let j: serde_json::Value = serde_json::from_str(&line).expect("JSON");
        assert_eq!(j["file"], "hw \"1\".chs");
        assert_eq!(j["line"], 1);
        assert_eq!(with_file("{}", "a"), "{\"file\":\"a\"}");
    }
}
