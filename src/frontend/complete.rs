//! What the line editor offers while typing, computed here without a
//! terminal: Tab completions (builtins with their signatures, variables,
//! keywords, `:` commands and their arguments, file names after `:load`)
//! and the hint after the cursor (the signature of the function being
//! called, or a preview of the line's result evaluated on a copy of the
//! session).

use super::commands::{COMMANDS, is_command};
use super::help::TOPICS;
use crate::builtins::{self, Area};
use crate::eval::env::Mode;
use crate::session::Session;
use crate::syntax::needs_more_input;

/// One completion: what replaces the word, and what the list shows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Candidate {
    /// The text that replaces the word being completed.
    pub replacement: String,
    /// What the candidate list shows (a builtin's signature, a variable's type).
    pub display: String,
}

/// Keywords of the language worth completing.
const KEYWORDS: &[&str] = &[
    "given", "derive", "mech", "assert", "explain", "for", "in", "pi", "deg", "rad", "true",
    "false",
];

/// Longest line the preview evaluates.
const PREVIEW_MAX_CHARS: usize = 300;

/// Whether `c` may be part of a name (letters, digits, `_`, a prime).
fn is_name_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_' || c == '\''
}

/// The byte offset where the name ending at `pos` starts.
fn word_start(line: &str, pos: usize) -> usize {
    line[..pos]
        .char_indices()
        .rev()
        .take_while(|(_, c)| is_name_char(*c))
        .last()
        .map_or(pos, |(i, _)| i)
}

/// Completions for the text before `pos` in `line` (a byte offset on a
/// char boundary): the start of the word they replace, and the candidates.
pub fn complete(session: &Session, line: &str, pos: usize) -> (usize, Vec<Candidate>) {
    let pos = pos.min(line.len());
    if !line.is_char_boundary(pos) {
        return (pos, Vec::new());
    }
    let before = &line[..pos];
    if is_command(before) {
        return complete_command(before);
    }
    let start = word_start(line, pos);
    let word = &line[start..pos];
    if word.is_empty() || word.starts_with(|c: char| c.is_ascii_digit()) {
        return (pos, Vec::new());
    }
    let mut out = Vec::new();
    for b in builtins::table() {
        for name in b.names().filter(|n| n.starts_with(word)) {
            out.push(Candidate {
                replacement: format!("{name}("),
                display: if name == b.name {
                    b.signature.to_string()
                } else {
                    format!("{name} = {}", b.signature)
                },
            });
        }
    }
    for (name, b) in session.env.bindings() {
        if name.starts_with(word) {
            out.push(Candidate {
                replacement: String::from(name),
                display: format!("{name} : {}", b.ty),
            });
        }
    }
    for k in KEYWORDS.iter().filter(|k| k.starts_with(word)) {
        out.push(plain(k));
    }
    out.sort_by(|a, b| a.replacement.cmp(&b.replacement));
    out.dedup_by(|a, b| a.replacement == b.replacement);
    (start, out)
}

fn plain(s: &str) -> Candidate {
    Candidate {
        replacement: s.to_string(),
        display: s.to_string(),
    }
}

/// Completions inside a `:` command: its name, or its argument.
fn complete_command(before: &str) -> (usize, Vec<Candidate>) {
    let lead = before.len() - before.trim_start().len();
    let body = &before[lead + 1..];
    let Some((name, arg)) = body.split_once(char::is_whitespace) else {
        let cands = COMMANDS
            .iter()
            .filter(|c| c.name.starts_with(body))
            .map(|c| Candidate {
                replacement: format!(":{}", c.name),
                display: format!(":{} {}", c.name, c.args).trim_end().to_string(),
            })
            .collect();
        return (lead, cands);
    };
    let arg = arg.trim_start();
    let start = before.len() - arg.len();
    let words: Vec<String> = match name {
        "help" => {
            let mut w: Vec<String> = builtins::all_names()
                .into_iter()
                .map(String::from)
                .collect();
            w.extend(TOPICS.iter().map(|(t, _)| t.to_string()));
            w.extend(Area::ALL.iter().map(|a| super::help::area_key(*a).into()));
            w.extend(COMMANDS.iter().map(|c| c.name.to_string()));
            w.extend(super::keywords::words().map(String::from));
            w
        }
        "frames" => vec!["strict".into(), "warn".into(), "off".into()],
        "exact" => vec!["on".into(), "off".into()],
        "load" | "save" | "save!" => return complete_path(before, start),
        _ => Vec::new(),
    };
    let mut cands: Vec<Candidate> = words
        .iter()
        .filter(|w| w.starts_with(arg))
        .map(|w| plain(w))
        .collect();
    cands.sort_by(|a, b| a.replacement.cmp(&b.replacement));
    cands.dedup();
    (start, cands)
}

/// File names for `:load`: entries of the typed directory that start with
/// the typed file part; directories end in `/`.
fn complete_path(before: &str, start: usize) -> (usize, Vec<Candidate>) {
    let typed = &before[start..];
    let (dir, file, file_start) = match typed.rfind('/') {
        Some(i) => (&typed[..=i], &typed[i + 1..], start + i + 1),
        None => ("", typed, start),
    };
    let Ok(entries) = std::fs::read_dir(if dir.is_empty() { "." } else { dir }) else {
        return (file_start, Vec::new());
    };
    let mut cands: Vec<Candidate> = entries
        .filter_map(Result::ok)
        .filter_map(|e| {
            let name = e.file_name().into_string().ok()?;
            if !name.starts_with(file) || (name.starts_with('.') && !file.starts_with('.')) {
                return None;
            }
            let is_dir = e.file_type().is_ok_and(|t| t.is_dir());
            Some(plain(&if is_dir { format!("{name}/") } else { name }))
        })
        .collect();
    cands.sort_by(|a, b| a.replacement.cmp(&b.replacement));
    (file_start, cands)
}

/// The hint shown after the cursor at the end of the line: the signature
/// of the builtin whose call is open (`MatrixLog6(` → its signature), else
/// the preview of the result. None elsewhere.
pub fn hint(session: &Session, line: &str, pos: usize) -> Option<String> {
    if pos != line.len() || line.trim().is_empty() || is_command(line) {
        return None;
    }
    if let Some(sig) = open_call_signature(line) {
        return Some(format!("  {sig}"));
    }
    preview(session, line).map(|p| format!("  ⇒ {p}"))
}

/// The signature of the innermost builtin call still open at the end of
/// `line`, if any.
pub fn open_call_signature(line: &str) -> Option<&'static str> {
    let code = line.lines().last().unwrap_or("");
    let code = code.split('#').next().unwrap_or("");
    let mut opens: Vec<usize> = Vec::new();
    for (i, c) in code.char_indices() {
        match c {
            '(' | '[' => opens.push(i),
            ')' | ']' => {
                opens.pop();
            }
            _ => {}
        }
    }
    let &open = opens.iter().rev().find(|&&i| code[i..].starts_with('('))?;
    if opens.last() != Some(&open) {
        return None;
    }
    let name = &code[word_start(code, open)..open];
    builtins::lookup(name).map(|b| b.signature)
}

/// The result of evaluating `line` on a copy of the session, on one short
/// line — only when it evaluates without error or warning within the
/// preview's budget ([`crate::budget::Budget::preview`]: a few tens of
/// milliseconds and a small count of numbers). Past it the preview gives
/// up silently: a keystroke never waits for a long line. Pure: it only
/// evaluates ([`Session::evaluate`]), so no file is ever written
/// (LANGUAGE.md §11).
pub fn preview(session: &Session, line: &str) -> Option<String> {
    if line.len() > PREVIEW_MAX_CHARS || needs_more_input(line) {
        return None;
    }
    // `explain X` previews the value of X, never its steps (LANGUAGE.md §14).
    let line = match line.trim_start().strip_prefix("explain") {
        Some(rest) if rest.starts_with([' ', '\t']) => rest,
        _ => line,
    };
    let mut copy = session.clone();
    copy.budget = crate::budget::Budget::preview();
    let (out, err, errors) = copy.evaluate_to_strings("<preview>", line, Mode::Run, false);
    if errors > 0 || !err.is_empty() {
        return None;
    }
    let flat = out
        .lines()
        .map(|l| squeeze_after_commas(l.trim()))
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ");
    if flat.is_empty() || flat == line.trim() {
        return None;
    }
    Some(shorten(&flat, 72))
}

/// Column alignment dropped: one space after each comma.
fn squeeze_after_commas(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let mut after_comma = false;
    for c in line.chars() {
        if !(after_comma && c == ' ') {
            out.push(c);
        }
        if c == ',' {
            out.push(' ');
            after_comma = true;
        } else if c != ' ' {
            after_comma = false;
        }
    }
    out
}

/// `s` cut to `max` characters with an ellipsis.
fn shorten(s: &str, max: usize) -> String {
    if s.chars().count() <= max {
        s.to_string()
    } else {
        let cut: String = s.chars().take(max - 1).collect();
        format!("{cut}…")
    }
}
