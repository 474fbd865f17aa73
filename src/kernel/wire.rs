//! The Jupyter messaging protocol (5.3) over ZeroMQ: the five sockets of
//! a connection file, through `jupyter-zmq-client` (pure-Rust `zeromq`,
//! signed messages) and `jupyter-protocol`'s message types. The session
//! lives on its own thread ([`worker`]) so that the control socket answers
//! `interrupt_request` and `shutdown_request` while a cell runs.

use std::path::Path;
use std::sync::mpsc as std_mpsc;

use jupyter_protocol::{
    CodeMirrorMode, CommInfoReply, CompleteReply, DisplayData, ErrorOutput, ExecuteInput,
    ExecuteReply, ExecuteResult, ExecutionCount, HistoryEntry, HistoryReply, HistoryRequest,
    InspectReply, InterruptReply, IsCompleteReply, JupyterMessage, JupyterMessageContent,
    KernelInfoReply, LanguageInfo, Media, ReplyError, ReplyStatus, ShutdownReply, Status,
    StreamContent, Transient, connection_info::ConnectionInfo,
};
use jupyter_zmq_client::{
    KernelIoPubConnection, KernelShellConnection, create_kernel_control_connection,
    create_kernel_heartbeat_connection, create_kernel_iopub_connection,
    create_kernel_shell_connection, create_kernel_stdin_connection,
};
use serde_json::{Map, Value as J};
use tokio::sync::{mpsc, oneshot};

use super::cell::{Failure, Notebook, Options, Output};
use crate::budget::Interrupt;

/// What the socket side asks of the session thread.
enum Job {
    Execute {
        code: String,
        store_history: bool,
        outputs: mpsc::UnboundedSender<Output>,
        done: oneshot::Sender<Result<(), Failure>>,
    },
    Complete {
        code: String,
        cursor: usize,
        reply: oneshot::Sender<(Vec<String>, usize, usize, J)>,
    },
    Inspect {
        code: String,
        cursor: usize,
        reply: oneshot::Sender<Option<String>>,
    },
    History {
        reply: oneshot::Sender<Vec<String>>,
    },
}

/// The session thread: one [`Notebook`], jobs in order.
fn worker(jobs: std_mpsc::Receiver<Job>, ready: oneshot::Sender<Interrupt>, options: Options) {
    let mut nb = Notebook::with(options);
    // SIGINT (Jupyter's `interrupt_mode: signal`, a `kill -INT`) sets the
    // same flag as `interrupt_request`.
    let _ = nb.interrupter().on_ctrl_c();
    let _ = ready.send(nb.interrupter());
    while let Ok(job) = jobs.recv() {
        match job {
            Job::Execute {
                code,
                store_history,
                outputs,
                done,
            } => {
                let r = nb.execute(&code, store_history, &mut |o| {
                    let _ = outputs.send(o);
                });
                let _ = done.send(r);
            }
            Job::Complete {
                code,
                cursor,
                reply,
            } => {
                let _ = reply.send(nb.complete(&code, cursor));
            }
            Job::Inspect {
                code,
                cursor,
                reply,
            } => {
                let _ = reply.send(nb.inspect(&code, cursor));
            }
            Job::History { reply } => {
                let _ = reply.send(nb.history.clone());
            }
        }
    }
}

/// `kernel_info_reply`: the language, its version, `.chs`, and an editor
/// mode close to chasles's notation (Julia's: `#` comments, Unicode names,
/// `[a b; c d]`, `0:4`, `'`).
fn kernel_info() -> KernelInfoReply {
    let version = env!("CARGO_PKG_VERSION").to_string();
    KernelInfoReply {
        status: ReplyStatus::Ok,
        protocol_version: "5.3".into(),
        implementation: "chasles".into(),
        implementation_version: version.clone(),
        language_info: LanguageInfo {
            name: "chasles".into(),
            version,
            mimetype: Some("text/x-chasles".into()),
            file_extension: Some(".chs".into()),
            pygments_lexer: Some("julia".into()),
            codemirror_mode: Some(CodeMirrorMode::Simple("julia".into())),
            nbconvert_exporter: None,
        },
        banner: crate::frontend::banner(),
        help_links: Vec::new(),
        debugger: false,
        error: None,
    }
}

/// Runs the kernel on the sockets of `connection_file` until a
/// `shutdown_request`, its session under `options`.
pub fn serve(connection_file: &Path, options: Options) -> Result<(), String> {
    let text = std::fs::read_to_string(connection_file).map_err(|e| {
        format!(
            "cannot read the connection file '{}': {}",
            connection_file.display(),
            crate::session::io_reason(&e)
        )
    })?;
    let info: ConnectionInfo = serde_json::from_str(&text).map_err(|e| {
        format!(
            "'{}' is not a Jupyter connection file: {e}",
            connection_file.display()
        )
    })?;
    let rt = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .map_err(|e| format!("cannot start the kernel's event loop: {e}"))?;
    rt.block_on(sockets(info, options))
}

fn wire_err(e: impl std::fmt::Display) -> String {
    format!("kernel: {e}")
}

async fn sockets(info: ConnectionInfo, options: Options) -> Result<(), String> {
    let id = uuid::Uuid::new_v4().to_string();
    let mut heartbeat = create_kernel_heartbeat_connection(&info)
        .await
        .map_err(wire_err)?;
    let shell = create_kernel_shell_connection(&info, &id)
        .await
        .map_err(wire_err)?;
    let mut control = create_kernel_control_connection(&info, &id)
        .await
        .map_err(wire_err)?;
    let _stdin = create_kernel_stdin_connection(&info, &id)
        .await
        .map_err(wire_err)?;
    let iopub = create_kernel_iopub_connection(&info, &id)
        .await
        .map_err(wire_err)?;

    let (jobs, queue) = std_mpsc::channel();
    let (ready, interrupt) = oneshot::channel();
    std::thread::Builder::new()
        .name("chasles-kernel".into())
        .stack_size(256 * 1024 * 1024)
        .spawn(move || worker(queue, ready, options))
        .map_err(|e| format!("cannot start the session thread: {e}"))?;
    let interrupt = interrupt
        .await
        .map_err(|_| "the session thread did not start".to_string())?;

    tokio::spawn(async move { while heartbeat.single_heartbeat().await.is_ok() {} });
    let (stop, stopped) = oneshot::channel::<()>();
    tokio::spawn(async move {
        let mut failures = 0;
        loop {
            let Ok(msg) = control.read().await else {
                failures += 1;
                if failures > 100 {
                    break;
                }
                continue;
            };
            failures = 0;
            let reply = match &msg.content {
                JupyterMessageContent::KernelInfoRequest(_) => kernel_info().as_child_of(&msg),
                JupyterMessageContent::InterruptRequest(_) => {
                    interrupt.interrupt();
                    InterruptReply::new().as_child_of(&msg)
                }
                JupyterMessageContent::ShutdownRequest(req) => {
                    let reply = ShutdownReply {
                        restart: req.restart,
                        status: ReplyStatus::Ok,
                        error: None,
                    };
                    let _ = control.send(reply.as_child_of(&msg)).await;
                    break;
                }
                _ => continue,
            };
            let _ = control.send(reply).await;
        }
        let _ = stop.send(());
    });
    let shell_task = tokio::spawn(shell_loop(shell, iopub, jobs));
    tokio::select! {
        _ = stopped => {}
        _ = shell_task => {}
    }
    Ok(())
}

/// The shell socket: requests in order, each framed by `busy` and `idle`
/// on iopub.
async fn shell_loop(
    shell: KernelShellConnection,
    mut iopub: KernelIoPubConnection,
    jobs: std_mpsc::Sender<Job>,
) {
    let (mut writer, mut reader) = shell.split();
    let mut count = 0usize;
    let mut failures = 0;
    loop {
        let msg = match reader.read().await {
            Ok(m) => m,
            Err(e) => {
                eprintln!("chasles kernel: unreadable message on shell: {e}");
                failures += 1;
                if failures > 100 {
                    return;
                }
                continue;
            }
        };
        failures = 0;
        let _ = iopub.send(Status::busy().as_child_of(&msg)).await;
        let reply: Option<JupyterMessage> = match &msg.content {
            JupyterMessageContent::KernelInfoRequest(_) => Some(kernel_info().as_child_of(&msg)),
            JupyterMessageContent::ExecuteRequest(req) => {
                let store = req.store_history && !req.silent;
                if store {
                    count += 1;
                }
                let n = ExecutionCount::new(count);
                if !req.silent {
                    let input = ExecuteInput {
                        code: req.code.clone(),
                        execution_count: n,
                    };
                    let _ = iopub.send(input.as_child_of(&msg)).await;
                }
                let result =
                    execute(&jobs, &mut iopub, &msg, &req.code, store, req.silent, n).await;
                let reply = match result {
                    Ok(()) => ExecuteReply {
                        execution_count: n,
                        user_expressions: Some(Default::default()),
                        ..ExecuteReply::default()
                    },
                    Err(f) => ExecuteReply {
                        status: ReplyStatus::Error,
                        execution_count: n,
                        error: Some(Box::new(ReplyError {
                            ename: f.ename,
                            evalue: f.evalue,
                            traceback: f.traceback,
                        })),
                        ..ExecuteReply::default()
                    },
                };
                Some(reply.as_child_of(&msg))
            }
            JupyterMessageContent::CompleteRequest(req) => {
                let (tx, rx) = oneshot::channel();
                let job = Job::Complete {
                    code: req.code.clone(),
                    cursor: req.cursor_pos,
                    reply: tx,
                };
                let (matches, start, end, meta) = ask(&jobs, job, rx)
                    .await
                    .unwrap_or_else(|| (Vec::new(), req.cursor_pos, req.cursor_pos, J::Null));
                let reply = CompleteReply {
                    matches,
                    cursor_start: start,
                    cursor_end: end,
                    metadata: match meta {
                        J::Object(m) => m,
                        _ => Map::new(),
                    },
                    status: ReplyStatus::Ok,
                    error: None,
                };
                Some(reply.as_child_of(&msg))
            }
            JupyterMessageContent::InspectRequest(req) => {
                let (tx, rx) = oneshot::channel();
                let job = Job::Inspect {
                    code: req.code.clone(),
                    cursor: req.cursor_pos,
                    reply: tx,
                };
                let text = ask(&jobs, job, rx).await.flatten();
                let reply = InspectReply {
                    found: text.is_some(),
                    data: text.map_or_else(Media::default, |t| {
                        Media::new(vec![jupyter_protocol::MediaType::Plain(t)])
                    }),
                    ..InspectReply::default()
                };
                Some(reply.as_child_of(&msg))
            }
            JupyterMessageContent::IsCompleteRequest(req) => {
                let reply = if Notebook::is_complete(&req.code) {
                    IsCompleteReply::complete()
                } else {
                    IsCompleteReply::incomplete(String::new())
                };
                Some(reply.as_child_of(&msg))
            }
            JupyterMessageContent::HistoryRequest(req) => {
                let (tx, rx) = oneshot::channel();
                let cells = ask(&jobs, Job::History { reply: tx }, rx)
                    .await
                    .unwrap_or_default();
                Some(HistoryReply::new(history(&cells, req)).as_child_of(&msg))
            }
            JupyterMessageContent::CommInfoRequest(_) => {
                Some(CommInfoReply::default().as_child_of(&msg))
            }
            JupyterMessageContent::ShutdownRequest(req) => {
                let reply = ShutdownReply {
                    restart: req.restart,
                    status: ReplyStatus::Ok,
                    error: None,
                };
                let _ = writer.send(reply.as_child_of(&msg)).await;
                let _ = iopub.send(Status::idle().as_child_of(&msg)).await;
                return;
            }
            _ => None,
        };
        if let Some(reply) = reply {
            let _ = writer.send(reply).await;
        }
        let _ = iopub.send(Status::idle().as_child_of(&msg)).await;
    }
}

/// Sends `job` to the session thread and waits for its answer.
async fn ask<T>(jobs: &std_mpsc::Sender<Job>, job: Job, rx: oneshot::Receiver<T>) -> Option<T> {
    jobs.send(job).ok()?;
    rx.await.ok()
}

/// Runs a cell on the session thread, forwarding its outputs to iopub as
/// they come: each value as `display_data`, the last one as the cell's
/// `execute_result`, streams as `stream`, the error as `error`.
async fn execute(
    jobs: &std_mpsc::Sender<Job>,
    iopub: &mut KernelIoPubConnection,
    parent: &JupyterMessage,
    code: &str,
    store_history: bool,
    silent: bool,
    count: ExecutionCount,
) -> Result<(), Failure> {
    let (outputs, mut received) = mpsc::unbounded_channel();
    let (done, mut finished) = oneshot::channel();
    let job = Job::Execute {
        code: code.to_string(),
        store_history,
        outputs,
        done,
    };
    let lost = || Failure {
        ename: "kernel".into(),
        evalue: "the session thread stopped".into(),
        traceback: vec!["the session thread stopped".into()],
    };
    if jobs.send(job).is_err() {
        return Err(lost());
    }
    let mut pending: Option<Map<String, J>> = None;
    let result = loop {
        tokio::select! {
            Some(out) = received.recv() => {
                if !silent {
                    forward(iopub, parent, out, &mut pending).await;
                }
            }
            r = &mut finished => break r.unwrap_or_else(|_| Err(lost())),
        }
    };
    while let Ok(out) = received.try_recv() {
        if !silent {
            forward(iopub, parent, out, &mut pending).await;
        }
    }
    if let Some(data) = pending {
        let r = ExecuteResult {
            execution_count: count,
            data: media(data),
            metadata: Map::new(),
            transient: Some(Transient::default()),
        };
        let _ = iopub.send(r.as_child_of(parent)).await;
    }
    result
}

/// One output to iopub, holding the latest value back (it may be the
/// cell's result).
async fn forward(
    iopub: &mut KernelIoPubConnection,
    parent: &JupyterMessage,
    out: Output,
    pending: &mut Option<Map<String, J>>,
) {
    if let Some(data) = pending.take() {
        let d = DisplayData::new(media(data));
        let _ = iopub.send(d.as_child_of(parent)).await;
    }
    let msg = match out {
        Output::Data(data) => {
            *pending = Some(data);
            return;
        }
        Output::Stream { stderr, text } => {
            let s = if stderr {
                StreamContent::stderr(&text)
            } else {
                StreamContent::stdout(&text)
            };
            s.as_child_of(parent)
        }
        Output::Error(f) => ErrorOutput {
            ename: f.ename,
            evalue: f.evalue,
            traceback: f.traceback,
        }
        .as_child_of(parent),
    };
    let _ = iopub.send(msg).await;
}

/// A MIME bundle as the protocol's type.
fn media(data: Map<String, J>) -> Media {
    serde_json::from_value(J::Object(data)).unwrap_or_default()
}

/// The entries of a history request: `tail` (the last n cells) and
/// `range` (cells start..stop), numbered by execution count in session 1.
fn history(cells: &[String], req: &HistoryRequest) -> Vec<HistoryEntry> {
    let entry = |i: usize, output: bool| {
        let code = cells[i].clone();
        if output {
            HistoryEntry::InputOutput(1, i + 1, (code, String::new()))
        } else {
            HistoryEntry::Input(1, i + 1, code)
        }
    };
    match req {
        HistoryRequest::Tail { n, output, .. } => {
            let n = usize::try_from(*n).unwrap_or(0).min(cells.len());
            (cells.len() - n..cells.len())
                .map(|i| entry(i, *output))
                .collect()
        }
        HistoryRequest::Range {
            start,
            stop,
            output,
            ..
        } => {
            let lo = usize::try_from(*start).unwrap_or(0).max(1);
            let hi = usize::try_from(*stop).unwrap_or(0).min(cells.len() + 1);
            (lo..hi.max(lo)).map(|k| entry(k - 1, *output)).collect()
        }
        HistoryRequest::Search {
            pattern,
            unique,
            output,
            n,
            ..
        } => {
            let mut seen = std::collections::HashSet::new();
            let mut found: Vec<HistoryEntry> = Vec::new();
            for i in (0..cells.len()).rev() {
                if glob(pattern, &cells[i]) && (!*unique || seen.insert(cells[i].clone())) {
                    found.push(entry(i, *output));
                }
            }
            if *n > 0 {
                found.truncate(*n as usize);
            }
            found.reverse();
            found
        }
    }
}

/// Whether `text` matches a history search pattern (`*` any text, `?` one
/// character), as IPython's history search reads it.
fn glob(pattern: &str, text: &str) -> bool {
    let p: Vec<char> = pattern.chars().collect();
    let t: Vec<char> = text.chars().collect();
    let (mut pi, mut ti, mut star, mut mark) = (0, 0, None, 0);
    while ti < t.len() {
        if pi < p.len() && (p[pi] == '?' || p[pi] == t[ti]) {
            pi += 1;
            ti += 1;
        } else if pi < p.len() && p[pi] == '*' {
            star = Some(pi);
            mark = ti;
            pi += 1;
        } else if let Some(s) = star {
            pi = s + 1;
            mark += 1;
            ti = mark;
        } else {
            return false;
        }
    }
    p[pi..].iter().all(|&c| c == '*')
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn history_tail_and_range() {
        let cells: Vec<String> = ["a = 1", "b = 2", "a + b"].map(String::from).to_vec();
        let tail = history(
            &cells,
            &HistoryRequest::Tail {
                n: 2,
                output: false,
                raw: true,
            },
        );
        let codes: Vec<String> = tail
            .iter()
            .map(|e| match e {
                HistoryEntry::Input(_, _, c) => c.clone(),
                HistoryEntry::InputOutput(_, _, (c, _)) => c.clone(),
            })
            .collect();
        assert_eq!(codes, ["b = 2", "a + b"]);
        let range = history(
            &cells,
            &HistoryRequest::Range {
                session: Some(1),
                start: 2,
                stop: 3,
                output: false,
                raw: true,
            },
        );
        assert!(matches!(&range[..], [HistoryEntry::Input(1, 2, c)] if c == "b = 2"));
    }

    #[test]
    fn glob_matches_like_ipython() {
        assert!(glob("a*", "a + b"));
        assert!(glob("*b", "a + b"));
        assert!(!glob("b*", "a + b"));
        assert!(glob("a?+*", "a + b"));
    }
}
