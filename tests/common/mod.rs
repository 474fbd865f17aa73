//! Helpers shared by the integration tests that run the real binary.

use std::process::Command;

/// Runs the `chasles` binary with `args` (colours off) and returns its exit
/// code (−1 for a signal), stdout and stderr.
pub fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_chasles"))
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .expect("chasles runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}
