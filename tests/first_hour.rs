//! A student's first hour (issue 13, "Help and the REPL" and the output
//! items): labelled tuples, angle units, did-you-mean that points the right
//! way, MATLAB and Python habits, `--exact`, θ = π logs and small hints.

mod common;
use common::{json_lines, run};

fn eval(src: &str) -> String {
    let (code, out, err) = run(&["-e", src]);
    assert_eq!(code, 0, "{src}: {err}");
    out
}

/// The `--json` lines of `chasles --json -e SRC`.
fn json(src: &str) -> Vec<serde_json::Value> {
    json_lines(&run(&["--json", "-e", src]).1)
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
    // 0.25 as typed is a decimal and prints as one (LANGUAGE.md §10)
    assert_eq!(out, "π/6\n√3/2\n0.25\n");
    // Floats with no exact form print the simple form they are a rounding
    // of (LANGUAGE.md §1), after `≈ `: the floats alone cannot say it is
    // the value; a float of none, and a short decimal, print as decimals.
    let floats = "MatrixLog3(Rotz(pi/3))\ncos(0.5235987755982988)\nsin(1)\neuler_zyx(Rotz(0.3))\nquat(Rotz(pi/2))";
    let (code, out, _) = run(&["--exact", "-e", floats]);
    assert_eq!(code, 0);
    assert_eq!(
        out,
        "≈ (0, 0, π/3)  : 3-vector\n≈ √3/2\n0.8415\n(0.3, 0, 0)  : 3-vector\n≈ (1/√2, 0, 0, 1/√2)  : 4-vector\n"
    );
    let (_, out, _) = run(&["-e", floats]);
    assert!(out.starts_with("(0, 0, 1.0472)"), "{out}");
    let (_, help, _) = run(&["--help"]);
    assert!(help.contains("--exact"), "{help}");
}

mod repl {
    use chasles::repl::commands::execute;
    use chasles::session::{Session, Settings};

    #[test]
    fn help_exit_and_quit_without_the_colon() {
        let mut s = Session::new(Settings::default());
        assert!(execute(&mut s, "help").out.contains("commands:"));
        assert!(execute(&mut s, "help Ad").out.starts_with("Adjoint("));
        assert!(execute(&mut s, "help(Ad)").out.starts_with("Adjoint("));
        assert!(execute(&mut s, "quit").quit);
        assert!(execute(&mut s, "exit").quit);
        assert!(execute(&mut s, "exit()").quit);
        // A bound name is a value, not a command.
        execute(&mut s, "help = 3");
        assert_eq!(execute(&mut s, "help").out, "3\n");
    }

    /// Odd inputs near the new commands never panic and answer something.
    #[test]
    fn odd_inputs_answer() {
        let mut s = Session::new(Settings::default());
        for input in [
            "help(",
            "help()",
            "help(())",
            "exit(1)",
            "quit 2",
            ":save!",
            ":save! ",
            ":history x",
            ":save /",
            ":save .",
            "help help",
            "help = ",
            "assert",
            "assert ==",
            "1 ==",
            "≈ 1",
            "1 ~= ",
            "~=",
            "a == b == c",
            "round(1, 99)",
            "deg2rad()",
            "rad2deg(mech < links 2; planar >)",
        ] {
            let r = execute(&mut s, input);
            assert!(
                !(r.out.is_empty() && r.err.is_empty() && !r.quit),
                "{input:?} says nothing"
            );
        }
    }

    #[test]
    fn save_writes_a_script_that_reruns_to_the_same_results() {
        let dir = std::env::temp_dir().join(format!("chasles-save-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("session.chs");
        let name = file.display().to_string();
        let mut s = Session::new(Settings::default());
        let mut printed = String::new();
        for input in [
            "T_sb = RpToTrans(Rotz(30 deg), (1, 2, 0))",
            "T_sc = T_sb * T_zz",
            "T_bc = Trans((0, 0, 1)); T_sc = T_sb * T_bc",
            "M = [1, 2\n3, 4]",
            "inv(",
            "M * 2",
            "ans",
            "given t : scalar",
            "f(x) = x^2 + 1",
            "f(3)",
        ] {
            printed.push_str(&execute(&mut s, input).out);
        }
        let hist = execute(&mut s, ":history").out;
        assert!(hist.starts_with("1  T_sb = RpToTrans"), "{hist}");
        assert!(!hist.contains("T_zz") && !hist.contains("inv("), "{hist}");
        assert!(hist.contains("4  M = [1, 2\n   3, 4]"), "{hist}");

        let r = execute(&mut s, &format!(":save {name}"));
        assert_eq!(r.out, format!("saved 9 statements to {name}\n"), "{r:?}");
        let rerun = std::process::Command::new(env!("CARGO_BIN_EXE_chasles"))
            .args(["run", &name])
            .output()
            .unwrap();
        assert!(rerun.status.success());
        assert_eq!(String::from_utf8_lossy(&rerun.stdout), printed);

        // An existing file is kept unless :save! is used.
        execute(&mut s, "x = 1");
        let r = execute(&mut s, &format!(":save {name}"));
        assert!(r.err.contains("exists; :save! "), "{r:?}");
        assert!(!std::fs::read_to_string(&file).unwrap().contains("x = 1"));
        let r = execute(&mut s, &format!(":save! {name}"));
        assert!(r.err.is_empty(), "{r:?}");
        assert!(std::fs::read_to_string(&file).unwrap().ends_with("x = 1\n"));
        // No temporary file is left beside it.
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
        assert!(!execute(&mut s, ":save").err.is_empty());
        // The header reruns with the session's settings.
        execute(&mut s, ":digits 6");
        execute(&mut s, ":exact on");
        execute(&mut s, ":frames warn");
        execute(&mut s, &format!(":save! {name}"));
        let head = std::fs::read_to_string(&file).unwrap();
        assert!(
            head.starts_with("# saved from the chasles REPL; rerun with: chasles run --frames warn --digits 6 --exact FILE\n"),
            "{head}"
        );
        execute(&mut s, ":reset");
        assert!(execute(&mut s, ":history").out.starts_with("no statements"));
        std::fs::remove_dir_all(&dir).ok();
    }
}

/// Did-you-mean names what does what was asked; habits get the chasles way.
#[test]
fn hints_point_the_right_way() {
    for (src, want) in [
        ("RotToQuat(Rotz(1))", "did you mean quat(R)?"),
        ("quat2rotm((1, 0, 0, 0))", "did you mean rot_quat(q)?"),
        ("rotm2eul(Rotz(1))", "did you mean euler_zyx(R)?"),
        ("sind(30)", "write sin(30 deg)"),
        ("syms t1 t2", "given t1, t2 : scalar"),
        ("format long", ":digits N"),
        (
            "np.array([1, 2])",
            "no `np` prefix: write the array directly",
        ),
        ("quit", ":quit"),
        ("exit", ":quit"),
        ("help", ":help NAME"),
        ("import numpy as np", "nothing to import"),
    ] {
        let (code, _, err) = run(&["-e", src]);
        assert_eq!(code, 1, "{src}");
        let help = err
            .lines()
            .find(|l| l.trim_start().starts_with("= help:"))
            .unwrap_or_default();
        assert!(help.contains(want), "{src}: {err}");
    }
}

/// `:help` cites the seed's numbering, and every keyword, unit and command
/// has help (LANGUAGE.md §11).
#[test]
fn help_for_everything() {
    use chasles::repl::commands::{COMMANDS, execute};
    use chasles::session::{Session, Settings};
    let mut s = Session::new(Settings::default());
    let mut help = |w: &str| {
        let r = execute(&mut s, &format!(":help {w}"));
        assert!(r.err.is_empty(), ":help {w}: {}", r.err);
        r.out
    };
    assert!(help("Ad").contains("Definition 3.6"));
    assert!(help("MatrixExp6").contains("Proposition 3.16"));
    assert!(help("RotInv").contains("Prop. 3.1"));
    assert!(help("exp").contains("Prop. 3.16"));
    for w in [
        "deg", "°", "rad", "mech", "given", "ans", "derive", "assert", "==", "≈", "~=", "pi", "π",
        "e", "inf", "I", "true", "false", "^T", "^-1",
    ] {
        assert!(!help(w).trim().is_empty(), "{w}");
    }
    for c in COMMANDS {
        assert!(!help(c.name).trim().is_empty(), "{}", c.name);
        assert!(help(&format!(":{}", c.name)).starts_with(':'), "{}", c.name);
    }
    assert!(help("deg").contains("Rotz(30 deg)"));
    assert!(help(":save!").starts_with(":save FILE"));
    let r = execute(&mut Session::new(Settings::default()), ":help RotToQuat");
    assert!(r.err.contains("did you mean quat(R)?"), "{}", r.err);
    assert!(help("").contains("words:  :help given"));
}

/// A label only when the value is in the set (issue 13): [ω]ᵀ = −[ω] is
/// still skew-symmetric, so it stays so(3), with numbers and with
/// symbols; [V]ᵀ is not se(3).
#[test]
fn the_transpose_of_so3_is_so3() {
    let j = json("w = (1, 2, 3)\n[w]^T\n[w].T + [w]\n[(1, 2, 3, 4, 5, 6)]^T");
    assert_eq!(j[1]["type"], "so3");
    assert_eq!(
        j[1]["value"],
        serde_json::json!([[0, 3, -2], [-3, 0, 1], [2, -1, 0]])
    );
    assert_eq!(j[2]["type"], "so3");
    assert_eq!(
        j[2]["value"],
        serde_json::json!([[0, 0, 0], [0, 0, 0], [0, 0, 0]])
    );
    assert_eq!(j[3]["type"], "matrix");
    let out = eval("given t : scalar; [(0, 0, t)]^T");
    assert!(out.ends_with(": so(3)\n"), "{out}");
}
