//! The frame table of LANGUAGE.md §6, row by row, in both modes: the same
//! rules must hold with numbers (`run`) and with none (`check`, `given`).

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};

/// The frames and JSON type of a result, or an error's kind and message.
type Outcome = Result<(Vec<String>, String), (String, String)>;

/// Runs `src` and returns the frames and type of the last statement's JSON
/// line, or the error kind and message.
fn last(src: &str, mode: Mode) -> Outcome {
    let mut s = Session::new(Settings {
        json: true,
        ..Settings::default()
    });
    let (out, _err, _) = s.run_to_strings("t.chs", src, mode, false);
    let line = out.lines().last().expect("a result");
    let v: serde_json::Value = serde_json::from_str(line).unwrap();
    if let Some(e) = v.get("error") {
        return Err((
            e["kind"].as_str().unwrap().to_string(),
            e["message"].as_str().unwrap().to_string(),
        ));
    }
    let frames = v["frames"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f.as_str().unwrap().to_string())
        .collect();
    Ok((frames, v["type"].as_str().unwrap_or("").to_string()))
}

const NUMBERS: &str = "T_ab = Trans((1, 0, 0))\nT_bc = RpToTrans(Rotz(0.3), (0, 1, 0))\nT_cb = inv(T_bc)\n\
p_b = (1, 2, 3)\np_c = (3, 2, 1)\nV_b = twist((0, 0, 1), (1, 0, 0))\nF_a = wrench((0, 0, 1), (0, 1, 0))\n\
F_b = wrench((1, 0, 0), (0, 0, 1))\nS_a = (0, 0, 1, 0, 0, 0)\nR_ab = Rotx(0.2)\n";
const SYMBOLS: &str = "given T_ab, T_bc, T_cb : SE3\ngiven p_b, p_c : vec3\ngiven V_b : twist\n\
given F_a, F_b : wrench\ngiven S_a : screw\ngiven R_ab : SO3\n";

fn both(expr: &str) -> [Outcome; 2] {
    [
        last(&format!("{NUMBERS}{expr}\n"), Mode::Run),
        last(&format!("{SYMBOLS}{expr}\n"), Mode::Check),
    ]
}

fn frames(expr: &str, want: &[&str]) {
    for r in both(expr) {
        match r {
            Ok((f, _)) => assert_eq!(f, want, "{expr}"),
            Err(e) => panic!("{expr}: unexpected error {e:?}"),
        }
    }
}

fn frame_error(expr: &str, needle: &str) {
    for r in both(expr) {
        match r {
            Err((kind, msg)) => {
                assert_eq!(kind, "frame", "{expr}: {msg}");
                assert!(msg.contains(needle), "{expr}: {msg}");
            }
            Ok(x) => panic!("{expr}: expected a frame error, got {x:?}"),
        }
    }
}

#[test]
fn composition_cancels_inner_frames() {
    frames("T_ab * T_bc", &["a", "c"]);
    frame_error("T_ab * T_cb", "frames do not cancel");
}

#[test]
fn transforming_points_and_vectors() {
    frames("T_ab * p_b", &["a"]);
    frames("R_ab * p_b", &["a"]);
    frame_error("T_ab * p_c", "frames do not cancel");
}

#[test]
fn inverse_and_transpose_swap() {
    frames("inv(T_ab)", &["b", "a"]);
    frames("R_ab.T", &["b", "a"]);
    frames("T_ab^-1", &["b", "a"]);
}

#[test]
fn adjoint_and_wrenches() {
    frames("Ad(T_ab)", &["a", "b"]);
    frames("Ad(T_ab) * V_b", &["a"]);
    frames("Ad(T_ab).T * F_a", &["b"]);
    frame_error("Ad(T_ab) * F_b", "wrench");
    // The power V_bᵀF_b is a plain scalar (the frame cancels), and both
    // factors must be in the same frame.
    for r in both("V_b.T * F_b") {
        assert_eq!(r, Ok((vec![], "scalar".to_string())));
    }
    frames("(Ad(T_ab) * V_b).T * F_a", &[]);
    frame_error("V_b.T * F_a", "frames do not cancel");
}

#[test]
fn exponentials_are_displacements() {
    frames("exp([S_a] 0.5) * T_ab", &["a", "b'"]);
    frames("inv(T_ab) * exp([S_a] 0.5)", &["b", "a'"]);
    frame_error("exp([S_a] 0.5) * T_bc", "frames do not cancel");
}

#[test]
fn log_is_tagged_with_the_outer_frame() {
    frames("log(T_ab)", &["a"]);
    frames("MatrixLog6(T_ab)", &["a"]);
}

#[test]
fn sums_need_the_same_frame() {
    frames("p_b + p_b", &["b"]);
    frames("p_b + (1, 1, 1)", &["b"]);
    frame_error("p_b + p_c", "different frames");
    frame_error("cross(p_b, p_c)", "different frames");
}

#[test]
fn names_are_checked_on_assignment() {
    frames("T_ac = T_ab * T_bc", &["a", "c"]);
    frame_error("T_ad = T_ab * T_bc", "the name T_ad says {d} in {a}");
    frames("T_ab' = exp([S_a] 0.5) * T_ab", &["a", "b'"]);
}

#[test]
fn untagged_values_match_anything() {
    frames("Rotz(0.1) * R_ab", &["a", "b'"]);
    frames("untag(T_ab) * T_bc", &["b", "c'"]);
}

/// Asserts that `out` contains every piece of `wants`.
fn contains_all(out: &str, wants: &[&str]) {
    for want in wants {
        assert!(out.contains(want), "{want:?} not in\n{out}");
    }
}

/// The text output of running `src`, which must have no error.
fn text(src: &str) -> String {
    let mut s = Session::new(Settings::default());
    let (out, err, n) = s.run_to_strings("t.chs", src, Mode::Run, false);
    assert_eq!(n, 0, "{err}");
    out
}

#[test]
fn symbols_simplify() {
    let out = text("given T_ab, T_bc, T_cd : SE3\ninv(T_ab) * T_ab\nT_ab * T_bc * T_cd\n");
    assert_eq!(out, "I  : SE(3) {b}←{b}\nT_ab T_bc T_cd  : SE(3) {a}←{d}\n");
}

#[test]
fn destructured_parts_keep_their_frames() {
    let out = text(
        "T_ab = SE3(Rotz(1), (1, 2, 3))\n(R, p) = TransToRp(T_ab)\n\
         (w, theta) = AxisAng3(MatrixLog3(R))\n(w_s, t) = AxisAng3((0, 0, 2))\n",
    );
    contains_all(
        &out,
        &[
            "]  : SO(3) {a}←{b}\np = (1, 2, 3)  : 3-vector {a}\n",
            "w = (0, 0, 1)  : 3-vector {a}\ntheta = 1\n",
            "w_s = (0, 0, 1)  : 3-vector {s}\nt = 2\n",
        ],
    );
}

#[test]
fn numbers_bound_later_reach_derived_symbols() {
    // §7: X is built over symbols; once they have numbers, X has them too,
    // partly numeric first, then fully.
    let out = text(
        "given T_ab, T_bc : SE3\ngiven theta : scalar\ngiven V_b : twist\n\
         X = T_ab * T_bc\nY = Rotz(theta) * Rotx(2 * theta)\nW = Ad(T_ab) * V_b\n\
         T_ab = Trans((1, 0, 0))\nX\nT_bc = Trans((0, 1, 0))\nX\n\
         A = [cos(theta), -sin(theta), 0; sin(theta), cos(theta), 0; 0, 0, 1]\n\
         theta = pi/2\nY\nV_b = (0, 0, 1, 1, 0, 0)\nW\nA\n",
    );
    assert!(
        out.contains(
            "A = [cos(theta), -sin(theta), 0\n     sin(theta), cos(theta),  0\n     0,          0,           1]  : SO(3)\n"
        ),
        "{out}"
    );
    assert!(
        out.ends_with("\n[0, -1, 0\n 1,  0, 0\n 0,  0, 1]  : SO(3)\n"),
        "{out}"
    );
    contains_all(
        &out,
        &[
            "\n[1, 0, 0, 1; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1] T_bc  : SE(3) {a}←{c}\n",
            "\n[1, 0, 0, 1\n 0, 1, 0, 1\n 0, 0, 1, 0\n 0, 0, 0, 1]  : SE(3) {a}←{c}\n",
            "\n[0, 1,  0\n 1, 0,  0\n 0, 0, -1]  : SO(3)\n",
            "\n(0, 0, 1, 1, -1, 0)  : twist {a}\n",
        ],
    );
}

#[test]
fn derive_again_shows_the_chain() {
    let out = text(
        "given T_ab, T_bc : SE3\nderive T_ac\nderive T_ac\nT_xy = Trans((1, 2, 3))\nderive T_xy\n",
    );
    assert_eq!(out.matches("T_ac = T_ab * T_bc\n").count(), 2, "{out}");
    // With nothing else linking {x} and {y}, the name itself is the chain.
    assert!(out.contains("T_xy = T_xy\n"), "{out}");
}
