//! The evaluation budget in a real terminal (issue 23, LANGUAGE.md §11):
//! Ctrl-C interrupts a running statement and the session keeps what it
//! had; the live preview of a line that would take seconds gives up within
//! its few milliseconds, so typing never waits. Every wait has a generous
//! timeout, so a broken REPL fails the test instead of hanging it.

#![cfg(unix)]

use std::process::Command;
use std::time::{Duration, Instant};

use rexpect::reader::Options;
use rexpect::session::{PtySession, spawn_with_options};

mod common;
use common::pty::{TIMEOUT_MS, expect, send};

fn start(name: &str) -> (PtySession, std::path::PathBuf) {
    let dir = std::env::temp_dir().join(format!("chasles-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temp dir");
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_chasles"));
    cmd.env("NO_COLOR", "1")
        .env("TERM", "xterm")
        .env("CHASLES_HISTORY", dir.join("history.txt"))
        .current_dir(&dir);
    let options = Options::new()
        .timeout_ms(Some(TIMEOUT_MS))
        .strip_ansi_escape_codes(true);
    let mut p = spawn_with_options(cmd, options).expect("the binary starts on a pty");
    expect(&mut p, ":help for help");
    expect(&mut p, ">>> ");
    (p, dir)
}

#[test]
fn ctrl_c_interrupts_a_long_statement_and_keeps_the_session() {
    let (mut p, dir) = start("interrupt");
    send(&mut p, "x = 5\r");
    expect(&mut p, "x = 5");
    expect(&mut p, ">>> ");
    // Minutes of work; before the budget, Ctrl-C killed the REPL here.
    send(&mut p, "y = len([det(k * eye(200)) for k in 1:1000000])\r");
    expect(&mut p, "for k in 1:1000000])");
    expect(&mut p, "\n");
    // Let the line editor hand the terminal back before Ctrl-C.
    std::thread::sleep(Duration::from_millis(700));
    p.send_control('c').expect("Ctrl-C is sent");
    expect(&mut p, "interrupted");
    expect(&mut p, ">>> ");
    // The session is as it was before the statement.
    send(&mut p, "x + 1\r");
    expect(&mut p, "\r\n6");
    expect(&mut p, ">>> ");
    send(&mut p, "y\r");
    expect(&mut p, "unknown name 'y'");
    expect(&mut p, ">>> ");
    // And the next statement runs as usual.
    send(&mut p, "z = x * 2\r");
    expect(&mut p, "z = 10");
    expect(&mut p, ">>> ");
    p.send_control('d').expect("Ctrl-D is sent");
    let _ = p.exp_eof();
    let _ = p.process().wait();
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_keystroke_echoes_while_the_line_would_take_seconds() {
    let (mut p, dir) = start("preview");
    // Each state of the line is a valid expression whose value takes
    // seconds (a million products); the preview must give up, not block.
    send(
        &mut p,
        "len([Rotz(a) * Rotz(b) for a in 1:1000, b in 1:1000]) + 1",
    );
    expect(&mut p, "+ 1");
    let mut took = Vec::new();
    for d in ['2', '3', '4', '5', '6', '7', '8', '9'] {
        let t = Instant::now();
        send(&mut p, &d.to_string());
        // Read the echo as it comes (rexpect's own waits poll every 100 ms).
        loop {
            match p.try_read() {
                Some(c) if c == d => break,
                Some(_) => {}
                None => {
                    assert!(t.elapsed() < Duration::from_secs(60), "no echo of {d}");
                    std::thread::sleep(Duration::from_millis(1));
                }
            }
        }
        took.push(t.elapsed());
    }
    took.sort();
    eprintln!("echo latencies: {took:?}");
    // The fastest echo bounds the preview (scheduling on a loaded machine
    // may delay some); a blocking preview would make every one seconds.
    assert!(took[0] < Duration::from_millis(100), "{took:?}");
    assert!(
        took[took.len() / 2] < Duration::from_millis(1500),
        "{took:?}"
    );
    p.send_control('c').expect("Ctrl-C is sent");
    expect(&mut p, ">>> ");
    p.send_control('d').expect("Ctrl-D is sent");
    let _ = p.exp_eof();
    let _ = p.process().wait();
    let _ = std::fs::remove_dir_all(&dir);
}
