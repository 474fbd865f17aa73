//! The interactive session (LANGUAGE.md §11).

use crate::eval::env::Mode;
use crate::session::{Session, Settings};

/// Runs the REPL on a terminal; returns the exit code.
pub fn run_terminal(settings: &Settings) -> i32 {
    let mut session = Session::new(*settings);
    let mut rl = match rustyline::DefaultEditor::new() {
        Ok(rl) => rl,
        Err(e) => {
            eprintln!("chasles: cannot start the line editor: {e}");
            return 2;
        }
    };
    let mut pending = String::new();
    loop {
        let prompt = if pending.is_empty() { ">>> " } else { "... " };
        match rl.readline(prompt) {
            Ok(line) => {
                pending.push_str(&line);
                pending.push('\n');
                if crate::syntax::needs_more_input(&pending) {
                    continue;
                }
                let src = std::mem::take(&mut pending);
                let _ = rl.add_history_entry(src.trim_end());
                let (out, err, _) = session.run_to_strings("<input>", &src, Mode::Run, true);
                print!("{out}");
                eprint!("{err}");
            }
            Err(rustyline::error::ReadlineError::Interrupted) => pending.clear(),
            Err(_) => return 0,
        }
    }
}
