//! The interactive session (LANGUAGE.md §11).
//!
//! Everything but the line editor lives below the front ends, in
//! [`crate::frontend`], shared with the kernel and the language server and
//! tested without a terminal: `commands` runs an input (statements or a
//! `:` command), `help` answers `:help` from the builtin table, `complete`
//! computes Tab completions and hints. `editor` adapts those to rustyline;
//! [`run_terminal`] is the loop, with persistent history.

mod editor;

// The shared modules under their former paths (`chasles::repl::commands`, …).
pub use crate::frontend::{banner, commands, complete, help, keywords, reference, save};

use std::io::{IsTerminal, Write};
use std::path::PathBuf;

use rustyline::error::ReadlineError;
use rustyline::history::DefaultHistory;
use rustyline::{ColorMode, CompletionType, Config, Editor};

use crate::session::{Session, Settings};
use editor::ReplHelper;

/// The prompt.
pub const PROMPT: &str = ">>> ";

/// The prompt of a continuation line, while a bracket is open.
pub const CONTINUE: &str = "... ";

/// Where history is kept: `$CHASLES_HISTORY` if set and not empty, else
/// `chasles/history.txt` in the user's data directory. It is read and
/// written only where the effects gate allows (`crate::effects::Gate::history`):
/// never under `--no-write`, only inside DIR under `--write-dir`.
pub fn history_path() -> Option<PathBuf> {
    match std::env::var_os("CHASLES_HISTORY") {
        Some(p) if !p.is_empty() => Some(PathBuf::from(p)),
        _ => dirs::data_dir().map(|d| d.join("chasles").join("history.txt")),
    }
}

/// Colours only on a terminal, and never with `NO_COLOR` set.
pub fn colour_enabled() -> bool {
    std::io::stdout().is_terminal() && std::env::var_os("NO_COLOR").is_none()
}

/// Runs the REPL on a terminal, writing files through `gate` (the live
/// preview writes nothing: it only evaluates); returns the exit code (0 on
/// Ctrl-D or `:quit`).
pub fn run_terminal(
    settings: &Settings,
    gate: crate::effects::Gate,
    budget: crate::budget::Budget,
) -> i32 {
    let mut session = Session::new(Settings {
        json: false,
        ..*settings
    });
    let history = history_path().and_then(|p| gate.history(&p));
    session.gate = gate;
    session.budget = budget;
    let colour = colour_enabled();
    let config = Config::builder()
        .completion_type(CompletionType::List)
        .completion_show_all_if_ambiguous(true)
        .auto_add_history(false)
        .color_mode(if colour {
            ColorMode::Enabled
        } else {
            ColorMode::Disabled
        })
        .build();
    let mut rl: Editor<ReplHelper, DefaultHistory> = match Editor::with_config(config) {
        Ok(rl) => rl,
        Err(e) => {
            eprintln!("chasles: cannot start the line editor: {e}");
            return 2;
        }
    };
    rl.set_helper(Some(ReplHelper {
        session: session.clone(),
        colour,
        continuing: false,
    }));
    if let Some(path) = &history {
        let _ = rl.load_history(path);
    }
    println!("{}", banner());
    loop {
        match read_input(&mut rl) {
            Ok(None) => continue,
            Ok(Some(input)) => {
                if input.trim().is_empty() {
                    continue;
                }
                let _ = rl.add_history_entry(input.trim_end());
                save_history(&mut rl, history.as_ref());
                let reply = commands::execute(&mut session, &input);
                let mut out = std::io::stdout().lock();
                let _ = out.write_all(reply.out.as_bytes());
                let _ = out.flush();
                drop(out);
                let _ = std::io::stderr().write_all(reply.err.as_bytes());
                if reply.quit {
                    break;
                }
                if let Some(h) = rl.helper_mut() {
                    h.session = session.clone();
                }
            }
            // Ctrl-C: the line is dropped; start a fresh one.
            Err(ReadlineError::Interrupted) => continue,
            // Ctrl-D on an empty line.
            Err(ReadlineError::Eof) => break,
            Err(e) => {
                eprintln!("chasles: cannot read the terminal: {e}");
                break;
            }
        }
    }
    save_history(&mut rl, history.as_ref());
    0
}

/// One input: a line, and more lines under the continuation prompt while
/// a bracket is open (Enter inside `[` starts a new row). `Ok(None)` when
/// Ctrl-C cancelled a continued input; Ctrl-D inside a bracket runs what
/// was typed (its error names the open bracket).
fn read_input(
    rl: &mut Editor<ReplHelper, DefaultHistory>,
) -> Result<Option<String>, ReadlineError> {
    let mut input = rl.readline(PROMPT)?;
    let continuing = |rl: &mut Editor<ReplHelper, DefaultHistory>, on: bool| {
        if let Some(h) = rl.helper_mut() {
            h.continuing = on;
        }
    };
    while !commands::is_command(&input) && crate::syntax::needs_more_input(&input) {
        continuing(rl, true);
        let line = rl.readline(CONTINUE);
        continuing(rl, false);
        match line {
            Ok(more) => {
                input.push('\n');
                input.push_str(&more);
            }
            Err(ReadlineError::Interrupted) => return Ok(None),
            Err(ReadlineError::Eof) => break,
            Err(e) => return Err(e),
        }
    }
    Ok(Some(input))
}

/// Appends the new history entries to the history file (creating its
/// directory); a failure is silent — history is a convenience.
fn save_history(rl: &mut Editor<ReplHelper, DefaultHistory>, path: Option<&PathBuf>) {
    let Some(path) = path else { return };
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        let _ = std::fs::create_dir_all(dir);
    }
    let _ = rl.append_history(path);
}
