//! The REPL without a terminal: a piped session through the real binary,
//! and every `:` command, completion and hint through the library.

use std::io::Write;
use std::process::Stdio;

use chasles::repl::commands::{Reply, execute};
use chasles::repl::complete::{complete, hint, open_call_signature, preview};
use chasles::session::{Session, Settings};

mod common;
use common::{command, report};

/// Runs one input and renders the reply for a snapshot.
fn show(session: &mut Session, input: &str) -> String {
    let Reply { out, err, quit } = execute(session, input);
    let mut s = format!(">>> {input}\n{out}");
    if !err.is_empty() {
        s.push_str("--- stderr\n");
        s.push_str(&err);
    }
    if quit {
        s.push_str("--- quit\n");
    }
    s
}

/// Runs inputs in order in one fresh session.
fn transcript(inputs: &[&str]) -> String {
    let mut session = Session::new(Settings::default());
    inputs.iter().map(|i| show(&mut session, i)).collect()
}

#[test]
fn piped_session() {
    let history =
        std::env::temp_dir().join(format!("chasles-piped-history-{}", std::process::id()));
    let mut child = command(&[])
        .env("CHASLES_HISTORY", &history)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the chasles binary runs");
    let input = "\
# a session piped in: no prompts, no : commands needed
T = [1, 0, 0, 1
     0, 1, 0, 2
     0, 0, 1, 3
     0, 0, 0, 1]
R_sb = Rotz(pi/2)
R_sb * (1, 0, 0)
ans[2]
T * T_cb
";
    child
        .stdin
        .take()
        .expect("stdin is piped")
        .write_all(input.as_bytes())
        .expect("the input is written");
    let out = child.wait_with_output().expect("the binary finishes");
    let text = report(&out);
    insta::assert_snapshot!(text);
    assert!(!history.exists(), "history is only written on a terminal");
}

#[test]
fn errors_keep_bindings() {
    let mut s = Session::new(Settings::default());
    let before = execute(&mut s, "T_ab = Trans((1, 2, 3))").out;
    for bad in [
        "T_ab * T_cb",
        "inv(",
        "T_ab = Rotz(1) * T_cd",
        "x = 1; y = T_ab * T_ab",
    ] {
        let r = execute(&mut s, bad);
        assert!(!r.err.is_empty(), "{bad} should fail");
    }
    // `x = 1` ran before the error in the same input and stays bound.
    assert_eq!(execute(&mut s, "x").out, "1\n");
    assert!(execute(&mut s, "y").err.contains("unknown name"));
    let again = execute(&mut s, "T_ab = T_ab").out;
    assert_eq!(again, before);
}

/// An error or warning from the body of a function typed in an earlier
/// input is shown at the call in this one: the body's offsets point into
/// the earlier input, and read in this one they put the caret under the
/// second `+` of `0 + 0 + f(1)` (column 10) with no call in sight.
#[test]
fn errors_in_a_function_typed_earlier_point_at_the_call() {
    let mut s = Session::new(Settings::default());
    execute(&mut s, "f(t) = t + (1, 2)");
    let err = execute(&mut s, "y = 0 + 0 + f(1)").err;
    assert!(err.starts_with("<input>:1:13: type error"), "{err}");
    assert!(
        err.contains("^^^^ in the body of f, defined in an earlier input"),
        "{err}"
    );
    execute(&mut s, ":frames warn");
    execute(&mut s, "g(A, B) = A * B");
    execute(&mut s, "R_ab = Rotz(1); R_cd = Rotz(1)");
    let r = execute(&mut s, "x = 1 + 2 + 3; g(R_ab, R_cd)");
    assert!(
        r.err
            .contains("<input>:1:16: warning: frames do not cancel"),
        "{}",
        r.err
    );
    // Defined and called in one input, the body is shown with the call.
    let err = execute(&mut s, "h(t) = t + (1, 2); h(1)").err;
    assert!(err.contains("<input>:1:10: type error"), "{err}");
    assert!(err.contains("in this call of h"), "{err}");
}

/// Lines pasted at once with `:` commands among them run piece by piece,
/// as a notebook cell does (the whole paste was one syntax error at the
/// `:`), stopping at the first error with its line in the paste.
#[test]
fn a_pasted_input_runs_its_commands() {
    let mut s = Session::new(Settings::default());
    let r = execute(&mut s, "x = 7\n:digits 2\npi\ny = nope\nz = 1\n");
    assert_eq!(r.out, "x = 7\ndigits: 2\n3.14\n");
    assert!(
        r.err
            .starts_with("<input>:4:5: name error: unknown name 'nope'"),
        "{}",
        r.err
    );
    assert!(execute(&mut s, "z").err.contains("unknown name 'z'"));
    let r = execute(&mut s, ":digits 3\n:quit\nw = 1");
    assert_eq!((r.out.as_str(), r.quit), ("digits: 3\n", true));
    assert!(execute(&mut s, "w").err.contains("unknown name 'w'"));
}

#[test]
fn help_overview_and_topics() {
    insta::assert_snapshot!(transcript(&[":help", ":help frames", ":help mechanisms"]));
}

#[test]
fn help_for_functions() {
    insta::assert_snapshot!(transcript(&[
        ":help MatrixLog6",
        ":help Ad",
        ":help matrix_exp3",
        ":help sin",
        ":help matrixlog",
        ":help qqqqqq",
        ":help :load",
    ]));
}

#[test]
fn every_builtin_example_runs() {
    let settings = Settings::default();
    for b in chasles::builtins::table() {
        let text = chasles::repl::help::function(b, &settings);
        assert!(text.starts_with(b.signature), "{}", b.name);
        let mut s = Session::new(settings);
        let r = execute(&mut s, b.example);
        assert!(r.err.is_empty(), "example of {}: {}", b.name, r.err);
    }
}

#[test]
fn vars_and_frames() {
    insta::assert_snapshot!(transcript(&[
        ":vars",
        ":frames",
        "T_sb = Trans((1, 0, 0))",
        "T_bc = SE3(Rotz(pi/2), (0, 1, 0))",
        "R_de = Roty(pi/4)",
        "given T_ef : SE3",
        "V_b = twist((0, 0, 1), (1, 0, 0))",
        "theta = 30 deg",
        "f(x) = 2 x",
        "T_sb * T_bc",
        ":vars",
        ":frames",
        ":frames warn",
        "T_sb * T_ef",
        ":frames off",
        ":frames loose",
        ":frames",
    ]));
}

#[test]
fn digits_exact_reset_quit() {
    insta::assert_snapshot!(transcript(&[
        "x = Rotz(pi/6)",
        ":digits",
        ":digits 2",
        "x",
        ":digits 99",
        ":digits two",
        ":exact",
        "x",
        "(pi/4, -pi/2, 2 pi / 3, sqrt(2), 1/sqrt(2), 0.1234)",
        ":exact",
        "x",
        ":exact on",
        ":exact maybe",
        ":reset",
        ":vars",
        "x",
        ":quit",
    ]));
}

#[test]
fn unknown_commands_suggest() {
    insta::assert_snapshot!(transcript(&[":hepl", ":var", ":dig 3", ":xyz", ":"]));
}

#[test]
fn load_scripts() {
    let dir = std::env::temp_dir().join(format!("chasles-repl-load-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let good = dir.join("good.chs");
    let bad = dir.join("bad.chs");
    let binary = dir.join("binary.chs");
    std::fs::write(&good, "T_ab = Trans((1, 2, 3))\nR_bc = Rotx(pi)\n").expect("write");
    std::fs::write(&bad, "p_a = (1, 2, 3)\nq = p_a * T_zz\nr = 5\n").expect("write");
    std::fs::write(&binary, [0xff, 0xfe, 0x00]).expect("write");
    let mut s = Session::new(Settings::default());
    let r = execute(&mut s, &format!(":load {}", good.display()));
    assert!(r.out.contains("loaded"), "{r:?}");
    assert!(r.err.is_empty(), "{r:?}");
    assert!(
        execute(&mut s, ":vars")
            .out
            .contains("T_ab : SE(3) {a}←{b}")
    );
    let r = execute(&mut s, &format!(":load {}", bad.display()));
    assert!(r.err.contains("unknown name 'T_zz'"), "{r:?}");
    assert!(r.err.contains("stopped at the error"), "{r:?}");
    let vars = execute(&mut s, ":vars").out;
    assert!(vars.contains("p_a") && !vars.contains("r :"), "{vars}");
    for missing in [
        dir.join("missing.chs").display().to_string(),
        dir.display().to_string(),
        binary.display().to_string(),
        String::new(),
    ] {
        let r = execute(&mut s, &format!(":load {missing}"));
        assert!(r.out.is_empty() && !r.err.is_empty(), "{missing}: {r:?}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn completion_candidates() {
    let mut s = Session::new(Settings::default());
    execute(&mut s, "T_sb = Trans((1, 2, 3))");
    execute(&mut s, "T_sc = Trans((0, 0, 1))");
    let names = |line: &str| {
        let (start, cands) = complete(&s, line, line.len());
        let shown: Vec<String> = cands
            .iter()
            .map(|c| format!("{} | {}", c.replacement, c.display))
            .collect();
        format!("{line:?} @{start}\n  {}\n", shown.join("\n  "))
    };
    let all: String = [
        "MatrixLo",
        "x = matrix_ex",
        "T_s",
        "inv(T_sc) * T_",
        "gi",
        "[k^2 fo",
        ":",
        ":fr",
        "  :he",
        ":help MatrixE",
        ":frames w",
        ":exact o",
        "2",
        "",
        "(",
    ]
    .iter()
    .map(|l| names(l))
    .collect();
    insta::assert_snapshot!(all);
}

#[test]
fn load_completes_file_names() {
    let s = Session::new(Settings::default());
    let (start, cands) = complete(&s, ":load examples/ch3_ex3_2", 24);
    assert_eq!(start, ":load examples/".len());
    assert!(
        cands
            .iter()
            .any(|c| c.replacement == "ch3_ex3_2_camera.chs"),
        "{cands:?}"
    );
    let (_, cands) = complete(&s, ":load exam", 10);
    assert!(
        cands.iter().any(|c| c.replacement == "examples/"),
        "{cands:?}"
    );
}

#[test]
fn completion_never_panics_on_odd_positions() {
    let s = Session::new(Settings::default());
    for line in ["θ_1 = 2", "ω", ":help ω", "Rot(", "é"] {
        for pos in 0..=line.len() + 2 {
            let _ = complete(&s, line, pos);
            let _ = hint(&s, line, pos);
        }
    }
}

#[test]
fn hints() {
    let mut s = Session::new(Settings::default());
    execute(&mut s, "T = Trans((1, 2, 3))");
    execute(&mut s, "f(x) = x + 1");
    assert_eq!(
        open_call_signature("MatrixLog6("),
        chasles::builtins::lookup("MatrixLog6").map(|b| b.signature)
    );
    assert_eq!(
        hint(&s, "MatrixLog6(T", 12).as_deref(),
        Some("  MatrixLog6(T: SE3) -> 6-vector")
    );
    // the innermost open call wins; a closed call gives way to the preview
    assert!(hint(&s, "inv(Rotz(", 9).is_some_and(|h| h.contains("Rotz(theta")));
    assert!(open_call_signature("inv(Rotz(1)").is_some_and(|h| h.starts_with("inv(")));
    assert_eq!(
        hint(&s, "MatrixLog6(T)", 13).as_deref(),
        Some("  ⇒ (0, 0, 0, 1, 2, 3)  : 6-vector")
    );
    assert_eq!(
        preview(&s, "Rotz(pi/2)").as_deref(),
        Some("[0, -1, 0; 1, 0, 0; 0, 0, 1]  : SO(3)")
    );
    // the preview ran on a copy: nothing was bound
    assert_eq!(preview(&s, "y = 1 + 1").as_deref(), Some("y = 2"));
    assert!(execute(&mut s, "y").err.contains("unknown name"));
    // a user function previews like any line: the budget bounds it
    assert_eq!(preview(&s, "f(2)").as_deref(), Some("3"));
    // no preview for errors, sizes or work past the preview's budget,
    // commands, the cursor mid-line
    let start = std::time::Instant::now();
    for line in [
        "T * T_cb",
        "eye(100 * 100)",
        "zeros(2000, 20)",
        "len([Rotz(a) * Rotz(b) for a in 1:1000, b in 1:1000])",
        ":vars",
        "2",
        "Rotz(",
    ] {
        assert!(preview(&s, line).is_none() || line == "Rotz(", "{line}");
        assert!(
            !hint(&s, line, line.len()).is_some_and(|h| h.contains('⇒')),
            "{line}"
        );
    }
    assert_eq!(hint(&s, "Rotz(1)", 3), None);
    // The preview gave up within its few milliseconds, not after the
    // seconds the comprehension would take (a generous bound: the machine
    // may be loaded).
    assert!(
        start.elapsed() < std::time::Duration::from_secs(3),
        "{:?}",
        start.elapsed()
    );
}

/// Each input is line 1 of its own source: printed pictures were all
/// `draw-1.svg`, each input's overwriting the last one's, and `:save`'s
/// script, rerun, wrote other files. A picture is named by the line its
/// statement has in the script `:save` writes, as `chasles run` of that
/// script names it (found by the front-end sweep, tests/frontends_agree.rs).
#[test]
fn printed_pictures_are_named_by_their_line_in_the_saved_script() {
    let dir = common::scratch("repl-pictures");
    let mut s = Session::new(Settings::default());
    s.gate = chasles::effects::Gate::anywhere(Some(dir.join("repl")));
    std::fs::create_dir_all(dir.join("repl")).unwrap();
    let mut shown = String::new();
    for input in [
        "draw(Rotz(1))",
        "x = 1; y = 2",
        "T_ab * T_cb",
        "M = [1, 0\n     0, 1]",
        "draw(Rotz(2))",
    ] {
        shown.push_str(&execute(&mut s, input).out);
    }
    assert!(shown.contains("draw-2.svg"), "{shown}");
    assert!(shown.contains("draw-7.svg"), "{shown}");
    let mut files: Vec<String> = std::fs::read_dir(dir.join("repl"))
        .unwrap()
        .map(|f| f.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    files.sort();
    assert_eq!(files, ["draw-2.svg", "draw-7.svg"]);
    // The saved script, rerun, writes the same files.
    execute(&mut s, &format!(":save {}", dir.join("s.chs").display()));
    let (code, _, err) = common::run(&[
        "run",
        "--draw-dir",
        &dir.join("run").to_string_lossy(),
        &dir.join("s.chs").to_string_lossy(),
    ]);
    assert_eq!(code, 0, "{err}");
    let mut rerun: Vec<String> = std::fs::read_dir(dir.join("run"))
        .unwrap()
        .map(|f| f.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    rerun.sort();
    assert_eq!(rerun, files);
}
