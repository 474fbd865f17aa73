//! Checks in scripts (LANGUAGE.md §3, issue 15): `==` exact, `≈` (typed
//! `~=`) within 1e-9 relative, `assert` stopping a script with exit 1 and
//! an `assert` error showing both sides — in `run`, `check`, `--json` and
//! the REPL.

use chasles::repl::commands::execute;
use chasles::session::{Session, Settings};

mod common;
use common::{json_lines, run};

#[test]
fn comparisons_give_bools() {
    let (code, out, _) = run(&[
        "--json",
        "-e",
        "0.1 + 0.2 == 0.3\n0.1 + 0.2 ~= 0.3\nRotz(pi/2) ≈ [0, -1, 0; 1, 0, 0; 0, 0, 1]\n(1, 2) == (1, 2)\n1e12 ≈ 1e12 + 1\n1 ≈ 1 + 1e-6",
    ]);
    assert_eq!(code, 0);
    let lines = json_lines(&out);
    let vals: Vec<_> = lines.iter().map(|l| l["value"].clone()).collect();
    assert_eq!(
        vals,
        // 0.1 + 0.2 == 0.3: decimals as typed are exact (LANGUAGE.md §3)
        [true, true, true, true, true, false].map(serde_json::Value::Bool)
    );
    assert!(lines.iter().all(|l| l["type"] == "bool"));
}

#[test]
fn a_failed_assert_stops_with_both_sides() {
    let src = "x = 1\nassert x + 1 == 3\ny = 2";
    let (code, out, err) = run(&["-e", src]);
    assert_eq!(code, 1);
    assert!(out.contains("x = 1") && !out.contains("y = 2"), "{out}");
    assert!(err.contains("<-e>:2:8: assert error"), "{err}");
    assert!(err.contains("left: 2") && err.contains("right: 3"), "{err}");

    let (code, out, _) = run(&["--json", "-e", src]);
    assert_eq!(code, 1);
    let lines = json_lines(&out);
    assert_eq!(lines.len(), 2, "a passing assert prints no line");
    assert_eq!(lines[1]["line"], 2);
    assert_eq!(lines[1]["error"]["kind"], "assert");
    assert_eq!(lines[1]["error"]["help"], "left = 2; right = 3");
}

#[test]
fn passing_asserts_print_nothing() {
    let (code, out, err) = run(&["-e", "assert Rotz(1) * Rotz(2) ≈ Rotz(3)\nassert 2 == 2"]);
    assert_eq!((code, out.as_str(), err.as_str()), (0, "", ""));
}

#[test]
fn check_looks_at_frames_and_shapes_only() {
    let dir = std::env::temp_dir().join(format!("chasles-checks-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("a.chs");
    std::fs::write(
        &f,
        "given T_ab, T_bc, T_ac : SE3\nassert T_ab * T_bc ≈ T_ac\nassert T_ab == T_ac\nassert 1 == (1, 2)\n",
    )
    .unwrap();
    let (code, out, err) = run(&["check", f.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(out.contains("2 errors"), "{out}");
    assert!(err.contains(":3:13: frame error"), "{err}");
    assert!(err.contains(":4:10: type error"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_repl_keeps_its_bindings_after_a_failed_assert() {
    let mut s = Session::new(Settings::default());
    execute(&mut s, "a = 2");
    let r = execute(&mut s, "assert a == 3");
    assert!(r.err.contains("assert error"), "{}", r.err);
    let r = execute(&mut s, "a == 2");
    assert_eq!(r.out.trim(), "true");
}

#[test]
fn assert_needs_a_bool() {
    let (code, _, err) = run(&["-e", "assert 3"]);
    assert_eq!(code, 1);
    assert!(
        err.contains("type error: assert needs a condition"),
        "{err}"
    );
    let (code, _, err) = run(&["-e", "assert TestIfSO3(2 * Rotz(1))"]);
    assert_eq!(code, 1);
    assert!(
        err.contains("assertion failed: `TestIfSO3(2 * Rotz(1))` is false"),
        "{err}"
    );
}

/// `I` takes its size from the other side of a comparison, as in a sum:
/// the book's R Rᵀ = I.
#[test]
fn identity_is_sized_by_the_other_side() {
    let (code, out, err) = run(&[
        "--json",
        "-e",
        "R = Rot((1, 2, 2)/3, 0.7)\nR Rᵀ ≈ I\nassert Trans((1, 2, 3)) * inv(Trans((1, 2, 3))) == I",
    ]);
    assert_eq!(code, 0, "{err}");
    let lines = json_lines(&out);
    assert_eq!(lines[1]["value"], serde_json::Value::Bool(true));
}

/// Symbols: equal trees are equal, what cancels is `I`, symbolic scalars
/// compare by canonical forms, and what neither settles (a kept call such
/// as sqrt) says it cannot decide and waits for numbers (issue 21).
#[test]
fn symbolic_sides() {
    let (code, out, err) = run(&[
        "-e",
        "given T_ab, T_bc : SE3\nT_ab * T_bc == T_ab * T_bc\ninv(T_ab) * T_ab == I\nassert T_ab * inv(T_ab) == eye(4)",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out, "true\ntrue\n");
    // symbolic scalars compare by their canonical forms (§7)
    let (code, out, err) = run(&["-e", "given t : scalar\nt + 1.00001 == t + 1.00002"]);
    assert_eq!((code, out.as_str()), (0, "false\n"), "{err}");
    let (code, out, err) = run(&["-e", "given t : scalar\nsqrt(t^2) == t"]);
    assert_eq!((code, out.as_str()), (0, "abs(t) == t\n"), "{err}");
    assert!(err.contains("note: cannot decide"), "{err}");
    let (code, out, err) = run(&["-e", "given t : scalar\nc = sqrt(t^2) == t\nt = -2\nc"]);
    assert_eq!((code, out.lines().last()), (0, Some("false")), "{err}");
    // an assert cannot wait: refused, never passed
    let (code, _, err) = run(&["-e", "given t : scalar\nassert sqrt(t^2) == t"]);
    assert_eq!(code, 1);
    assert!(err.contains("domain error: cannot decide"), "{err}");
}
