//! A client of one `chasles lsp` process over stdio, as an editor drives
//! it (LANGUAGE.md §15): Content-Length framed JSON-RPC, every wait bounded
//! so that a silent server fails the test instead of hanging it. Used by
//! `tests/lsp.rs` and `tests/frontends_agree.rs`.

use std::io::{BufRead, BufReader, Read, Write};
use std::path::Path;
use std::process::{Child, ChildStdin, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::{Duration, Instant};

use serde_json::{Value, json};

/// How long one answer may take (generous: CI's machine is small and shared).
pub const WAIT: Duration = Duration::from_secs(60);

/// A client speaking to one server process.
pub struct Client {
    pub child: Child,
    pub stdin: ChildStdin,
    rx: Receiver<Value>,
    /// The id of the last request sent.
    pub next_id: i64,
    /// Notifications read while waiting for something else.
    pub pending: Vec<Value>,
}

impl Client {
    /// Starts `chasles ARGS` (flags, then `lsp`), in `dir` when given, and
    /// initializes it: the client and the `initialize` result.
    pub fn start_with(dir: Option<&Path>, args: &[&str]) -> (Client, Value) {
        let mut command = super::command(args);
        if let Some(dir) = dir {
            command.current_dir(dir);
        }
        let mut child = command
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("chasles lsp starts");
        let stdin = child.stdin.take().unwrap();
        let mut out = BufReader::new(child.stdout.take().unwrap());
        let (tx, rx) = channel();
        std::thread::spawn(move || {
            loop {
                let mut len = None;
                loop {
                    let mut line = String::new();
                    if out.read_line(&mut line).unwrap_or(0) == 0 {
                        return;
                    }
                    let line = line.trim_end();
                    if line.is_empty() {
                        break;
                    }
                    if let Some(n) = line.strip_prefix("Content-Length: ") {
                        len = n.parse::<usize>().ok();
                    }
                }
                let mut body = vec![0; len.expect("a Content-Length header")];
                if out.read_exact(&mut body).is_err() {
                    return;
                }
                let v: Value = serde_json::from_slice(&body).expect("a JSON message");
                if tx.send(v).is_err() {
                    return;
                }
            }
        });
        let mut c = Client {
            child,
            stdin,
            rx,
            next_id: 0,
            pending: Vec::new(),
        };
        let init = c.request(
            "initialize",
            json!({"processId": null, "rootUri": null, "capabilities": {}}),
        );
        c.notify("initialized", json!({}));
        (c, init)
    }

    /// Writes one framed message.
    pub fn send(&mut self, v: Value) {
        let body = v.to_string();
        write!(self.stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).unwrap();
        self.stdin.flush().unwrap();
    }

    /// The next message, within [`WAIT`].
    pub fn next(&mut self, what: &str) -> Value {
        self.rx.recv_timeout(WAIT).unwrap_or_else(|_| {
            panic!("no answer from chasles lsp within {WAIT:?} waiting for {what}")
        })
    }

    /// Sends a notification.
    pub fn notify(&mut self, method: &str, params: Value) {
        self.send(json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    /// Sends a request and returns its result (failing on an error reply).
    pub fn request(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        self.send(json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        loop {
            let v = self.next(method);
            if v["id"] == json!(id) {
                assert!(v.get("error").is_none(), "{method} failed: {v}");
                return v["result"].clone();
            }
            self.pending.push(v);
        }
    }

    /// The diagnostics published for `uri` at `version`.
    pub fn diagnostics_of(&mut self, uri: &str, version: i64) -> Vec<Value> {
        let is_it = |v: &Value| {
            v["method"] == "textDocument/publishDiagnostics"
                && v["params"]["uri"] == uri
                && v["params"]["version"] == json!(version)
        };
        let v = match self.pending.iter().position(is_it) {
            Some(i) => self.pending.remove(i),
            None => loop {
                let v = self.next("publishDiagnostics");
                if is_it(&v) {
                    break v;
                }
                self.pending.push(v);
            },
        };
        v["params"]["diagnostics"].as_array().unwrap().clone()
    }

    /// The exit code, once the process has exited (within [`WAIT`]).
    pub fn exit_code(&mut self, after: &str) -> i32 {
        let start = Instant::now();
        loop {
            if let Some(s) = self.child.try_wait().unwrap() {
                return s.code().unwrap_or(-1);
            }
            assert!(
                start.elapsed() < WAIT,
                "chasles lsp did not exit after {after}"
            );
            std::thread::sleep(Duration::from_millis(20));
        }
    }
}

impl Drop for Client {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
