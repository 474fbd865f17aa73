//! Reproducible random cases for the differential tests: case `i` of a
//! run is drawn from its own seed, `CHASLES_DIFF_SEED` + i (0 + i by
//! default, so CI runs the same cases every time), and a failing case is
//! reported with that seed, its script, and the smallest failing case
//! shrinking finds. `CHASLES_DIFF_CASES` sets how many cases run (more on
//! demand); `CHASLES_DIFF_SEED=random` starts at a random seed (printed),
//! and `CHASLES_DIFF_SEED=S CHASLES_DIFF_CASES=1` reruns case S alone;
//! `CHASLES_DIFF_TIMES` prints each case's time; `CHASLES_DIFF_ALL` runs
//! on past a failure (printed with its seed, not shrunk) and fails at the
//! end with the count.

use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::panic::{AssertUnwindSafe, catch_unwind};

/// How many cases to run: `CHASLES_DIFF_CASES` × `share` (at least 1),
/// or `default`.
pub fn count(default: u64, share: f64) -> u64 {
    std::env::var("CHASLES_DIFF_CASES")
        .ok()
        .and_then(|s| s.parse::<u64>().ok())
        .map_or(default, |n| ((n as f64 * share) as u64).max(1))
}

/// The first seed: `CHASLES_DIFF_SEED`, a random one for `random`, else 0.
pub fn first_seed() -> u64 {
    match std::env::var("CHASLES_DIFF_SEED").ok().as_deref() {
        Some("random") => {
            let t = std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(1, |d| d.as_nanos() as u64);
            // (spread, so that two runs started close together differ)
            t.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 16
        }
        Some(s) => s.parse().unwrap_or(0),
        None => 0,
    }
}

/// A runner whose random numbers come from `seed` alone.
fn runner(seed: u64) -> TestRunner {
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&seed.to_le_bytes());
    bytes[8..16].copy_from_slice(&seed.wrapping_mul(0x9E37_79B9_7F4A_7C15).to_le_bytes());
    TestRunner::new_with_rng(
        Config::default(),
        TestRng::from_seed(RngAlgorithm::ChaCha, &bytes),
    )
}

/// `check` on one value, a panic turned into a failure.
fn try_one<V>(check: &impl Fn(&V) -> Result<(), String>, v: &V) -> Result<(), String> {
    match catch_unwind(AssertUnwindSafe(|| check(v))) {
        Ok(r) => r,
        Err(p) => Err(format!(
            "panicked: {}",
            p.downcast_ref::<String>()
                .cloned()
                .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default()
        )),
    }
}

/// Runs `check` on `cases` values of `strategy`, each from its own seed;
/// panics with the first failure's seed and message and the smallest
/// failing case shrinking finds (`name` says which test).
pub fn run<S: Strategy>(
    name: &str,
    cases: u64,
    strategy: S,
    check: impl Fn(&S::Value) -> Result<(), String>,
) {
    let first = first_seed();
    if std::env::var_os("CHASLES_DIFF_SEED").is_some() {
        eprintln!("{name}: seeds {first}..{}", first + cases);
    }
    let (mut slowest, mut total) = ((0, 0.0f64), 0.0);
    let all = std::env::var_os("CHASLES_DIFF_ALL").is_some();
    let mut failed = Vec::new();
    for seed in first..first + cases {
        let mut r = runner(seed);
        let Ok(mut tree) = strategy.new_tree(&mut r) else {
            continue;
        };
        let clock = std::time::Instant::now();
        let result = try_one(&check, &tree.current());
        let took = clock.elapsed().as_secs_f64();
        if std::env::var_os("CHASLES_DIFF_TIMES").is_some() {
            eprintln!("{name}: seed {seed} took {took:.3} s");
        }
        total += took;
        if took > slowest.1 {
            slowest = (seed, took);
        }
        let Err(found) = result else {
            continue;
        };
        if all {
            eprintln!("{name}: case with seed {seed} failed\n{found}\n");
            failed.push(seed);
            continue;
        }
        // shrink: the simplest value that still fails
        let mut smallest = found.clone();
        let mut steps = 0;
        if tree.simplify() {
            while steps < 2000 {
                steps += 1;
                match try_one(&check, &tree.current()) {
                    Err(m) => {
                        smallest = m;
                        if !tree.simplify() {
                            break;
                        }
                    }
                    Ok(()) => {
                        if !tree.complicate() {
                            break;
                        }
                    }
                }
            }
        }
        panic!(
            "{name}: case with seed {seed} failed \
             (rerun: CHASLES_DIFF_SEED={seed} CHASLES_DIFF_CASES=1)\n{found}\n\
             --- smallest failing case ({steps} shrinking steps):\n{smallest}"
        );
    }
    eprintln!(
        "{name}: {cases} cases in {total:.1} s; the slowest, seed {}, {:.2} s",
        slowest.0, slowest.1
    );
    assert!(
        failed.is_empty(),
        "{name}: {} cases failed, seeds {failed:?}",
        failed.len()
    );
}
