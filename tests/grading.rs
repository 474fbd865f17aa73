//! Running many scripts and grading them (LANGUAGE.md §§1, 14), through
//! the real binary: `chasles FILE.chs`, a fresh session per file with
//! `--prelude`, `--timeout` per script, `check` going on past an
//! unreadable file, `"file"` in every JSON object and the diagnostics on
//! stderr under `--json`.

mod common;
use common::{LIMIT, Out, command, finish, json_lines, scratch};

use std::path::Path;
use std::process::Stdio;

/// The binary with `args`, run in `dir`, stdin closed, bounded by [`LIMIT`].
fn in_dir(dir: &Path, args: &[&str]) -> Out {
    let child = command(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("chasles starts");
    finish(child, LIMIT)
}

fn write(dir: &Path, name: &str, text: &[u8]) {
    std::fs::write(dir.join(name), text).expect("a script written");
}

#[test]
fn a_file_name_runs_the_file_as_run_does() {
    let dir = scratch("positional");
    write(&dir, "hw.chs", b"R = Rotz(90 deg)\nR * (1, 0, 0)\n");
    let run = in_dir(&dir, &["run", "hw.chs"]);
    let bare = in_dir(&dir, &["hw.chs"]);
    assert_eq!(bare.code, Some(0), "{bare:?}");
    assert_eq!(bare.stdout, run.stdout);
    assert!(bare.stdout.ends_with("(0, 1, 0)  : 3-vector\n"), "{bare:?}");
    // Flags before and after the file are the run's.
    let json = in_dir(&dir, &["--digits", "2", "hw.chs", "--json"]);
    let lines = json_lines(&json.stdout);
    assert_eq!(lines.len(), 2, "{json:?}");
    assert_eq!(lines[1]["type"], "vector");
    assert!(
        (lines[1]["value"][1].as_f64().unwrap() - 1.0).abs() < 1e-15,
        "{json:?}"
    );
    // Command names win over a file of that name; a mistyped command is
    // not read as a file.
    write(&dir, "check", b"1 +\n");
    let check = in_dir(&dir, &["check", "hw.chs"]);
    assert_eq!(check.code, Some(0), "{check:?}");
    assert!(
        check.stdout.contains("hw.chs: 2 statements checked"),
        "{check:?}"
    );
    let typo = in_dir(&dir, &["chek", "hw.chs"]);
    assert_eq!(typo.code, Some(2), "{typo:?}");
    assert!(
        typo.stderr
            .contains("'chek' is neither a command (run, check, kernel) nor a file"),
        "{typo:?}"
    );
    let missing = in_dir(&dir, &["missing.chs"]);
    assert_eq!(missing.code, Some(2), "{missing:?}");
    assert!(
        missing
            .stderr
            .contains("cannot read 'missing.chs': no such file")
    );
}

#[test]
fn each_file_runs_in_a_fresh_session_after_the_prelude() {
    let dir = scratch("fresh");
    write(&dir, "a.chs", b"x = 1\n");
    write(&dir, "b.chs", b"x + 1\n");
    let out = in_dir(&dir, &["run", "a.chs", "b.chs"]);
    assert_eq!(out.code, Some(1), "{out:?}");
    assert_eq!(out.stdout, "x = 1\n");
    assert!(
        out.stderr
            .contains("b.chs:1:1: name error: unknown name 'x'"),
        "{out:?}"
    );
    write(&dir, "prelude.chs", b"x = 40\ny = 1\n");
    let out = in_dir(&dir, &["run", "--prelude", "prelude.chs", "b.chs", "b.chs"]);
    assert_eq!(out.code, Some(0), "{out:?}");
    // The prelude's values are not printed; each file sees x = 40.
    assert_eq!(out.stdout, "41\n41\n");
    // A file that fails does not stop the next one.
    let out = in_dir(&dir, &["run", "b.chs", "a.chs"]);
    assert_eq!(out.code, Some(1), "{out:?}");
    assert_eq!(out.stdout, "x = 1\n");
    let missing = in_dir(&dir, &["run", "--prelude", "nope.chs", "a.chs"]);
    assert_eq!(missing.code, Some(2), "{missing:?}");
    assert!(missing.stderr.contains("--prelude: cannot read 'nope.chs'"));
}

#[test]
fn the_timeout_is_each_scripts() {
    let dir = scratch("timeout");
    write(
        &dir,
        "loop.chs",
        b"y = len([det(k * eye(200)) for k in 1:1000000])\n",
    );
    write(&dir, "quick.chs", b"1 + 1\n");
    let out = in_dir(&dir, &["run", "--timeout", "0.5", "loop.chs", "quick.chs"]);
    assert_eq!(out.code, Some(1), "{out:?}");
    assert!(
        out.stderr.contains("loop.chs:1:")
            && out
                .stderr
                .contains("the time budget is spent: the run took more than 500 ms"),
        "{out:?}"
    );
    // The second script's clock starts when it starts.
    assert_eq!(out.stdout, "2\n", "{out:?}");
}

#[test]
fn check_reports_each_file_on_its_own_line_past_one_not_utf8() {
    let dir = scratch("check");
    write(
        &dir,
        "a.chs",
        b"given T_ab, T_bc : SE3\nT_ac = T_ab * T_bc\n",
    );
    write(&dir, "latin1.chs", b"theta = 30 deg # \xe9tudiant\n");
    write(&dir, "c.chs", b"given T_ab, T_cb : SE3\nT_ab * T_cb\n");
    let out = in_dir(&dir, &["check", "a.chs", "latin1.chs", "c.chs"]);
    assert_eq!(out.code, Some(2), "{out:?}");
    assert_eq!(
        out.stdout,
        "a.chs: 2 statements checked, frames consistent\n\
         latin1.chs: not checked: 'latin1.chs' is not UTF-8 text: invalid byte at offset 17\n\
         c.chs: 1 error\n"
    );
    assert!(out.stderr.contains("c.chs:2:6: frame error"), "{out:?}");
    // check evaluates no assert: it has nothing to report.
    let report = in_dir(&dir, &["check", "--report", "junit", "r.xml", "a.chs"]);
    assert_eq!(report.code, Some(2), "{report:?}");
    assert!(
        report.stderr.contains("--report is for `run`"),
        "{report:?}"
    );
    assert!(!dir.join("r.xml").exists());
    // Without the unreadable file, a script error is exit 1.
    assert_eq!(in_dir(&dir, &["check", "a.chs", "c.chs"]).code, Some(1));
    // One statement is one, not "1 statements".
    write(&dir, "one.chs", b"T_ab = Rotz(1)\n");
    let one = in_dir(&dir, &["check", "one.chs"]);
    assert_eq!(
        one.stdout,
        "one.chs: 1 statement checked, frames consistent\n"
    );
}

#[test]
fn json_objects_name_their_file_and_stderr_keeps_the_diagnostics() {
    let dir = scratch("json");
    write(&dir, "a.chs", b"x = 1\n");
    write(
        &dir,
        "b.chs",
        b"T_ab = Trans((1, 0, 0))\nT_cb = T_ab\nT_ab * T_cb\n",
    );
    let out = in_dir(
        &dir,
        &["run", "--json", "--frames", "strict", "a.chs", "b.chs"],
    );
    assert_eq!(out.code, Some(1), "{out:?}");
    let lines = json_lines(&out.stdout);
    let files: Vec<&str> = lines.iter().map(|l| l["file"].as_str().unwrap()).collect();
    assert_eq!(files, ["a.chs", "b.chs", "b.chs"], "{out:?}");
    assert_eq!(lines[2]["line"], 2);
    assert_eq!(lines[2]["error"]["kind"], "frame");
    // What `2> NAME.err` keeps: the rendered error, as without --json.
    assert!(
        out.stderr
            .starts_with("b.chs:2:8: frame error: the value is {b} in {a}"),
        "{out:?}"
    );
    assert!(out.stderr.contains("2 │ T_cb = T_ab"), "{out:?}");
    // `check --json` names the file too.
    let check = in_dir(&dir, &["check", "--json", "b.chs"]);
    assert_eq!(json_lines(&check.stdout)[0]["file"], "b.chs", "{check:?}");
}

#[test]
fn completions_and_the_manual_page_are_generated() {
    let dir = scratch("completions");
    let bash = in_dir(&dir, &["completions", "bash"]);
    assert_eq!(bash.code, Some(0), "{bash:?}");
    assert!(bash.stdout.contains("_chasles()"), "{}", bash.stdout);
    for word in [
        "--no-write",
        "--report",
        "--prelude",
        "run",
        "check",
        "kernel",
    ] {
        assert!(bash.stdout.contains(word), "{word}");
    }
    // bash reads it without a syntax error.
    std::fs::write(dir.join("chasles.bash"), &bash.stdout).unwrap();
    if let Ok(out) = std::process::Command::new("bash")
        .args(["-n", "chasles.bash"])
        .current_dir(&dir)
        .output()
    {
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let zsh = in_dir(&dir, &["completions", "zsh"]);
    assert!(zsh.stdout.starts_with("#compdef chasles"), "{}", zsh.stdout);
    let fish = in_dir(&dir, &["completions", "fish"]);
    assert!(
        fish.stdout.contains("complete -c chasles"),
        "{}",
        fish.stdout
    );
    let bad = in_dir(&dir, &["completions", "tcsh"]);
    assert_eq!(bad.code, Some(2), "{bad:?}");
    let man = in_dir(&dir, &["man"]);
    assert_eq!(man.code, Some(0), "{man:?}");
    assert!(man.stdout.starts_with(".ie \\n(.g"), "{}", man.stdout);
    assert!(man.stdout.contains(".TH chasles 1"), "{}", man.stdout);
    assert!(man.stdout.contains("\\-\\-no\\-write"), "{}", man.stdout);
    assert!(man.stdout.contains("completions"), "{}", man.stdout);
}
