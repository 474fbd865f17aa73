//! A long script runs on three threads (issue 40): one reads statements
//! ahead, one evaluates, one writes the text. The run must be the run on
//! one thread (`CHASLES_THREADS=1`), byte for byte, stdout and stderr
//! interleaved as one stream, whatever stops or silences it: errors with
//! and without `--keep-going`, warnings, failed asserts, `;`, `--quiet`,
//! `--json`, `check`, `--digits`.

mod common;
use common::{LIMIT, command, scratch};

use std::fs::File;
use std::process::Stdio;
use std::time::{Duration, Instant};

/// Statements of every kind of outcome; repeated past the length where a
/// script is read and written on threads of their own (`AHEAD_FROM`).
const BLOCK: &[&str] = &[
    "S = (0, 0, 1, 0, 2, 0)",
    "T_ab = exp([S] 0.1)",
    "T_bc = exp([S] 0.2);",
    "T_ac = T_ab * T_bc",
    "X = log(T_ac)",
    "V_a = Ad(T_ab) * (1, 2, 3, 4, 5, 6)",
    "A = Ad(T_ab)",
    "x = exp(1000)",
    "r = (1, 2).T",
    "L = [Rotz(a) for a in 1:2]",
    "n = 1 / 3",
    "(u, w) = (1, 2)",
    "given th : scalar",
    "Rotz(th)",
    "C = zeros(7, 7);",
    "true",
];

/// Blocks in a script: enough to pass the length from which a script runs
/// on three threads.
const BLOCKS: usize = 2 * chasles::syntax::AHEAD_FROM / 250;

/// A script of `blocks` blocks with `bad` (an error or a failed assert)
/// after block `at`.
fn script(blocks: usize, bad: &str, at: usize) -> String {
    let mut s = String::new();
    for b in 0..blocks {
        for line in BLOCK {
            s.push_str(line);
            s.push('\n');
        }
        if b == at {
            s.push_str(bad);
            s.push('\n');
        }
    }
    s
}

/// The exit code and what the binary wrote, stdout and stderr into one
/// file in the order written, with `threads` threads allowed or one.
fn merged(args: &[&str], file: &str, one_thread: bool, dir: &std::path::Path) -> (i32, String) {
    let path = dir.join(if one_thread { "one.txt" } else { "three.txt" });
    let out = File::create(&path).expect("an output file");
    let err = out.try_clone().expect("the same file for stderr");
    let mut cmd = command(args);
    cmd.arg(file)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(out)
        .stderr(err);
    if one_thread {
        cmd.env("CHASLES_THREADS", "1");
    } else {
        cmd.env_remove("CHASLES_THREADS");
    }
    // Bounded: a deadlock between the threads fails the test, not CI.
    let mut child = cmd.spawn().expect("chasles runs");
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("the run's status") {
            break status;
        }
        if started.elapsed() > LIMIT {
            let _ = child.kill();
            panic!("chasles {args:?} did not end within {LIMIT:?}");
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let text = std::fs::read_to_string(&path).expect("the output");
    (status.code().unwrap_or(-1), text)
}

/// Runs `src` with `args` both ways and checks they agree; returns the
/// exit code and the text.
fn same_both_ways(name: &str, args: &[&str], src: &str) -> (i32, String) {
    assert!(
        src.len() > 32 * 1024,
        "{} bytes: not long enough",
        src.len()
    );
    let dir = scratch(name);
    std::fs::write(dir.join("long.chs"), src).expect("the script");
    let one = merged(args, "long.chs", true, &dir);
    let three = merged(args, "long.chs", false, &dir);
    assert_eq!(one.0, three.0, "exit codes");
    if one.1 != three.1 {
        let at = one
            .1
            .bytes()
            .zip(three.1.bytes())
            .take_while(|(a, b)| a == b)
            .count();
        let from = at.saturating_sub(200);
        panic!(
            "the outputs differ at byte {at}:\none thread:\n{}\nthree:\n{}",
            &one.1[from..(at + 200).min(one.1.len())],
            &three.1[from..(at + 200).min(three.1.len())]
        );
    }
    one
}

#[test]
fn keep_going_interleaves_errors_and_values_as_on_one_thread() {
    let src = script(BLOCKS, "z = nope", 70);
    let (code, text) = same_both_ways("keep", &["run", "--keep-going"], &src);
    assert_eq!(code, 1);
    // Every block's warning, the one error, between block 70's values and
    // block 71's.
    assert_eq!(
        text.matches("warning: the result is infinite").count(),
        BLOCKS
    );
    assert_eq!(text.matches("unknown name 'nope'").count(), 1);
    let error = text.find("unknown name 'nope'").expect("the error");
    let before = &text[..error];
    assert_eq!(before.matches("X = [").count(), 71);
    assert_eq!(before.matches("warning: the result").count(), 71);
    assert_eq!(text.matches("T_ab = [").count(), BLOCKS);
    // `T_bc = ...;` and `C = ...;` printed nothing.
    assert!(!text.contains("T_bc = ") && !text.contains("C = "));
}

#[test]
fn an_error_stops_the_run_where_it_stopped_on_one_thread() {
    let src = script(BLOCKS, "y = 1/0", 40);
    let (code, text) = same_both_ways("stop", &["run"], &src);
    assert_eq!(code, 1);
    assert_eq!(text.matches("T_ab = [").count(), 41);
    assert_eq!(text.matches("division by zero").count(), 1);
}

#[test]
fn failed_asserts_quiet_and_digits_are_as_on_one_thread() {
    let src = script(BLOCKS, "assert 1 == 2", 3);
    let (code, text) = same_both_ways("quiet", &["run", "--quiet", "--keep-going"], &src);
    assert_eq!(code, 1);
    assert!(!text.contains("T_ab = ["), "quiet prints no value");
    assert_eq!(text.matches("assertion failed").count(), 1);
    let (_, text) = same_both_ways("digits", &["run", "--digits", "9", "--keep-going"], &src);
    assert!(text.contains("n = 0.333333333\n"), "{}", &text[..400]);
}

#[test]
fn json_and_check_read_ahead_as_on_one_thread() {
    let src = script(BLOCKS, "z = nope", 60);
    let (_, text) = same_both_ways("json", &["run", "--json", "--keep-going"], &src);
    assert!(text.contains("\"name\":\"T_ab\""));
    let (code, text) = same_both_ways("check", &["check"], &src);
    assert_eq!(code, 1);
    assert_eq!(text.matches("unknown name 'nope'").count(), 1);
}
