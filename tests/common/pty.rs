//! The steps of a session on a pseudo-terminal (the line editor live):
//! waiting for a text with a generous timeout, so that a broken REPL fails
//! the test instead of hanging it, and typing keys.

use rexpect::session::PtySession;

/// How long one expected output may take (the CI machine is slow).
pub const TIMEOUT_MS: u64 = 60_000;

/// Waits for `text`; on a timeout the test fails showing what was read.
pub fn expect(p: &mut PtySession, text: &str) {
    if let Err(e) = p.exp_string(text) {
        panic!("waiting for {text:?}: {e}");
    }
}

/// Types `keys` (a `\r` is Enter).
pub fn send(p: &mut PtySession, keys: &str) {
    p.send(keys).expect("the terminal takes input");
    p.flush().expect("the terminal takes input");
}
