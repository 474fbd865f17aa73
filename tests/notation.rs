//! The book's notation (LANGUAGE.md §§2, 4, 7; issue 13): each form gives
//! the value the book means, the same as its spelled-out equivalent, and
//! the forms that read two ways are errors naming both readings.

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};

mod common;
use common::{errors, last_numbers, numbers, same, try_json};

const SETUP: &str = "w = (0, 0.866, 0.5)\nθ = 30 deg\nR = Rot(w, θ)\nA = [0, 1; -1, 0]\nt = 0.5\nT_sb = SE3(Rotz(0.3), (1, 2, 3))\nT_bc = SE3(Rotx(0.2), (0, 1, 0))\nV_b = (1, 2, 3, 4, 5, 6)";

#[test]
fn nested_brackets_are_rows() {
    // numpy's nested lists are rows, not columns: the silent wrong answer.
    let rows = [0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
    assert_eq!(
        last_numbers("R_sb = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]"),
        rows
    );
    assert_eq!(last_numbers("[[0, -1, 0],\n [1, 0, 0],\n [0, 0, 1]]"), rows);
    // Pasted numpy and MATLAB output reads as printed.
    assert_eq!(
        last_numbers("[[ 0. -1.  0.] [ 1.  0.  0.] [ 0.  0.  1.]]"),
        rows
    );
    assert_eq!(
        last_numbers("[[ 0. -1.  0.]\n [ 1.  0.  0.]\n [ 0.  0.  1.]]"),
        rows
    );
    assert_eq!(last_numbers("[0 -1 0; 1 0 0; 0 0 1]"), rows);
    assert_eq!(last_numbers("[1.e-3 -2 +3]"), [0.001, -2.0, 3.0]);
    // The book's bracket inside a block is not a row list.
    same(
        "w = (1, 2, 3)",
        "[[w], (4, 5, 6); 0, 0, 0, 0]",
        "[[w], (4, 5, 6); 0, 0]",
    );
    same("", "[[1, 2, 3]]", "[(1, 2, 3)]");
}

#[test]
fn space_separated_rows_with_names_read_two_ways() {
    for (src, readings) in [
        (
            "[2 pi]",
            "write `2, pi` for two entries or `2 * pi` for the product",
        ),
        (
            "x = 1\n[1 -x]",
            "write `1, -x` for two entries or `1 - x` for the difference",
        ),
    ] {
        let e = errors(src);
        assert!(e.contains("inside brackets is ambiguous"), "{e}");
        assert!(e.contains(readings), "{e}");
    }
}

#[test]
fn superscripts_transpose_and_invert() {
    same(SETUP, "R^T", "R.T");
    same(SETUP, "Rᵀ", "R.T");
    same(SETUP, "R^{T}", "R.T");
    same(SETUP, "R^{-1}", "inv(R)");
    same(SETUP, "R^-1", "inv(R)");
    same(SETUP, "V_b^T", "V_b.T");
    same(SETUP, "Ad(T_sb)^T", "Ad(T_sb).T");
    same(SETUP, "[w]^T", "[w].T");
    same(SETUP, "R⁻¹", "inv(R)");
    same(SETUP, "[w]²", "[w]^2");
    same(SETUP, "(1 - cos θ)[w]²", "(1 - cos(θ)) * [w]^2");
    // `^T` transposes even when a name T is bound.
    same(&format!("{SETUP}\nT = 2"), "R^T", "R.T");
    // e^(x) is exp(x) for matrices and for scalars (tested below).
    same(SETUP, "e^(A t)", "exp(A * t)");
    same(SETUP, "e^([w] θ)", "exp([w] * θ)");
    same(SETUP, "e^2", "exp(2)");
}

/// What `setup` then `x` prints, the setup's own lines left out.
fn shown(setup: &str, x: &str) -> String {
    let all = common::printed(&format!("{setup}\n{x}"));
    let before = common::printed(setup);
    all.strip_prefix(&before).unwrap_or(&all).to_string()
}

/// `e^(x)` is `exp(x)` (LANGUAGE.md §4) for scalars and symbols as for
/// matrices: the same value, the same exact form (so `==` is true, not
/// false by rounding), the same closed form, derivative and explanation;
/// `e^x` and `e^-t` are the same powers of e. A bound `e` is its value.
#[test]
fn e_to_a_scalar_is_exp() {
    let given = "given t : scalar\nw = (0, 0, 1)";
    for (a, b) in [
        ("e^(t)", "exp(t)"),
        ("e^t", "exp(t)"),
        ("e^-t", "exp(-t)"),
        ("e^{t}", "exp(t)"),
        ("e^(2 t) + 1", "exp(2 t) + 1"),
        ("diff(e^(t), t)", "diff(exp(t), t)"),
        ("diff(e^(t^2), t)", "diff(exp(t^2), t)"),
        ("e^([w] t)", "exp([w] t)"),
        ("explain e^([w] t)", "explain exp([w] t)"),
        ("explain e^([w] 0.5)", "explain exp([w] 0.5)"),
    ] {
        assert_eq!(shown(given, a), shown(given, b), "{a} vs {b}");
    }
    // diff's steps quote the source (`d/dt e^(t^2): …`): the same rules
    // and values, node by node
    let rules = |x: &str| -> Vec<String> {
        shown(given, x)
            .lines()
            .map(|l| match l.split_once(": ") {
                Some((step, rule)) if step.contains("d/dt") => rule.to_string(),
                _ => l.to_string(),
            })
            .collect()
    };
    assert_eq!(
        rules("explain diff(e^(t^2), t)"),
        rules("explain diff(exp(t^2), t)")
    );
    // the closed form and its derivative print as exp's (it printed
    // 2.718281828459045^t and left diff(2.718281828459045^t, t) unevaluated)
    assert_eq!(shown(given, "e^(t)"), "exp(t)\n");
    assert_eq!(shown(given, "diff(e^(t), t)"), "exp(t)\n");
    assert_eq!(shown(given, "diff(e^-t, t)"), "-exp(-t)\n");
    let chain = shown(given, "explain diff(e^(t), t)");
    assert!(
        chain.contains("chain rule") && !chain.contains("power rule"),
        "{chain}"
    );
    // == decides by exp's exact form (it said false by rounding, or cannot
    // decide, before)
    for eq in [
        "e^(t) == exp(t)",
        "e^-t == exp(-t)",
        "e^(2) == exp(2)",
        "e^2 == exp(2)",
        "e^(-1) == exp(-1)",
        "e^(1/2) == sqrt(exp(1))",
        "e^(log(5)) == 5",
        "e^(2) e^(3) == e^(5)",
    ] {
        assert_eq!(shown(given, eq), "true\n", "{eq}");
    }
    assert_eq!(shown(given, "e^(0)"), "1\n");
    // numbers bound later: exp's value, as typed first
    assert_eq!(
        common::printed("given s\ny = e^(s) == exp(1);\ns = 1;\ny"),
        "true\n"
    );
    assert_eq!(
        common::printed("given s\ny = e^(s);\ns = 2;\ny == exp(2)"),
        "true\n"
    );
    // a bound e is a value like any other: its powers are powers
    assert_eq!(common::printed("e = 3;\ne^(2)"), "9\n");
    assert_eq!(common::printed("e = 3;\ne^(2) == 9"), "true\n");
    assert_eq!(common::printed("f(e) = e^2;\nf(3)"), "9\n");
    assert_eq!(common::printed("given e;\ne^(2)"), "e^2\n");
}

#[test]
fn juxtaposition_multiplies() {
    same(SETUP, "A t", "A * t");
    same(SETUP, "exp(A t)", "exp(A * t)");
    same(SETUP, "sin(θ) A", "sin(θ) * A");
    same(SETUP, "T_sb T_bc", "T_sb * T_bc");
    same(SETUP, "Ad(T_sb) V_b", "Ad(T_sb) * V_b");
    same(
        "S1 = (0, 0, 1, 0, 0, 0)\nS2 = (0, 0, 1, 0, -1, 0)\nM = SE3(eye(3), (2, 0, 0))\nθ1 = 0.3\nθ2 = 0.4",
        "exp([S1] θ1) exp([S2] θ2) M",
        "exp([S1] * θ1) * exp([S2] * θ2) * M",
    );
    // A bracket of a 3- or 6-vector after `)` or a name is the book's
    // bracket, multiplied, and the power is the bracket's.
    same(SETUP, "(1 - cos θ)[w]^2", "(1 - cos(θ)) * [w]^2");
    same(SETUP, "sin(θ) [w]", "sin(θ) * [w]");
    same(SETUP, "θ[w]", "θ * [w]");
    // Numbers inside are an index.
    same(SETUP, "R[2, 3]", "R[2, 3]");
    assert_eq!(last_numbers("x = (4, 5, 6)\nx[2]"), [5.0]);
}

#[test]
fn scalar_functions_without_parentheses() {
    same(SETUP, "sin θ", "sin(θ)");
    same(SETUP, "cos 30°", "cos(30 deg)");
    same(SETUP, "sqrt 2", "sqrt(2)");
    same(SETUP, "tan pi", "tan(pi)");
    same(SETUP, "sin θ [w]", "sin(θ) * [w]");
    same(SETUP, "1 - cos θ", "1 - cos(θ)");
    same(SETUP, "sin θ cos θ", "sin(θ) * cos(θ)");
    // The book's minus sign, as copied from the PDF.
    same(SETUP, "1 − cos θ", "1 - cos(θ)");
    same(SETUP, "−θ", "-θ");
    assert_eq!(last_numbers("[1 −2]"), [1.0, -2.0]);
    same(SETUP, "cos θ / 2", "cos(θ) / 2");
    for (src, help) in [
        ("sin θ^2", "write (sin θ)^2, or sin(θ^2)"),
        ("sin θ²", "write (sin θ)², or sin(θ²)"),
        ("sin 2θ", "write sin(2θ), or (sin 2) θ for the product"),
        ("cos θ/2", "write cos(θ/2), or (cos θ)/2"),
    ] {
        let e = errors(&format!("θ = 1\n{src}"));
        assert!(
            e.contains("reads two ways") && e.contains(help),
            "{src}: {e}"
        );
    }
    // The old hints pointed the wrong way (`sin * θ`, an index).
    assert!(!errors("θ = 1\nsin θ^2").contains("sin * θ"));
}

#[test]
fn cot_sec_csc_without_parentheses() {
    // LANGUAGE.md §4: the scalar functions apply to one atom, tan's
    // relatives included (issue 21).
    same(SETUP, "cot θ", "cot(θ)");
    same(SETUP, "sec θ", "sec(θ)");
    same(SETUP, "csc θ", "csc(θ)");
    same(SETUP, "sec θ [w]", "sec(θ) * [w]");
    let close = |src: &str, want: f64| {
        let got = last_numbers(src);
        assert!(
            got.len() == 1 && (got[0] - want).abs() < 1e-12,
            "{src} = {got:?}"
        );
    };
    close("cot 30°", 3f64.sqrt());
    close("sec 60°", 2.0);
    close("csc 30°", 2.0);
    close("x = 1\n1 - sec x", 1.0 - 1.0 / 1f64.cos());
    // Symbolic: the same canonical form as with parentheses.
    let text = |src: &str| {
        let lines = try_json(src).unwrap_or_else(|e| panic!("{src}:\n{e}"));
        lines.last().expect("a value")["value"].clone()
    };
    for (f, want) in [("cot", "cot(t)"), ("sec", "1/cos(t)"), ("csc", "1/sin(t)")] {
        let bare = text(&format!("given t : scalar\n{f} t"));
        assert_eq!(bare, text(&format!("given t : scalar\n{f}(t)")), "{f}");
        assert_eq!(bare, want, "{f} t");
    }
    // The same two readings as `sin θ^2` are refused.
    let e = errors("θ = 1\ncot θ^2");
    assert!(e.contains("write (cot θ)^2, or cot(θ^2)"), "{e}");
}

#[test]
fn identity_takes_the_size_it_needs() {
    // Rodrigues' formula (3.51) with I.
    same(
        SETUP,
        "I + sin θ [w] + (1 - cos θ)[w]^2",
        "eye(3) + sin(θ) * [w] + (1 - cos(θ)) * [w]^2",
    );
    same(SETUP, "T_sb - I", "T_sb - eye(4)");
    same(SETUP, "I - T_sb", "eye(4) - T_sb");
    same(SETUP, "2 I + A", "2 * eye(2) + A");
    same(SETUP, "I * V_b", "eye(6) * V_b");
    same(SETUP, "[I, (1, 2, 3); 0, 1]", "SE3(eye(3), (1, 2, 3))");
    // A bound I is the user's.
    assert_eq!(last_numbers("I = 7\nI + 1"), [8.0]);
    let e = errors("I");
    assert!(
        e.contains("`I` has no size here") && e.contains("eye(3)"),
        "{e}"
    );
}

#[test]
fn lone_zero_is_the_zero_block() {
    same(SETUP, "[R, (1, 2, 3); 0, 1]", "[R, (1, 2, 3); 0, 0, 0, 1]");
    same(SETUP, "[R, (1, 2, 3); 0, 1]", "SE3(R, (1, 2, 3))");
    // Block se(3) of the book: [[ω], v; 0, 0].
    same(
        SETUP,
        "[[w], (1, 2, 3); 0, 0]",
        "[[w], (1, 2, 3); 0, 0, 0, 0]",
    );
}

#[test]
fn numbered_frames() {
    let lines = try_json("T_01 = Trans((1, 0, 0))\nT_12 = Trans((0, 1, 0))\nT_02 = T_01 * T_12\nT_s1 = Trans((0, 0, 1))\np_{1} = (1, 2, 3)\nT_{0,1} = T_01\nT_{0,1} * p_{1}").expect("runs");
    assert_eq!(lines[0]["frames"], serde_json::json!(["0", "1"]));
    assert_eq!(lines[2]["frames"], serde_json::json!(["0", "2"]));
    assert_eq!(lines[3]["frames"], serde_json::json!(["s", "1"]));
    assert_eq!(lines[5]["frames"], serde_json::json!(["0", "1"]));
    assert_eq!(lines[6]["frames"], serde_json::json!(["0"]));
    // T_01 * T_21 is a frame error like any other.
    let e = errors("T_01 = Trans((1, 0, 0))\nT_21 = Trans((0, 1, 0))\nT_01 * T_21");
    assert!(e.contains("frame error") && e.contains("1 ≠ 2"), "{e}");
    // S_1, B_2, theta_1 stay indices.
    let lines = try_json("S_1 = (0, 0, 1, 0, 0, 0)\ntheta_1 = 1").expect("runs");
    assert_eq!(lines[0]["frames"], serde_json::json!([]));
    // The same frames spelled otherwise are named in the help.
    let e = errors("T_01 = Trans((1, 0, 0))\nT_{0,1}");
    assert!(e.contains("T_01 names the same frames"), "{e}");
    // T_123 asks for braces.
    let e = errors("T_123 = Trans((1, 0, 0))");
    assert!(e.contains("T_{1,23} or T_{12,3}"), "{e}");
}

#[test]
fn statements_as_chasles_prints_them() {
    // given with the spellings chasles prints.
    let lines =
        try_json("given T_sa : SE(3)\ngiven W_s : so(3)\ngiven T_ab : SE3\ngiven p_b : 3-vector\nT_sa T_ab p_b").expect("runs");
    assert_eq!(lines.last().unwrap()["frames"], serde_json::json!(["s"]));
    // One tuple as a function's arguments.
    same(SETUP, "rot_zyx(euler_zyx(R))", "R");
    same("f(a, b) = a - b", "f((5, 2))", "3");
    // A newline after a trailing comma continues the row.
    assert_eq!(last_numbers("[1, 2,\n 3, 4]"), [1.0, 2.0, 3.0, 4.0]);
    // `ans / deg` converts radians to degrees.
    assert_eq!(last_numbers("pi / 2\nans / deg"), [90.0]);
}

/// Builtin calls nested in each other's arguments, and one given a tuple
/// to spread, each read their own arguments' kinds, checking and running
/// alike, also after a statement whose inner call failed (issue 14 keeps
/// the arguments' types on one stack).
#[test]
fn nested_calls_read_their_own_arguments() {
    let src = "R = rot_zyx(euler_zyx(Rotz(0.3)))\n\
               x = Rotz(Rotx(1, 2))\n\
               p = cross(Rotz(0.1) * (1, 0, 0), exp([(0, 0, 1)] 0.2) * (0, 1, 0))\n\
               q = AxisAng3((0, 0, 2))\n";
    for mode in [Mode::Check, Mode::Run] {
        let mut s = Session::new(Settings {
            json: true,
            ..Settings::default()
        });
        let (out, err, n) = s.run_to_strings("t.chs", src, mode, true);
        assert_eq!(n, 1, "{err}");
        let lines: Vec<serde_json::Value> = out
            .lines()
            .map(|l| serde_json::from_str(l).expect("json"))
            .collect();
        let types: Vec<&str> = lines.iter().filter_map(|l| l["type"].as_str()).collect();
        assert_eq!(types, ["SO3", "vector", "tuple"], "{mode:?}");
        if mode == Mode::Run {
            let r = numbers(&lines[0]["value"]);
            let (c, si) = (0.3f64.cos(), 0.3f64.sin());
            let want = [c, -si, 0.0, si, c, 0.0, 0.0, 0.0, 1.0];
            assert!(
                r.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-12),
                "{r:?}"
            );
            let p = numbers(&lines[2]["value"]);
            // (cos 0.1, sin 0.1, 0) × (−sin 0.2, cos 0.2, 0) = (0, 0, cos(0.2 − 0.1)).
            assert_eq!(p[..2], [0.0, 0.0]);
            assert!((p[2] - 0.1f64.cos()).abs() < 1e-12, "{p:?}");
            assert_eq!(numbers(&lines[3]["value"]), [0.0, 0.0, 1.0, 2.0]);
        }
    }
}

/// Each of `cases` after `setup` passes both `run` and `check`.
fn passes_both(setup: &str, cases: &[&str]) {
    for x in cases {
        let src = format!("{setup}{x}\n");
        for mode in [Mode::Run, Mode::Check] {
            assert_eq!(first_error(&src, mode), None, "{x} ({mode:?})");
        }
    }
}

/// The first error of `src` in `mode`, as (kind, message); None when it
/// runs (or checks) cleanly.
fn first_error(src: &str, mode: Mode) -> Option<(String, String)> {
    let mut s = Session::new(Settings {
        json: true,
        ..Settings::default()
    });
    let (out, _, _) = s.run_to_strings("t.chs", src, mode, false);
    out.lines()
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .find_map(|v| {
            let e = v.get("error")?;
            Some((
                e["kind"].as_str()?.to_string(),
                e["message"].as_str()?.to_string(),
            ))
        })
}

/// `check` refuses an index that `run` refuses wherever the sizes and the
/// indices are known without numbers, with the same error: `L[1]` of the
/// 4×8 `[T_ab, T_bc]` passed `check` as a scalar, as did an index out of
/// range of a tuple, vector or matrix, a range past a matrix's columns
/// and a range over a tuple; `x[1.5]` said "out of range" where it is not
/// a whole number. Found by a differential sweep of `run` against `check`.
#[test]
fn check_refuses_the_indices_run_refuses() {
    let setup = "T_ab = RpToTrans(Rotz(1), (1, 2, 3))\nT_bc = RpToTrans(Rotx(1), (0, 2, 3))\n\
                 L = [T_ab, T_bc]\nt = (T_ab, T_bc)\nv = (1, 2, 3)\nM = [1, 2; 3, 4; 5, 6]\n\
                 xs = [k^2 for k in 1:4]\n";
    let not_whole = "is not a whole number (indices count entries from 1, as in the book)";
    let refused = [
        (
            "L[1] * L[2]",
            "a matrix takes two indices: M[i, j], M[i, :] or M[:, j]",
        ),
        ("M[7]", "a matrix takes two indices"),
        ("v[4]", "index 4 is out of range 1..3"),
        ("v[-1]", "index -1 is out of range 1..3"),
        ("v[end + 1]", "index 4 is outside 1..3 (the entries)"),
        ("t[3]", "index 3 is out of range 1..2"),
        ("t[1, 1]", "a tuple takes one index"),
        ("t[1:2]", "cannot index a (SE(3), SE(3)) with a range"),
        ("T_ab[5, 1]", "index 5 is out of range 1..4"),
        ("T_ab[1:3, 5]", "index 5 is outside 1..4 (the columns)"),
        ("M[1:4, 1]", "index 4 is outside 1..3 (the rows)"),
        ("v[1:2:5]", "index 5 is outside 1..3 (the entries)"),
        ("v[1.5]", not_whole),
        ("t[1.5]", not_whole),
        ("M[1.5, 1]", not_whole),
        ("v[2.5:3]", not_whole),
        ("xs[1.5]", not_whole),
        ("xs[0]", "index 0 is outside the list"),
    ];
    for (x, want) in refused {
        let src = format!("{setup}{x}\n");
        for mode in [Mode::Run, Mode::Check] {
            let (kind, msg) = first_error(&src, mode)
                .unwrap_or_else(|| panic!("{x}: {mode:?} did not refuse it"));
            assert!(msg.contains(want), "{x} ({mode:?}): {kind}: {msg}");
            assert!(kind == "domain" || kind == "type", "{x}: {kind}");
        }
        // the same error in both modes
        assert_eq!(
            first_error(&src, Mode::Run).map(|e| e.0),
            first_error(&src, Mode::Check).map(|e| e.0),
            "{x}"
        );
    }
    let accepted = [
        "L[1, 8]",
        "L[1:4, 5:8]",
        "v[3]",
        "v[end]",
        "M[:, 2]",
        "M[3, :]",
        "t[2]",
        "T_ab[1:3, 4]",
        "xs[4]",
    ];
    passes_both(setup, &accepted);
    assert_eq!(last_numbers(&format!("{setup}L[2, 8]")), [2.0]);
    assert_eq!(last_numbers(&format!("{setup}M[1:2, 2]")), [2.0, 4.0]);
}

/// `I` bound to a rotation or transform name is that group's identity
/// (the name is the context that sizes it, §4): `R_01 = I` said "`I` has
/// no size here".
#[test]
fn identity_under_a_rotation_or_transform_name() {
    let lines = try_json("R_01 = I\nT_01 = I\nR_12 = Rotz(0.5)\nR_01 * R_12").expect("runs");
    assert_eq!(lines[0]["type"], "SO3");
    assert_eq!(lines[0]["frames"], serde_json::json!(["0", "1"]));
    assert_eq!(
        numbers(&lines[0]["value"]),
        [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
    );
    assert_eq!(lines[1]["type"], "SE3");
    let mut eye4 = [0.0; 16];
    for i in 0..4 {
        eye4[5 * i] = 1.0;
    }
    assert_eq!(numbers(&lines[1]["value"]), eye4);
    assert_eq!(lines[3]["frames"], serde_json::json!(["0", "2"]));
    let (c, s) = (0.5f64.cos(), 0.5f64.sin());
    assert_eq!(
        numbers(&lines[3]["value"]),
        [c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0]
    );
    // checked alike, with the frames of the name
    for mode in [Mode::Run, Mode::Check] {
        assert_eq!(
            first_error("R_01 = I\nR_21 = Rotz(1)\nR_01 * R_21", mode).map(|e| e.0),
            Some("frame".into())
        );
    }
    // a name that says no group leaves `I` unsized, and says how to size it
    for src in ["R = I", "p_ab = I", "x = I"] {
        let e = errors(src);
        assert!(
            e.contains("`I` has no size here") && e.contains("eye(3)"),
            "{e}"
        );
    }
}

/// Sizes and kinds `check` knows refuse what `run` refuses: a sum or
/// product with a tuple (`2 * t` passed `check`; `run` said "expected
/// numbers"), `cross` of a twist, `dot` of a 3- and a 6-vector. Found by
/// the run/check differential sweep.
#[test]
fn check_refuses_tuple_arithmetic_and_misfit_vectors_as_run_does() {
    let setup = "T_ab = Trans((1, 0, 0))\nt = (T_ab, 2)\nv = (1, 2, 3)\nV = (1, 2, 3, 4, 5, 6)\n";
    let refused = [
        ("2 * t", "cannot multiply a scalar and a (SE(3), scalar)"),
        ("t * T_ab", "cannot multiply a (SE(3), scalar) and an SE(3)"),
        (
            "t + t",
            "cannot add a (SE(3), scalar) and a (SE(3), scalar)",
        ),
        ("t - t", "cannot add"),
        ("t / 2", "cannot"),
        (
            "cross(V, v)",
            "argument 1 of cross must be a 3-vector, not a twist",
        ),
        (
            "cross(v, V)",
            "argument 2 of cross must be a 3-vector, not a twist",
        ),
        ("dot(v, V)", "dot of a 3-vector and a 6-vector"),
    ];
    for (x, want) in refused {
        let src = format!("{setup}{x}\n");
        for mode in [Mode::Run, Mode::Check] {
            let (kind, msg) = first_error(&src, mode)
                .unwrap_or_else(|| panic!("{x}: {mode:?} did not refuse it"));
            assert_eq!(kind, "type", "{x} ({mode:?}): {msg}");
            assert!(msg.contains(want), "{x} ({mode:?}): {msg}");
        }
    }
    // the parts are operands
    assert_eq!(last_numbers(&format!("{setup}2 * t[2]")), [4.0]);
    assert_eq!(last_numbers(&format!("{setup}dot(V, V)")), [91.0]);
    assert_eq!(
        last_numbers(&format!("{setup}cross(v, (0, 0, 1))")),
        [2.0, -1.0, 0.0]
    );
}

/// A row of blocks whose heights the kinds know to differ is refused by
/// `check` as by `run` (`[T_ab, v]` passed `check`); a lone `0`, as tall
/// as its row needs, still fits anywhere.
#[test]
fn check_refuses_a_row_of_blocks_of_different_heights() {
    let setup =
        "T_ab = Trans((1, 0, 0))\nR_ab = Rotz(0.3)\nv = (1, 2, 3)\nV = (1, 2, 3, 4, 5, 6)\n";
    for (x, want) in [
        (
            "[T_ab, v]",
            "row 1 of the bracket joins blocks of 4 and 3 rows",
        ),
        (
            "[R_ab, V; 0, 1]",
            "row 1 of the bracket joins blocks of 3 and 6 rows",
        ),
    ] {
        let src = format!("{setup}{x}\n");
        for mode in [Mode::Run, Mode::Check] {
            let (kind, msg) = first_error(&src, mode)
                .unwrap_or_else(|| panic!("{x}: {mode:?} did not refuse it"));
            assert_eq!(
                (kind.as_str(), msg.as_str()),
                ("type", want),
                "{x} ({mode:?})"
            );
        }
    }
    passes_both(
        setup,
        &["[R_ab, v; 0, 1]", "[R_ab, 0; 0, R_ab]", "[v; V]", "[0, v]"],
    );
    assert_eq!(
        last_numbers(&format!("{setup}[R_ab, v; 0, 1][1:3, 4]")),
        [1.0, 2.0, 3.0]
    );
}

/// `eye(n)` and `zeros(r, c)` of literal sizes have, when checked, the
/// kind their numbers will have: `eye(3) * T_ab` and `zeros(2, 3) *
/// zeros(2, 3)` passed `check` (sizes unknown) where `run` refuses them.
#[test]
fn check_knows_the_size_of_eye_and_zeros_of_literal_sizes() {
    let setup = "T_ab = Trans((1, 0, 0))\nM = [1, 2; 3, 4; 5, 6]\n";
    for (x, want) in [
        ("eye(3) * T_ab", "cannot multiply an SO(3) by an SE(3)"),
        (
            "zeros(2, 3) * zeros(2, 3)",
            "cannot multiply a 2×3 matrix by a 2×3 matrix",
        ),
        ("zeros(3) + M", "cannot add a 3×3 matrix and a 3×2 matrix"),
        ("eye(3)[4, 1]", "index 4 is out of range 1..3"),
    ] {
        let src = format!("{setup}{x}\n");
        for mode in [Mode::Run, Mode::Check] {
            let (_, msg) = first_error(&src, mode)
                .unwrap_or_else(|| panic!("{x}: {mode:?} did not refuse it"));
            assert!(msg.contains(want), "{x} ({mode:?}): {msg}");
        }
    }
    passes_both(
        setup,
        &[
            "eye(4) * T_ab",
            "T_cd = eye(4)",
            "zeros(3, 2) + M",
            "M * eye(2)",
        ],
    );
    assert_eq!(
        last_numbers(&format!("{setup}zeros(3, 2) + M")),
        [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
    );
}

/// A size bound to a name written with literals is known to `check` as
/// the literal is: `k = 3; eye(k) * T_ab` passed `check` ("3 statements
/// checked, frames consistent") where `run` refuses it; `n = 4; (0:n)[9]`
/// likewise. A name bound anew (again, as a parameter, by a comprehension,
/// by `given`) is no longer known, and passes as it runs.
#[test]
fn check_knows_a_size_bound_to_a_literal() {
    let setup = "T_ab = Trans((1, 0, 0))\nk = 3\n";
    for (x, want) in [
        ("eye(k) * T_ab", "cannot multiply an SO(3) by an SE(3)"),
        (
            "m = k; eye(m) * T_ab",
            "cannot multiply an SO(3) by an SE(3)",
        ),
        ("eye(k - 1) * T_ab", "cannot multiply an SO(2) by an SE(3)"),
        (
            "zeros(k, 1) * T_ab",
            "cannot multiply a 3-vector by an SE(3)",
        ),
        ("(0:k)[9]", "index 9 is outside the list (it has 4 items"),
    ] {
        let src = format!("{setup}{x}\n");
        for mode in [Mode::Run, Mode::Check] {
            let (_, msg) = first_error(&src, mode)
                .unwrap_or_else(|| panic!("{x}: {mode:?} did not refuse it"));
            assert!(msg.contains(want), "{x} ({mode:?}): {msg}");
        }
    }
    passes_both(
        setup,
        &[
            "eye(k + 1) * T_ab",
            "k = 4; eye(k) * T_ab",
            "f(k) = eye(k) * T_ab; f(4)",
            "[eye(k) * T_ab for k in 4:4]",
            "(0:k)[4]",
        ],
    );
}

/// A scalar in a row of blocks is 1×1 unless it is a lone `0`, which is
/// the zero block its row and column need (§4): `[1, v]`, `[z, v]` with
/// z = 0, `[-0, v]` and `[a, v]` with a given passed `check` and `run`
/// refuses them. Rows of widths the kinds know to differ are refused by
/// `check` as by `run` (`[R, 0; 1, 1]`). Over given names, `run` refused
/// nothing: `[T, p]` with T : SE3 was a "4×5 matrix", `[R_ab, p; 0, 0, 1]`
/// a 4×4 one; now both modes refuse them with the numbers' message.
#[test]
fn a_scalar_beside_a_block_is_one_by_one_unless_a_lone_zero() {
    let setup = "R = Rotz(0.3)\nv = (1, 2, 3)\nz = 0\ngiven a\ngiven T : SE3\ngiven R_ab : SO3\ngiven p : vec3\n";
    for (x, want) in [
        (
            "[1, v]",
            "row 1 of the bracket joins blocks of 1 and 3 rows",
        ),
        (
            "[z, v]",
            "row 1 of the bracket joins blocks of 1 and 3 rows",
        ),
        (
            "[-0, v]",
            "row 1 of the bracket joins blocks of 1 and 3 rows",
        ),
        (
            "[1 - 1, v]",
            "row 1 of the bracket joins blocks of 1 and 3 rows",
        ),
        (
            "[a, v]",
            "row 1 of the bracket joins blocks of 1 and 3 rows",
        ),
        (
            "[R, 1; 0, 1]",
            "row 1 of the bracket joins blocks of 3 and 1 rows",
        ),
        // (the lone 0 is as tall as its row's tallest: run compares with it)
        (
            "[0, 1, v]",
            "row 1 of the bracket joins blocks of 3 and 1 rows",
        ),
        (
            "[R, 0; 1, 1]",
            "rows of the bracket have different widths: 4 and 2 (row 2)",
        ),
        (
            "[R, v; 0, 0, 1]",
            "rows of the bracket have different widths: 4 and 3 (row 2)",
        ),
        (
            "[T, a]",
            "row 1 of the bracket joins blocks of 4 and 1 rows",
        ),
        (
            "[T, p]",
            "row 1 of the bracket joins blocks of 4 and 3 rows",
        ),
        (
            "[R_ab, p; 0, 0, 1]",
            "rows of the bracket have different widths: 4 and 3 (row 2)",
        ),
    ] {
        let src = format!("{setup}{x}\n");
        for mode in [Mode::Run, Mode::Check] {
            let (kind, msg) = first_error(&src, mode)
                .unwrap_or_else(|| panic!("{x}: {mode:?} did not refuse it"));
            assert_eq!(
                (kind.as_str(), msg.as_str()),
                ("type", want),
                "{x} ({mode:?})"
            );
        }
    }
    passes_both(
        setup,
        &[
            "[0, v]",
            "[0.0, v]",
            "[R, 0; 0, 1]",
            "[1, 0; 0, R]",
            "[R, 0; 0, R]",
            "[1, 2; v, v]",
            "[R_ab, p; 0, 1]",
            "[R_ab, p; 0, 0, 0, 1]",
            "[a, a; a, a]",
        ],
    );
    assert_eq!(
        last_numbers(&format!("{setup}[0, v]")),
        [0.0, 1.0, 0.0, 2.0, 0.0, 3.0]
    );
}

/// An index that is a given name with no number (alone or plus or minus a
/// literal) is refused by `check` as by `run`; once the name has a number
/// both pass.
#[test]
fn check_refuses_an_index_that_has_no_number_yet() {
    for (x, shown) in [("v[n]", "n"), ("v[n + 1]", "n + 1"), ("v[3 - n]", "3 - n")] {
        let src = format!("given n\nv = (1, 2, 3)\n{x}\n");
        for mode in [Mode::Run, Mode::Check] {
            let (kind, msg) = first_error(&src, mode)
                .unwrap_or_else(|| panic!("{x}: {mode:?} did not refuse it"));
            assert_eq!(
                (kind.as_str(), msg.as_str()),
                (
                    "domain",
                    format!("an index must be a number: `{shown}` has no number yet").as_str()
                ),
                "{x} ({mode:?})"
            );
        }
    }
    let src = "given n\nn = 2\nv = (1, 2, 3)\nv[n + 1]\n";
    for mode in [Mode::Run, Mode::Check] {
        assert_eq!(first_error(src, mode), None, "{mode:?}");
    }
    assert_eq!(last_numbers(src), [3.0]);
}

/// Found by a differential sweep of `check` against `run` on random
/// scripts of the book's names: `check` gave a slice of literal positions
/// no length (`T_bc[1:3]` was an n-vector, so `M[3, 3] - T_bc[1:3]`,
/// `det(F_a[1:3])` and `[M[1:3], 2]` passed it), a stack of columns
/// `[p_a; p_b]` and a row's transpose `p_a.T.T` were r×1 matrices (run: a
/// 6-vector, a 3-vector, in every message). Now both refuse with run's
/// words, and `an n-vector` is spelled so.
#[test]
fn check_knows_the_sizes_of_slices_stacks_and_transposes() {
    let setup = "T_bc = RpToTrans(Roty(0.4), (0, 1, 0))\nF_a = wrench((0, 0, 1), (0, 1, 0))\n\
                 M = [1, 2, 3; 4, 5, 6; 7, 8, 10]\np_a = (1, 2, 3)\np_b = (3, 2, 1)\n";
    for (x, kind, want) in [
        (
            "M[3, 3] - T_bc[1:3]",
            "type",
            "cannot add a scalar and a 3-vector",
        ),
        (
            "det(F_a[1:3])",
            "type",
            "argument 1 of det must be a square matrix, not a 3-vector",
        ),
        (
            "[M[1:3], 2]",
            "type",
            "row 1 of the bracket joins blocks of 3 and 1 rows",
        ),
        (
            "M[1:2, :] * p_a.T",
            "type",
            "cannot multiply a 2×3 matrix by a 1×3 matrix",
        ),
        (
            "log([p_a; p_b])",
            "type",
            "log takes a rotation or transform (SO(3), SE(3), SO(2), SE(2)), not a 6-vector",
        ),
        (
            "R_ac = p_a.T.T",
            "type",
            "R_ac names a rotation, in SO(3) or SO(2), but the value is a 3-vector",
        ),
    ] {
        let src = format!("{setup}{x}\n");
        for mode in [Mode::Run, Mode::Check] {
            let got = first_error(&src, mode);
            assert_eq!(
                got,
                Some((kind.to_string(), want.to_string())),
                "{x} ({mode:?})"
            );
        }
    }
    passes_both(
        setup,
        &[
            "T_bc[1:3, 4] + p_b",
            "M[1:2, 2:3] * M[2:3, 1:2]",
            "[p_a; p_b][4:6] + p_b",
        ],
    );
    // a size checking does not know: an n-vector
    let src = "T_bc = RpToTrans(Roty(0.4), (0, 1, 0))\nk = len(1:3)\ninv(T_bc[1:k])\n";
    assert_eq!(
        first_error(src, Mode::Check),
        Some(("type".into(), "cannot invert an n-vector".into()))
    );
}

/// A given name's entries, as its numbers' are: `T_ab[2]` of a given SE(3)
/// printed `T_ab[2]` (numbers: 'a matrix takes two indices'), and a range
/// of a given name was refused by `run` ('cannot index an SE(3) with a
/// range') where `check` passed it. Now `T_ab[1:3, 4]` is the vector of
/// its entries, in {a}, made numbers when T_ab gets them; a vector's slice
/// keeps its frame, over symbols as over numbers.
#[test]
fn a_given_names_entries_are_indexed_as_its_numbers() {
    let setup = "given T_ab : SE3\ngiven p_a : vec3\ngiven V_b : twist\np_b = (1, 2, 3)\n";
    for (x, kind, want) in [
        (
            "T_ab[2]",
            "domain",
            "a matrix takes two indices: M[i, j], M[i, :] or M[:, j]",
        ),
        (
            "T_ab[5, 1]",
            "domain",
            "index 5 is out of range 1..4 (indices start at 1, as in the book)",
        ),
        (
            "p_a[1:3] + p_b",
            "frame",
            "cannot add quantities in different frames",
        ),
        // (a vector of formulas: its slice printed (1 + cos(t), …) {b})
        (
            "given t\nq_a = (cos(t), sin(t), 0)\nq_a[1:3] + p_b",
            "frame",
            "cannot add quantities in different frames",
        ),
        (
            "V_b[4:6] + T_ab[1:3, 4]",
            "frame",
            "cannot add quantities in different frames",
        ),
        (
            "det(T_ab[1:3, 4])",
            "type",
            "argument 1 of det must be a square matrix, not a 3-vector",
        ),
    ] {
        let src = format!("{setup}{x}\n");
        for mode in [Mode::Run, Mode::Check] {
            assert_eq!(
                first_error(&src, mode),
                Some((kind.to_string(), want.to_string())),
                "{x} ({mode:?})"
            );
        }
    }
    let src = format!(
        "{setup}x = T_ab[1:3, 4]\nR = T_ab[1:3, 1:3]\nT_ab = RpToTrans(Rotz(0.3), (1, 2, 3))\nx\nR[2, 1]\n"
    );
    for mode in [Mode::Run, Mode::Check] {
        assert_eq!(first_error(&src, mode), None, "{mode:?}");
    }
    let lines = try_json(&src).unwrap();
    let x = &lines[lines.len() - 2];
    assert_eq!(numbers(&x["value"]), [1.0, 2.0, 3.0]);
    assert_eq!(x["frames"], serde_json::json!(["a"]));
    let r = numbers(&lines[lines.len() - 1]["value"]);
    assert!((r[0] - 0.3f64.sin()).abs() < 1e-15, "{r:?}");
}

/// The rotation block of a transform is its R, an SO(3) between the
/// transform's frames, with symbols and with numbers alike (§5: a label is
/// printed when the value is in that set): `MatrixExp6(…)[1:3, 1:3]` was a
/// 3×3 matrix typed first and SO(3) with the numbers bound later (a kept
/// call's entries, classified); `T_ab[1:3, 1:3]` had no frames, so
/// `R_ba = T_ab[1:3, 1:3]` passed. Other blocks stay matrices.
#[test]
fn the_rotation_block_of_a_transform_is_its_rotation() {
    let kind = |src: &str| {
        let lines = try_json(src).unwrap_or_else(|e| panic!("{src}\n{e}"));
        let last = &lines[lines.len() - 1];
        let ty = last["type"].as_str().unwrap_or_default().to_string();
        match ty.as_str() {
            "symbolic" => last["kind"].as_str().unwrap_or_default().to_string(),
            _ => ty,
        }
    };
    for x in [
        "MatrixExp6([(0, 0, 1, 1, 0, 0)]*a)[1:3, 1:3]",
        "MatrixExp6([(a, 0, 1, 1, 0, 0)])[1:3, 1:3]",
        "RpToTrans(Rotz(a), (1, 2, 3))[1:3, 1:3]",
        "Trans((a, 2, 3))[1:3, 1:3]",
    ] {
        let first = kind(&format!("a = 1\n{x}"));
        let over = kind(&format!("given a\n{x}"));
        let later = kind(&format!("given a\nX = {x}\na = 1\nX"));
        assert_eq!(
            (first.as_str(), over.as_str(), later.as_str()),
            ("SO3", "SO3", "SO3"),
            "{x}"
        );
    }
    let setup = "given T_ab : SE3\ngiven S_ab : SE2\n";
    for x in ["T_ab[1:3, 1:3]", "S_ab[1:2, 1:2]"] {
        let lines = try_json(&format!("{setup}{x}")).unwrap();
        let last = &lines[lines.len() - 1];
        assert_eq!(last["frames"], serde_json::json!(["a", "b"]), "{x}: {last}");
    }
    let (kind_of, msg) = first_error(&format!("{setup}R_ba = T_ab[1:3, 1:3]\n"), Mode::Check)
        .expect("check refuses the frames");
    assert_eq!(kind_of, "frame", "{msg}");
    passes_both(setup, &["R_ab = T_ab[1:3, 1:3]; R_ab^T * T_ab[1:3, 4]"]);
    assert_eq!(kind("T = Trans((1, 2, 3))\nT[2:3, 2:3]"), "matrix");
    assert_eq!(kind("given a\nRotz(a)[1:2, 1:2]"), "matrix");
}
