//! What every front end shares (LANGUAGE.md §§11, 13, 15): the REPL, the
//! Jupyter kernel and the language server each drive a session through
//! this layer and import no other front end.
//!
//! [`commands`] runs an input (statements or a `:` command), [`save`]
//! runs statements recording what each wrote and keeps the history that
//! `:save` writes, [`help`] answers `:help` from the builtin table,
//! [`keywords`] and [`reference`](mod@reference) hold the words of the language and the
//! generated builtin reference, [`complete`] computes completions, hints
//! and the live preview. Nothing here touches a terminal or a socket.

pub mod commands;
pub mod complete;
pub mod help;
pub mod keywords;
mod open;
pub mod reference;
pub mod save;

/// The line shown when an interactive session starts (the REPL's first
/// line, the kernel's banner).
pub fn banner() -> String {
    format!(
        "chasles {} — rigid-body motion as in Modern Robotics, ch. 2–3\n\
         :help for help, Tab completes, Ctrl-D quits",
        env!("CARGO_PKG_VERSION")
    )
}
