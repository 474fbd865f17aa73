//! The Jupyter kernel driven by Jupyter's own tools (LANGUAGE.md §13):
//! `tests/jupyter/kernel_test.py` runs `jupyter_kernel_test`'s protocol
//! suite and the interrupt tests, `tests/jupyter/notebook_test.py` executes
//! `notebooks/ch3_tour.ipynb` with `nbclient` and checks its outputs, and
//! `tests/jupyter/explain_notebook_test.py` does the same for
//! `notebooks/explain.ipynb` (`explain` rendered, §14). Each
//! installs the kernelspec of this build into a temporary
//! `JUPYTER_DATA_DIR` first.
//!
//! They need a Python with the pinned tools of
//! `tests/jupyter/requirements.txt`: `CHASLES_JUPYTER_PYTHON` names it, else
//! `target/jupyter-venv` (which `.ci/run` creates) is used when present.
//! Without one the tests print `skipped: …` beside their `ok` (on the
//! uncaptured stderr) and pass, unless `CHASLES_REQUIRE_JUPYTER`
//! is set (as `.ci/run` sets it), when they fail.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The Python with the Jupyter test tools, if any (skipped, and said so
/// on the test's output, without one).
fn python() -> Option<PathBuf> {
    common::test_python()
}

/// A fresh folder with the kernelspec of this build installed in
/// `data/`; the script runs in it.
fn sandbox(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("chasles-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("work")).expect("a temporary folder");
    let out = Command::new(env!("CARGO_BIN_EXE_chasles"))
        .args(["kernel", "install", "--user"])
        .env("JUPYTER_DATA_DIR", dir.join("data"))
        .output()
        .expect("chasles runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let spec = dir.join("data/kernels/chasles/kernel.json");
    let text = std::fs::read_to_string(&spec).expect("kernel.json written");
    assert!(text.contains("\"--connection-file\""), "{text}");
    dir
}

fn run_script(python: &Path, script: &str, name: &str) {
    let dir = sandbox(name);
    let out = Command::new(python)
        .arg(root().join("tests/jupyter").join(script))
        .current_dir(dir.join("work"))
        .env("JUPYTER_DATA_DIR", dir.join("data"))
        .env("JUPYTER_RUNTIME_DIR", dir.join("runtime"))
        .env("JUPYTER_PLATFORM_DIRS", "1")
        .env("CHASLES_BIN", env!("CARGO_BIN_EXE_chasles"))
        .output()
        .expect("python runs");
    let _ = std::fs::remove_dir_all(&dir);
    let report = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{script} failed:\n{report}");
    assert!(report.contains("\nOK"), "{report}");
}

#[test]
fn the_protocol_suite_and_interrupts() {
    if let Some(python) = python() {
        run_script(&python, "kernel_test.py", "kernel-test");
    }
}

#[test]
fn the_tour_notebook_runs_end_to_end() {
    if let Some(python) = python() {
        run_script(&python, "notebook_test.py", "notebook-test");
    }
}

#[test]
fn the_explain_notebook_runs_end_to_end() {
    if let Some(python) = python() {
        run_script(&python, "explain_notebook_test.py", "explain-notebook-test");
    }
}
