//! The front ends against each other (LANGUAGE.md §§1, 11, 13, 15): they
//! decide no mathematics, all go through one session, and so must agree.
//! A seeded sweep over every script under `examples/` and `tests/errors/`
//! and variants of them (frames swapped so that products stop cancelling,
//! syntax errors, unknown names, wrong argument counts, non-rotation
//! matrices, `given` symbols, multi-line statements, tabs and Unicode
//! names, CRLF, a byte-order mark):
//!
//! - `chasles lsp` publishes, for a document opened and after incremental
//!   and full `didChange` edits, the diagnostics `chasles check FILE` prints
//!   for the same text: the same errors, warnings and notes, at the same
//!   place (0-based lines and UTF-16 columns against 1-based lines and
//!   columns in characters), with the same kind, message and help;
//! - the REPL, fed the script's lines as a user types them (a line, more
//!   while a bracket is open), prints what `chasles run --keep-going` prints
//!   for the file, statement by statement, with the same diagnostics at the
//!   same lines — so an error loses none of the REPL's bindings;
//! - a notebook kernel's session, given the same inputs as cells, shows the
//!   same values (`text/plain`) and the same errors.
//!
//! `tests/sweeps/frontends_sweep.py` is the larger sweep (more variants per
//! script, `run` against `check`); this one is fast and runs in CI.

mod common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use chasles::effects::Gate;
use chasles::kernel::cell::{Notebook, Options, Output};
use chasles::repl::commands::execute;
use chasles::session::{Session, Settings};
use common::lsp::Client;
use serde_json::{Value, json};

const SEED: u64 = 0x5eed_0033;

/// Variants of each script beside the script itself, for the language
/// server; `CHASLES_SWEEP=N` asks for N (a larger sweep, minutes long).
fn per_script() -> usize {
    std::env::var("CHASLES_SWEEP")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(1)
}

// ------------------------------------------------------------- the cases

/// A small deterministic generator (xorshift64*).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn pick<'a, T>(&mut self, xs: &'a [T]) -> &'a T {
        &xs[self.below(xs.len())]
    }
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The scripts of `examples/` and `tests/errors/<kind>/`, by name.
fn scripts() -> Vec<(String, String)> {
    let mut paths = Vec::new();
    for dir in std::fs::read_dir(root().join("tests/errors")).unwrap() {
        let dir = dir.unwrap().path();
        if dir.is_dir() {
            paths.extend(std::fs::read_dir(dir).unwrap().map(|f| f.unwrap().path()));
        }
    }
    paths.extend(
        std::fs::read_dir(root().join("examples"))
            .unwrap()
            .map(|f| f.unwrap().path()),
    );
    paths.retain(|p| p.extension().is_some_and(|e| e == "chs"));
    paths.sort();
    paths
        .into_iter()
        .map(|p| {
            let name = p
                .strip_prefix(root())
                .unwrap()
                .to_string_lossy()
                .into_owned();
            (name, std::fs::read_to_string(&p).unwrap())
        })
        .collect()
}

/// A line inserted at a random line of `t`.
fn insert(rng: &mut Rng, t: &str, lines: &[&'static str]) -> String {
    let mut ls: Vec<&str> = t.split('\n').collect();
    let at = rng.below(ls.len() + 1);
    ls.insert(at, *rng.pick(lines));
    ls.join("\n")
}

/// One variant of `t` by a mutation picked at random; its name.
fn variant(rng: &mut Rng, t: &str) -> (&'static str, String) {
    match rng.below(11) {
        0 => ("frames swapped", swap_frames(rng, t)),
        1 => {
            let mut ls: Vec<String> = t.split('\n').map(str::to_string).collect();
            let i = rng.below(ls.len());
            let junk = rng.pick(&[")", "(", "@", "= =", "[1, 2", "*", "1 +", "$", ",,"]);
            ls[i].push(' ');
            ls[i].push_str(junk);
            ("syntax error", ls.join("\n"))
        }
        2 => (
            "unknown name",
            insert(
                rng,
                t,
                &[
                    "x = Rotzz(1)",
                    "y = undefined_thing + 1",
                    "T_ab * T_zz",
                    "np.array([1, 2])",
                    "syms x",
                    "R_sc",
                ],
            ),
        ),
        3 => (
            "wrong argument count",
            insert(
                rng,
                t,
                &[
                    "Rotz(1, 2)",
                    "a = Ad()",
                    "MatrixExp3(1, 2, 3)",
                    "b = cross((1, 0, 0))",
                ],
            ),
        ),
        4 => (
            "not a rotation",
            insert(
                rng,
                t,
                &[
                    "R_ab = [1, 2, 3; 4, 5, 6; 7, 8, 9]",
                    "R_cd = [1, 0, 0; 0, 1, 0; 0, 0, 1.001]",
                    "T_ab = [1, 0, 0, 1; 0, 2, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1]",
                    "log([1, 2; 3, 4])",
                ],
            ),
        ),
        5 => {
            let head = rng.pick(&[
                "given T_ab, T_bc : SE3\nT_ab * T_cb\n",
                "given θ, t1 : scalar\nRotz(θ) * Rotz(t1)\n",
                "given R_sb : SO3\ngiven w_b : vec3\nR_sb * w_b\nR_sb.T * w_b\n",
                "given V_b : twist\ngiven T_sb : SE3\nAd(T_sb) * V_b\nAd(T_sb) * V_s\n",
            ]);
            ("given symbols", format!("{head}{t}"))
        }
        6 => (
            "multi-line statements",
            insert(
                rng,
                t,
                &[
                    "M = [1, 0, 0\n     0, 1, 0\n     0, 0, 2]\nR_ab = M",
                    "T_ab = [1, 0, 0, 1;\n  0, 1, 0, 2;\n  0, 0, 1, 3;\n  0, 0, 0, 1]\nT_ab * T_cb",
                    "v = (1,\n  2,\n  3) +\n (1, 2)",
                    "x = Rotz(\n  30 deg) * (1,\n 0, 0) * T_xy",
                ],
            ),
        ),
        7 => (
            "tabs and Unicode names",
            insert(
                rng,
                t,
                &[
                    "θ\t= 30°\n\tR_ab = Rotz(θ)\tT_cd",
                    "ω̂ = (0, 0, 1)\nR_ab = Rot(ω̂, 1) * R_cd",
                    "𝜃 = 1; ω̂_b = (0, 0, 1); 𝜃 * ω̂_b + (1, 2)",
                    "\t\tθ₁ = π/2\n\t\tRotz(θ₁) * T_ab_bad",
                ],
            ),
        ),
        8 => ("CRLF", t.replace("\r\n", "\n").replace('\n', "\r\n")),
        9 => ("byte-order mark", format!("\u{feff}{t}")),
        _ => (
            "ans, explain, derive, brackets in comments",
            insert(
                rng,
                t,
                &[
                    "Rotz(1)\nans * ans\nans[1, 2]",
                    "explain log(Rotz(2))\nexplain T_zz * T_ab",
                    "given T_ab, T_bc : SE3\nderive T_ac\nderive T_aq",
                    "x = 1 # see (3.5 and [w\ny = [1, 2] # [\nx + y",
                    "f(t) = t + (1, 2)\nf(1)\nf(2, 3)",
                    "assert Rotz(1) ≈ Rotz(1.1)\nassert 1 == 1",
                ],
            ),
        ),
    }
}

/// One use of a two-frame name with its frames swapped (`T_ab` → `T_ba`),
/// or a product that does not cancel appended when there is none.
fn swap_frames(rng: &mut Rng, t: &str) -> String {
    let b = t.as_bytes();
    let spots: Vec<usize> = (0..b.len().saturating_sub(4))
        .filter(|&i| {
            (b[i] == b'R' || b[i] == b'T')
                && b[i + 1] == b'_'
                && b[i + 2].is_ascii_lowercase()
                && b[i + 3].is_ascii_lowercase()
                && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'))
                && b.get(i + 4)
                    .is_none_or(|c| !(c.is_ascii_alphanumeric() || *c == b'_' || *c == b'\''))
        })
        .collect();
    if spots.is_empty() {
        return format!("{t}\nT_ab = Trans((1, 2, 3))\nT_cb = Trans((0, 1, 0))\nT_ab * T_cb\n");
    }
    let i = *rng.pick(&spots);
    let mut s = t.to_string();
    s.replace_range(
        i + 2..i + 4,
        &format!("{}{}", b[i + 3] as char, b[i + 2] as char),
    );
    s
}

/// The scripts and `per` variants of each (the script itself too when
/// `original`): (name, text).
fn cases(per: usize, original: bool) -> Vec<(String, String)> {
    let mut rng = Rng(SEED);
    let mut out = Vec::new();
    for (name, text) in scripts() {
        for k in 0..per {
            let (how, mut v) = variant(&mut rng, &text);
            let mut how = how.to_string();
            if rng.below(3) == 0 {
                let (again, w) = variant(&mut rng, &v);
                v = w;
                how = format!("{how}, {again}");
            }
            out.push((format!("{name} #{k} ({how})"), v));
        }
        if original {
            out.push((name, text));
        }
    }
    out
}

// ------------------------------------------------------------ diagnostics

/// One diagnostic as every front end can report it: its byte offset in the
/// text, `error`/`warning`/`note` (with the error's kind), the message and
/// the first line of its help.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
struct Diag {
    at: usize,
    severity: String,
    message: String,
    help: Option<String>,
    /// Shown at the call of a function whose body, where the error is,
    /// was typed in an earlier REPL input or cell.
    earlier: bool,
}

/// The byte offset of a 1-based line and a 1-based column in characters
/// (as the command line prints them) in `text`.
fn offset_of_char_col(text: &str, line: usize, col: usize) -> usize {
    let start: usize = text.split('\n').take(line - 1).map(|l| l.len() + 1).sum();
    let l = text.split('\n').nth(line - 1).unwrap_or("");
    start + l.chars().take(col - 1).map(char::len_utf8).sum::<usize>()
}

/// The byte offset of a 0-based line and a column in UTF-16 units (as the
/// language server counts them).
fn offset_of_utf16(text: &str, line: usize, units: usize) -> usize {
    let start: usize = text.split('\n').take(line).map(|l| l.len() + 1).sum();
    let l = text.split('\n').nth(line).unwrap_or("");
    let mut n = 0;
    for (i, c) in l.char_indices() {
        if n >= units {
            return start + i;
        }
        n += c.len_utf16();
    }
    start + l.len()
}

/// A header `NAME:LINE:COL: kind error: message` (or `warning:`, `note:`)
/// whose NAME passes `named`: the name, line, column, severity, message.
fn header(
    line: &str,
    named: impl Fn(&str) -> bool,
) -> Option<(String, usize, usize, String, String)> {
    // (messages may hold ": ": split at the first severity word)
    let sev_at = [" error: ", ": warning: ", ": note: "]
        .iter()
        .filter_map(|s| line.find(s).map(|i| (i, *s)))
        .min()?;
    let (head, rest) = line.split_at(sev_at.0);
    let (head, severity) = if sev_at.1 == " error: " {
        let (h, kind) = head.rsplit_once(": ")?;
        (h, format!("{kind} error"))
    } else {
        (head, sev_at.1.trim_matches([':', ' ']).to_string())
    };
    let message = rest[sev_at.1.len()..].to_string();
    let mut it = head.rsplitn(3, ':');
    let col: usize = it.next()?.parse().ok()?;
    let ln: usize = it.next()?.parse().ok()?;
    let name = it.next()?;
    if !named(name) || ln == 0 || col == 0 {
        return None;
    }
    Some((name.to_string(), ln, col, severity, message))
}

/// Every diagnostic rendered in `stderr` for the names `named` accepts:
/// (name, line, column, severity, message, first help line).
fn rendered(stderr: &str, named: impl Fn(&str) -> bool) -> Vec<(String, usize, usize, Diag)> {
    let mut out: Vec<(String, usize, usize, Diag)> = Vec::new();
    for line in stderr.lines() {
        if let Some((name, ln, col, severity, message)) = header(line, &named) {
            out.push((
                name,
                ln,
                col,
                Diag {
                    at: 0,
                    severity,
                    message,
                    help: None,
                    earlier: false,
                },
            ));
        } else if let Some(last) = out.last_mut() {
            if let Some(h) = line.trim_start().strip_prefix("= help: ")
                && last.3.help.is_none()
            {
                last.3.help = Some(h.to_string());
            }
            last.3.earlier |= line.contains("in an earlier input");
        }
    }
    out
}

/// The diagnostics of `check` (or `run`) for `text`, placed in it (the
/// command line reads the text without its byte-order mark).
fn placed(text: &str, found: &[(String, usize, usize, Diag)]) -> Vec<Diag> {
    let (body, skip) = match text.strip_prefix('\u{feff}') {
        Some(b) => (b, '\u{feff}'.len_utf8()),
        None => (text, 0),
    };
    let mut v: Vec<Diag> = found
        .iter()
        .map(|(_, l, c, d)| Diag {
            at: offset_of_char_col(body, *l, *c) + skip,
            ..d.clone()
        })
        .collect();
    v.sort();
    v
}

// ------------------------------------------------------------ chasles lsp

/// This file's step over the shared client ([`common::lsp`]).
impl Client {
    /// A change to `uri` at `version`, checked at once (a request on a
    /// changed document checks it first, without the debounce).
    fn change(&mut self, uri: &str, version: i64, change: Value) {
        self.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": uri, "version": version}, "contentChanges": [change]}),
        );
        self.request(
            "textDocument/documentSymbol",
            json!({"textDocument": {"uri": uri}}),
        );
    }
}

/// The published diagnostics placed in `text`.
fn from_lsp(text: &str, ds: &[Value]) -> Vec<Diag> {
    let mut v: Vec<Diag> = ds
        .iter()
        .map(|d| {
            let start = &d["range"]["start"];
            let severity = match d["severity"].as_i64() {
                Some(1) => format!("{} error", d["code"].as_str().unwrap()),
                Some(2) => "warning".into(),
                _ => "note".into(),
            };
            let help = d["relatedInformation"].as_array().and_then(|r| {
                r.iter()
                    .filter_map(|x| x["message"].as_str()?.strip_prefix("help: "))
                    .map(|h| h.lines().next().unwrap_or("").to_string())
                    .next()
            });
            Diag {
                at: offset_of_utf16(
                    text,
                    start["line"].as_u64().unwrap() as usize,
                    start["character"].as_u64().unwrap() as usize,
                ),
                severity,
                message: d["message"].as_str().unwrap().to_string(),
                help,
                earlier: false,
            }
        })
        .collect();
    v.sort();
    v
}

/// The one change that turns `old` into `new`: the range between their
/// common ends (in the protocol's positions) and the text between.
fn incremental(old: &str, new: &str) -> Value {
    let a = old
        .char_indices()
        .zip(new.chars())
        .find(|((_, x), y)| x != y)
        .map_or(old.len().min(new.len()), |((i, _), _)| i);
    let a = (0..=a)
        .rev()
        .find(|&i| new.is_char_boundary(i) && old.is_char_boundary(i))
        .unwrap();
    let mut b = 0;
    let (ob, nb) = (old.as_bytes(), new.as_bytes());
    while b < ob.len() - a && b < nb.len() - a && ob[ob.len() - 1 - b] == nb[nb.len() - 1 - b] {
        b += 1;
    }
    while !old.is_char_boundary(old.len() - b) || !new.is_char_boundary(new.len() - b) {
        b -= 1;
    }
    // (a position between the \r and the \n of a line break is no position
    // of the protocol's: a client never sends one)
    let crlf_at = |i: usize| i > 0 && ob.get(i - 1..=i) == Some(b"\r\n".as_slice());
    let a = if crlf_at(a) { a - 1 } else { a };
    if b > 0 && crlf_at(old.len() - b) {
        b -= 1;
    }
    let pos = |i: usize| {
        let before = &old[..i];
        let line = before.matches('\n').count();
        let col = &before[before.rfind('\n').map_or(0, |j| j + 1)..];
        json!({"line": line, "character": col.encode_utf16().count()})
    };
    json!({"range": {"start": pos(a), "end": pos(old.len() - b)}, "text": &new[a..new.len() - b]})
}

/// Writes each case to `dir` as `cN.chs`.
fn write_cases(dir: &Path, cases: &[(String, String)]) -> Vec<String> {
    cases
        .iter()
        .enumerate()
        .map(|(i, (_, t))| {
            let p = dir.join(format!("c{i}.chs"));
            std::fs::write(&p, t).unwrap();
            p.to_string_lossy().into_owned()
        })
        .collect()
}

/// `chasles ARGS FILES...` and its diagnostics by file.
fn diagnostics_of(
    args: &[&str],
    files: &[String],
) -> BTreeMap<String, Vec<(String, usize, usize, Diag)>> {
    let mut all: Vec<&str> = args.to_vec();
    all.extend(files.iter().map(String::as_str));
    let (_, _, err) = common::run(&all);
    assert!(!err.contains("panicked"), "{err}");
    let mut by: BTreeMap<String, Vec<_>> = files.iter().map(|f| (f.clone(), Vec::new())).collect();
    for d in rendered(&err, |n| by.contains_key(n)) {
        by.get_mut(&d.0).unwrap().push(d);
    }
    by
}

#[test]
fn the_language_server_publishes_what_check_prints() {
    let dir = common::scratch("lsp-check");
    let cases = cases(per_script(), true);
    let files = write_cases(&dir, &cases);
    let checked = diagnostics_of(&["check"], &files);
    let mut lsp = Client::start_with(None, &["lsp"]).0;
    let mut wrong = Vec::new();
    let (mut opened, mut edited) = (0, 0);
    for (i, ((name, text), file)) in cases.iter().zip(&files).enumerate() {
        let uri = format!("file:///sweep/c{i}.chs");
        lsp.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": uri, "languageId": "chasles", "version": 1, "text": text}}),
        );
        let got = from_lsp(text, &lsp.diagnostics_of(&uri, 1));
        let want = placed(text, &checked[file]);
        opened += 1;
        if got != want {
            wrong.push(format!(
                "{name} (opened):\n  lsp   {got:?}\n  check {want:?}"
            ));
        }
        // Edited into the next case's text in one incremental change, then
        // back in full.
        let j = (i + 1) % cases.len();
        let (next, next_file) = (&cases[j].1, &files[j]);
        for (version, change, text, file) in [
            (2, incremental(text, next), next, next_file),
            (3, json!({"text": text}), text, file),
        ] {
            lsp.change(&uri, version, change);
            let got = from_lsp(text, &lsp.diagnostics_of(&uri, version));
            let want = placed(text, &checked[file]);
            edited += 1;
            if got != want {
                wrong.push(format!(
                    "{name} (edited, version {version}):\n  lsp   {got:?}\n  check {want:?}"
                ));
            }
        }
        lsp.notify(
            "textDocument/didClose",
            json!({"textDocument": {"uri": uri}}),
        );
    }
    eprintln!("lsp vs check: {opened} documents opened, {edited} edits");
    assert!(
        wrong.is_empty(),
        "{} disagreements:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}

// ------------------------------------------------------- REPL and kernel

/// The inputs a user types for `text`: each line, and the lines after it
/// while a bracket is open (the REPL's continuation prompt), with the
/// 1-based line of the script where each starts.
fn inputs(text: &str) -> Vec<(usize, String)> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut out = Vec::new();
    let mut lines = text.lines().enumerate();
    while let Some((i, line)) = lines.next() {
        let mut input = line.to_string();
        while chasles::syntax::needs_more_input(&input) {
            let Some((_, more)) = lines.next() else { break };
            input.push('\n');
            input.push_str(more);
        }
        if !input.trim().is_empty() {
            out.push((i + 1, input));
        }
    }
    out
}

/// What a front end printed for one script: the values' text, and the
/// diagnostics by their line and column in the script.
#[derive(Debug, Default, PartialEq)]
struct Printed {
    out: String,
    diags: Vec<(usize, usize, String, String)>,
}

/// `chasles run --keep-going --no-write` of every case in one process, its
/// stdout split by a separator script between them.
fn run_all(dir: &Path, files: &[String]) -> Vec<Printed> {
    const SEP: &str = "sep_frontends_agree = 987654321";
    let sep = dir.join("sep.chs");
    std::fs::write(&sep, format!("{SEP}\n")).unwrap();
    let sep = sep.to_string_lossy().into_owned();
    let mut args = vec!["run", "--keep-going", "--no-write"];
    for f in files {
        args.push(f);
        args.push(&sep);
    }
    let (_, out, err) = common::run(&args);
    assert!(!err.contains("panicked"), "{err}");
    let outs: Vec<&str> = out.split(&format!("{SEP}\n")).collect();
    assert_eq!(outs.len(), files.len() + 1, "a separator per script");
    let mut by: BTreeMap<&str, Vec<_>> = BTreeMap::new();
    for (name, l, c, d) in rendered(&err, |n| files.iter().any(|f| f == n)) {
        let f = files.iter().find(|f| **f == name).unwrap();
        by.entry(f.as_str())
            .or_default()
            .push((l, c, d.severity, d.message));
    }
    files
        .iter()
        .zip(outs)
        .map(|(f, o)| Printed {
            out: o.to_string(),
            diags: by.remove(f.as_str()).unwrap_or_default(),
        })
        .collect()
}

/// A diagnostic of an input or a cell at the script's line `line`; one in
/// the body of a function typed in an earlier input is shown at the call,
/// where the earlier input is (by design, LANGUAGE.md §11; `chasles run`
/// shows the body, in the same file): placed nowhere, (0, 0).
fn at(line: usize, col: usize, d: Diag) -> (usize, usize, String, String) {
    if d.earlier {
        (0, 0, d.severity, d.message)
    } else {
        (line, col, d.severity, d.message)
    }
}

/// The REPL (its library: what `run_terminal` does with each input) fed
/// the inputs of `text`, writing nothing, as `--no-write` runs.
fn repl(text: &str) -> Printed {
    let mut s = Session::new(Settings::default());
    s.gate = Gate::deny();
    let mut p = Printed::default();
    for (line, input) in inputs(text) {
        let r = execute(&mut s, &input);
        p.out.push_str(&r.out);
        for (_, l, c, d) in rendered(&r.err, |n| n == "<input>") {
            p.diags.push(at(line + l - 1, c, d));
        }
    }
    p
}

/// A notebook session given the inputs of `text` as cells: what it
/// prints, and the `application/json` of each value, its line the
/// script's.
fn notebook(text: &str) -> (Printed, Vec<Value>) {
    let mut nb = Notebook::with(Options {
        gate: Gate::deny(),
        ..Options::default()
    });
    let mut p = Printed::default();
    let mut json = Vec::new();
    for (line, input) in inputs(text) {
        let cell = format!("In[{}]", nb.next_count());
        nb.execute(&input, true, &mut |o| match o {
            Output::Data(b) => {
                p.out.push_str(b["text/plain"].as_str().unwrap());
                p.out.push('\n');
                if let Some(j) = b.get("application/json") {
                    // (read back from its text, as run's lines are: the
                    // test's reading of a float may be off by a unit in the
                    // last place, the same on both sides)
                    let mut j: Value = serde_json::from_str(&j.to_string()).unwrap();
                    j["line"] = json!(j["line"].as_u64().unwrap() as usize + line - 1);
                    json.push(j);
                }
            }
            Output::Stream { text, .. } => {
                for (_, l, c, d) in rendered(&text, |n| n == cell) {
                    p.diags.push(at(line + l - 1, c, d));
                }
            }
            Output::Error(f) => {
                let (_, l, c, d) = rendered(&f.traceback.join("\n"), |n| n == cell)
                    .pop()
                    .expect("an error's traceback starts with its header");
                p.diags.push(at(line + l - 1, c, d));
            }
        })
        .ok();
    }
    (p, json)
}

/// `chasles run --json --keep-going --no-write` of `files`: each file's
/// objects that carry a value, without their `"file"`.
fn run_json(files: &[&String]) -> Vec<Vec<Value>> {
    let mut args = vec!["run", "--json", "--keep-going", "--no-write"];
    args.extend(files.iter().map(|f| f.as_str()));
    let (_, out, err) = common::run(&args);
    assert!(!err.contains("panicked"), "{err}");
    let mut by: BTreeMap<String, Vec<Value>> = BTreeMap::new();
    for line in out.lines() {
        let mut j: Value = serde_json::from_str(line).expect("a JSON line");
        if j.get("value").is_none() {
            continue;
        }
        let f = j.as_object_mut().unwrap().remove("file").unwrap();
        by.entry(f.as_str().unwrap().to_string())
            .or_default()
            .push(j);
    }
    files
        .iter()
        .map(|f| by.remove(f.as_str()).unwrap_or_default())
        .collect()
}

/// Why the REPL and a notebook cannot print what `run` prints for `text`,
/// by design: a line the REPL reads as a command (`help`, `quit`, §11), or
/// a bracket left open, after which the REPL reads the next lines into the
/// same input (its continuation prompt) where `run` reports the bracket
/// and goes on at the next line.
fn by_design(text: &str, ran: &Printed) -> Option<&'static str> {
    let s = Session::new(Settings::default());
    let ins = inputs(text);
    if ins
        .iter()
        .any(|(_, i)| chasles::repl::commands::bare_command(&s, i).is_some())
    {
        return Some("a bare REPL command");
    }
    // (an input the REPL read on past its first line, where `run` found a
    // syntax error: `x = 1 (` takes the next lines into one input, while
    // `run` reports the error and reads them as statements of their own)
    let read_on = ins.iter().any(|(line, i)| {
        let last = line + i.lines().count() - 1;
        last > *line
            && ran
                .diags
                .iter()
                .any(|d| d.2 == "syntax error" && (*line..=last).contains(&d.0))
    });
    let unclosed = ran.diags.iter().any(|d| d.3.starts_with("unclosed"))
        || read_on
        || ins
            .last()
            .is_some_and(|(_, i)| chasles::syntax::needs_more_input(i));
    unclosed.then_some("a bracket left open")
}

/// `draw-LINE.svg` as `draw-N.svg`: `run` names a printed picture by its
/// line in the file, the REPL by its line in the script `:save` writes.
fn unnumbered(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut rest = s;
    while let Some(i) = rest.find("draw-") {
        out.push_str(&rest[..i + 5]);
        rest = &rest[i + 5..];
        let digits = rest.len() - rest.trim_start_matches(|c: char| c.is_ascii_digit()).len();
        if digits > 0 {
            out.push('N');
        }
        rest = &rest[digits..];
    }
    out.push_str(rest);
    out
}

/// `got` (the REPL's or a notebook's prints) against `want` (`run`'s) for
/// `text`, after what differs by design: picture numbers; diagnostics shown
/// at the call of a function typed earlier (matched by message); and in a
/// notebook, printed pictures shown inline, never written (§13), so with
/// no warning that `--no-write` skipped them (a `save` still warns).
fn compare(text: &str, got: &Printed, want: &Printed, notebook: bool) -> Option<String> {
    let norm = |p: &Printed| Printed {
        out: unnumbered(&p.out),
        diags: p
            .diags
            .iter()
            .map(|(l, c, s, m)| (*l, *c, s.clone(), unnumbered(m)))
            .collect(),
    };
    let got = norm(got);
    let mut want = norm(want);
    let lines: Vec<&str> = text.lines().collect();
    if notebook {
        want.diags.retain(|(l, _, s, m)| {
            !(s == "warning"
                && m.contains("not written: writing files is turned off")
                && !lines
                    .get(l.wrapping_sub(1))
                    .is_some_and(|t| t.contains("save(")))
        });
    }
    for g in got.diags.iter().filter(|g| g.0 == 0) {
        if let Some(w) = want
            .diags
            .iter_mut()
            .find(|w| w.0 != 0 && w.2 == g.2 && w.3 == g.3)
        {
            (w.0, w.1) = (0, 0);
        }
    }
    (got != want).then(|| difference(&got, &want))
}

#[test]
fn the_repl_and_a_notebook_print_what_run_prints() {
    let dir = common::scratch("repl-run");
    // One variant of each script (the script itself is what
    // tests/examples.rs runs), more with CHASLES_SWEEP.
    let cases = cases(per_script().div_ceil(2), false);
    let files = write_cases(&dir, &cases);
    let ran = run_all(&dir, &files);
    let mut wrong = Vec::new();
    let (mut compared, mut skipped) = (0, BTreeMap::<&str, usize>::new());
    let mut in_notebook = Vec::new();
    for (((name, text), want), file) in cases.iter().zip(&ran).zip(&files) {
        if let Some(why) = by_design(text, want) {
            *skipped.entry(why).or_default() += 1;
            continue;
        }
        compared += 1;
        // (by default each case goes to one of the two, in turn, to stay
        // fast; CHASLES_SWEEP gives every case to both)
        let both = std::env::var_os("CHASLES_SWEEP").is_some();
        if (both || compared % 2 == 1)
            && let Some(d) = compare(text, &repl(text), want, false)
        {
            wrong.push(format!("{name}: REPL\n{d}"));
        }
        if both || compared % 2 == 0 {
            let (got, json) = notebook(text);
            if let Some(d) = compare(text, &got, want, true) {
                wrong.push(format!("{name}: notebook\n{d}"));
            }
            in_notebook.push((name, file, json));
        }
    }
    // The notebook's application/json is what `run --json` prints.
    let json_files: Vec<&String> = in_notebook.iter().map(|c| c.1).collect();
    for ((name, file, got), mut want) in in_notebook.iter().zip(run_json(&json_files)) {
        // (a printed picture is shown inline, with no file to skip, §13)
        let text = &cases[files.iter().position(|f| f == *file).unwrap()].1;
        let lines: Vec<&str> = text.lines().collect();
        for j in &mut want {
            let line = j["line"].as_u64().unwrap() as usize;
            let saves = lines.get(line - 1).is_some_and(|l| l.contains("save("));
            let obj = j.as_object_mut().unwrap();
            if let Some(Value::Array(ws)) = obj.get_mut("warnings") {
                ws.retain(|w| {
                    saves
                        || !w["message"]
                            .as_str()
                            .unwrap()
                            .contains("not written: writing files is turned off")
                });
                if ws.is_empty() {
                    obj.remove("warnings");
                }
            }
        }
        if *got != want {
            let i = got.iter().zip(&want).take_while(|(a, b)| a == b).count();
            wrong.push(format!(
                "{name}: notebook's application/json\n  notebook: {:?}\n  run --json: {:?}",
                got.get(i),
                want.get(i)
            ));
        }
    }
    eprintln!("REPL or notebook vs run: {compared} scripts; not compared, by design: {skipped:?}");
    assert!(
        wrong.is_empty(),
        "{} disagreements:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}

/// Where two front ends' prints first differ.
fn difference(got: &Printed, want: &Printed) -> String {
    let mut s = String::new();
    if got.out != want.out {
        let (g, w): (Vec<&str>, Vec<&str>) =
            (got.out.lines().collect(), want.out.lines().collect());
        let i = g.iter().zip(&w).take_while(|(a, b)| a == b).count();
        s.push_str(&format!(
            "  out line {}: {:?}\n       run: {:?}\n",
            i + 1,
            g.get(i),
            w.get(i)
        ));
    }
    if got.diags != want.diags {
        let only = |a: &[(usize, usize, String, String)], b: &[(usize, usize, String, String)]| {
            a.iter()
                .filter(|x| !b.contains(x))
                .cloned()
                .collect::<Vec<_>>()
        };
        s.push_str(&format!(
            "  diagnostics only here: {:?}\n  only in run: {:?}\n",
            only(&got.diags, &want.diags),
            only(&want.diags, &got.diags)
        ));
    }
    s
}

/// `chasles check` and `chasles run` name the same fix for an unknown
/// name: the help's `given` type was SE3 for every name in check mode and
/// scalar in run mode for a name without an underscore (`given ω̂ : SE3`
/// from `check` and the editor, `given ω̂ : scalar` from `run`), found by
/// tests/sweeps/frontends_sweep.py comparing run with check.
#[test]
fn check_and_run_name_the_same_fix_for_an_unknown_name() {
    let dir = common::scratch("unknown-names");
    let text = "ω̂ * 2\nv + 1\nR_cd * (1, 0, 0)\ntheta_1 + 1\nV_s\nS1\nx = 2 x_max\n";
    let file = dir.join("unknown.chs").to_string_lossy().into_owned();
    std::fs::write(&file, text).unwrap();
    let files = [file.clone()];
    let checked = diagnostics_of(&["check"], &files);
    let ran = diagnostics_of(&["run", "--keep-going"], &files);
    let (checked, ran) = (placed(text, &checked[&file]), placed(text, &ran[&file]));
    assert_eq!(checked.len(), 7, "{checked:?}");
    assert_eq!(checked, ran);
    let helps: Vec<&str> = checked.iter().map(|d| d.help.as_deref().unwrap()).collect();
    assert!(helps[0].ends_with("given ω̂ : vec3"), "{helps:?}");
    assert!(helps[1].ends_with("given v : scalar"), "{helps:?}");
    assert!(helps[2].ends_with("given R_cd : SO3"), "{helps:?}");
    assert!(helps[3].ends_with("given theta_1 : scalar"), "{helps:?}");
}

/// `explain` of what has no book algorithm by its shape alone (a name, a
/// number, a negation, a user function's call) is refused by `chasles
/// check` and the editor as `run` refuses it: check computed no steps and
/// said nothing (found by tests/sweeps/frontends_sweep.py comparing run
/// with check). One that depends on the numbers (`explain 1 + 2`) is
/// refused by `run` only.
#[test]
fn check_refuses_an_explain_with_no_algorithm_as_run_does() {
    let dir = common::scratch("explain-shape");
    let text = "x = 3\nexplain x\nexplain (2)\nexplain -Rotz(1)\nf(t) = t\nexplain f(1)\n\
                explain log(Rotz(1))\nm = mech < links 4; joints R R R R; planar >\nexplain m\n";
    let file = dir.join("explain.chs").to_string_lossy().into_owned();
    std::fs::write(&file, text).unwrap();
    let files = [file.clone()];
    let checked = placed(text, &diagnostics_of(&["check"], &files)[&file]);
    let ran = placed(
        text,
        &diagnostics_of(&["run", "--keep-going"], &files)[&file],
    );
    assert_eq!(checked.len(), 4, "{checked:?}");
    assert_eq!(checked, ran);
}
