//! The evaluation budget: the one mechanism that every long loop asks
//! whether to go on (LANGUAGE.md §1 `--timeout`, `--max-memory`, exit 130;
//! §11 Ctrl-C and the bounded preview). It carries an interrupt flag (set
//! by Ctrl-C, or by a Jupyter `interrupt_request` from another thread), a
//! deadline (`--timeout`, the REPL preview's few milliseconds) and a count
//! of the numbers a statement holds, capped for one statement and for the
//! whole run. What a value holds besides its numbers counts as numbers
//! of 8 bytes (`eval::env::numbers`): the recipe that keeps an exact
//! number's form, at about its bytes, fixed when it is made
//! (`values::exact::Exact::weight`: a node, its operands, what no one
//! else holds under them).
//!
//! A front end makes a [`Budget`] and [`Budget::enter`]s it on the thread
//! that evaluates; every layer below (statements, comprehensions, ranges,
//! the symbolic engine's products, drawing, matrix kernels) asks the free
//! functions [`check`], [`stopped`], [`hold`] and [`room`] of the budget in
//! force on its thread, so no signature carries it. A loop with no error
//! type stops at [`stopped`] with whatever it has; the session asks
//! [`check`] after every statement and puts the budget's error in place of
//! such a cut-short result, so it is never bound or printed.
//!
//! This is a bottom layer, beside `span`: it knows nothing of the language.

use std::cell::{Cell, RefCell};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

mod units;

use units::seconds;
pub use units::{bytes, count, parse_seconds, parse_size};

/// The numbers one statement may hold by default (400 MB of `f64`): a
/// comprehension of matrices larger than this is a mistake in a calculator
/// for rigid-body motion, not a workspace.
pub const STATEMENT_NUMBERS: u64 = 50_000_000;

/// The bytes a whole run may hold by default (`--max-memory 4G`): its
/// bindings and the statement running.
pub const RUN_BYTES: u64 = 4_000_000_000;

/// How long the REPL's live preview may compute before it gives up.
pub const PREVIEW_TIME: Duration = Duration::from_millis(30);

/// The numbers the REPL's live preview may hold (a 100×100 matrix, twice
/// over): more is never shown on one line, and a kernel on such a matrix
/// takes a millisecond.
pub const PREVIEW_NUMBERS: u64 = 20_000;

/// Bytes per number held (an `f64`).
const BYTES_PER_NUMBER: u64 = 8;

/// A handle that interrupts evaluation from any thread: Ctrl-C's handler,
/// a Jupyter kernel's control channel. Clones share one flag; the
/// evaluation in progress under a [`Budget`] made with it stops at its next
/// check, and the statement fails with [`Stop::Interrupted`] (the session
/// keeps its bindings as they were before it).
#[derive(Debug, Clone, Default)]
pub struct Interrupt(Arc<AtomicBool>);

impl Interrupt {
    /// A new flag, not set.
    pub fn new() -> Interrupt {
        Interrupt::default()
    }
    /// Asks the evaluation to stop (safe from any thread or a signal
    /// handler's thread).
    pub fn interrupt(&self) {
        self.0.store(true, Ordering::SeqCst);
    }
    /// Whether an interrupt is pending.
    pub fn is_set(&self) -> bool {
        self.0.load(Ordering::SeqCst)
    }
    /// Clears the flag: the front end does this once it has reported the
    /// interrupt, before the next statement.
    pub fn clear(&self) {
        self.0.store(false, Ordering::SeqCst);
    }
    /// Makes Ctrl-C (SIGINT) set this flag for the rest of the process. A
    /// second Ctrl-C while the first is still pending after a second ends
    /// the process with exit code 130 (a computation that does not reach a
    /// check). Err when a handler is already installed.
    pub fn on_ctrl_c(&self) -> Result<(), String> {
        let flag = self.clone();
        let mut first: Option<Instant> = None;
        ctrlc::set_handler(move || {
            if flag.is_set() {
                if first.is_some_and(|t| t.elapsed() > Duration::from_secs(1)) {
                    std::process::exit(130);
                }
            } else {
                first = Some(Instant::now());
                flag.interrupt();
            }
        })
        .map_err(|e| e.to_string())
    }
}

/// Why an evaluation stopped before its end.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stop {
    /// Ctrl-C or another thread's [`Interrupt::interrupt`].
    Interrupted,
    /// The deadline passed: the time allowed (`--timeout`).
    Timeout(Duration),
    /// Holding `wanted` numbers would pass the cap of `limit`.
    Memory {
        /// The numbers it would have taken.
        wanted: u64,
        /// The most allowed.
        cap: u64,
        /// Which cap.
        limit: Limit,
        /// The numbers held outside the statement and counted in `wanted`
        /// (the bindings, for the run's cap).
        base: u64,
    },
}

/// Which memory cap a [`Stop::Memory`] names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Limit {
    /// The default cap of one statement ([`STATEMENT_NUMBERS`]).
    Statement,
    /// The whole run's cap (`--max-memory`, default [`RUN_BYTES`]).
    Run,
    /// `--max-memory` given: it caps a statement and the run alike.
    Given,
}

impl Stop {
    /// The same stop with the size it would have taken replaced by a
    /// better estimate (a comprehension knows how many items it would
    /// have made).
    pub fn wanting(self, numbers: u64) -> Stop {
        match self {
            Stop::Memory {
                cap,
                limit,
                wanted,
                base,
            } => Stop::Memory {
                wanted: wanted.max(base.saturating_add(numbers)),
                cap,
                limit,
                base,
            },
            s => s,
        }
    }
    /// What a user can do about it.
    pub fn help(&self) -> &'static str {
        match self {
            Stop::Interrupted => "the statement was stopped; the session is as it was before it",
            Stop::Timeout(_) => "raise --timeout, or compute less (fewer frames, larger steps)",
            Stop::Memory {
                limit: Limit::Statement,
                ..
            } => {
                "build smaller lists (larger steps, fewer items), or raise the cap with --max-memory SIZE"
            }
            Stop::Memory { .. } => {
                "hold less (rebind names to smaller values), or raise --max-memory SIZE"
            }
        }
    }
}

impl std::fmt::Display for Stop {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Stop::Interrupted => write!(f, "interrupted"),
            Stop::Timeout(d) => write!(
                f,
                "the time budget is spent: the run took more than {} (--timeout)",
                seconds(*d)
            ),
            Stop::Memory {
                wanted, cap, limit, ..
            } => {
                let whose = match limit {
                    Limit::Statement => "one statement may hold",
                    Limit::Run => "the run may hold",
                    Limit::Given => "--max-memory allows",
                };
                write!(
                    f,
                    "this would hold {} numbers ({}); {whose} at most {} numbers ({})",
                    count(*wanted),
                    bytes(wanted.saturating_mul(BYTES_PER_NUMBER)),
                    count(*cap),
                    bytes(cap.saturating_mul(BYTES_PER_NUMBER)),
                )
            }
        }
    }
}

impl std::error::Error for Stop {}

/// The limits of an evaluation: what a front end sets up once (from
/// `--timeout` and `--max-memory`, or the preview's small ones) and the
/// session [`enter`](Budget::enter)s while it evaluates.
#[derive(Debug, Clone)]
pub struct Budget {
    interrupt: Interrupt,
    /// When the time allowed ends, and how long it was (for the message).
    deadline: Option<(Instant, Duration)>,
    statement_cap: u64,
    run_cap: u64,
    /// Whether `--max-memory` set the caps (named in their error).
    given: bool,
}

impl Default for Budget {
    fn default() -> Budget {
        Budget::new()
    }
}

impl Budget {
    /// No deadline, the default caps ([`STATEMENT_NUMBERS`] a statement,
    /// [`RUN_BYTES`] the run) and a fresh interrupt flag.
    pub fn new() -> Budget {
        Budget {
            interrupt: Interrupt::new(),
            deadline: None,
            statement_cap: STATEMENT_NUMBERS,
            run_cap: RUN_BYTES / BYTES_PER_NUMBER,
            given: false,
        }
    }

    /// The REPL preview's budget: [`PREVIEW_TIME`] from now and
    /// [`PREVIEW_NUMBERS`], with a flag of its own.
    pub fn preview() -> Budget {
        Budget {
            statement_cap: PREVIEW_NUMBERS,
            run_cap: u64::MAX,
            ..Budget::new()
        }
        .with_timeout(PREVIEW_TIME)
    }

    /// The same budget, ending `timeout` from now (`--timeout`: the whole
    /// run, from its start).
    pub fn with_timeout(mut self, timeout: Duration) -> Budget {
        self.deadline = Instant::now()
            .checked_add(timeout)
            .map(|end| (end, timeout));
        self
    }

    /// The same budget holding at most `bytes` (`--max-memory`): the run's
    /// bindings with the statement running, and each statement.
    pub fn with_max_memory(mut self, bytes: u64) -> Budget {
        let n = (bytes / BYTES_PER_NUMBER).max(1);
        self.run_cap = n;
        self.statement_cap = n;
        self.given = true;
        self
    }

    /// The same budget, stopped by `interrupt` (a flag shared with a signal
    /// handler or a kernel's control thread).
    pub fn with_interrupt(mut self, interrupt: Interrupt) -> Budget {
        self.interrupt = interrupt;
        self
    }

    /// The handle that interrupts evaluations under this budget, from any
    /// thread.
    pub fn interrupt_handle(&self) -> Interrupt {
        self.interrupt.clone()
    }

    /// Puts this budget in force on the current thread until the returned
    /// guard drops (the budget before it is then in force again). Counts
    /// start at zero.
    pub fn enter(&self) -> Active {
        let limits = Limits {
            deadline: self.deadline,
            statement_cap: self.statement_cap,
            run_cap: self.run_cap,
            given: self.given,
        };
        let flag = Some(self.interrupt.0.clone());
        Active {
            flag: FLAG.replace(flag),
            limits: LIMITS.replace(limits),
            counts: COUNTS.replace(Counts::default()),
        }
    }
}

/// A [`Budget`] in force on this thread; dropping it restores the one
/// before.
#[must_use = "the budget is in force only while this guard lives"]
pub struct Active {
    flag: Option<Arc<AtomicBool>>,
    limits: Limits,
    counts: Counts,
}

impl Drop for Active {
    fn drop(&mut self) {
        FLAG.replace(self.flag.take());
        LIMITS.set(self.limits);
        COUNTS.set(self.counts);
    }
}

#[derive(Debug, Clone, Copy)]
struct Limits {
    deadline: Option<(Instant, Duration)>,
    statement_cap: u64,
    run_cap: u64,
    given: bool,
}

/// The numbers held: by the bindings before this statement, and by the
/// statement so far.
#[derive(Debug, Clone, Copy, Default)]
struct Counts {
    bindings: u64,
    statement: u64,
}

thread_local! {
    static FLAG: RefCell<Option<Arc<AtomicBool>>> = const { RefCell::new(None) };
    static LIMITS: Cell<Limits> = const {
        Cell::new(Limits {
            deadline: None,
            statement_cap: STATEMENT_NUMBERS,
            run_cap: RUN_BYTES / BYTES_PER_NUMBER,
            given: false,
        })
    };
    static COUNTS: Cell<Counts> = const { Cell::new(Counts { bindings: 0, statement: 0 }) };
    static REFUSED: Cell<Option<Stop>> = const { Cell::new(None) };
}

/// Whether the evaluation on this thread must stop now: interrupted, or
/// past its deadline. For loops with no error type (the symbolic engine,
/// drawing): they stop with what they have, and the session reports the
/// budget's error in place of the result.
#[inline]
pub fn stopped() -> bool {
    check().is_err()
}

/// Ok while the evaluation on this thread may go on; else why it must stop
/// (interrupted, or past its deadline). Cheap: an atomic load, and a clock
/// read only when a deadline is set.
#[inline]
pub fn check() -> Result<(), Stop> {
    let interrupted = FLAG.with_borrow(|f| f.as_ref().is_some_and(|f| f.load(Ordering::Relaxed)));
    if interrupted {
        return Err(Stop::Interrupted);
    }
    match LIMITS.get().deadline {
        Some((end, d)) if Instant::now() >= end => Err(Stop::Timeout(d)),
        _ => Ok(()),
    }
}

/// A new statement starts, with `bindings` numbers held by the session's
/// bindings: the statement holds none yet.
pub fn begin_statement(bindings: u64) {
    REFUSED.set(None);
    COUNTS.set(Counts {
        bindings,
        statement: 0,
    });
}

/// The numbers the current statement holds so far (a mark for
/// [`release_to`]).
pub fn held() -> u64 {
    COUNTS.get().statement
}

/// The statement no longer holds more than `mark` numbers (a finished
/// list is counted again by whatever holds it).
pub fn release_to(mark: u64) {
    let mut c = COUNTS.get();
    c.statement = c.statement.min(mark);
    COUNTS.set(c);
}

/// Counts `n` more numbers held by the current statement (a list's new
/// item); Err when that passes a cap (nothing is counted then).
pub fn hold(n: u64) -> Result<(), Stop> {
    room(n)?;
    let mut c = COUNTS.get();
    c.statement = c.statement.saturating_add(n);
    COUNTS.set(c);
    Ok(())
}

/// Ok when the current statement may hold `n` more numbers (a new matrix,
/// a value to bind), without counting them.
#[inline]
pub fn room(n: u64) -> Result<(), Stop> {
    let c = COUNTS.get();
    let l = LIMITS.get();
    let statement = c.statement.saturating_add(n);
    let limit = if l.given {
        Limit::Given
    } else {
        Limit::Statement
    };
    let refused = if statement > l.statement_cap {
        Stop::Memory {
            wanted: statement,
            cap: l.statement_cap,
            limit,
            base: 0,
        }
    } else if statement.saturating_add(c.bindings) > l.run_cap {
        Stop::Memory {
            wanted: statement.saturating_add(c.bindings),
            cap: l.run_cap,
            limit: if l.given { Limit::Given } else { Limit::Run },
            base: c.bindings,
        }
    } else {
        return Ok(());
    };
    REFUSED.set(Some(refused));
    Err(refused)
}

/// The last memory refusal of the current statement, taken: a
/// comprehension whose item was refused names the size the whole list
/// would have taken ([`Stop::wanting`]).
pub fn take_refusal() -> Option<Stop> {
    REFUSED.take()
}

#[cfg(test)]
mod tests;
