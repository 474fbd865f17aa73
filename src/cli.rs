//! The command line (LANGUAGE.md §1): `chasles`, `chasles run FILE...`,
//! `chasles check FILE...`, `chasles -e 'STATEMENTS'`, with `--json`,
//! `--frames`, `--digits`, `--exact`, `--keep-going`, `--timeout`,
//! `--max-memory`. Exit codes: 0 success, 1 a script error (a budget
//! exceeded too), 2 bad usage or an unreadable file, 130 interrupted
//! (Ctrl-C) after what was printed.

use std::ffi::OsString;
use std::io::{IsTerminal, Write};

use clap::{CommandFactory, Parser, Subcommand};

mod batch;
mod writer;

use crate::effects::Gate;
use crate::eval::env::{FrameMode, Mode};
use crate::session::Settings;

pub use crate::session::{MAX_SOURCE_BYTES, read_source};

#[derive(Parser, Debug)]
#[command(
    name = "chasles",
    version,
    about = "A calculator for rigid-body motion (Modern Robotics, chapters 2–3)",
    long_about = "A calculator for rigid-body motion (Modern Robotics, chapters 2–3).\n\
                  With no command: the REPL (or, with stdin not a terminal, runs stdin)."
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// Evaluate one string of statements.
    #[arg(
        short = 'e',
        long = "eval",
        value_name = "STATEMENTS",
        allow_hyphen_values = true
    )]
    eval: Option<std::ffi::OsString>,
    #[command(flatten)]
    opts: Opts,
}

#[derive(clap::Args, Debug, Clone)]
struct Opts {
    /// One JSON object per statement instead of text.
    #[arg(long, global = true)]
    json: bool,
    /// Frame mismatches: an error, a warning, or ignored.
    #[arg(long, global = true, value_name = "strict|warn|off", default_value = "strict", value_parser = parse_frames)]
    frames: FrameMode,
    /// Decimals in text output (trailing zeros trimmed).
    #[arg(long, global = true, value_name = "N", default_value_t = 4, value_parser = clap::value_parser!(u16).range(0..=17))]
    digits: u16,
    /// Keep running after an error.
    #[arg(long, global = true)]
    keep_going: bool,
    /// Print only errors, warnings and failed asserts (batch runs,
    /// grading): no value is printed, as if every statement ended by `;`.
    #[arg(long, global = true)]
    quiet: bool,
    /// Print exact numbers as such: 1/√2, √3/2, π/6 (floats stay decimals;
    /// text output; the REPL's :exact).
    #[arg(long, global = true)]
    exact: bool,
    /// Symbolic values in the book's shorthand (c₁, s₁₂).
    #[arg(long, global = true, conflicts_with = "latex")]
    short: bool,
    /// Symbolic values as LaTeX (bmatrix, \theta_1).
    #[arg(long, global = true)]
    latex: bool,
    /// Where pictures printed but not saved are written (default: the
    /// current folder, or the --write-dir); created if missing.
    #[arg(long, global = true, value_name = "DIR", conflicts_with = "no_write")]
    draw_dir: Option<std::path::PathBuf>,
    /// Write nothing: every write (save, printed pictures, :save) is
    /// skipped with a warning naming the file, and the script goes on.
    #[arg(long, global = true, conflicts_with = "write_dir")]
    no_write: bool,
    /// Confine every write to DIR (created if missing): names are taken
    /// inside it; absolute paths, `..` and links leading out are refused.
    #[arg(long, global = true, value_name = "DIR")]
    write_dir: Option<std::path::PathBuf>,
    /// Stop the run after SECONDS (a domain error, exit 1): for running
    /// scripts one did not write.
    #[arg(long, global = true, value_name = "SECONDS", value_parser = crate::budget::parse_seconds)]
    timeout: Option<std::time::Duration>,
    /// The most the run's numbers may take (512M, 2G; default 4G); without
    /// it, one statement may hold at most 400 MB (50,000,000 numbers).
    #[arg(long, global = true, value_name = "SIZE", value_parser = crate::budget::parse_size)]
    max_memory: Option<u64>,
    /// Run FILE first in each script's fresh session (its values are not
    /// printed, its errors are).
    #[arg(long, global = true, value_name = "FILE")]
    prelude: Option<std::path::PathBuf>,
    /// With `run`: every assert of every script as a test case, written to
    /// FILE as JUnit XML or Gradescope's results.json (name from the
    /// assert's trailing comment, points from `[N pts]` in it).
    #[arg(long, global = true, num_args = 2, value_names = ["junit|gradescope", "FILE"])]
    report: Vec<OsString>,
}

impl Opts {
    /// `--report FORMAT FILE`, read: Err is the message for exit code 2.
    fn report(&self) -> Result<Option<(crate::grade::Format, std::path::PathBuf)>, String> {
        let [format, file] = self.report.as_slice() else {
            return Ok(None);
        };
        let format = format
            .to_str()
            .and_then(crate::grade::Format::parse)
            .ok_or_else(|| {
                format!(
                    "--report: '{}' is not one of junit, gradescope",
                    crate::diagnostics::escape::bytes(format.as_encoded_bytes())
                )
            })?;
        Ok(Some((format, file.into())))
    }

    /// The evaluation budget of `--timeout` and `--max-memory`, its clock
    /// started now, interrupted by Ctrl-C.
    fn budget(&self) -> crate::budget::Budget {
        let mut b = crate::budget::Budget::new();
        if let Some(t) = self.timeout {
            b = b.with_timeout(t);
        }
        if let Some(m) = self.max_memory {
            b = b.with_max_memory(m);
        }
        // A second handler cannot be installed (only in tests calling
        // `main_with_args` twice): Ctrl-C then keeps its default.
        let _ = b.interrupt_handle().on_ctrl_c();
        b
    }

    /// The output settings of `--frames`, `--digits`, `--json`, `--exact`,
    /// `--short` and `--latex`.
    fn settings(&self) -> Settings {
        Settings {
            frames: self.frames,
            digits: self.digits as usize,
            json: self.json,
            exact: self.exact,
            sym: self.sym_mode(),
        }
    }

    /// What the kernel's session gets from the flags, as a script does
    /// (LANGUAGE.md §§1, 13): the settings, the effects gate, the memory
    /// budget, and `--timeout` for each cell. Err is the exit code after
    /// the message.
    fn kernel_options(&self) -> Result<crate::kernel::cell::Options, i32> {
        let mut budget = crate::budget::Budget::new();
        if let Some(m) = self.max_memory {
            budget = budget.with_max_memory(m);
        }
        Ok(crate::kernel::cell::Options {
            settings: self.settings(),
            gate: gate(self)?,
            budget,
            timeout: self.timeout,
        })
    }

    /// How symbolic values print (LANGUAGE.md §7).
    fn sym_mode(&self) -> crate::sym::print::Mode {
        use crate::sym::print::Mode;
        match (self.short, self.latex) {
            (_, true) => Mode::Latex,
            (true, _) => Mode::Short,
            _ => Mode::Text,
        }
    }
}

/// The effects gate the flags ask for (`crate::effects`): `--no-write`
/// refuses, `--write-dir` confines (with `--draw-dir` inside it), else
/// writes go where asked and printed pictures to `.` or `--draw-dir`
/// (created when missing). Err is the exit code after the message.
fn gate(opts: &Opts) -> Result<Gate, i32> {
    let made = if opts.no_write {
        Ok(Gate::deny())
    } else if let Some(root) = &opts.write_dir {
        Gate::within(root, opts.draw_dir.as_deref())
    } else {
        match &opts.draw_dir {
            None => Ok(Gate::anywhere(Some(".".into()))),
            Some(d) => std::fs::create_dir_all(d)
                .map(|()| Gate::anywhere(Some(d.clone())))
                .map_err(|e| {
                    format!(
                        "cannot use --draw-dir '{}': {}",
                        crate::session::shown_path(d),
                        crate::session::io_reason(&e)
                    )
                }),
        }
    };
    made.map_err(|m| {
        emit_err(&format!("chasles: {m}\n"));
        2
    })
}

fn parse_frames(s: &str) -> Result<FrameMode, String> {
    FrameMode::parse(s).ok_or_else(|| format!("'{s}' is not one of strict, warn, off"))
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Run scripts in order, printing each result (`-` reads stdin).
    Run {
        #[arg(required = true, value_name = "FILE")]
        files: Vec<std::path::PathBuf>,
    },
    /// Type- and frame-check scripts without evaluating; report every error.
    Check {
        #[arg(required = true, value_name = "FILE")]
        files: Vec<std::path::PathBuf>,
    },
    /// The Jupyter kernel (started by Jupyter with --connection-file), or
    /// `kernel install` to write its kernelspec.
    Kernel {
        /// The connection file Jupyter writes for the kernel.
        #[arg(long, value_name = "FILE")]
        connection_file: Option<std::path::PathBuf>,
        #[command(subcommand)]
        action: Option<KernelAction>,
    },
    /// The language server (LANGUAGE.md §15): diagnostics, hover,
    /// completion and definitions for `.chs` files, over stdio.
    Lsp,
    /// Print shell completions for bash, zsh or fish (e.g. `chasles
    /// completions bash > ~/.local/share/bash-completion/completions/chasles`).
    Completions {
        #[arg(value_name = "SHELL")]
        shell: clap_complete::Shell,
    },
    /// Print the manual page (roff): `chasles man > chasles.1`, `man
    /// ./chasles.1`.
    Man,
    /// `chasles FILE.chs ...`: a name that is no command is a script,
    /// run as `chasles run FILE.chs ...` is (as `python FILE` runs one).
    #[command(external_subcommand)]
    File(Vec<OsString>),
}

#[derive(Subcommand, Debug)]
enum KernelAction {
    /// Install the kernelspec `chasles` so that Jupyter lists the kernel
    /// (default: --user).
    Install {
        /// In the user's Jupyter data folder ($JUPYTER_DATA_DIR, else the
        /// platform's).
        #[arg(long, conflicts_with = "sys_prefix")]
        user: bool,
        /// In the active Python environment ($VIRTUAL_ENV or $CONDA_PREFIX).
        #[arg(long)]
        sys_prefix: bool,
    },
}

/// `chasles kernel …`: serve a notebook or install the kernelspec.
fn kernel(
    connection_file: Option<&std::path::Path>,
    action: Option<&KernelAction>,
    opts: &Opts,
) -> i32 {
    use crate::kernel::install::{self, Place};
    match (connection_file, action) {
        (None, Some(KernelAction::Install { sys_prefix, .. })) => {
            let place = if *sys_prefix {
                Place::SysPrefix
            } else {
                Place::User
            };
            match install::install(place) {
                Ok(dir) => {
                    println!(
                        "installed the Jupyter kernel 'chasles' in {}",
                        dir.display()
                    );
                    0
                }
                Err(msg) => {
                    emit_err(&format!("chasles: {msg}\n"));
                    2
                }
            }
        }
        (Some(file), None) => match opts.kernel_options().map(|o| crate::kernel::serve(file, o)) {
            Err(code) => code,
            Ok(Ok(())) => 0,
            Ok(Err(msg)) => {
                emit_err(&format!("chasles: {msg}\n"));
                2
            }
        },
        _ => {
            emit_err(
                "chasles: use `chasles kernel install [--user|--sys-prefix]`; Jupyter starts \
                 `chasles kernel --connection-file FILE`\n",
            );
            2
        }
    }
}

/// Writes to stdout; a closed pipe ends the program quietly.
fn emit(out: &mut impl Write, s: &str) {
    // (two copies into the buffer, not the formatting machinery)
    if out
        .write_all(s.as_bytes())
        .and_then(|()| out.write_all(b"\n"))
        .is_err()
    {
        std::process::exit(0);
    }
}

/// Writes generated text (completions, the manual page) to stdout; exit 0
/// (a closed pipe too).
fn print_bytes(bytes: &[u8]) -> i32 {
    let _ = std::io::stdout().lock().write_all(bytes);
    0
}

fn emit_err(s: &str) {
    let mut e = std::io::stderr().lock();
    let _ = e.write_all(s.as_bytes());
}

/// A name in the place of a command that is neither a command nor a file
/// there (a mistyped `chasles chek`): exit 2 with the commands listed,
/// rather than "cannot read 'chek'".
fn not_a_script(name: &std::ffi::OsStr) -> Option<i32> {
    let path = std::path::Path::new(name);
    if name == "-" || path.exists() || path.extension().is_some() {
        return None;
    }
    emit_err(&format!(
        "chasles: '{}' is neither a command (run, check, kernel) nor a file\n\
         usage: chasles [run] FILE.chs ...; chasles --help lists the commands\n",
        crate::session::shown_path(path)
    ));
    Some(2)
}

/// The statements of `-e`: UTF-8 text (a leading byte-order mark
/// skipped), else the message for exit code 2.
fn eval_text(arg: &std::ffi::OsStr) -> Result<String, String> {
    match arg.to_str() {
        Some(t) => Ok(t.strip_prefix('\u{feff}').unwrap_or(t).to_string()),
        None => {
            let bytes = arg.as_encoded_bytes();
            let at = bytes.utf8_chunks().next().map_or(0, |c| c.valid().len());
            Err(format!(
                "-e: the statements are not UTF-8 text (invalid byte at offset {at}): {}",
                crate::diagnostics::escape::bytes(bytes)
            ))
        }
    }
}

/// The whole program; returns the exit code.
/// Arguments are OS strings: one that is not UTF-8 is a clear error
/// (exit 2), never a panic.
pub fn main_with_args<I, T>(args: I) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<std::ffi::OsString> + Clone,
{
    let args: Vec<OsString> = args.into_iter().map(Into::into).collect();
    let cli = match Cli::try_parse_from(&args) {
        // `chasles FILE.chs ...`: parsed again as `chasles run FILE.chs ...`
        // (the flags are global, so they may stand before or after).
        Ok(Cli {
            command: Some(Command::File(rest)),
            ..
        }) if !rest.is_empty() => {
            if let Some(code) = not_a_script(&rest[0]) {
                return code;
            }
            let at = args.len() - rest.len();
            let mut again = args[..at].to_vec();
            again.push("run".into());
            again.extend(rest);
            Cli::try_parse_from(again)
        }
        other => other,
    };
    let cli = match cli {
        Ok(c) => c,
        Err(e) => {
            if !e.use_stderr() {
                let _ = e.print();
                return 0;
            }
            // clap quotes the arguments: their control characters escaped.
            let text = e.render().to_string();
            emit_err(&crate::diagnostics::escape::controls_keep_lines(&text));
            return 2;
        }
    };
    match (&cli.command, &cli.eval) {
        (Some(_), Some(_)) => {
            emit_err(
                "chasles: -e cannot be combined with a command (run, check, kernel, lsp, …)\n",
            );
            2
        }
        (None, Some(src)) => match eval_text(src) {
            Ok(src) => batch::run(
                &[batch::Source::given("<-e>", src)],
                Mode::Run,
                &cli.opts,
                false,
            ),
            Err(msg) => {
                emit_err(&format!("chasles: {msg}\n"));
                2
            }
        },
        (Some(Command::Run { files }), None) => {
            batch::run(&batch::load(files), Mode::Run, &cli.opts, true)
        }
        (Some(Command::Completions { shell }), None) => {
            let mut out = Vec::new();
            clap_complete::generate(*shell, &mut Cli::command(), "chasles", &mut out);
            print_bytes(&out)
        }
        (Some(Command::Man), None) => {
            let mut out = Vec::new();
            match clap_mangen::Man::new(Cli::command()).render(&mut out) {
                Ok(()) => print_bytes(&out),
                Err(e) => {
                    emit_err(&format!("chasles: cannot render the manual page: {e}\n"));
                    2
                }
            }
        }
        (Some(Command::File(names)), None) => {
            let files: Vec<std::path::PathBuf> = names.iter().map(Into::into).collect();
            batch::run(&batch::load(&files), Mode::Run, &cli.opts, true)
        }
        (Some(Command::Check { files }), None) => {
            batch::run(&batch::load(files), Mode::Check, &cli.opts, true)
        }
        (
            Some(Command::Kernel {
                connection_file,
                action,
            }),
            None,
        ) => kernel(connection_file.as_deref(), action.as_ref(), &cli.opts),
        (Some(Command::Lsp), None) => crate::lsp::serve(cli.opts.settings()),
        (None, None) => {
            if std::io::stdin().is_terminal() {
                let gate = match gate(&cli.opts) {
                    Ok(g) => g,
                    Err(code) => return code,
                };
                crate::repl::run_terminal(&cli.opts.settings(), gate, cli.opts.budget())
            } else {
                batch::run(&batch::load(&["-".into()]), Mode::Run, &cli.opts, false)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    //! `chasles kernel` honours the flags of a script run (LANGUAGE.md
    //! §§1, 13): the session the kernel builds from them refuses or
    //! confines writes and stops a cell at `--timeout`.

    use super::*;
    use crate::kernel::cell::{Failure, Notebook};
    use std::time::{Duration, Instant};

    /// The kernel's session as `chasles kernel FLAGS --connection-file F`
    /// makes it.
    fn notebook(flags: &[&str]) -> Notebook {
        let mut args = vec!["chasles", "kernel"];
        args.extend_from_slice(flags);
        args.extend(["--connection-file", "kernel.json"]);
        let cli = Cli::try_parse_from(args).expect("the flags parse");
        Notebook::with(cli.opts.kernel_options().expect("the options"))
    }

    fn cell(nb: &mut Notebook, code: &str) -> Result<(), Failure> {
        nb.execute(code, true, &mut |_| {})
    }

    #[test]
    fn the_kernel_skips_writes_under_no_write() {
        let mut nb = notebook(&["--no-write"]);
        // Skipped with a warning (LANGUAGE.md §1); the cell goes on.
        assert_eq!(
            cell(&mut nb, "save(draw(Rotz(1)), \"k.svg\"); x = 1"),
            Ok(())
        );
        assert!(nb.session.env.get("x").is_some());
        // A printed picture is shown inline: nothing to refuse.
        assert_eq!(cell(&mut nb, "draw(Rotz(1))"), Ok(()));
        assert!(!std::path::Path::new("k.svg").exists());
    }

    #[test]
    fn the_kernel_confines_writes_under_write_dir() {
        let dir = std::env::temp_dir().join(format!("chasles-kernel-wd-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let mut nb = notebook(&["--write-dir", &dir.to_string_lossy()]);
        assert_eq!(cell(&mut nb, "save(draw(Rotz(1)), \"in.svg\")"), Ok(()));
        assert!(dir.join("in.svg").is_file());
        let err = cell(&mut nb, "save(draw(Rotz(1)), \"../out.svg\")").expect_err("refused");
        assert!(err.evalue.contains("(--write-dir)"), "{err:?}");
        assert!(!dir.join("../out.svg").exists());
        // Printed pictures stay inline, as without the flag.
        assert_eq!(cell(&mut nb, "pic = draw(Rotz(1))"), Ok(()));
        assert!(!dir.join("pic.svg").exists());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn the_kernel_stops_each_cell_at_the_timeout() {
        let mut nb = notebook(&["--timeout", "0.2"]);
        let start = Instant::now();
        let long = "y = len([det(k * eye(200)) for k in 1:1000000])";
        let err = cell(&mut nb, long).expect_err("stopped");
        assert!(
            err.evalue
                .contains("the time budget is spent: the run took more than 200 ms (--timeout)"),
            "{err:?}"
        );
        assert!(
            start.elapsed() < Duration::from_secs(30),
            "{:?}",
            start.elapsed()
        );
        // The time is each cell's: a later cell runs in full.
        std::thread::sleep(Duration::from_millis(300));
        assert_eq!(cell(&mut nb, "x = 1"), Ok(()));
        assert!(nb.session.env.get("x").is_some());
        assert!(nb.session.env.get("y").is_none());
    }
}
