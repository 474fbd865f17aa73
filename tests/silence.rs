//! Silence (LANGUAGE.md §§1, 3): a statement ended by `;` runs and binds
//! but prints nothing, as in MATLAB and Julia; `--quiet` prints only
//! errors, warnings and failed asserts. Errors and warnings always print,
//! in text and in `--json`, from `run`, `-e`, stdin, the REPL's session and
//! the notebook kernel.

mod common;
use common::{chasles, json_lines, run_in, scratch};

use chasles::kernel::cell::{Notebook, Output};
use chasles::session::Session;

#[test]
fn a_semicolon_silences_its_statement_only() {
    let out = chasles(&["-e", "R = Rotz(pi/2); p = R * (1, 0, 0)"], None);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    // R was bound (p is its product) but only p printed: R (1, 0, 0) = (0, 1, 0).
    assert_eq!(out.stdout, "p = (0, 1, 0)  : 3-vector\n");
    assert_eq!(out.stderr, "");
}

#[test]
fn a_trailing_semicolon_silences_the_last_statement_too() {
    // Blanks and a comment after the `;`; a `;` inside brackets separates
    // rows and inside a comment is text.
    let src = "x = 2 ;  # x; shown?\ny = [1, 2; 3, 4]\nz = x + 1;\nx * 10 # no; end\n";
    let out = chasles(&["-e", src], None);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert_eq!(out.stdout, "y = [1, 2\n     3, 4]  : 2×2 matrix\n20\n");
}

#[test]
fn json_has_no_object_for_a_silent_statement_and_keeps_errors() {
    let src = "a = 3;\nb = a + 1\nc = a * 2; d = nope;\n";
    let out = chasles(&["--json", "--keep-going", "-e", src], None);
    assert_eq!(out.code, Some(1));
    let lines = json_lines(&out.stdout);
    assert_eq!(lines.len(), 2, "{}", out.stdout);
    assert_eq!(lines[0]["name"], "b");
    assert_eq!(lines[0]["value"], 4);
    // The silenced statement's error is still an object.
    assert_eq!(lines[1]["line"], 3);
    assert_eq!(lines[1]["error"]["kind"], "name");
}

#[test]
fn a_silent_number_that_is_not_finite_still_warns_and_is_bound() {
    // A silenced number moves into its binding (nothing shows it): the
    // warning of its inf and NaN entries is still given, once, at its
    // statement, and the name holds the value.
    let src = "x = 1e308 * 10;\ny = (1, inf - inf, 3);\nx\ny[2]\n";
    let out = chasles(&["-e", src], None);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert_eq!(out.stdout, "inf\nNaN\n");
    assert_eq!(
        out.stderr
            .matches("warning: the result is infinite")
            .count(),
        2,
        "{}",
        out.stderr
    );
    assert_eq!(
        out.stderr.matches("warning: the result has NaN").count(),
        2,
        "{}",
        out.stderr
    );
    assert!(out.stderr.contains("1 │ x = 1e308 * 10;"), "{}", out.stderr);
    assert!(
        out.stderr.contains("2 │ y = (1, inf - inf, 3);"),
        "{}",
        out.stderr
    );
    // (in JSON, the silent statements' warnings are objects of their own)
    let out = chasles(&["--json", "-e", "x = 1e308 * 10;"], None);
    let lines = json_lines(&out.stdout);
    assert_eq!(lines.len(), 1, "{}", out.stdout);
    assert_eq!(lines[0]["line"], 1, "{}", out.stdout);
}

#[test]
fn warnings_and_errors_of_a_silent_statement_print() {
    // 1.001 is within 1e-2 of SO(3): bound projected, with a warning.
    let out = chasles(
        &["-e", "R_sb = [1, 0, 0; 0, 1, 0; 0, 0, 1.001]; R_sb[3, 3]"],
        None,
    );
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert_eq!(out.stdout, "1\n");
    assert!(
        out.stderr.contains("warning: R_sb names a rotation matrix"),
        "{}",
        out.stderr
    );
    let out = chasles(&["-e", "x = 1;\ny = T_ab * 2;\nz = 3;"], None);
    assert_eq!(out.code, Some(1));
    assert_eq!(out.stdout, "");
    assert!(
        out.stderr.contains("<-e>:2:5: name error"),
        "{}",
        out.stderr
    );
}

#[test]
fn quiet_prints_only_errors_warnings_and_failed_asserts() {
    let src = "x = Rotz(1)\nassert det(x) ≈ 1\ny = x * (1, 0, 0)\nassert y[1] == 2\nz = 5\n";
    let out = chasles(&["--quiet", "--keep-going", "-e", src], None);
    assert_eq!(out.code, Some(1));
    assert_eq!(out.stdout, "");
    // The failed assert, with its two sides: y[1] = cos 1 = 0.5403.
    assert!(
        out.stderr.contains("<-e>:4:8: assert error"),
        "{}",
        out.stderr
    );
    assert!(out.stderr.contains("left = 0.5403"), "{}", out.stderr);
    // A passing run says nothing at all.
    let ok = chasles(&["--quiet", "-e", "x = Rotz(1)\ndet(x)"], None);
    assert_eq!(
        (ok.code, ok.stdout.as_str(), ok.stderr.as_str()),
        (Some(0), "", "")
    );
    // JSON: only the error's object.
    let json = chasles(&["--quiet", "--json", "--keep-going", "-e", src], None);
    let lines = json_lines(&json.stdout);
    assert_eq!(lines.len(), 1, "{}", json.stdout);
    assert_eq!(lines[0]["line"], 4);
    assert_eq!(lines[0]["error"]["kind"], "assert");
    // Warnings still print under --quiet.
    let w = chasles(
        &["--quiet", "-e", "R_sb = [1, 0, 0; 0, 1, 0; 0, 0, 1.001]"],
        None,
    );
    assert_eq!(w.stdout, "");
    assert!(
        w.stderr.contains("warning: R_sb names a rotation matrix"),
        "{}",
        w.stderr
    );
    // From stdin and from a file too.
    let piped = chasles(&["--quiet"], Some(b"x = 1\ny = x + 1\n"));
    assert_eq!((piped.code, piped.stdout.as_str()), (Some(0), ""));
    let dir = scratch("quiet-run");
    std::fs::write(dir.join("s.chs"), "x = 1\nx + 1\n").expect("written");
    let (code, stdout, _) = run_in(&["run", "--quiet", "s.chs"], &dir);
    assert_eq!((code, stdout.as_str()), (0, ""));
    let (_, loud, _) = run_in(&["run", "s.chs"], &dir);
    assert_eq!(loud, "x = 1\n2\n");
}

#[test]
fn a_silent_save_writes_and_a_silent_picture_is_not_printed() {
    let dir = scratch("silent-pictures");
    let src = "pic = draw(Rotz(1));\nsave(pic, \"kept.svg\");\ndraw(Rotz(2));\n";
    let (code, stdout, stderr) = run_in(&["-e", src], &dir);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(stdout, "");
    assert!(dir.join("kept.svg").is_file());
    // Printed, a picture is written to NAME.svg; silenced, it is not.
    assert!(!dir.join("pic.svg").exists());
    assert!(!dir.join("draw-3.svg").exists());
}

#[test]
fn quiet_is_a_semicolon_on_every_statement() {
    // A picture only printed is not written; one `save` names is.
    let dir = scratch("quiet-pictures");
    let src = "pic = draw(Rotz(1))\nsave(pic, \"kept.svg\")\n";
    let (code, stdout, stderr) = run_in(&["--quiet", "-e", src], &dir);
    assert_eq!((code, stdout.as_str()), (0, ""), "{stderr}");
    assert!(dir.join("kept.svg").is_file());
    assert!(!dir.join("pic.svg").exists());
    let (_, loud, _) = run_in(&["-e", src], &dir);
    assert!(loud.contains("pic.svg"), "{loud}");
    assert!(dir.join("pic.svg").is_file());
}

#[test]
fn check_mode_silences_too() {
    let out = chasles(
        &["check", "--json", "-"],
        Some(b"T_ab = Trans((1, 0, 0));\nT_ab\n"),
    );
    let lines = json_lines(&out.stdout);
    assert_eq!(lines.len(), 1, "{}", out.stdout);
    assert_eq!(lines[0]["line"], 2);
    assert_eq!(lines[0]["type"], "SE3");
}

#[test]
fn the_repl_session_silences_and_save_keeps_the_semicolon() {
    let mut s = Session::default();
    let (out, err, n) = chasles::repl::save::run_recording(&mut s, "<repl>", "a = 2; b = a * 3");
    assert_eq!((out.as_str(), err.as_str(), n), ("b = 6\n", "", 0));
    assert_eq!(
        s.accepted,
        vec!["a = 2;".to_string(), "b = a * 3".to_string()]
    );
    // The saved script reruns to the same output.
    let again = s.accepted.join("\n");
    let mut fresh = Session::default();
    let (rerun, _, _) = chasles::repl::save::run_recording(&mut fresh, "<repl>", &again);
    assert_eq!(rerun, out);
}

#[test]
fn a_notebook_line_ended_by_semicolon_displays_nothing() {
    let mut nb = Notebook::new();
    let mut shown = Vec::new();
    nb.execute("R = Rotz(pi);\nx = R[1, 1]", true, &mut |o| shown.push(o))
        .expect("the cell runs");
    let values: Vec<_> = shown
        .iter()
        .filter_map(|o| match o {
            Output::Data(d) => d.get("text/plain").cloned(),
            _ => None,
        })
        .collect();
    assert_eq!(values, vec![serde_json::json!("x = -1")]);
    let mut quiet = Vec::new();
    nb.execute("y = x * 2;", true, &mut |o| quiet.push(o))
        .expect("the cell runs");
    assert!(quiet.is_empty(), "{quiet:?}");
    assert!(nb.session.env.get("y").is_some());
}

#[test]
fn every_reading_of_a_statement_marks_its_semicolon() {
    use chasles::syntax::parse_program;
    // The fast path from the source; the splitter's (a newline inside
    // parentheses); pest's (a string, nested deeper than the fast path
    // takes); a comment holding `;`; the last statement with no newline.
    let deep = format!("{}1{}", "(".repeat(20), ")".repeat(20));
    let src = format!(
        "a = 1;\nb = (1,\n 2) ;\nc = 3 # not; silent\nsave(draw(Rotz(1)), \"x;y.svg\");\nd = {deep};\ne = {deep}\nf = 2;"
    );
    let silent: Vec<bool> = parse_program(&src)
        .into_iter()
        .map(|s| s.expect("parses").silent)
        .collect();
    assert_eq!(silent, [true, true, false, true, true, false, true]);
}
