//! Issue 22, "the first try should work": each form a student types in the
//! second hour gives the value of its spelled-out equivalent (LANGUAGE.md
//! §§2–4, 8, 9, 12), and the readings that are MATLAB's are errors that
//! name the chasles form.

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};

mod common;
use common::{error, json_lines, run, same, try_json};

const R: &str = "R = Rotz(pi/6) Rotx(pi/4); p = (1, 2, 3); A = [1, 2; 3, 4]; n = 5";

#[test]
fn transpose_before_a_parenthesis() {
    same(R, "[R^T, -R^T (p); 0, 1]", "inv(SE3(R, p))");
    same(R, "R^T(p)", "R.T * p");
    same(R, "R^{T} (p)", "R.T * p");
}

#[test]
fn a_value_before_a_parenthesis_multiplies() {
    same(R, "R (1, 0, 0)", "R * (1, 0, 0)");
    same(R, "A (1, -3)", "A * (1, -3)");
    same(R, "n (n - 1)/2", "10");
    same(R, "2 (n - 1)", "8");
    let e = error(&format!("{R}\nR(1, 2)"));
    assert!(e.contains("R[1, 2]"), "{e}");
    assert!(!e.contains("did you mean"), "{e}");
}

#[test]
fn given_names_are_scalars_without_a_type() {
    same("given α, β", "Rotz(α) Rotz(β) == Rotz(α + β)", "true");
}

#[test]
fn roots_dots_and_crosses() {
    same("", "√2", "sqrt(2)");
    same("", "1/√2", "1/sqrt(2)");
    same("", "3√2/4", "3 sqrt(2)/4");
    same("", "√(1 + 3)", "2");
    same(R, "p · (0, 1, 0)", "dot(p, (0, 1, 0))");
    same("ŵ = (0, 0, 1); v1 = (1, 2, 3)", "ŵ·v1", "3");
    same(R, "p × (0, 0, 1) + p", "cross(p, (0, 0, 1)) + p");
}

#[test]
fn orders_of_numbers() {
    same("", "1 < 2", "true");
    same("", "2 <= 2", "true");
    same("", "3 > 4", "false");
    same("", "3 ≥ 3", "true");
    assert!(try_json("assert pi > 3").is_ok());
    let e = error("assert 3 < 2");
    assert!(e.contains("assert error") && e.contains("left: 3"), "{e}");
    let e = error("(1, 2) < (3, 4)");
    assert!(e.contains("only numbers are ordered"), "{e}");
}

#[test]
fn habits() {
    same("", "diag(1, 2, 3)", "[1, 0, 0; 0, 2, 0; 0, 0, 3]");
    same("", "diag((1, 2))", "[1, 0; 0, 2]");
    same("", "linspace(0, 1, 5)", "0:0.25:1");
    same(R, "frame(R, p)", "SE3(R, p)");
    same("", "Trans(2, 2, 0)", "Trans((2, 2, 0))");
}

#[test]
fn nested_comprehensions_as_python_writes_them() {
    same(
        "",
        "[a + 10 b for a in 1:2 for b in 1:3]",
        "[a + 10 b for a in 1:2, b in 1:3]",
    );
}

#[test]
fn ranges_and_end_index() {
    let setup = "S = (0, 0, 1, 3, 0, 0); T = SE3(Rotz(1), (1, 2, 3)); v = (4, 5, 6)";
    same(setup, "S[1:3]", "S.w");
    same(setup, "S[4:6]", "S.v");
    same(setup, "T[1:3, 4]", "T.p");
    same(setup, "T[1:3, 1:3]", "T.R");
    same(setup, "v[end]", "6");
    same(setup, "v[end - 1]", "5");
    same(setup, "v[2:end]", "(5, 6)");
    let e = error(&format!("{setup}\nv[2:4]"));
    assert!(e.contains("index 4 is outside 1..3"), "{e}");
}

#[test]
fn mechanisms_with_names_commas_and_contacts() {
    same("N = 4", "mech < links N; joints R, R, R, R; planar >", "1");
    same("n = 6", "mech < legs n UPS; spatial >", "6");
    same("k = 3", "mech < links k + 1; joints (k)R; planar >", "3");
    // Counts multiply side by side, as the README writes `links 2 n + 1`.
    same(
        "n = 3",
        "mech < links 2 n + 1; joints (2 n)R; planar >",
        "6",
    );
    same("n = 3", "mech < legs 2 n UPS; spatial >", "6");
    same(
        "n = 3",
        "mech < links n (n - 1) + 1; joints (n (n - 1)) R; planar >",
        "6",
    );
    // A bare name before a joint is refused, showing the one spelling.
    for (src, fix) in [
        (
            "n = 2
mech < links n; joints n R; planar >",
            "`(n)R`",
        ),
        (
            "n = 2
mech < links 5; joints 2 n R; planar >",
            "`(2 n)R`",
        ),
        (
            "n = 2
mech < links 3; joints n sliding; planar >",
            "`(n) sliding`",
        ),
    ] {
        let e = error(src);
        assert!(
            e.contains("a joint count given by a name is written in parentheses")
                && e.contains(fix),
            "{src}: {e}"
        );
        assert!(!e.contains("unknown joint letter"), "{e}");
    }
    // Exercise 2.18: a caterpillar of 8 links and 7 RP pairs; six sliding
    // point contacts with the leaf (planar f = 2).
    same("", "mech < links 8; joints 7RP; planar >", "14");
    same("", "mech < links 8; joints 7RP, 6 sliding; planar >", "8");
    // Exercise 2.19: spatial contacts, sliding f = 5 and rolling f = 3.
    same("", "mech < links 14; joints 4U 8R sliding; spatial >", "21");
    same(
        "",
        "mech < links 14; joints 4U 8R 4 rolling; spatial >",
        "10",
    );
    same("", "mech < links 3; joints 2R rolling; planar >", "0");
    let lines = try_json("mech < links 8; joints 7RP, 6 sliding; planar >").expect("runs");
    let formula = lines[0]["value"]["formula"].as_str().unwrap_or_default();
    assert_eq!(formula, "dof = 3(8 − 1 − 13) + 7·2 + 6·2 = 8");
}

#[test]
fn near_the_domain_clamps_beyond_it_fails() {
    // (floats with no exact form: exp(0) has none, clamped within 1e-12;
    // a number as typed is exact, clamped within 4 units in the last place)
    same("", "acos(exp(0) + 2e-16)", "0");
    same("", "sqrt(exp(0) - 1 - 2e-16)", "0");
    same("", "asin(-exp(0) - 1e-15)", "-pi/2");
    let e = error("acos(1.001)");
    assert!(e.contains("acos(1.001)"), "{e}");
    // a typed number a few units in the last place out is the edge
    // (issue 36; it was a domain error), beyond that it is refused
    same("", "acos(1 + 2e-16)", "0");
    let e = error("acos(1 + 2e-15)");
    assert!(e.contains("must be in [−1, 1]"), "{e}");
}

#[test]
fn an_error_in_a_function_shows_the_call() {
    let e = error("f(x) = sqrt(x - 3)\ny = 1\nf(2)");
    assert!(e.contains("t.chs:1:13"), "{e}");
    assert!(
        e.contains("3 │ f(2)") && e.contains("in this call of f"),
        "{e}"
    );
}

#[test]
fn an_error_in_a_function_is_the_calling_statements_json_object() {
    // one JSON object per statement (§1): the error of `f(2)` on line 3 is
    // line 3's, at the call, not line 1's (the definition, which held)
    let (code, out, _) = run(&["--json", "-e", "f(x) = sqrt(x - 3)\ny = 1\nf(2)"]);
    assert_eq!(code, 1);
    let lines = json_lines(&out);
    let e = lines.last().expect("an error");
    assert_eq!(
        (&e["line"], &e["error"]["col"]),
        (&3.into(), &1.into()),
        "{out}"
    );
    assert_eq!(e["error"]["kind"], "domain");
    // through two functions, and in check as in run
    let src = "T_ab = Trans((1, 0, 0))\nT_cb = Trans((0, 1, 0))\ng(X, Y) = X * Y\nh(X) = g(X, T_cb)\n\nh(T_ab)\n";
    let path = common::scratch("function_error_line").join("f.chs");
    std::fs::write(&path, src).unwrap();
    for cmd in ["run", "check"] {
        let (_, out, _) = run(&[cmd, "--json", path.to_str().unwrap()]);
        let e = json_lines(&out).pop().expect("an error");
        assert_eq!(
            (&e["line"], &e["error"]["kind"]),
            (&6.into(), &"frame".into()),
            "{cmd}: {out}"
        );
    }
}

#[test]
fn a_list_of_points_draws() {
    let lines = try_json("pts = [point((k, 0, 0)) for k in 1:3]").expect("runs");
    assert_eq!(lines[0]["type"], "list");
    let mut s = Session::new(Settings::default());
    let (out, err, n) = s.run_to_strings(
        "t.chs",
        "pts = [point((k, 0, 0)) for k in 1:3]\nlen(pts)",
        Mode::Run,
        false,
    );
    assert_eq!(n, 0, "{err}");
    assert!(out.contains("picture: point (1, 0, 0)"), "{out}");
    assert!(out.contains("list of 3 pictures"), "{out}");
}

/// `q` before it has a value, as the book's point on a screw axis: the
/// help said "a script ends at its last line" (the habit of typing q to
/// quit), which misleads inside `ScrewToAxis(q, s, h)`.
#[test]
fn an_unknown_q_is_a_point_to_give_not_a_quit() {
    let e = error("S = ScrewToAxis(q, (0, 0, 1), 2)");
    assert!(
        e.contains("unknown name 'q'") && e.contains("given q : vec3"),
        "{e}"
    );
    assert!(!e.contains("script ends"), "{e}");
}
