//! Fuzz target: arbitrary UTF-8 through parse → check → evaluate, in both
//! `Mode::Check` and `Mode::Run`, on a fresh session each. Any panic, stack
//! overflow, hang (libFuzzer `-timeout`) or allocation beyond `-rss_limit_mb`
//! is a finding.
#![no_main]

use chasles::eval::env::Mode;
use chasles::session::Session;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(src) = std::str::from_utf8(data) else {
        return;
    };
    for mode in [Mode::Check, Mode::Run] {
        let mut session = Session::default();
        let (_out, _err, _errors) = session.run_to_strings("<fuzz>", src, mode, true);
    }
});
