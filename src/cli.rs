//! The command line (LANGUAGE.md §1): `chasles`, `chasles run FILE...`,
//! `chasles check FILE...`, `chasles -e 'STATEMENTS'`, with `--json`,
//! `--frames`, `--digits`, `--exact`, `--keep-going`, `--timeout`,
//! `--max-memory`. Exit codes: 0 success, 1 a script error (a budget
//! exceeded too), 2 bad usage or an unreadable file, 130 interrupted
//! (Ctrl-C) after what was printed.

use std::io::{IsTerminal, Write};

use clap::{Parser, Subcommand};

use crate::effects::Gate;
use crate::eval::env::{FrameMode, Mode};
use crate::session::{Session, Settings};

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
    /// Refuse every file write (save, printed pictures, :save) with an
    /// error.
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
}

impl Opts {
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

fn emit_err(s: &str) {
    let mut e = std::io::stderr().lock();
    let _ = e.write_all(s.as_bytes());
}

/// Runs the sources through one session; returns the exit code.
fn run_sources(sources: &[(String, String)], mode: Mode, opts: &Opts) -> i32 {
    let settings = opts.settings();
    let mut session = Session::new(settings);
    session.budget = opts.budget();
    session.quiet = opts.quiet;
    if mode == Mode::Run {
        match gate(opts) {
            Ok(g) => session.gate = g,
            Err(code) => return code,
        }
    }
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let mut errors = 0;
    let mut statements = 0;
    for (file, src) in sources {
        let keep_going = opts.keep_going || mode == Mode::Check;
        errors += session.run(src, mode, keep_going, |r| {
            statements += 1;
            // `check` prints only errors and its summary (or JSON lines).
            if mode == Mode::Run || settings.json {
                let text = r.stdout(&settings, src);
                if !text.is_empty() {
                    emit(&mut out, &text);
                }
            }
            let err = r.stderr(&settings, file, src);
            if !err.is_empty() {
                let _ = out.flush();
                emit_err(&err);
            }
        });
        if session.interrupted {
            let _ = out.flush();
            emit_err("chasles: interrupted\n");
            return 130;
        }
        if errors > 0 && !opts.keep_going && mode == Mode::Run {
            break;
        }
    }
    if mode == Mode::Check && !settings.json {
        let files: Vec<&str> = sources.iter().map(|(f, _)| f.as_str()).collect();
        let summary = if errors == 0 {
            format!(
                "{}: {statements} statements checked, frames consistent",
                files.join(", ")
            )
        } else {
            format!(
                "{}: {errors} error{}",
                files.join(", "),
                if errors == 1 { "" } else { "s" }
            )
        };
        emit(&mut out, &summary);
    }
    if out.flush().is_err() {
        return 0;
    }
    i32::from(errors > 0)
}

/// Loads files, reporting unreadable ones (exit 2). Each is named in
/// messages as given, with bytes that are not UTF-8 and control characters
/// escaped.
fn load(files: &[std::path::PathBuf]) -> Result<Vec<(String, String)>, i32> {
    let mut sources = Vec::new();
    for f in files {
        match read_source(f) {
            Ok(s) => sources.push((
                if f.as_os_str() == "-" {
                    "<stdin>".to_string()
                } else {
                    crate::session::shown_path(f)
                },
                s,
            )),
            Err(msg) => {
                emit_err(&format!("chasles: {msg}\n"));
                return Err(2);
            }
        }
    }
    Ok(sources)
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
    let cli = match Cli::try_parse_from(args) {
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
            emit_err("chasles: -e cannot be combined with a command (run, check, kernel)\n");
            2
        }
        (None, Some(src)) => match eval_text(src) {
            Ok(src) => run_sources(&[("<-e>".into(), src)], Mode::Run, &cli.opts),
            Err(msg) => {
                emit_err(&format!("chasles: {msg}\n"));
                2
            }
        },
        (Some(Command::Run { files }), None) => match load(files) {
            Ok(s) => run_sources(&s, Mode::Run, &cli.opts),
            Err(code) => code,
        },
        (Some(Command::Check { files }), None) => match load(files) {
            Ok(s) => run_sources(&s, Mode::Check, &cli.opts),
            Err(code) => code,
        },
        (
            Some(Command::Kernel {
                connection_file,
                action,
            }),
            None,
        ) => kernel(connection_file.as_deref(), action.as_ref(), &cli.opts),
        (None, None) => {
            if std::io::stdin().is_terminal() {
                let gate = match gate(&cli.opts) {
                    Ok(g) => g,
                    Err(code) => return code,
                };
                crate::repl::run_terminal(&cli.opts.settings(), gate, cli.opts.budget())
            } else {
                match load(&["-".into()]) {
                    Ok(s) => run_sources(&s, Mode::Run, &cli.opts),
                    Err(code) => code,
                }
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
    fn the_kernel_refuses_writes_under_no_write() {
        let mut nb = notebook(&["--no-write"]);
        let err = cell(&mut nb, "save(draw(Rotz(1)), \"k.svg\")").expect_err("refused");
        assert!(
            err.evalue
                .contains("cannot write 'k.svg': writing files is turned off (--no-write)"),
            "{err:?}"
        );
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
