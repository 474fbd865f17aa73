//! The command-line contract of LANGUAGE.md §1, through the real binary:
//! JSON lines, exit codes, `check`, `-e`, `--frames`, `--digits`,
//! `--keep-going`, and printed values parsing back to the same value.

mod common;
use common::{chasles, json_lines};

fn close(a: &serde_json::Value, b: f64) -> bool {
    (a.as_f64().expect("a number") - b).abs() < 1e-12
}

#[test]
fn json_lines_follow_the_schema() {
    let src =
        "T_ab = Trans((1, 0, 0))\nT_bc = Trans((0, 2, 0))\nT_ac = T_ab * T_bc\npi/2\nT_ab * T_ab\n";
    let out = chasles(&["--json", "--keep-going", "-e", src], None);
    assert_eq!(out.code, Some(1));
    let lines = json_lines(&out.stdout);
    assert_eq!(lines.len(), 5);
    assert_eq!(lines[2]["line"], 3);
    assert_eq!(lines[2]["name"], "T_ac");
    assert_eq!(lines[2]["type"], "SE3");
    assert_eq!(lines[2]["frames"], serde_json::json!(["a", "c"]));
    assert_eq!(
        lines[2]["value"],
        serde_json::json!([[1, 0, 0, 1], [0, 1, 0, 2], [0, 0, 1, 0], [0, 0, 0, 1]])
    );
    assert_eq!(lines[3]["name"], serde_json::Value::Null);
    assert_eq!(lines[3]["type"], "scalar");
    assert!(close(&lines[3]["value"], std::f64::consts::FRAC_PI_2));
    assert_eq!(lines[4]["line"], 5);
    assert_eq!(lines[4]["error"]["kind"], "frame");
    assert_eq!(lines[4]["error"]["col"], 6);
}

#[test]
fn json_values_are_full_precision() {
    let out = chasles(
        &["--json", "-e", "MatrixLog3([0, 0, 1; 1, 0, 0; 0, 1, 0])"],
        None,
    );
    let v = &json_lines(&out.stdout)[0]["value"];
    let expected = 2.0 * std::f64::consts::PI / 3.0 / 3f64.sqrt();
    for i in 0..3 {
        assert!(close(&v[i], expected), "{v}");
    }
}

#[test]
fn run_stops_at_the_first_error_unless_keep_going() {
    let src = "x = 1\ny = nope\nz = 3\n";
    let stop = chasles(&["-e", src], None);
    assert_eq!(stop.code, Some(1));
    assert!(stop.stdout.contains("x = 1"));
    assert!(!stop.stdout.contains("z = 3"));
    assert!(
        stop.stderr
            .contains("<-e>:2:5: name error: unknown name 'nope'"),
        "{}",
        stop.stderr
    );
    let go = chasles(&["--keep-going", "-e", src], None);
    assert_eq!(go.code, Some(1));
    assert!(go.stdout.contains("z = 3"));
}

#[test]
fn check_reports_every_error_without_numbers() {
    let dir = std::env::temp_dir().join(format!("chasles-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("derivation.chs");
    std::fs::write(
        &path,
        "given T_ab, T_bc, T_cd : SE3\nT_ad = T_ab * T_bc * T_cd\nT_ab * T_cd\nT_xy = T_ab * T_bc\n",
    )
    .unwrap();
    let out = chasles(&["check", path.to_str().unwrap()], None);
    assert_eq!(out.code, Some(1));
    assert_eq!(
        out.stderr.matches("frame error").count(),
        2,
        "{}",
        out.stderr
    );
    assert!(out.stdout.contains("2 errors"), "{}", out.stdout);
    std::fs::write(&path, "given T_ab, T_bc : SE3\nT_ac = T_ab * T_bc\n").unwrap();
    let ok = chasles(&["check", path.to_str().unwrap()], None);
    assert_eq!(ok.code, Some(0), "{}", ok.stderr);
    assert!(ok.stdout.contains("frames consistent"));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn frames_warn_and_off() {
    let src = "T_ab = Trans((1, 0, 0))\nT_cb = Trans((0, 1, 0))\nT_ab * T_cb\n";
    let warn = chasles(&["--frames", "warn", "-e", src], None);
    assert_eq!(warn.code, Some(0));
    assert!(
        warn.stderr.contains("warning: frames do not cancel"),
        "{}",
        warn.stderr
    );
    assert!(warn.stdout.contains("[1, 0, 0, 1"), "{}", warn.stdout);
    let off = chasles(&["--frames", "off", "-e", src], None);
    assert_eq!(off.code, Some(0));
    assert!(off.stderr.is_empty(), "{}", off.stderr);
    let bad = chasles(&["--frames", "loose", "-e", "1"], None);
    assert_eq!(bad.code, Some(2));
}

#[test]
fn digits_controls_decimals() {
    assert_eq!(
        chasles(&["--digits", "2", "-e", "pi"], None).stdout,
        "3.14\n"
    );
    assert_eq!(
        chasles(&["--digits", "10", "-e", "pi"], None).stdout,
        "3.1415926536\n"
    );
    assert_eq!(chasles(&["-e", "-0.0"], None).stdout, "0\n");
    assert_eq!(
        chasles(&["-e", "2 * 0.5000000000000001"], None).stdout,
        "1\n"
    );
}

#[test]
fn piped_stdin_runs_like_run() {
    let out = chasles(&[], Some(b"Rotz(pi/2) * (1, 0, 0)\n"));
    assert_eq!(out.code, Some(0));
    assert_eq!(out.stdout, "(0, 1, 0)  : 3-vector\n");
    let dash = chasles(&["run", "-"], Some(b"1 + 1\n"));
    assert_eq!(dash.stdout, "2\n");
}

#[test]
fn usage_errors_exit_2() {
    assert_eq!(chasles(&["run"], None).code, Some(2));
    assert_eq!(chasles(&["--digits", "x", "-e", "1"], None).code, Some(2));
    let missing = chasles(&["run", "/nonexistent/file.chs"], None);
    assert_eq!(missing.code, Some(2));
    assert!(
        missing.stderr.contains("no such file"),
        "{}",
        missing.stderr
    );
    let dir = chasles(&["run", "."], None);
    assert_eq!(dir.code, Some(2));
    assert!(dir.stderr.contains("directory"), "{}", dir.stderr);
}

/// Printed matrices parse back to the same value (with enough digits).
#[test]
fn printed_values_parse_back() {
    let src = "T = RpToTrans(Rot((1, 2, 3), 0.7), (1.5, -2.25, 1e-3))";
    let printed = chasles(&["--digits", "17", "-e", src], None).stdout;
    let value_text = printed.split("  :").next().unwrap().to_string();
    let back = chasles(
        &[
            "--json",
            "--digits",
            "17",
            "-e",
            &format!(
                "{src}\nU = {}\nnorm(U - T)",
                value_text.trim_start_matches("T = ")
            ),
        ],
        None,
    );
    let lines = json_lines(&back.stdout);
    assert_eq!(lines.len(), 3, "{}", back.stderr);
    assert_eq!(lines[1]["value"], lines[0]["value"], "{printed}");
    assert!(close(&lines[2]["value"], 0.0));
}

#[test]
fn frame_error_names_both_frames_and_the_fix() {
    let src = "T_ab = Trans((1, 0, 0))\nT_cb = Trans((0, 1, 0))\nT_ab * T_cb\n";
    let out = chasles(&["-e", src], None);
    assert_eq!(out.code, Some(1));
    let err = out.stderr;
    assert!(
        err.starts_with("<-e>:3:6: frame error: frames do not cancel\n"),
        "{err}"
    );
    assert!(
        err.contains("{b} in {a}") && err.contains("{b} in {c}"),
        "{err}"
    );
    assert!(err.contains("b ≠ c"), "{err}");
    assert!(err.contains("did you mean inv(T_cb)"), "{err}");
}

#[test]
fn derive_finds_a_chain_and_names_reachable_frames() {
    let src = "T_ad = Trans((1, 0, 0))\nT_db = Trans((0, 1, 0))\nT_bc = Trans((0, 0, 1))\nT_de = Trans((2, 0, 0))\nderive T_ce\n";
    let out = chasles(&["--json", "-e", src], None);
    let lines = json_lines(&out.stdout);
    assert_eq!(lines[4]["name"], "T_ce");
    assert_eq!(lines[4]["frames"], serde_json::json!(["c", "e"]));
    // T_ce = inv(T_bc) inv(T_db) T_de: a translation by (2, -1, -1).
    assert_eq!(lines[4]["value"][0][3], 2);
    assert_eq!(lines[4]["value"][1][3], -1);
    assert_eq!(lines[4]["value"][2][3], -1);
    // its JSON carries the chain text prints
    assert_eq!(lines[4]["chain"], "inv(T_bc) * inv(T_db) * T_de");
    let text = chasles(&["-e", src], None).stdout;
    assert!(
        text.contains("T_ce = inv(T_bc) * inv(T_db) * T_de"),
        "{text}"
    );
    let none = chasles(
        &[
            "-e",
            "T_ab = Trans((1, 0, 0))\nT_cd = Trans((0, 1, 0))\nderive T_ad",
        ],
        None,
    );
    assert_eq!(none.code, Some(1));
    assert!(
        none.stderr
            .contains("no chain of known transforms from {a} to {d}"),
        "{}",
        none.stderr
    );
    assert!(
        none.stderr
            .contains("from {a} the known transforms reach {a}, {b}"),
        "{}",
        none.stderr
    );
}

/// `derive T_cc` is the empty chain: the identity of {c} to itself, of
/// the size of the transforms that reach {c} (it was "no chain from {c}
/// to {c}", whose help listed {c} as reachable).
#[test]
fn derive_of_a_frame_to_itself_is_the_identity() {
    let src =
        "T_ab = Trans((1, 2, 3))\nderive T_bb\nT_xy = SE2(0.5, 1, 2)\nderive T_yy\nderive R_qq";
    let out = chasles(&["--json", "-e", src], None);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let lines = json_lines(&out.stdout);
    let eye = |n: usize| -> serde_json::Value {
        (0..n)
            .map(|i| (0..n).map(|j| u8::from(i == j)).collect::<Vec<_>>())
            .collect::<Vec<_>>()
            .into()
    };
    for (line, name, ty, n) in [
        (1, "T_bb", "SE3", 4),
        (3, "T_yy", "SE2", 3),
        (4, "R_qq", "SO3", 3),
    ] {
        let l = &lines[line];
        assert_eq!(l["name"], name, "{l}");
        assert_eq!(l["type"], ty, "{l}");
        assert_eq!(l["value"], eye(n), "{l}");
        assert_eq!(l["chain"], "I", "{l}");
        let f = &name[2..3];
        assert_eq!(l["frames"], serde_json::json!([f, f]), "{l}");
    }
}

/// A numeric identity among `given` transforms is no factor of the
/// printed product (LANGUAGE.md §7: expressions over symbols print
/// simplified, as `inv(T_ab) * T_ab` prints `I`): `T_ab * T_bc` with
/// `T_bc = eye(4)` printed `T_ab [1, 0, 0, 0; …; 0, 0, 0, 1]`, and
/// `derive T_ce` through it printed the identity matrix in its value. A
/// scalar symbol times `eye(3)` stays the matrix.
#[test]
fn a_numeric_identity_in_a_product_over_symbols_is_no_factor() {
    let src = "given T_ab, T_db, T_de : SE3\nT_bc = eye(4)\nT_ab * T_bc\nderive T_ce\ngiven R : SO3\neye(3) * R * eye(3)\ngiven t\nt * eye(3)";
    let out = chasles(&["-e", src], None);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let lines: Vec<&str> = out.stdout.lines().collect();
    assert!(lines.contains(&"T_ab  : SE(3) {a}←{c}"), "{}", out.stdout);
    assert!(
        lines.contains(&"T_ce = inv(T_db) T_de  : SE(3) {c}←{e}"),
        "{}",
        out.stdout
    );
    assert!(lines.contains(&"R  : SO(3)"), "{}", out.stdout);
    assert!(lines.contains(&"[t, 0, 0"), "{}", out.stdout);
}
