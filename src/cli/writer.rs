//! The writing thread of a long batch run (issue 40): while the session
//! evaluates statement n, a second thread writes the text of the statements
//! before it, so that a script of many printed statements pays for
//! formatting their numbers on the other core.
//!
//! What a statement prints crosses as a [`Job`]: its stdout text with the
//! numbers still to be written ([`Printed`]) and its stderr text (warnings,
//! the error). The thread writes the jobs in order, each one's stdout
//! before its stderr and stdout flushed before stderr is written, as the
//! run on one thread does, so the two streams interleave as before. Jobs
//! go in batches over a bounded channel and come back emptied, so their
//! storage is used again and the thread is never more than a few batches
//! behind.

use std::io::Write;
use std::sync::mpsc;

use super::{emit, emit_err};
use crate::output::later::Printed;
use crate::output::text::Style;

/// What one statement writes.
#[derive(Default)]
pub(super) struct Job {
    /// Its text on stdout (empty when it prints nothing).
    pub out: Printed,
    /// Its text on stderr (empty when it has none).
    pub err: String,
}

/// Jobs per batch.
const BATCH: usize = 256;

/// Full batches the writing thread may be behind by.
const QUEUE: usize = 3;

/// A batch is sent once its jobs hold this many bytes of text, so that the
/// text waiting to be written stays small whatever the values' size (a
/// large matrix is written out here, not later).
const BATCH_BYTES: usize = 64 * 1024;

/// The evaluating side: takes each statement's [`Job`] in turn.
pub(super) struct Writer {
    /// To the writing thread: a batch and how many of its jobs are filled
    /// (none when no thread could be started: jobs are written in line).
    to_thread: Option<mpsc::SyncSender<(Vec<Job>, usize)>>,
    /// Batches the thread is done with.
    back: mpsc::Receiver<Vec<Job>>,
    batch: Vec<Job>,
    filled: usize,
    /// The bytes of text the filled jobs hold.
    held: usize,
    /// For writing in line.
    style: Style,
    text: String,
}

impl Writer {
    /// The next statement's job, empty, for [`Writer::done`] to send.
    pub fn next(&mut self) -> &mut Job {
        if self.filled == self.batch.len() {
            self.batch.push(Job::default());
        }
        let job = &mut self.batch[self.filled];
        job.out.clear();
        job.err.clear();
        job
    }

    /// The job [`Writer::next`] gave is filled: it is written, now or by
    /// the thread with its batch (a statement that writes nothing, a
    /// silenced one, is not sent at all).
    pub fn done(&mut self) {
        let job = &self.batch[self.filled];
        if job.out.is_empty() && job.err.is_empty() {
            return;
        }
        self.held += job.out.held() + job.err.len();
        self.filled += 1;
        match &self.to_thread {
            None => {
                let mut out = std::io::stdout().lock();
                for job in &self.batch[..self.filled] {
                    write(&mut out, job, self.style, &mut self.text);
                }
                let _ = out.flush();
                self.filled = 0;
                self.held = 0;
            }
            Some(_) if self.filled == BATCH || self.held >= BATCH_BYTES => self.send(),
            Some(_) => {}
        }
    }

    /// Sends the filled jobs, taking back an emptied batch when there is
    /// one.
    fn send(&mut self) {
        let Some(to) = &self.to_thread else { return };
        let next = self.back.try_recv().unwrap_or_default();
        let full = std::mem::replace(&mut self.batch, next);
        // The thread ends only when this side is dropped.
        let _ = to.send((full, self.filled));
        self.filled = 0;
        self.held = 0;
    }
}

/// Runs `body` with a [`Writer`] whose jobs a second thread writes to
/// stdout (through a buffer of its own) and stderr, in order; returns when
/// every job is written. Whatever was written to stdout before must be
/// flushed first.
pub(super) fn beside<R>(style: Style, body: impl FnOnce(&mut Writer) -> R) -> R {
    std::thread::scope(|scope| {
        let (to_thread, full) = mpsc::sync_channel::<(Vec<Job>, usize)>(QUEUE);
        let (back_to_caller, back) = mpsc::channel();
        let thread = std::thread::Builder::new()
            .name("chasles-write".into())
            .spawn_scoped(scope, move || {
                let mut out = std::io::BufWriter::new(std::io::stdout());
                let mut text = String::with_capacity(192);
                for (batch, filled) in full {
                    for job in &batch[..filled] {
                        write(&mut out, job, style, &mut text);
                    }
                    let _ = back_to_caller.send(batch);
                }
                let _ = out.flush();
            });
        let mut writer = Writer {
            to_thread: thread.is_ok().then_some(to_thread),
            back,
            batch: Vec::with_capacity(BATCH),
            filled: 0,
            held: 0,
            style,
            text: String::new(),
        };
        let result = body(&mut writer);
        writer.send();
        // Dropping the sender ends the thread's loop; the scope waits for
        // it to write the rest.
        drop(writer);
        result
    })
}

/// Writes one job: its stdout text (its numbers written here), then its
/// stderr text after flushing stdout.
fn write(out: &mut impl Write, job: &Job, style: Style, text: &mut String) {
    if !job.out.is_empty() {
        text.clear();
        job.out.finish(text, style);
        emit(out, text);
    }
    if !job.err.is_empty() {
        let _ = out.flush();
        emit_err(&job.err);
    }
}
