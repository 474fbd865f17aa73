//! The book as tests: every script under `examples/` runs through the real
//! binary and its whole output (stdout, stderr, exit code) is snapshotted.
//! The numbers in the snapshots are checked against the book by the header
//! comments of each script. Error scripts under `tests/errors/<kind>/` are
//! snapshotted the same way, one folder per error kind.

use std::path::Path;

mod common;
use common::{command, report};

/// The whole output of the binary with `args`, as snapshotted.
fn run(args: &[&str]) -> String {
    report(&command(args).output().expect("the chasles binary runs"))
}

/// Held by each `insta::glob!` test while it runs. insta keeps the
/// failures of a glob on one process-wide stack (`insta::glob`'s
/// `GLOB_STACK`), so two globs running at once would report one's failing
/// snapshot under the other's name (`error_scripts ... FAILED` for an
/// example's diff). One glob at a time names the right test.
static ONE_GLOB_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// The lock of [`ONE_GLOB_AT_A_TIME`], whether or not a glob before failed.
fn one_glob() -> std::sync::MutexGuard<'static, ()> {
    ONE_GLOB_AT_A_TIME
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

fn rel(path: &Path) -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    path.strip_prefix(root)
        .unwrap_or(path)
        .to_string_lossy()
        .replace('\\', "/")
}

#[test]
fn example_scripts() {
    let _one = one_glob();
    // A fresh folder: a printed picture replaces only a picture chasles
    // printed (an older build's, unmarked, would be kept and renamed).
    let _ = std::fs::remove_dir_all(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("target/example-pictures"),
    );
    insta::glob!("../examples", "*.chs", |path| {
        // Pictures printed but not saved go under target/, never into the tree.
        let out = run(&["run", "--draw-dir", "target/example-pictures", &rel(path)]);
        assert!(out.starts_with("exit: 0\n"), "{} failed:\n{out}", rel(path));
        insta::assert_snapshot!(out);
    });
}

#[test]
fn error_scripts() {
    let _one = one_glob();
    insta::glob!("errors", "*/*.chs", |path| {
        let out = run(&["run", "--keep-going", &rel(path)]);
        let kind = path
            .parent()
            .and_then(|p| p.file_name())
            .map(|k| k.to_string_lossy().to_string())
            .unwrap_or_default();
        assert!(
            out.starts_with("exit: 1\n"),
            "{} should fail:\n{out}",
            rel(path)
        );
        if [
            "syntax", "name", "type", "frame", "domain", "arity", "assert",
        ]
        .contains(&kind.as_str())
        {
            assert!(
                out.contains(&format!("{kind} error")),
                "{} should report a {kind} error:\n{out}",
                rel(path)
            );
        }
        insta::assert_snapshot!(out);
    });
}
