//! A real terminal session: the binary runs on a pseudo-terminal, so the
//! line editor is live (multi-line input, Tab completion, Ctrl-C, Ctrl-D,
//! history). Every wait has a generous timeout, so a broken REPL fails
//! the test instead of hanging it.

#![cfg(unix)]

use std::process::Command;

use rexpect::process::WaitStatus;
use rexpect::reader::Options;
use rexpect::session::{PtySession, spawn_with_options};

mod common;
use common::pty::{TIMEOUT_MS, expect, send};

/// Waits for the prompt of a fresh line.
fn prompt(p: &mut PtySession) {
    expect(p, ">>> ");
}

#[test]
fn terminal_session() {
    let dir = std::env::temp_dir().join(format!("chasles-repl-pty-{}", std::process::id()));
    let history = dir.join("history.txt");
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_chasles"));
    cmd.env("NO_COLOR", "1")
        .env("TERM", "xterm")
        .env("CHASLES_HISTORY", &history);
    let options = Options::new()
        .timeout_ms(Some(TIMEOUT_MS))
        .strip_ansi_escape_codes(true);
    let mut p = spawn_with_options(cmd, options).expect("the binary starts on a pty");

    expect(&mut p, ":help for help");
    prompt(&mut p);

    // A 4×4 matrix typed row by row: Enter inside `[` starts the next row
    // under the continuation prompt; a blank Enter there shows it again.
    send(&mut p, "T = [1, 0, 0, 1\r");
    expect(&mut p, "... ");
    send(&mut p, "\r");
    expect(&mut p, "... ");
    send(&mut p, "0, 1, 0, 2\r");
    send(&mut p, "0, 0, 1, 3\r");
    send(&mut p, "0, 0, 0, 1]\r");
    expect(&mut p, "     0, 0, 1, 3\r\n     0, 0, 0, 1]  : SE(3)");
    prompt(&mut p);

    // Tab completes the common prefix and lists both candidates with
    // their signatures.
    send(&mut p, "MatrixLo\t");
    expect(&mut p, "MatrixLog6(T: SE3) -> 6-vector");
    send(&mut p, "6(T)\r");
    expect(&mut p, "\r\n(0, 0, 0, 1, 2, 3)  : 6-vector");
    prompt(&mut p);

    // An error, and an unfinished call cancelled with Ctrl-C.
    send(&mut p, "T * T_cb\r");
    expect(&mut p, "unknown name 'T_cb'");
    prompt(&mut p);
    send(&mut p, "inv(\r");
    send(&mut p, "T");
    p.send_control('c').expect("Ctrl-C is sent");
    prompt(&mut p);

    // The binding survived both.
    send(&mut p, "T\r");
    expect(
        &mut p,
        "[1, 0, 0, 1\r\n 0, 1, 0, 2\r\n 0, 0, 1, 3\r\n 0, 0, 0, 1]  : SE(3)",
    );
    prompt(&mut p);
    send(&mut p, ":vars\r");
    expect(
        &mut p,
        "T   : SE(3) = [1, 0, 0, 1; 0, 1, 0, 2; 0, 0, 1, 3; 0, 0, 0, 1]",
    );
    prompt(&mut p);

    // Ctrl-D on an empty line quits cleanly.
    p.send_control('d').expect("Ctrl-D is sent");
    if let Err(e) = p.exp_eof() {
        panic!("the REPL did not end on Ctrl-D: {e}");
    }
    let status = p.process().wait().expect("the exit status");
    assert!(
        matches!(status, WaitStatus::Exited(_, 0)),
        "exit status {status:?}"
    );

    let saved = std::fs::read_to_string(&history).unwrap_or_default();
    assert!(saved.contains("MatrixLog6(T)"), "history: {saved:?}");
    assert!(saved.contains(":vars"), "history: {saved:?}");
    let _ = std::fs::remove_dir_all(&dir);
}
