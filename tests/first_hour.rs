//! A student's first hour (issue 13, "Help and the REPL" and the output
//! items): labelled tuples, angle units, did-you-mean that points the right
//! way, MATLAB and Python habits, `--exact`, θ = π logs and small hints.

use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
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

fn eval(src: &str) -> String {
    let (code, out, err) = run(&["-e", src]);
    assert_eq!(code, 0, "{src}: {err}");
    out
}

fn json(src: &str) -> Vec<serde_json::Value> {
    let (_, out, _) = run(&["--json", "-e", src]);
    out.lines()
        .map(|l| serde_json::from_str(l).expect("JSON line"))
        .collect()
}

#[test]
fn tuples_print_their_parts_names() {
    let out = eval("screw_params((0, 0, 1, 0, -2, 0.5))");
    assert_eq!(
        out,
        "q = (2, 0, 0)  : 3-vector\ns = (0, 0, 1)  : 3-vector\nh = 0.5\n"
    );
    let out = eval("axis_ang3((0, 0, 2))");
    assert_eq!(out, "w = (0, 0, 1)  : 3-vector\ntheta = 2\n");
    assert!(eval("TransToRp(Trans((1, 2, 3)))").contains("p = (1, 2, 3)"));
    assert!(eval("AxisAng6((0, 0, 2, 1, 0, 0))").contains("theta = 2"));
    // JSON keeps the schema: a plain list, no name.
    let j = json("axis_ang3((0, 0, 2))");
    assert_eq!(j[0]["name"], serde_json::Value::Null);
    assert_eq!(j[0]["value"], serde_json::json!([[0, 0, 1], 2]));
}

#[test]
fn angle_units_and_conversions() {
    let j = json(
        "pi/6 rad\n(pi/6) rad\n2 rad\ndeg2rad(30)\nrad2deg((pi/6, pi/2))\ndeg2rad([90, 180; 0, 45])",
    );
    let x = |i: usize| j[i]["value"].as_f64().unwrap();
    assert!((x(0) - std::f64::consts::FRAC_PI_6).abs() < 1e-15);
    assert!((x(1) - std::f64::consts::FRAC_PI_6).abs() < 1e-15);
    assert_eq!(x(2), 2.0);
    assert!((x(3) - std::f64::consts::FRAC_PI_6).abs() < 1e-15);
    let v: Vec<f64> = j[4]["value"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert!((v[0] - 30.0).abs() < 1e-12 && (v[1] - 90.0).abs() < 1e-12);
    assert_eq!(j[5]["type"], "matrix");
    assert!((j[5]["value"][0][1].as_f64().unwrap() - std::f64::consts::PI).abs() < 1e-15);
}

/// At θ = π the logs follow the book's order (3.58), (3.59), (3.60) — the
/// axis the book's MatrixLog3 gives — and a note says −ω̂ is as valid.
#[test]
fn half_turn_logs_follow_the_book() {
    let (code, out, err) = run(&["--json", "-e", "MatrixLog3(Rot((0.8, 0, -0.6), pi))"]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    let v: Vec<f64> = j["value"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let pi = std::f64::consts::PI;
    // (3.58): ω̂ = (r13, r23, 1 + r33)/√(2(1 + r33)) = (−0.8, 0, 0.6).
    for (x, want) in v.iter().zip([-0.8 * pi, 0.0, 0.6 * pi]) {
        assert!((x - want).abs() < 1e-14, "{v:?}");
    }
    assert!(
        err.contains(
            "note: θ = π: ω̂ is the book's, from (3.58) (§3.2.3.3); −ω̂ is an equally valid answer"
        ),
        "{err}"
    );
    let (_, _, err) = run(&["-e", "log(RpToTrans(Rot((0.6, -0.8, 0), pi), (1, 2, 3)))"]);
    assert!(err.contains("from (3.59)"), "{err}");
    let (_, _, err) = run(&["-e", "log(Rotx(pi))"]);
    assert!(err.contains("from (3.60)"), "{err}");
    let (_, _, err) = run(&["-e", "log(Rotx(3))"]);
    assert!(err.is_empty(), "{err}");
}

#[test]
fn screw_to_axis_normalises_with_a_warning() {
    let (code, out, err) = run(&["-e", "ScrewToAxis((0, 0, 0), (0, 0, 2), 0.5)"]);
    assert_eq!(code, 0);
    assert_eq!(out, "(0, 0, 1, 0, 0, 0.5)  : screw axis\n");
    assert!(
        err.contains(
            "warning: ŝ = (0, 0, 2) is not a unit vector (‖ŝ‖ = 2); normalised to (0, 0, 1)"
        ),
        "{err}"
    );
    let (_, _, err) = run(&["-e", "ScrewToAxis((0, 0, 0), (0, 0, 1), 0.5)"]);
    assert!(err.is_empty(), "{err}");
    let (code, _, err) = run(&["-e", "ScrewToAxis((0, 0, 0), (0, 0, 0), 0.5)"]);
    assert_eq!(code, 1);
    assert!(err.contains("domain error"), "{err}");
}

#[test]
fn exact_on_the_command_line() {
    let (code, out, _) = run(&["--exact", "-e", "pi/6\nsqrt(3)/2\n0.25"]);
    assert_eq!(code, 0);
    assert_eq!(out, "π/6\n√3/2\n1/4\n");
    let (_, help, _) = run(&["--help"]);
    assert!(help.contains("--exact"), "{help}");
}
