//! Helpers shared by the integration tests, one definition each: running
//! the real `chasles` binary (once, in a folder, or bounded by a time limit
//! so that a hang fails instead of blocking), running a script through a
//! fresh [`Session`] and reading what it printed or its JSON lines
//! (LANGUAGE.md §1), the numbers of a JSON value, random points, a scratch
//! folder, (in [`lsp`]) a client of `chasles lsp`, and (in [`pty`]) the steps
//! of a session on a pseudo-terminal.
//!
//! Each test file is its own crate and uses only a part of these, hence
//! the `dead_code` allowance.

#![allow(dead_code)]

use std::ffi::OsStr;
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};

pub mod lsp;
#[cfg(unix)]
pub mod pty;

// ------------------------------------------------------------ the binary

/// How long one run of the binary may take before the test calls it a
/// hang (generous: the CI machine is small and shared).
pub const LIMIT: Duration = Duration::from_secs(120);

/// The `chasles` binary with `args`, colours off.
pub fn command(args: &[&str]) -> Command {
    command_os(args)
}

/// [`command`] with arguments that need not be UTF-8.
pub fn command_os<S: AsRef<OsStr>>(args: &[S]) -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_chasles"));
    cmd.args(args).env("NO_COLOR", "1");
    cmd
}

/// Exit code (−1 for a signal), stdout and stderr of a finished run.
fn parts(out: &Output) -> (i32, String, String) {
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Runs the `chasles` binary with `args` (colours off) and returns its exit
/// code (−1 for a signal), stdout and stderr.
pub fn run(args: &[&str]) -> (i32, String, String) {
    parts(&command(args).output().expect("chasles runs"))
}

/// [`run`] in the folder `dir` (where relative paths are written).
pub fn run_in(args: &[&str], dir: &Path) -> (i32, String, String) {
    parts(
        &command(args)
            .current_dir(dir)
            .output()
            .expect("chasles runs"),
    )
}

/// A finished run as a snapshot shows it: the exit code, then stdout and
/// stderr under their headings.
pub fn report(out: &Output) -> String {
    format!(
        "exit: {}\n--- stdout\n{}--- stderr\n{}",
        out.status
            .code()
            .map_or("signal".to_string(), |c| c.to_string()),
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// The output of one bounded run of the binary.
#[derive(Debug)]
pub struct Out {
    /// The exit code; `None` for a signal.
    pub code: Option<i32>,
    /// Stdout, decoded lossily.
    pub stdout: String,
    /// Stderr, decoded lossily.
    pub stderr: String,
    /// Stderr exactly as written (to check for raw control bytes).
    pub stderr_bytes: Vec<u8>,
    /// How long the run took.
    pub took: Duration,
}

/// Starts the binary with `args`, stdin closed, stdout and stderr piped.
pub fn spawn(args: &[&str]) -> Child {
    command(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the chasles binary starts")
}

/// Waits for `child` at most `limit`; a hang kills it and fails the test.
pub fn finish(mut child: Child, limit: Duration) -> Out {
    let start = Instant::now();
    let mut out_pipe = child.stdout.take().expect("stdout is piped");
    let mut err_pipe = child.stderr.take().expect("stderr is piped");
    let out_reader = std::thread::spawn(move || {
        let mut s = Vec::new();
        let _ = out_pipe.read_to_end(&mut s);
        s
    });
    let err_reader = std::thread::spawn(move || {
        let mut s = Vec::new();
        let _ = err_pipe.read_to_end(&mut s);
        s
    });
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait") {
            break status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("chasles did not finish within {limit:?} (a hang)");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let stdout = out_reader.join().unwrap_or_default();
    let stderr_bytes = err_reader.join().unwrap_or_default();
    Out {
        code: status.code(),
        stdout: String::from_utf8_lossy(&stdout).into_owned(),
        stderr: String::from_utf8_lossy(&stderr_bytes).into_owned(),
        stderr_bytes,
        took: start.elapsed(),
    }
}

/// Runs the binary with `args` and `stdin` (closed when `None`), failing
/// the test instead of blocking if it has not finished within `limit`.
pub fn run_with<S: AsRef<OsStr>>(args: &[S], stdin: Option<&[u8]>, limit: Duration) -> Out {
    let mut child = command_os(args)
        .stdin(if stdin.is_some() {
            Stdio::piped()
        } else {
            Stdio::null()
        })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the chasles binary starts");
    if let Some(bytes) = stdin {
        let mut pipe = child.stdin.take().expect("stdin is piped");
        let bytes = bytes.to_vec();
        std::thread::spawn(move || {
            let _ = pipe.write_all(&bytes);
        });
    }
    finish(child, limit)
}

/// Runs the binary with `args`, stdin closed, within [`LIMIT`].
pub fn bounded(args: &[&str]) -> Out {
    run_with(args, None, LIMIT)
}

/// [`run_with`] within [`LIMIT`].
pub fn chasles(args: &[&str], stdin: Option<&[u8]>) -> Out {
    run_with(args, stdin, LIMIT)
}

// ---------------------------------------------------- a script in a session

/// Runs `src` in a fresh session (`json` output or not): stdout, stderr
/// and the number of errors.
fn session_run(src: &str, json: bool, keep_going: bool) -> (String, String, usize) {
    let mut s = Session::new(Settings {
        json,
        ..Settings::default()
    });
    s.run_to_strings("t.chs", src, Mode::Run, keep_going)
}

/// Stdout and stderr of `src` in a fresh session, failing on any error.
pub fn outputs(src: &str) -> (String, String) {
    let (out, err, n) = session_run(src, false, false);
    assert_eq!(n, 0, "{src}\n{err}");
    (out, err)
}

/// What `src` prints in a fresh session, failing on any error.
pub fn printed(src: &str) -> String {
    outputs(src).0
}

/// The error text of `src` (stopping at the first error), as a terminal
/// shows it; fails if `src` runs cleanly.
pub fn error(src: &str) -> String {
    let (_, err, n) = session_run(src, false, false);
    assert!(n > 0, "{src} should fail");
    err
}

/// Every error of `src` (`--keep-going`), messages and help as printed;
/// fails if `src` runs cleanly.
pub fn errors(src: &str) -> String {
    let (_, err, n) = session_run(src, false, true);
    assert!(n > 0, "{src} should fail");
    err
}

/// Each line of `text` as a JSON value (the `--json` output, §1).
pub fn json_lines(text: &str) -> Vec<serde_json::Value> {
    text.lines()
        .map(|l| serde_json::from_str(l).expect("one JSON object a line"))
        .collect()
}

/// The JSON line of each statement of `src`, or the error text.
pub fn try_json(src: &str) -> Result<Vec<serde_json::Value>, String> {
    let (out, err, n) = session_run(src, true, false);
    if n > 0 {
        return Err(err);
    }
    Ok(json_lines(&out))
}

/// The JSON line of each statement of `src`, failing on any error.
pub fn json(src: &str) -> Vec<serde_json::Value> {
    try_json(src).unwrap_or_else(|e| panic!("{src}\n{e}"))
}

/// The numbers of a JSON value, in reading order (rows of a matrix one
/// after the other; a bool as 0 or 1; a mechanism as its dof).
pub fn numbers(v: &serde_json::Value) -> Vec<f64> {
    match v {
        serde_json::Value::Array(xs) => xs.iter().flat_map(numbers).collect(),
        serde_json::Value::Bool(b) => vec![f64::from(u8::from(*b))],
        serde_json::Value::Object(o) => o.get("dof").map(numbers).unwrap_or_default(),
        x => vec![x.as_f64().expect("a number")],
    }
}

/// The numbers of the last statement of `src`.
pub fn last_numbers(src: &str) -> Vec<f64> {
    numbers(&json(src).last().expect("a value")["value"])
}

/// The last statement of `setup; a` gives the same numbers as that of
/// `setup; b` (within 1e-12).
pub fn same(setup: &str, a: &str, b: &str) {
    let x = last_numbers(&format!("{setup}\n{a}"));
    let y = last_numbers(&format!("{setup}\n{b}"));
    assert_eq!(x.len(), y.len(), "{a} vs {b}");
    for (u, v) in x.iter().zip(&y) {
        assert!((u - v).abs() <= 1e-12, "{a} = {x:?} but {b} = {y:?}");
    }
}

// ------------------------------------------------------------ examples

/// The numbers of an example as they are written (their byte ranges),
/// not those inside names (`Rotz`, `t2`, `1e-7` is one number).
pub fn literals(src: &str) -> Vec<(usize, usize)> {
    let b = src.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    let mut in_string = false;
    while i < b.len() {
        let c = b[i];
        if c == b'"' {
            in_string = !in_string;
        }
        let word_before = i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_');
        if !in_string && c.is_ascii_digit() && !word_before {
            let start = i;
            while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
                i += 1;
            }
            if i + 1 < b.len() && b[i] == b'e' && (b[i + 1] == b'-' || b[i + 1].is_ascii_digit()) {
                i += 2;
                while i < b.len() && b[i].is_ascii_digit() {
                    i += 1;
                }
            }
            out.push((start, i));
            continue;
        }
        i += 1;
    }
    out
}

// ------------------------------------------------------------ random points

/// A small deterministic generator (xorshift) of the points at which a
/// closed form is compared with numbers.
pub struct Rng(pub u64);

impl Rng {
    /// The next number, uniform in [-1, 1).
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

// ------------------------------------------------------------------ files

/// A fresh, empty scratch folder under the target folder, named after the
/// test file and `name` (so that test files running at once never share).
pub fn scratch(name: &str) -> PathBuf {
    let d =
        Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{}-{name}", env!("CARGO_CRATE_NAME")));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("a temporary folder");
    d
}

// ------------------------------------------------- the Python test tools

/// Says on the test's real stderr (not captured, so `cargo test` shows it
/// beside the test's `ok`) that a check was skipped and why.
pub fn say_skipped(why: &str) {
    let _ = writeln!(std::io::stderr().lock(), "skipped: {why}");
}

/// The Python with the pinned tools of `tests/jupyter/requirements.txt`
/// (Jupyter's test tools, xmlschema): `CHASLES_JUPYTER_PYTHON`, else
/// `target/jupyter-venv` (which `.ci/run` creates) when present. Without
/// one the caller skips its check and says so, unless
/// `CHASLES_REQUIRE_JUPYTER` is set (as `.ci/run` sets it): then the test
/// fails.
pub fn test_python() -> Option<PathBuf> {
    let named = std::env::var_os("CHASLES_JUPYTER_PYTHON")
        .filter(|p| !p.is_empty())
        .map(PathBuf::from);
    let venv = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/jupyter-venv/bin/python");
    let found = named.or_else(|| venv.is_file().then_some(venv));
    if found.is_none() {
        let msg = "no Python with the test tools of tests/jupyter/requirements.txt: set \
                   CHASLES_JUPYTER_PYTHON or run .ci/run";
        assert!(
            std::env::var_os("CHASLES_REQUIRE_JUPYTER").is_none(),
            "{msg}"
        );
        say_skipped(msg);
    }
    found
}
