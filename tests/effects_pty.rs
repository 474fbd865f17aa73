//! The live preview on a real terminal (issue 23): typing a line that
//! saves or prints a picture, one key at a time, writes no file before
//! Enter — the hint evaluates every prefix, and none of them may touch the
//! folder. Enter then writes exactly what was asked.

#![cfg(unix)]

use std::path::Path;
use std::process::Command;
use std::time::Duration;

use rexpect::reader::Options;
use rexpect::session::{PtySession, spawn_with_options};

mod common;
use common::pty::{TIMEOUT_MS, expect};

/// Types `line` one character at a time, as a person does, so that the
/// line editor refreshes its hint (the preview) after every key.
fn type_slowly(p: &mut PtySession, line: &str) {
    for c in line.chars() {
        p.send(&c.to_string()).expect("the terminal takes input");
        p.flush().expect("the terminal takes input");
        std::thread::sleep(Duration::from_millis(15));
    }
}

fn listing(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .expect("lists")
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n != "history.txt")
        .collect();
    v.sort();
    v
}

#[test]
fn typing_a_save_line_writes_nothing_before_enter() {
    let dir = std::env::temp_dir().join(format!("chasles-effects-pty-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    std::fs::write(dir.join("keep.svg"), "mine").expect("writes");
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_chasles"));
    cmd.current_dir(&dir)
        .env("NO_COLOR", "1")
        .env("TERM", "xterm")
        .env("CHASLES_HISTORY", dir.join("history.txt"));
    let options = Options::new()
        .timeout_ms(Some(TIMEOUT_MS))
        .strip_ansi_escape_codes(true);
    let mut p = spawn_with_options(cmd, options).expect("the binary starts on a pty");
    expect(&mut p, ">>> ");

    for line in [
        "save(draw(Rotz(1)), \"keep.svg\")",
        "save(draw(Rotz(1)), \"a.svg.svg\")",
        "draw(Rotz(1))",
        "pic = draw(Rotx(1))",
    ] {
        type_slowly(&mut p, line);
        // The hint shows the picture it would make: the preview ran.
        expect(&mut p, "picture: 1 frame in {s}");
        p.send_control('c').expect("Ctrl-C is sent");
        expect(&mut p, ">>> ");
    }
    assert_eq!(listing(&dir), ["keep.svg"]);
    assert_eq!(
        std::fs::read_to_string(dir.join("keep.svg")).unwrap(),
        "mine"
    );

    // Enter runs the line: now it is written.
    type_slowly(&mut p, "pic = draw(Rotx(1))\r");
    // (rexpect reads bytes as Latin-1: the arrow is not matched.)
    expect(&mut p, " pic.svg\r\n");
    expect(&mut p, ">>> ");
    assert_eq!(listing(&dir), ["keep.svg", "pic.svg"]);
    p.send_control('d').expect("Ctrl-D is sent");
    let _ = p.exp_eof();
    let _ = p.process().wait();
    let _ = std::fs::remove_dir_all(&dir);
}

/// Under `--no-write` the REPL keeps no history file (LANGUAGE.md §§1,
/// 11): the line editor's history is a write like `save`'s; without the
/// flag the same session writes it.
#[test]
fn no_write_keeps_no_history() {
    for (flags, kept) in [(&["--no-write"][..], false), (&[][..], true)] {
        let dir =
            std::env::temp_dir().join(format!("chasles-history-pty-{}-{kept}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("a temporary folder");
        let history = dir.join("history.txt");
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_chasles"));
        cmd.args(flags)
            .current_dir(&dir)
            .env("NO_COLOR", "1")
            .env("TERM", "xterm")
            .env("CHASLES_HISTORY", &history);
        let options = Options::new()
            .timeout_ms(Some(TIMEOUT_MS))
            .strip_ansi_escape_codes(true);
        let mut p = spawn_with_options(cmd, options).expect("the binary starts on a pty");
        expect(&mut p, ">>> ");
        p.send("x = 41 + 1\r").expect("the terminal takes input");
        p.flush().expect("the terminal takes input");
        expect(&mut p, "x = 42");
        expect(&mut p, ">>> ");
        p.send_control('d').expect("Ctrl-D is sent");
        let _ = p.exp_eof();
        let _ = p.process().wait();
        assert_eq!(history.exists(), kept, "{flags:?}");
        if kept {
            let text = std::fs::read_to_string(&history).expect("readable");
            assert!(text.contains("x = 41 + 1"), "{text}");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
