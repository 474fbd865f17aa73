//! Grading a folder (LANGUAGE.md §14; README "Grading student scripts"):
//! the README's command line, run as it is on `tests/grading/submissions/`
//! (good scripts, a frame error, a picture, an endless loop, writes
//! outside the folder, a file that is not UTF-8), gives each student the
//! right exit code, JSON lines and diagnostics, and writes nothing; its
//! JUnit report is valid against `tests/grading/junit.xsd` and has the
//! right case for each assert; `--report gradescope` has Gradescope's
//! documented fields and the right score.

mod common;
use common::{LIMIT, Out, command, finish, scratch, test_python};

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A scratch folder holding a copy of the fixture as `submissions/`.
fn course(name: &str) -> PathBuf {
    let dir = scratch(name);
    let subs = dir.join("submissions");
    std::fs::create_dir_all(&subs).expect("a folder");
    for entry in std::fs::read_dir(root().join("tests/grading/submissions")).expect("the fixture") {
        let path = entry.expect("an entry").path();
        std::fs::copy(&path, subs.join(path.file_name().unwrap())).expect("a copy");
    }
    dir
}

/// The README's grading block (the ```sh block of "Grading student
/// scripts"), with the 10 s budget cut to 5 s to keep the test short.
fn readme_block() -> String {
    let readme = std::fs::read_to_string(root().join("README.md")).expect("README");
    let section = &readme[readme
        .find("### Grading student scripts")
        .expect("the section")..];
    let start = section.find("```sh\n").expect("a ```sh block") + "```sh\n".len();
    let block = &section[start..];
    let block = &block[..block.find("```").expect("its end")];
    assert!(block.contains("xargs -0 -n 1 -P 8"), "{block}");
    assert!(block.contains("--timeout 10"), "{block}");
    block.replace("--timeout 10", "--timeout 5")
}

fn sh(dir: &Path, script: &str) -> Out {
    let bin = Path::new(env!("CARGO_BIN_EXE_chasles")).parent().unwrap();
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let child = Command::new("sh")
        .args(["-c", script])
        .current_dir(dir)
        .env("PATH", path)
        .env("NO_COLOR", "1")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("sh runs");
    finish(child, LIMIT)
}

fn read(path: PathBuf) -> String {
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Every file under `dir`, as paths relative to it.
fn files(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else {
                out.push(p.strip_prefix(dir).unwrap().to_string_lossy().into_owned());
            }
        }
    }
    out.sort();
    out
}

#[test]
fn the_readmes_command_grades_the_folder() {
    let dir = course("readme");
    let escaped = [
        dir.join("../../escaped.svg"),
        PathBuf::from("/tmp/chasles-escaped.svg"),
    ];
    for e in &escaped {
        let _ = std::fs::remove_file(e);
    }
    let out = sh(&dir, &readme_block());
    assert!(out.stderr.is_empty(), "{out:?}");
    let mut codes: Vec<String> = read(dir.join("results/exit-codes.txt"))
        .lines()
        .map(String::from)
        .collect();
    codes.sort();
    assert_eq!(
        codes,
        [
            "escape 0",
            "frames 1",
            "good 0",
            "latin1 2",
            "loop 1",
            "picture 0",
            "wrong 1"
        ]
    );
    // Each JSON line names its file; the diagnostics are in NAME.err.
    let good = read(dir.join("results/good.jsonl"));
    for line in good.lines() {
        let j: serde_json::Value = serde_json::from_str(line).expect("a JSON line");
        assert_eq!(j["file"], "submissions/good.chs", "{line}");
    }
    let frames = read(dir.join("results/frames.err"));
    assert!(
        frames.contains("submissions/frames.chs:5:13: frame error: frames do not cancel"),
        "{frames}"
    );
    let picture = read(dir.join("results/picture.err"));
    assert!(
        picture.contains(
            "warning: 'draw-3.svg' not written: writing files is turned off (--no-write)"
        ),
        "{picture}"
    );
    let looping = read(dir.join("results/loop.err"));
    assert!(
        looping.contains("the time budget is spent: the run took more than 5 s"),
        "{looping}"
    );
    let latin1 = read(dir.join("results/latin1.err"));
    assert!(
        latin1.contains("'submissions/latin1.chs' is not UTF-8 text: invalid byte at offset 27"),
        "{latin1}"
    );
    // Nothing was written but the results, inside the folder or outside.
    for e in &escaped {
        assert!(!e.exists(), "{}", e.display());
    }
    let written: Vec<String> = files(&dir)
        .into_iter()
        .filter(|f| !f.starts_with("submissions/"))
        .collect();
    let mut expected: Vec<String> = ["all.log", "exit-codes.txt", "report.xml"]
        .iter()
        .map(|f| format!("results/{f}"))
        .collect();
    for n in [
        "escape", "frames", "good", "latin1", "loop", "picture", "wrong",
    ] {
        expected.push(format!("results/{n}.err"));
        expected.push(format!("results/{n}.jsonl"));
    }
    expected.sort();
    assert_eq!(written, expected);
    junit_report_is_right(&dir.join("results/report.xml"));
}

/// The cases of the README's report: one suite per script, the verdict
/// of each assert, valid against the JUnit schema.
fn junit_report_is_right(path: &Path) {
    let text = read(path.to_path_buf());
    let doc = roxmltree::Document::parse(&text).expect("well-formed XML");
    let top = doc.root_element();
    assert_eq!(top.tag_name().name(), "testsuites");
    let suites: Vec<_> = top
        .children()
        .filter(|n| n.has_tag_name("testsuite"))
        .collect();
    let names: Vec<&str> = suites
        .iter()
        .map(|s| s.attribute("name").unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "submissions/escape.chs",
            "submissions/frames.chs",
            "submissions/good.chs",
            "submissions/latin1.chs",
            "submissions/loop.chs",
            "submissions/picture.chs",
            "submissions/wrong.chs"
        ]
    );
    // (name, verdict, message part) of each case, suite by suite.
    let verdicts: Vec<Vec<(String, &str, String)>> = suites
        .iter()
        .map(|s| {
            s.children()
                .filter(|n| n.has_tag_name("testcase"))
                .map(|c| {
                    let bad = c
                        .children()
                        .find(|n| n.has_tag_name("failure") || n.has_tag_name("error"));
                    (
                        c.attribute("name").unwrap().to_string(),
                        bad.map_or("passed", |b| b.tag_name().name()),
                        bad.and_then(|b| b.attribute("message"))
                            .unwrap_or("")
                            .to_string(),
                    )
                })
                .collect()
        })
        .collect();
    let v = |s: usize, c: usize| (verdicts[s][c].0.as_str(), verdicts[s][c].1);
    assert_eq!(verdicts[0].len(), 1);
    assert_eq!(v(0, 0), ("(a) still graded", "passed"));
    assert_eq!(v(1, 0), ("(a) the offset", "passed"));
    // --keep-going: (b) runs after the refused product, on no T_ac.
    assert_eq!(v(1, 1), ("(b) the chain", "failure"));
    assert!(
        verdicts[1][1].2.contains("name error: unknown name 'T_ac'"),
        "{verdicts:?}"
    );
    assert_eq!(v(2, 0), ("(a) the object, x in {c}", "passed"));
    assert_eq!(v(2, 1), ("(b) a rotation", "passed"));
    assert_eq!(v(3, 0), ("(a) never read", "error"));
    assert!(verdicts[3][0].2.contains("not UTF-8"), "{verdicts:?}");
    assert_eq!(v(4, 0), ("(a) before the loop", "passed"));
    assert_eq!(v(4, 1), ("(b) after the loop", "error"));
    assert!(
        verdicts[4][1].2.contains("the time budget is spent"),
        "{verdicts:?}"
    );
    assert_eq!(v(5, 0), ("(a) x goes to y", "passed"));
    assert_eq!(v(6, 0), ("(a) cos 30°", "failure"));
    assert!(
        verdicts[6][0].2.contains("assert error: assertion failed"),
        "{verdicts:?}"
    );
    assert_eq!(v(6, 1), ("(b) sin 30°", "passed"));
    assert_eq!(top.attribute("tests"), Some("11"));
    assert_eq!(top.attribute("failures"), Some("2"));
    assert_eq!(top.attribute("errors"), Some("2"));
    if let Some(python) = test_python() {
        let out = Command::new(python)
            .arg(root().join("tests/grading/validate_junit.py"))
            .arg(root().join("tests/grading/junit.xsd"))
            .arg(path)
            .output()
            .expect("python runs");
        assert!(
            out.status.success(),
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

#[test]
fn the_gradescope_report_has_the_documented_fields_and_score() {
    let dir = course("gradescope");
    let mut args = vec![
        "run",
        "--no-write",
        "--keep-going",
        "--timeout",
        "3",
        "--report",
        "gradescope",
        "results.json",
    ];
    let scripts: Vec<String> = files(&dir.join("submissions"))
        .into_iter()
        .map(|f| format!("submissions/{f}"))
        .collect();
    args.extend(scripts.iter().map(String::as_str));
    let child = command(&args)
        .current_dir(&dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("chasles starts");
    let out = finish(child, LIMIT);
    assert_eq!(out.code, Some(2), "an unreadable file is exit 2");
    let j: serde_json::Value = serde_json::from_str(&read(dir.join("results.json"))).expect("JSON");
    // good 3 of 3, frames 1 of 4, latin1 0 of 1, loop 1 of 2, picture 1 of
    // 1, escape 1 of 1, wrong 1 of 3 (its (a) is worth 2).
    assert_eq!(j["score"], 8);
    assert_eq!(j["max_score"], 15);
    let tests = j["tests"].as_array().expect("tests[]");
    assert_eq!(tests.len(), 11);
    for t in tests {
        assert!(t["name"].is_string(), "{t}");
        assert!(t["score"].is_number() && t["max_score"].is_number(), "{t}");
        assert!(t["output"].is_string(), "{t}");
        let status = t["status"].as_str().expect("a status");
        assert!(status == "passed" || status == "failed", "{t}");
        assert_eq!(
            status == "passed",
            t["score"] == t["max_score"] && t["max_score"] != 0,
            "{t}"
        );
    }
    let wrong = tests
        .iter()
        .find(|t| t["name"] == "(a) cos 30°")
        .expect("wrong (a)");
    assert_eq!(
        (wrong["score"].as_f64(), wrong["max_score"].as_f64()),
        (Some(0.0), Some(2.0))
    );
    assert!(
        wrong["output"]
            .as_str()
            .unwrap()
            .contains("assertion failed"),
        "{wrong}"
    );
    assert!(
        j["output"]
            .as_str()
            .unwrap()
            .contains("submissions/loop.chs: stopped"),
        "{j}"
    );
}
