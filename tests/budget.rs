//! The evaluation budget from the command line (issue 23, LANGUAGE.md §1):
//! memory and time bombs are refused with the limit and the size named,
//! `--timeout` stops a long script with exit 1, `--max-memory` caps the
//! whole run, and Ctrl-C (SIGINT) stops `run` with exit 130 after what was
//! printed. Every wait is bounded, so a regression fails instead of hanging.

use std::process::Command;
use std::time::{Duration, Instant};

mod common;
use common::{bounded, finish, spawn};

#[test]
fn a_list_of_large_matrices_is_refused_with_its_size() {
    // Without the budget: "memory allocation failed", SIGABRT.
    let out = bounded(&[
        "--keep-going",
        "-e",
        "x = 5\nx = [eye(2000) for k in 1:300]\nx",
    ]);
    assert_eq!(out.code, Some(1), "{}", out.stderr);
    assert!(
        out.stderr.contains(
            "domain error: this would hold 1,200,000,300 numbers (9.6 GB); \
             one statement may hold at most 50,000,000 numbers (400 MB)"
        ),
        "{}",
        out.stderr
    );
    assert!(out.stderr.contains("--max-memory"), "{}", out.stderr);
    // The session is as it was: x is still 5.
    assert_eq!(out.stdout, "x = 5\n5\n");
}

#[test]
fn a_grid_of_small_matrices_is_refused_with_its_size() {
    // Without the budget: 3.5 GB in 10 s.
    let out = bounded(&["--json", "-e", "[eye(64) for a in 1:1000, b in 1:1000]"]);
    assert_eq!(out.code, Some(1), "{}", out.stderr);
    let line: serde_json::Value = serde_json::from_str(out.stdout.trim()).expect("a JSON line");
    assert_eq!(line["error"]["kind"], "domain");
    let message = line["error"]["message"].as_str().unwrap_or("");
    assert!(
        message.starts_with("this would hold 4,097,000,000 numbers (32.8 GB)"),
        "{message}"
    );
    // Refused long before it would have been built.
    assert!(out.took < Duration::from_secs(60), "{:?}", out.took);
}

#[test]
fn max_memory_caps_the_whole_run() {
    // Each list fits in 100 MB; the bindings together do not.
    let src = "a = len([eye(100) for k in 1:1000])\n\
               b = [eye(100) for k in 1:1000]\n\
               c = [eye(100) for k in 1:1000]";
    let out = bounded(&["--max-memory", "100M", "-e", src]);
    assert_eq!(out.code, Some(1), "{}", out.stderr);
    assert!(
        out.stdout.starts_with("a = 1000\nb = list of 1000"),
        "{}",
        out.stdout
    );
    assert!(
        out.stderr
            .contains("<-e>:3:5: domain error: this would hold")
            && out
                .stderr
                .contains("--max-memory allows at most 12,500,000 numbers (100 MB)"),
        "{}",
        out.stderr
    );
    // A bad size is a usage error.
    let out = bounded(&["--max-memory", "lots", "-e", "1"]);
    assert_eq!(out.code, Some(2), "{}", out.stderr);
    assert!(
        out.stderr.contains("'lots' is not a size"),
        "{}",
        out.stderr
    );
}

#[test]
fn the_recipes_of_exact_numbers_count_against_the_budget() {
    let in_1m = |src: &str| bounded(&["--max-memory", "1M", "-e", src]);
    // Each sine of an exact t keeps its recipe (for `==` to bound it):
    // 128 bytes an item (the recipe's node, t held in it), counted as
    // numbers of 8 bytes. 10,001 of them pass 1 MB, though their floats
    // alone are 80 kB; 500,001 took 1.1 GB uncounted.
    let out = in_1m("xs = [sin(t) for t in 0:0.001:10]");
    assert_eq!(out.code, Some(1), "{}", out.stderr);
    let message = out.stderr.lines().next().unwrap_or("");
    assert!(
        message.starts_with("<-e>:1:6: domain error: this would hold ")
            && message.ends_with("; --max-memory allows at most 125,000 numbers (1 MB)"),
        "{message}"
    );
    let wanted: u64 = message["<-e>:1:6: domain error: this would hold ".len()..]
        .split(' ')
        .next()
        .unwrap_or("")
        .replace(',', "")
        .parse()
        .expect("a count");
    assert!((125_000..400_000).contains(&wanted), "{wanted}");
    // Fractions are held inline, no recipe: the range itself and the
    // list of its items fit (2 numbers an item).
    let out = in_1m("xs = [t for t in 0:0.001:5]\nsum(xs) == 12502.5");
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert!(out.stdout.ends_with("true\n"), "{}", out.stdout);
    // A 3-vector of fractions holds them inline, no recipe over copies
    // of its entries: 5,000 fit in 1 MB (3 numbers an item and its place
    // in the list; as recipes they were 315,000 numbers), 40,000 do not.
    let out = in_1m("xs = [(k/1000, 0, 0) for k in 1:5000]\nxs[4000] == (4, 0, 0)");
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert!(out.stdout.ends_with("true\n"), "{}", out.stdout);
    let out = in_1m("xs = [(k/1000, 0, 0) for k in 1:40000]");
    assert_eq!(out.code, Some(1), "{}", out.stderr);
    assert!(
        out.stderr.contains("this would hold 160,000 numbers"),
        "{}",
        out.stderr
    );
}

#[test]
fn timeout_stops_a_long_script() {
    let dir = std::env::temp_dir().join(format!("chasles-budget-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temp dir");
    let script = dir.join("long.chs");
    std::fs::write(
        &script,
        "x = 1\ny = len([det(k * eye(200)) for k in 1:1000000])\nz = 3\n",
    )
    .expect("the script is written");
    let path = script.to_string_lossy().to_string();
    let out = bounded(&["--timeout", "1", "--keep-going", "run", &path]);
    assert_eq!(out.code, Some(1), "{}", out.stderr);
    assert_eq!(out.stdout, "x = 1\n", "the run stops at the time budget");
    assert!(
        out.stderr.contains(
            "long.chs:2:9: domain error: the time budget is spent: the run took more than 1 s (--timeout)"
        ),
        "{}",
        out.stderr
    );
    // Well before the minutes the statement would take.
    assert!(out.took < Duration::from_secs(60), "{:?}", out.took);
    // `check` takes the flag too.
    let out = bounded(&["--timeout", "5", "check", &path]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let out = bounded(&["--timeout", "-1", "check", &path]);
    assert_eq!(out.code, Some(2), "{}", out.stderr);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_symbolic_expansion_stops_at_the_timeout() {
    let out = bounded(&[
        "--timeout",
        // the expansion takes seconds in a debug build: √2 keeps it on the
        // general product (rational coefficients take the packed one,
        // `sym::dense`, in milliseconds)
        "0.1",
        "-e",
        "given a, b, c, d : scalar\nx = (a + b + c + d + sqrt(2))^14",
    ]);
    assert_eq!(out.code, Some(1), "{}", out.stderr);
    assert!(
        out.stderr.contains("more than 100 ms (--timeout)"),
        "{}",
        out.stderr
    );
}

/// Whether process `pid` catches SIGINT (its handler is installed).
#[cfg(target_os = "linux")]
fn catches_sigint(pid: u32) -> bool {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("SigCgt:"))
        .and_then(|mask| u64::from_str_radix(mask.trim(), 16).ok())
        .is_some_and(|mask| mask & (1 << (2 - 1)) != 0)
}

#[cfg(target_os = "linux")]
#[test]
fn ctrl_c_stops_run_with_exit_130_after_what_was_printed() {
    let child = spawn(&[
        "-e",
        "x = 1\ny = len([det(k * eye(200)) for k in 1:1000000])\nz = 3",
    ]);
    let pid = child.id();
    let start = Instant::now();
    while !catches_sigint(pid) {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no SIGINT handler"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
    // The first statement runs in microseconds; give it ample time.
    std::thread::sleep(Duration::from_millis(500));
    let sent = Command::new("kill")
        .args(["-INT", &pid.to_string()])
        .status()
        .expect("kill runs");
    assert!(sent.success());
    let out = finish(child, Duration::from_secs(60));
    assert_eq!(out.code, Some(130), "{}", out.stderr);
    assert_eq!(out.stdout, "x = 1\n");
    assert_eq!(out.stderr, "chasles: interrupted\n");
}
