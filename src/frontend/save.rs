//! The session as a script (LANGUAGE.md §11): the REPL records each
//! statement that ran without error; `:history` lists them and `:save FILE`
//! writes them as a script that reruns to the same results. The file is
//! written by the effects gate (`crate::effects`), atomically, and an
//! existing file is kept unless the command is `:save! FILE`.

use std::path::{Path, PathBuf};

use crate::effects::{Effect, WriteError};
use crate::eval::env::{FrameMode, Mode};
use crate::session::{Report, Session};

/// Runs `src` in the session like [`Session::run_to_strings`], and records
/// the text of every statement that succeeded in `session.accepted`.
pub fn run_recording(session: &mut Session, file: &str, src: &str) -> (String, String, usize) {
    let (mut out, mut err) = (String::new(), String::new());
    let settings = session.settings;
    let n = run_recording_each(session, src, |r| {
        r.append_to(&settings, file, src, &mut out, &mut err);
    });
    (out, err, n)
}

/// Runs `src` in the session as the REPL does (stopping at the first
/// error), calling `each` with every statement's report, and records the
/// text of every statement that succeeded in `session.accepted`. The
/// terminal prints the reports as text; the notebook kernel as rich output.
pub fn run_recording_each(
    session: &mut Session,
    src: &str,
    mut each: impl FnMut(&Report),
) -> usize {
    let mut accepted = Vec::new();
    // (a picture printed in this input is named by its line in `:save`'s
    // script, the header and the accepted statements before it)
    session.lines_before = script_lines(session);
    let n = session.run(src, Mode::Run, false, |r| {
        each(r);
        if let Ok(outcome) = &r.result
            && let Some(text) = src.get(outcome.span.start..outcome.span.end)
            && !text.trim().is_empty()
        {
            // (a silent statement stays silent when the script reruns)
            let silent = crate::syntax::silenced(src, outcome.span.end);
            accepted.push(format!("{}{}", text.trim(), if silent { ";" } else { "" }));
        }
    });
    session.accepted.extend(accepted);
    n
}

/// The lines of the script `:save` would write now.
fn script_lines(session: &Session) -> usize {
    1 + session
        .accepted
        .iter()
        .map(|s| s.matches('\n').count() + 1)
        .sum::<usize>()
}

/// `:history`: the accepted statements, numbered.
pub fn history(session: &Session) -> String {
    if session.accepted.is_empty() {
        return "no statements yet (:history lists the ones that ran without error)".into();
    }
    let width = session.accepted.len().to_string().len();
    session
        .accepted
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let s = s.replace('\n', &format!("\n{}", " ".repeat(width + 2)));
            format!("{:>width$}  {s}", i + 1)
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The script `:save` writes: a header saying how to rerun it (with the
/// session's frame checking, digits and exact printing), then the accepted
/// statements one per line.
pub fn script(session: &Session) -> String {
    let s = &session.settings;
    let mut flags = String::new();
    if s.frames != FrameMode::Strict {
        flags.push_str(&format!(" --frames {}", s.frames.as_str()));
    }
    if s.digits != crate::session::Settings::default().digits {
        flags.push_str(&format!(" --digits {}", s.digits));
    }
    if s.exact {
        flags.push_str(" --exact");
    }
    let mut out = format!("# saved from the chasles REPL; rerun with: chasles run{flags} FILE\n");
    for s in &session.accepted {
        out.push_str(s);
        out.push('\n');
    }
    out
}

/// `:save FILE` (`overwrite` false) or `:save! FILE`: Ok is the message
/// for stdout, Err the one for stderr. The file is written by the
/// session's effects gate (atomically; skipped under `--no-write`,
/// confined by `--write-dir`).
pub fn save(session: &mut Session, arg: &str, overwrite: bool) -> Result<String, String> {
    let name = arg.trim().trim_matches(|c| c == '"' || c == '\'');
    if name.is_empty() {
        return Err(":save needs a file name, e.g. :save session.chs".into());
    }
    let path = match (name.strip_prefix("~/"), dirs::home_dir()) {
        (Some(rest), Some(home)) => home.join(rest),
        _ => PathBuf::from(name),
    };
    let shown = crate::effects::show(Path::new(name));
    let effect = Effect::Write {
        path,
        bytes: script(session).into_bytes(),
        overwrite,
    };
    match session.gate.perform(&effect) {
        Ok(crate::effects::Done::Skipped(m)) => Err(format!(":save: {m}")),
        Ok(_) => Ok(format!(
            "saved {} statement{} to {shown}",
            session.accepted.len(),
            if session.accepted.len() == 1 { "" } else { "s" }
        )),
        Err(WriteError::Exists(_)) => Err(format!(
            ":save: '{shown}' exists; :save! {shown} overwrites it"
        )),
        Err(WriteError::Refused(m)) => Err(format!(":save: {m}")),
    }
}
