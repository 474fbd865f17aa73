//! One REPL input, as the library sees it (no line editor here, so every
//! command is testable without a terminal): statements run in the session
//! — a failing statement binds nothing — and `:` commands (LANGUAGE.md §11)
//! inspect or change it.

use super::help;
use crate::check::ty::Ty;
use crate::diagnostics::suggest::did_you_mean;
use crate::eval::env::{Env, FrameMode};
use crate::eval::graph::FrameGraph;
use crate::eval::value::Value;
use crate::output::text;
use crate::session::Session;

/// One `:` command for help and completion.
#[derive(Debug, Clone, Copy)]
pub struct Command {
    /// The name without the colon.
    pub name: &'static str,
    /// The arguments, as a synopsis (`[N]`, `FILE`).
    pub args: &'static str,
    /// One line of meaning.
    pub doc: &'static str,
}

/// Every `:` command, in help order.
pub const COMMANDS: &[Command] = &[
    Command {
        name: "help",
        args: "[name]",
        doc: "topics and functions by area; one function's signature and example",
    },
    Command {
        name: "vars",
        args: "",
        doc: "the bindings with their types and frames",
    },
    Command {
        name: "frames",
        args: "[strict|warn|off]",
        doc: "the graph of known frames, or set frame checking",
    },
    Command {
        name: "load",
        args: "FILE",
        doc: "run a script into this session",
    },
    Command {
        name: "save",
        args: "FILE",
        doc: "write the statements that ran as a script that reruns them (:save! FILE overwrites)",
    },
    Command {
        name: "history",
        args: "",
        doc: "the statements of this session that ran without error",
    },
    Command {
        name: "reset",
        args: "",
        doc: "forget every binding",
    },
    Command {
        name: "digits",
        args: "[N]",
        doc: "decimals in text output (0 to 17; default 4)",
    },
    Command {
        name: "exact",
        args: "[on|off]",
        doc: "toggle exact forms: exact numbers as 1/√2, √3/2, π/6, and a float that rounds one after ≈",
    },
    Command {
        name: "short",
        args: "[on|off]",
        doc: "symbolic values in the book's shorthand: c₁, s₁₂ (§7)",
    },
    Command {
        name: "latex",
        args: "[on|off]",
        doc: "symbolic values as LaTeX: bmatrix, \\theta_1 (§7)",
    },
    Command {
        name: "open",
        args: "",
        doc: "open the last picture written with the system viewer (§12)",
    },
    Command {
        name: "quit",
        args: "",
        doc: "leave the REPL (also Ctrl-D, or quit / exit without the colon)",
    },
];

/// What one input produced: text for stdout and stderr, and whether the
/// REPL should end.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Reply {
    /// For stdout (each line ends in a newline).
    pub out: String,
    /// For stderr: errors and warnings.
    pub err: String,
    /// True after `:quit`.
    pub quit: bool,
}

impl Reply {
    pub(super) fn out(text: impl Into<String>) -> Reply {
        Reply {
            out: line(text.into()),
            ..Reply::default()
        }
    }
    pub(super) fn err(text: impl Into<String>) -> Reply {
        Reply {
            err: line(text.into()),
            ..Reply::default()
        }
    }
}

fn line(mut s: String) -> String {
    if !s.is_empty() && !s.ends_with('\n') {
        s.push('\n');
    }
    s
}

/// Whether `input` is a `:` command rather than statements.
pub fn is_command(input: &str) -> bool {
    input.trim_start().starts_with(':')
}

/// A piece of a notebook cell or a pasted REPL input: statements (with the
/// input's line number of their first line) or one `:` command.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Piece<'a> {
    /// Statements, and the line of the input their first line is.
    Statements(usize, String),
    /// One `:` command line, trimmed.
    Command(&'a str),
}

/// Splits a cell or an input into runs of statements and `:` command lines
/// (a line starting with `:` while no bracket is open).
pub fn pieces(code: &str) -> Vec<Piece<'_>> {
    let mut out = Vec::new();
    let mut chunk = String::new();
    let mut first = 1;
    for (i, line) in code.lines().enumerate() {
        if is_command(line) && !crate::syntax::needs_more_input(&chunk) {
            if !chunk.trim().is_empty() {
                out.push(Piece::Statements(first, std::mem::take(&mut chunk)));
            }
            chunk.clear();
            out.push(Piece::Command(line.trim()));
            first = i + 2;
        } else {
            if chunk.is_empty() {
                first = i + 1;
            }
            chunk.push_str(line);
            chunk.push('\n');
        }
    }
    if !chunk.trim().is_empty() {
        out.push(Piece::Statements(first, chunk));
    }
    out
}

/// Runs one REPL input: a `:` command, or statements (stopping at the
/// first error; what failed binds nothing, so earlier bindings survive).
/// An interrupt (Ctrl-C) ends it with `interrupted`, the session as it
/// was before the statement it stopped; the interrupt is then cleared.
pub fn execute(session: &mut Session, input: &str) -> Reply {
    let mut reply = execute_input(session, input);
    if session.interrupted {
        reply.err.push_str("interrupted\n");
        session.interrupted = false;
    }
    session.budget.interrupt_handle().clear();
    reply
}

fn execute_input(session: &mut Session, input: &str) -> Reply {
    // Lines pasted at once, `:` commands among statements: each piece in
    // turn, as a notebook cell runs them (LANGUAGE.md §13).
    let parts = pieces(input);
    if parts.len() > 1 {
        return execute_pieces(session, parts);
    }
    if is_command(input) {
        return command(session, input.trim());
    }
    if let Some(cmd) = bare_command(session, input) {
        return command(session, &cmd);
    }
    let (out, err, _) = super::save::run_recording(session, "<input>", input);
    Reply {
        out,
        err,
        quit: false,
    }
}

/// The pieces of one input in order, until an error, an interrupt or
/// `:quit`; statements numbered by their line in the input.
fn execute_pieces(session: &mut Session, parts: Vec<Piece<'_>>) -> Reply {
    let mut reply = Reply::default();
    for piece in parts {
        let (r, failed) = match piece {
            Piece::Command(line) => (command(session, line), false),
            Piece::Statements(first, chunk) => match bare_command(session, &chunk) {
                Some(cmd) => (command(session, &cmd), false),
                None => {
                    let src = format!("{}{chunk}", "\n".repeat(first.saturating_sub(1)));
                    let (out, err, errors) = super::save::run_recording(session, "<input>", &src);
                    let quit = false;
                    (Reply { out, err, quit }, errors > 0)
                }
            },
        };
        reply.out.push_str(&r.out);
        reply.err.push_str(&r.err);
        reply.quit |= r.quit;
        if failed || reply.quit || session.interrupted {
            break;
        }
    }
    reply
}

/// `help`, `help NAME`, `exit`, `quit` (and Python's `help(NAME)`,
/// `exit()`, `quit()`)
/// typed without the colon, as the command they mean — unless the word is
/// bound as a variable.
pub fn bare_command(session: &Session, input: &str) -> Option<String> {
    let t = input.trim();
    // Python's help(name).
    if let Some(inner) = t.strip_prefix("help(").and_then(|s| s.strip_suffix(')'))
        && session.env.get("help").is_none()
        && !builtins_or_fn(session, "help")
    {
        return Some(format!(":help {}", inner.trim()));
    }
    let (word, rest) = t.split_once(char::is_whitespace).unwrap_or((t, ""));
    let word = word.trim_end_matches("()");
    if session.env.get(word).is_some() {
        return None;
    }
    match word {
        "help" if rest.trim().chars().all(|c| !"=(),;[]".contains(c)) => {
            Some(format!(":help {}", rest.trim()))
        }
        "exit" | "quit" if rest.is_empty() => Some(":quit".into()),
        _ => None,
    }
}

/// Whether `name` is a user function (or a builtin) of the session.
fn builtins_or_fn(session: &Session, name: &str) -> bool {
    session.env.func(name).is_some() || crate::builtins::lookup(name).is_some()
}

/// Runs one `:` command (`input` starts with `:`).
pub fn command(session: &mut Session, input: &str) -> Reply {
    let body = input.trim().trim_start_matches(':');
    let (name, arg) = match body.split_once(char::is_whitespace) {
        Some((n, a)) => (n, a.trim()),
        None => (body, ""),
    };
    match name {
        "help" | "h" | "?" => match help::help(arg, &session.settings) {
            Ok(text) => Reply::out(text),
            Err(msg) => Reply::err(msg),
        },
        "vars" => Reply::out(vars(&session.env, session.settings.text_style())),
        "frames" => frames(session, arg),
        "load" => load(session, arg),
        "reset" => {
            session.env = Env::default();
            session.accepted.clear();
            Reply::out("bindings cleared")
        }
        "save" | "save!" => match super::save::save(session, arg, name == "save!") {
            Ok(msg) => Reply::out(msg),
            Err(msg) => Reply::err(msg),
        },
        "history" => Reply::out(super::save::history(session)),
        "digits" => digits(session, arg),
        "exact" => exact(session, arg),
        "short" => sym_mode(session, arg, crate::sym::print::Mode::Short),
        "latex" => sym_mode(session, arg, crate::sym::print::Mode::Latex),
        "open" => super::open::open(session),
        "quit" | "q" | "exit" => Reply {
            quit: true,
            ..Reply::default()
        },
        "" => Reply::err("a command name must follow ':' (:help lists them)"),
        _ => {
            let mut msg = format!("unknown command ':{name}'");
            if let Some(s) = suggest_command(name) {
                msg.push_str(&format!("; did you mean ':{s}'?"));
            }
            msg.push_str(" (:help lists the commands)");
            Reply::err(msg)
        }
    }
}

/// The command closest to a mistyped `name`: by edit distance, then two
/// swapped letters (`hepl`), then a unique prefix (`:dig`).
pub fn suggest_command(name: &str) -> Option<&'static str> {
    let names: Vec<&str> = COMMANDS.iter().map(|c| c.name).collect();
    if let Some(s) = did_you_mean(name, &names) {
        return Some(s);
    }
    let sorted = |s: &str| {
        let mut v: Vec<char> = s.to_lowercase().chars().collect();
        v.sort_unstable();
        v
    };
    if let Some(s) = names.iter().find(|n| sorted(n) == sorted(name)) {
        return Some(s);
    }
    let mut prefixed = names.iter().filter(|n| n.starts_with(name));
    match (prefixed.next(), prefixed.next()) {
        (Some(s), None) if !name.is_empty() => Some(s),
        _ => None,
    }
}

/// The type and frames of a binding as `:vars` shows them.
fn type_of(ty: &Ty, val: Option<&Value>) -> String {
    let kind = match val {
        Some(Value::Sym(_)) | None => ty.kind,
        Some(v) => v.kind(),
    };
    Ty::new(kind, ty.frames).to_string()
}

/// `:vars`: each binding with its type and frames, and its value when
/// that fits on a short line.
pub fn vars(env: &Env, style: text::Style) -> String {
    let bindings = env.bindings();
    if bindings.is_empty() && env.fns.is_empty() {
        return "no bindings yet (bind one with `name = expr`)".into();
    }
    let width = bindings
        .iter()
        .map(|(n, _)| n.chars().count())
        .max()
        .unwrap_or(0);
    let mut out = String::new();
    for (name, b) in bindings {
        let pad = " ".repeat(width - name.chars().count());
        let mut row = format!("{name}{pad} : {}", type_of(&b.ty, b.val.as_ref()));
        if b.symbolic {
            row.push_str("  (given)");
        } else if let Some(v) = &b.val {
            let shown = text::inline(v, style);
            if shown.chars().count() <= 48 {
                row.push_str(&format!(" = {shown}"));
            }
        }
        out.push_str(row.trim_end());
        out.push('\n');
    }
    let mut fns: Vec<_> = env
        .fns
        .values()
        .filter(|f| env.get(&f.name).is_none())
        .collect();
    fns.sort_by(|a, b| a.name.cmp(&b.name));
    for f in fns {
        out.push_str(&format!("{}({}) : function\n", f.name, f.params.join(", ")));
    }
    out.trim_end().to_string()
}

/// `:frames` with no argument shows the graph; with `strict|warn|off` it
/// sets frame checking.
fn frames(session: &mut Session, arg: &str) -> Reply {
    if arg.is_empty() {
        return Reply::out(frame_graph(&session.env, session.settings.frames));
    }
    match FrameMode::parse(arg) {
        Some(mode) => {
            session.settings.frames = mode;
            Reply::out(format!("frame checking: {}", mode.as_str()))
        }
        None => Reply::err(format!(
            "':frames {arg}': expected strict, warn or off (or nothing, to show the frame graph)"
        )),
    }
}

/// `:frames`: which frames the known rotations and transforms connect,
/// one connected component at a time, plus the vectors expressed in each
/// frame (the session's [`FrameGraph`]).
pub fn frame_graph(env: &Env, mode: FrameMode) -> String {
    let graph = FrameGraph::of(env);
    let comps = graph.components();
    if comps.is_empty() {
        return format!(
            "no framed values yet (name them like T_ab = …, p_s = …)\nframe checking: {}",
            mode.as_str()
        );
    }
    let mut out = String::new();
    for comp in &comps {
        let braced: Vec<String> = comp.frames.iter().map(|f| format!("{{{f}}}")).collect();
        out.push_str(&format!("frames {}\n", braced.join(", ")));
        for ((a, c), names) in &comp.edges {
            out.push_str(&format!("  {{{a}}} — {{{c}}}  ({})\n", names.join(", ")));
        }
        for (f, names) in &comp.quantities {
            out.push_str(&format!("  in {{{f}}}: {}\n", names.join(", ")));
        }
    }
    out.push_str(&format!("frame checking: {}", mode.as_str()));
    out
}

/// `:load FILE`: runs a script into the session, stopping at its first
/// error (what ran before the error stays bound).
fn load(session: &mut Session, arg: &str) -> Reply {
    let path = arg.trim().trim_matches(|c| c == '"' || c == '\'');
    if path.is_empty() {
        return Reply::err(":load needs a file name, e.g. :load examples/ch3_ex3_2_camera.chs");
    }
    let path = match (path.strip_prefix("~/"), dirs::home_dir()) {
        (Some(rest), Some(home)) => home.join(rest).to_string_lossy().into_owned(),
        _ => path.to_string(),
    };
    let src = match crate::session::read_source(&path) {
        Ok(s) => s,
        Err(msg) => return Reply::err(format!(":load: {msg}")),
    };
    let (out, mut err, errors) = super::save::run_recording(session, &path, &src);
    let mut reply = Reply {
        out,
        err: String::new(),
        quit: false,
    };
    if errors == 0 {
        reply.out.push_str(&format!("loaded {path}\n"));
    } else {
        err.push_str(&format!(
            "{path}: stopped at the error; the statements before it stay bound\n"
        ));
    }
    reply.err = err;
    reply
}

/// `:digits [N]`.
fn digits(session: &mut Session, arg: &str) -> Reply {
    if arg.is_empty() {
        return Reply::out(format!("digits: {}", session.settings.digits));
    }
    match arg.parse::<usize>() {
        Ok(n) if n <= 17 => {
            session.settings.digits = n;
            Reply::out(format!("digits: {n}"))
        }
        _ => Reply::err(format!(
            "':digits {arg}': expected a whole number from 0 to 17"
        )),
    }
}

/// `:short [on|off]`, `:latex [on|off]`: toggles (or sets) how symbolic
/// values print.
fn sym_mode(session: &mut Session, arg: &str, mode: crate::sym::print::Mode) -> Reply {
    use crate::sym::print::Mode;
    let name = if mode == Mode::Short {
        "short"
    } else {
        "latex"
    };
    let on = match arg {
        "" => session.settings.sym != mode,
        "on" => true,
        "off" => false,
        _ => return Reply::err(format!("':{name} {arg}': expected on, off or nothing")),
    };
    session.settings.sym = if on { mode } else { Mode::Text };
    Reply::out(format!("{name}: {}", if on { "on" } else { "off" }))
}

/// `:exact [on|off]`: toggles (or sets) the printing of exact forms.
fn exact(session: &mut Session, arg: &str) -> Reply {
    let on = match arg {
        "" => !session.settings.exact,
        "on" => true,
        "off" => false,
        _ => return Reply::err(format!("':exact {arg}': expected on, off or nothing")),
    };
    session.settings.exact = on;
    Reply::out(if on {
        "exact: on (exact numbers print as such: 1/√2, √3/2, π/6; a float that rounds one prints it after ≈)"
    } else {
        "exact: off"
    })
}
