//! The frame table of LANGUAGE.md §6, row by row, in both modes: the same
//! rules must hold with numbers (`run`) and with none (`check`, `given`).

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};

mod common;
use common::printed;

/// The frames and JSON type of a result, or an error's kind and message.
type Outcome = Result<(Vec<String>, String), (String, String)>;

/// The JSON line of the last statement of `src`, run in `mode`.
fn last_json(src: &str, mode: Mode) -> serde_json::Value {
    let mut s = Session::new(Settings {
        json: true,
        ..Settings::default()
    });
    let (out, _err, _) = s.run_to_strings("t.chs", src, mode, false);
    let line = out.lines().last().expect("a result");
    serde_json::from_str(line).unwrap()
}

/// Runs `src` and returns the frames and type of the last statement's JSON
/// line, or the error kind and message.
fn last(src: &str, mode: Mode) -> Outcome {
    let v = last_json(src, mode);
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
F_b = wrench((1, 0, 0), (0, 0, 1))\nS_a = (0, 0, 1, 0, 0, 0)\nR_ab = Rotx(0.2)\n\
B_b = (0, 0, 1, 1, 0, 0)\nw_b = (0, 0, 1)\nV_a = Ad(T_ab) * V_b\np_a = (1, 2, 3)\n";
const SYMBOLS: &str = "given T_ab, T_bc, T_cb : SE3\ngiven p_b, p_c : vec3\ngiven V_b : twist\n\
given F_a, F_b : wrench\ngiven S_a : screw\ngiven R_ab : SO3\n\
given B_b : screw\ngiven w_b : vec3\ngiven V_a : twist\ngiven p_a : vec3\n";

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

#[test]
fn symbols_simplify() {
    let out = printed("given T_ab, T_bc, T_cd : SE3\ninv(T_ab) * T_ab\nT_ab * T_bc * T_cd\n");
    assert_eq!(out, "I  : SE(3) {b}←{b}\nT_ab T_bc T_cd  : SE(3) {a}←{d}\n");
}

#[test]
fn destructured_parts_keep_their_frames() {
    let out = printed(
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
    let out = printed(
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
    let out = printed(
        "given T_ab, T_bc : SE3\nderive T_ac\nderive T_ac\nT_xy = Trans((1, 2, 3))\nderive T_xy\n",
    );
    assert_eq!(out.matches("T_ac = T_ab * T_bc\n").count(), 2, "{out}");
    // With nothing else linking {x} and {y}, the name itself is the chain.
    assert!(out.contains("T_xy = T_xy\n"), "{out}");
}

// Issue 11: the frame algebra is an algebra.

/// The type of the last result when running with numbers.
fn run_type(expr: &str) -> String {
    match last(&format!("{NUMBERS}{expr}\n"), Mode::Run) {
        Ok((_, t)) => t,
        Err(e) => panic!("{expr}: {e:?}"),
    }
}

#[test]
fn conjugation_closes_on_one_frame() {
    // [V_a] = T_ab [V_b] T_ab⁻¹ (3.77) and [ω_a] = R_ab [ω_b] R_abᵀ (Prop. 3.5).
    frames("T_ab * [V_b] * inv(T_ab)", &["a"]);
    frames("T_ab * ([V_b] * inv(T_ab))", &["a"]);
    frames("T_ab * [V_b] * inv(T_ab) + [V_a]", &["a"]);
    frames("se3ToVec(T_ab * [V_b] * inv(T_ab))", &["a"]);
    frames("R_ab * [w_b] * R_ab.T", &["a"]);
    assert_eq!(run_type("T_ab * [V_b] * inv(T_ab)"), "se3");
    // Also with symbols only: g [X] g⁻¹ is back in the Lie algebra.
    for r in both("X = T_ab * [V_b]\nX * inv(T_ab)") {
        assert_eq!(r, Ok((vec!["a".to_string()], "se3".to_string())));
    }
    for r in both("R_ab * [w_b] * R_ab.T") {
        assert_eq!(r, Ok((vec!["a".to_string()], "so3".to_string())));
    }
    assert_eq!(run_type("se3ToVec(T_ab * [V_b] * inv(T_ab))"), "twist");
    assert_eq!(run_type("R_ab * [w_b] * R_ab.T"), "so3");
    // Conjugating by a displacement keeps the frame too.
    frames("exp([S_a] 0.3) * [V_a] * inv(exp([S_a] 0.3))", &["a"]);
    assert_eq!(
        run_type("se3ToVec(exp([S_a] 0.3) * [V_a] * exp(-[S_a] 0.3))"),
        "twist"
    );
    // An untagged [ω] is in the frame it meets.
    frames("R_ab * [(0, 0, 1)] * R_ab.T", &["a"]);
    // A vector of a map between two frames is refused (a twist is in one).
    frame_error("se3ToVec(T_ab * [V_b])", "a quantity in one frame");
    // Conjugating the wrong frame's quantity is refused.
    frame_error("T_ab * [V_a] * inv(T_ab)", "frames do not cancel");
}

#[test]
fn products_with_moved_frames_are_associative() {
    for (a, b, want) in [
        (
            "exp([S_a] 0.3) * T_ab * T_bc",
            "exp([S_a] 0.3) * (T_ab * T_bc)",
            vec!["a", "c'"],
        ),
        (
            "T_ab * exp([B_b] 0.3) * T_bc",
            "T_ab * (exp([B_b] 0.3) * T_bc)",
            vec!["a", "c'"],
        ),
        (
            "inv(T_ab) * exp([S_a] 0.3) * T_ab",
            "inv(T_ab) * (exp([S_a] 0.3) * T_ab)",
            vec!["b"],
        ),
        (
            "T_ab * exp([B_b] 0.3) * exp([B_b] 0.2)",
            "T_ab * (exp([B_b] 0.3) * exp([B_b] 0.2))",
            vec!["a", "b'"],
        ),
    ] {
        frames(a, &want);
        frames(b, &want);
    }
    // The body-frame displacement is a displacement in {b}: exp([B_b] θ)
    // with B_b = [Ad_T_ba] S_a.
    assert_eq!(run_type("inv(T_ab) * exp([S_a] 0.3) * T_ab"), "SE3");
    // A named moved frame cancels with the computed one.
    frames(
        "T_ab' = exp([S_a] 0.3) * T_ab\nT_ac = T_ab * T_bc\nT_b'c = inv(T_ab') * T_ac\nT_ab' * T_b'c",
        &["a", "c"],
    );
    // Powers are products: exp([S_a] θ)² moves {b} twice, as the product
    // does ({b} moved, printed {b'}; a name's primes are kept as written).
    frames("exp([S_a] 0.3)^2 * T_ab", &["a", "b'"]);
    frames("exp([S_a] 0.3) * exp([S_a] 0.3) * T_ab", &["a", "b'"]);
    frames("T_ab'' = T_ab * exp([B_b] 0.3)\nT_ab''", &["a", "b''"]);
    frames(
        "T_ab'' = T_ab * exp([B_b] 0.3)\nT_ab'' * exp([B_b] 0.3)",
        &["a", "b'"],
    );
    frames(
        "T_ab' = exp([S_a] 0.3) * T_ab\nexp([S_a] 0.3) * T_ab * inv(T_ab')",
        &["a", "a"],
    );
}

#[test]
fn a_transposed_transform_is_not_a_transform() {
    frame_error(
        "T_ab.T * p_a",
        "T_ab.T is the transpose of a transform, not a transform: the transpose is the inverse only for rotations",
    );
    frame_error(
        "transpose(T_ab) * T_ab",
        "the transpose is the inverse only for rotations",
    );
    frame_error(
        "T_bc * T_ab.T",
        "the transpose is the inverse only for rotations",
    );
    // In the book's superscripts too.
    frame_error("T_ab^T * p_a", "T_ab^T is the transpose of a transform");
    frame_error("T_abᵀ p_a", "T_abᵀ is the transpose of a transform");
    frames("R_ab^T * R_ab", &["b", "b"]);
    // Printed, it is a plain 4×4 matrix with no frames; transposed back, T_ab.
    for r in both("T_ab.T") {
        assert_eq!(r, Ok((vec![], "matrix".to_string())));
    }
    frames("T_ab.T.T * T_bc", &["a", "c"]);
    // With frame checks off, the product is still no point transform.
    let mut s = Session::new(Settings {
        frames: chasles::eval::env::FrameMode::Off,
        ..Settings::default()
    });
    let (_, err, n) = s.run_to_strings(
        "t.chs",
        &format!("{NUMBERS}T_ab.T * p_a\n"),
        Mode::Run,
        false,
    );
    assert_eq!(n, 1, "{err}");
    assert!(
        err.contains("domain error: a 4×4 matrix moves a point"),
        "{err}"
    );
    // For rotations the transpose is the inverse.
    frames("R_ab.T * R_ab", &["b", "b"]);
}

#[test]
fn the_wrong_operator_for_the_quantity_is_one_kind_of_error() {
    frame_error(
        "Ad(T_ab).T * V_a",
        "[Ad_T]ᵀ acts on wrenches, not on twists",
    );
    frame_error(
        "Ad(T_ab) * F_b",
        "a wrench does not change frame through [Ad_T]",
    );
}

/// The text output and the error/warning stream of running `src`.
fn text_and_err(src: &str) -> (String, String) {
    let mut s = Session::new(Settings::default());
    let (out, err, _) = s.run_to_strings("t.chs", src, Mode::Run, false);
    (out, err)
}

#[test]
fn naming_a_moved_frame_by_its_unmoved_letter_warns() {
    let (out, err) = text_and_err(&format!("{NUMBERS}Tq_ab = exp([S_a] 0.3) * T_ab\n"));
    assert!(out.contains("]  : SE(3) {a}←{b}\n"), "{out}");
    contains_all(
        &err,
        &[
            "warning: Tq_ab calls the moved frame {b'} by the name of the unmoved frame {b}",
            "name it Tq_ab' to keep them apart",
        ],
    );
    // The book's primes (T_sb', T_sb'') and another letter do not warn.
    for ok in [
        "T_ab' = exp([S_a] 0.3) * T_ab",
        "T_ab' = exp([S_a] 0.3) * exp([S_a] 0.3) * T_ab",
        "T_ab'' = T_ab * exp([B_b] 0.3)",
        "T_ac = T_ab * T_bc",
    ] {
        let (_, err) = text_and_err(&format!("{NUMBERS}{ok}\n"));
        assert!(!err.contains("warning"), "{ok}: {err}");
    }
}

// Issue 13: what a binding makes of a value (LANGUAGE.md §2, §5).

#[test]
fn scalars_take_no_frames_from_their_name() {
    for r in both("theta_b = 30 deg") {
        assert_eq!(r, Ok((vec![], "scalar".to_string())));
    }
    // The power is the same in every frame (§3.4): P_b − P_a is fine.
    for r in both("P_b = V_b.T * F_b\nP_a = V_a.T * F_a\nP_b - P_a") {
        assert_eq!(r, Ok((vec![], "scalar".to_string())));
    }
    frames("theta_b = 2\ntheta_b * p_a", &["a"]);
}

#[test]
fn rotation_and_transform_names_assert_their_group() {
    // Within 1e-9: accepted silently, with the group's type.
    let (out, err) = text_and_err("R_sb = [0, -1, 0; 1, 0, 0; 0, 0, 1]\n");
    assert!(
        out.ends_with(": SO(3) {s}←{b}\n") && err.is_empty(),
        "{out}{err}"
    );
    // Within 1e-2 (book values rounded to 3 digits): projected, with a warning.
    let (out, err) = text_and_err("R_sb = [0, -1, 0; 1, 0, 0; 0, 0, 1.001]\nR_sb[3, 3]\n");
    assert!(out.ends_with("\n1\n"), "{out}");
    contains_all(
        &err,
        &[
            "warning: R_sb names a rotation matrix, and the matrix is 2.00e-3 from SO(3) (DistanceToSO3)",
        ],
    );
    let (out, err) = text_and_err("T_ab = [1, 0, 0, 1; 0, 1, 0, 2; 0, 0, 1, 3; 0, 0, 0, 1.002]\n");
    assert!(out.contains(": SE(3) {a}←{b}\n"), "{out}");
    assert!(err.contains("(DistanceToSE3); projected"), "{err}");
    // A planar transform under a T_ name is SE(2).
    let (out, _) = text_and_err("T_ab = [0, -1, 1; 1, 0, 2; 0, 0, 1]\n");
    assert!(out.ends_with(": SE(2) {a}←{b}\n"), "{out}");
    // Farther: a domain error giving the distance.
    let (_, err) = text_and_err("R_sb = [1, 0, 0; 0, 1, 0; 0, 0, 2]\n");
    assert!(
        err.contains("domain error: R_sb names a rotation matrix, but the matrix is 3 from SO(3) (DistanceToSO3)"),
        "{err}"
    );
}

#[test]
fn explicit_conversions_read_any_matrix_of_their_size() {
    // SO3(M) says M is a rotation (§5), even when its numbers read as SE(2)
    // (last row (0, 0, 1)): within 1e-2 projected with a warning, farther a
    // domain error giving the distance.
    let (out, err) = text_and_err("R = SO3([0, -1, 0.001; 1, 0, 0; 0, 0, 1])\nR[1, 3]\n");
    assert!(
        out.contains(": SO(3)\n") && out.ends_with("\n0.0005\n"),
        "{out}"
    );
    assert!(
        err.contains("warning: not exactly in SO(3): distance 1.41e-3; projected"),
        "{err}"
    );
    let (out, err) = text_and_err("SO3([0, -1, 0.1; 1, 0, 0; 0, 0, 1])\n");
    assert!(out.is_empty(), "{out}");
    assert!(
        err.contains("domain error: not a rotation matrix: distance from SO(3) is 0.1418"),
        "{err}"
    );
    // A vector is still no matrix.
    let (_, err) = text_and_err("SO3((1, 2, 3))\n");
    assert!(
        err.contains("type error: SO3 takes a 3×3 matrix, not a 3-vector"),
        "{err}"
    );
    // SE3(M) of a 4×4 reads a transform the same way, keeping the frames.
    let (out, err) =
        text_and_err("T_ab = SE3([1, 0, 0, 1; 0, 1, 0, 2; 0, 0, 1, 3; 0, 0, 0, 1.001])\n");
    assert!(out.ends_with("0, 0, 0, 1]  : SE(3) {a}←{b}\n"), "{out}");
    assert!(err.contains("distance 1.00e-3; projected"), "{err}");
    let (_, err) = text_and_err("SE3([1, 0, 0, 0; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 2])\n");
    assert!(err.contains("distance from SE(3) is 1"), "{err}");
    // A rotation-only function given a 3×3 read as SE(2) but within 1e-2
    // of SO(3) treats it as §5 treats a rotation: projected, with a warning
    // (as binding it to R_sb does), literal or bound.
    for src in [
        "MatrixLog3([1, 0, 0; 0, 1, 0.0005; 0, 0, 1])\n",
        "M = [1, 0, 0; 0, 1, 0.0005; 0, 0, 1];\nMatrixLog3(M)\n",
    ] {
        let (out, err) = text_and_err(src);
        assert_eq!(out.trim(), "(-0.0002, 0, 0)  : 3-vector", "{src}{err}");
        assert!(err.contains("distance 7.07e-4; projected"), "{err}");
    }
    let (out, err) = text_and_err("RotInv([1, 0, 0; 0, 1, 0.0005; 0, 0, 1])[3, 2]\n");
    assert_eq!(out.trim(), "0.0002", "{err}");
    // A planar transform far from SO(3) stays a type error, whose help
    // names SO3(M).
    let (out, err) = text_and_err("RotInv(SE2(1, 2, 3))\n");
    assert!(out.is_empty(), "{out}");
    assert!(
        err.contains("type error: argument 1 of RotInv must be an SO(3), not an SE(2)"),
        "{err}"
    );
    assert!(err.contains("SO3(M) reads a matrix as a rotation"), "{err}");
}

/// An untyped 3×3 within 1e-2 of both SO(3) and SE(2) and in neither is
/// read as the nearer by `log`, and the reading is said, with the
/// distances and how to choose the other (§5); `explain log` reads it the
/// same way (it read such a matrix as a rotation while `log` gave se(2)).
/// A name chooses: R_ab is a rotation, with no note.
#[test]
fn a_3x3_near_both_so3_and_se2_says_which_reading_log_took() {
    let (out, err) = text_and_err("M = diag(1, 1, 1.000000001)\nlog(M)\n");
    assert!(out.ends_with("0, 0, 0]  : se(2)\n"), "{out}");
    assert!(
        err.contains(
            "note: this 3×3 is 2.00e-9 from SO(3) and 1.00e-9 from SE(2): read as SE(2), the nearer"
        ),
        "{err}"
    );
    assert!(err.contains("SO3(M) reads it as a rotation"), "{err}");
    let (out, err) = text_and_err("R_ab = diag(1, 1, 1.000000001)\nlog(R_ab)\n");
    assert!(out.ends_with("0, 0, 0]  : so(3) {a}\n"), "{out}");
    assert!(!err.contains("read as"), "{err}");
    let (out, err) = text_and_err("log(SO3(diag(1, 1, 1.000000001)))\n");
    assert!(
        out.ends_with(": so(3)\n") && !err.contains("read as"),
        "{out}{err}"
    );
    // The reading and the value: a quarter turn with x = 0.001 is 1e-9
    // from SE(2), 1.41e-3 from SO(3); as SE(2) the translation is kept.
    let m = "M = [0, -1, 0.001; 1, 0, 0; 0, 0, 1.000000001]\n";
    let (out, err) = text_and_err(&format!("{m}log(M)[1, 3]\n"));
    assert!(out.ends_with("\n0.0008\n"), "{out}");
    assert!(
        err.contains("1.41e-3 from SO(3) and 1.00e-9 from SE(2): read as SE(2)"),
        "{err}"
    );
    let (out, _) = text_and_err(&format!("{m}explain log(M)\n"));
    assert!(out.contains("SE(2) as SE(3)"), "{out}");
    // In SE(2) exactly (within 1e-9), no note.
    let (out, err) = text_and_err("log([0, -1, 0.001; 1, 0, 0; 0, 0, 1])\n");
    assert!(out.ends_with(": se(2)\n") && err.is_empty(), "{out}{err}");
    // JSON carries the note.
    let last = last_json("M = diag(1, 1, 1.000000001)\nlog(M)\n", Mode::Run);
    assert_eq!(last["type"], "se2", "{last}");
    assert!(
        last["warnings"].to_string().contains("read as SE(2)"),
        "{last}"
    );
}

/// A tuple written out and bound to a framed name: the name claims its
/// parts' frames, so a part that says otherwise is the frame error a
/// single value would be (`q_ab = (T_ab, T_cb)` was accepted and tagged
/// {a}←{b}), in run and check, with numbers and with symbols. Parts in
/// the name's frames (R_ab, a vector in {a} or {b}), untagged parts and
/// scalars pass; an untagged part takes the name's frames, as `T_ab = M`.
#[test]
fn a_framed_name_claims_the_frames_of_a_tuples_parts() {
    for setup in [NUMBERS, "given T_ab, T_cb : SE3\n"] {
        for (x, want) in [
            (
                "q_ab = (T_ab, T_cb)",
                "part 2 of the tuple is {b} in {c}, but the name q_ab says {b} in {a}",
            ),
            (
                "q_cd = (T_ab, 1)",
                "part 1 of the tuple is {b} in {a}, but the name q_cd says {d} in {c}",
            ),
        ] {
            for mode in [Mode::Run, Mode::Check] {
                assert_eq!(
                    last(&format!("{setup}{x}\n"), mode),
                    Err(("frame".into(), want.into())),
                    "{setup}{x} ({mode:?})"
                );
            }
        }
    }
    let ok = "R_ab = Rotz(0.3)\np_a = (1, 2, 3)\np_b = (1, 0, 0)\nM = eye(4)\n";
    for (x, frames) in [
        ("q_ab = (R_ab, p_a)\nq_ab[2]", vec!["a"]),
        ("q_ab = (R_ab, p_b)\nq_ab[2]", vec!["b"]),
        ("q_ab = (M, 1)\nq_ab[1]", vec!["a", "b"]),
        ("q_ab = (R_ab, 2)\nq_ab[1]", vec!["a", "b"]),
    ] {
        for mode in [Mode::Run, Mode::Check] {
            let got = last(&format!("{ok}{x}\n"), mode);
            let want: Vec<String> = frames.iter().map(|f| f.to_string()).collect();
            assert!(
                matches!(&got, Ok((f, _)) if *f == want),
                "{x} ({mode:?}): {got:?}"
            );
        }
    }
}

#[test]
fn type_labels_only_for_members_of_the_set() {
    // [ω]² is symmetric, not so(3); a power of a plain matrix is a plain matrix.
    assert_eq!(run_type("[w_b]^2"), "matrix");
    assert_eq!(run_type("[1, 2; 3, 4]^0"), "matrix");
    assert_eq!(run_type("[w_b]^1"), "so3");
    assert_eq!(run_type("Rotz(0.3)^2"), "SO3");
    assert_eq!(run_type("exp([S_a] 0.3)^2"), "SE3");
}

#[test]
fn only_the_books_letters_name_screws_twists_and_wrenches() {
    for (name, want) in [
        ("S", "screw"),
        ("S1", "screw"),
        ("S_b", "screw"),
        ("B2", "screw"),
        ("V_s", "twist"),
        ("F_b", "wrench"),
        ("Sum", "vector"),
        ("Bq", "vector"),
        ("Fk", "vector"),
    ] {
        assert_eq!(
            run_type(&format!("{name} = (0, 0, 1, 1, 2, 3)")),
            want,
            "{name}"
        );
    }
}

// A free vector is not a point (LANGUAGE.md §4), with numbers and with
// symbols alike (§7): the contract sweep of session 28 found `given w_b :
// vec3` let `T_sb * w_b` through (a `given` vector took no role from its
// letters), so a derivation checked with symbols passed what numbers refuse.

/// The verdict on the last statement of `src`: its frames, or its error's
/// kind, message and help.
fn verdict(src: &str, mode: Mode) -> Result<Vec<String>, [String; 3]> {
    let v = last_json(src, mode);
    if let Some(e) = v.get("error") {
        let text = |k: &str| e[k].as_str().unwrap_or("").to_string();
        return Err([text("kind"), text("message"), text("help")]);
    }
    Ok(v["frames"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f.as_str().unwrap().to_string())
        .collect())
}

/// The verdicts on `expr` with numbers, with symbols (run) and with
/// symbols (`chasles check`), all three the same.
fn one_verdict(expr: &str) -> Result<Vec<String>, [String; 3]> {
    const NUMBERS: &str = "T_sb = Trans((1, 2, 3))\nR_sb = Rotz(0.3)\nω_b = (0, 0, 1)\n\
w_b = (0, 0, 1)\nV_b = (0, 0, 1, 1, 0, 0)\nv_b = V_b.v\nf_b = (0, 1, 0)\nm_b = (1, 1, 0)\nŝ_b = (0, 0, 1)\n\
p_b = (1, 2, 3)\nq = (3, 2, 1)\ngiven u_b : free\nu_b = (0, 1, 0)\ngiven c_b, n_b : point\n\
c_b = (1, 0, 0)\nn_b = (0, 0, 2)\n";
    const SYMBOLS: &str = "given T_sb : SE3\ngiven R_sb : SO3\n\
given ω_b, w_b, v_b, f_b, m_b, ŝ_b, p_b, q : vec3\ngiven u_b : free\ngiven c_b, n_b : point\n";
    let numbers = verdict(&format!("{NUMBERS}{expr}\n"), Mode::Run);
    let symbols = verdict(&format!("{SYMBOLS}{expr}\n"), Mode::Run);
    let checked = verdict(&format!("{SYMBOLS}{expr}\n"), Mode::Check);
    assert_eq!(numbers, symbols, "{expr}: numbers vs symbols");
    assert_eq!(symbols, checked, "{expr}: run vs check");
    numbers
}

#[test]
fn a_transform_refuses_free_vectors_with_numbers_and_symbols_alike() {
    for (v, what) in [
        ("ω_b", "an angular velocity"),
        ("w_b", "an angular velocity"),
        ("v_b", "a linear velocity"),
        ("f_b", "a force"),
        ("m_b", "a moment"),
        ("ŝ_b", "a unit axis"),
        ("u_b", "a free vector"),
    ] {
        for expr in [format!("T_sb * {v}"), format!("x_s = T_sb * {v}")] {
            let Err([kind, message, help]) = one_verdict(&expr) else {
                panic!("{expr}: a transform moved a free vector");
            };
            assert_eq!(kind, "type", "{expr}");
            assert_eq!(
                message,
                format!(
                    "T_sb * {v} applies a transform to a free vector: {v} is {what}, not a point"
                )
            );
            assert!(
                help.contains(&format!("write T_sb.R * {v} (the book's R_sb {v})")),
                "{expr}: {help}"
            );
        }
        // a rotation moves it: R ω (3.35)
        assert_eq!(one_verdict(&format!("T_sb.R * {v}")), Ok(vec!["s".into()]));
        assert_eq!(one_verdict(&format!("R_sb * {v}")), Ok(vec!["s".into()]));
    }
    // v_b may be a point (Fig. 3.13): the help says how to declare it
    // (numbers typed as a literal, `v_b = (0, 0, 1.5)`, are the figure's
    // point already; the numbers above are a twist's linear velocity)
    let Err([_, _, help]) = one_verdict("T_sb * v_b") else {
        panic!("T_sb * v_b");
    };
    assert!(help.ends_with("given v_b : point"), "{help}");
    // points move: p_b, q by their letters, c_b and n_b declared
    for p in ["p_b", "c_b", "n_b"] {
        assert_eq!(one_verdict(&format!("T_sb * {p}")), Ok(vec!["s".into()]));
    }
    assert_eq!(one_verdict("T_sb * q"), Ok(vec!["s".into()]));
    // a derivation over symbols stops where numbers would: x_s never gets
    // the point transform's (1, 2, 4)
    let err = common::error(
        "given T_sb : SE3\ngiven w_b : vec3\nx_s = T_sb * w_b\nT_sb = Trans((1, 2, 3))\nw_b = (0, 0, 1)\nx_s\n",
    );
    assert!(
        err.contains("3:12: type error: T_sb * w_b applies a transform to a free vector"),
        "{err}"
    );
}

/// `given v_s : free` is kept when numbers are typed for v_s: the literal
/// rule of Fig. 3.13 (`v_b = (0, 0, 1.5)` is the figure's point) read the
/// declared velocity as a point, so `inv(T_sb) v_s` gave R^T (v_s − p) =
/// (0, 0, 0) for v_s = (1, 0, 0), not the velocity's R^T v_s. Undeclared,
/// the figure's literal is still a point.
#[test]
fn a_velocity_declared_free_stays_free_when_numbers_are_typed() {
    let setup = "T_sb = [Rotz(0.5), (1, 0, 0); 0, 1]\ngiven v_s : free\nv_s = (1, 0, 0)\n";
    let err = common::error(&format!("{setup}inv(T_sb) v_s\n"));
    assert!(
        err.contains("applies a transform to a free vector: v_s is a linear velocity"),
        "{err}"
    );
    let v = common::last_numbers(&format!("{setup}T_sb.R^T v_s\n"));
    let (c, s) = (0.5f64.cos(), 0.5f64.sin());
    assert!(
        (v[0] - c).abs() < 1e-12 && (v[1] + s).abs() < 1e-12,
        "{v:?}"
    );
    // the figure's point, undeclared
    let p =
        common::last_numbers("T_sb = [Rotz(0.5), (1, 0, 0); 0, 1]\nv_b = (0, 0, 1.5)\nT_sb v_b\n");
    assert_eq!(p, vec![1.0, 0.0, 1.5]);
}

/// Example 3.4's T_sc = e^{[S]θ} T_sb, checked as the book writes it: the
/// moved frame {b'} is compared with {c}, as binding `T_sc = exp(L) T_sb`
/// names it (`exp(L) * T_sb ≈ T_sc` was "cannot compare quantities in
/// different frames"); two named frames still do not compare.
#[test]
fn a_moved_frame_compares_with_the_frame_it_is_claimed_to_be() {
    let setup = "T_sb = [cos(30°), -sin(30°), 1; sin(30°), cos(30°), 2; 0, 0, 1]\n\
                 T_sc = [cos(60°), -sin(60°), 2; sin(60°), cos(60°), 1; 0, 0, 1]\n\
                 L = log(displacement(T_sb, T_sc))\n";
    for (cmp, want) in [
        ("exp(L) * T_sb ≈ T_sc", "true"),
        ("T_sc ≈ exp(L) T_sb", "true"),
        ("exp(L/2) * T_sb ≈ T_sc", "false"),
    ] {
        let out = printed(&format!("{setup}{cmp}\n"));
        assert_eq!(out.lines().last(), Some(want), "{cmp}: {out}");
    }
    let err = common::error(&format!("{setup}T_sb ≈ T_sc\n"));
    assert!(
        err.contains("cannot compare quantities in different frames"),
        "{err}"
    );
}

#[test]
fn destructuring_a_tuple_of_framed_values_keeps_each_ones_frames() {
    // `(A, B) = (T_ab, T_cb)` is two bindings at once: A is {a}←{b} and
    // B is {c}←{b}, so A * B does not cancel (it ran as an untagged
    // product, the tuple literal's one tag being none)
    frame_error("(A, B) = (T_ab, T_cb); A * B", "frames do not cancel");
    frames("(A, B) = (T_ab, T_bc); A * B", &["a", "c"]);
    frames("(X, k) = (T_bc, 2); X", &["b", "c"]);
    frame_error("(R_cd, k) = (R_ab, 2)", "the name R_cd says");
    // swapping evaluates both sides first
    frames("(A, B) = (T_ab, T_bc); (A, B) = (B, A); B * A", &["a", "c"]);
}

#[test]
fn a_whole_exponent_of_literals_is_known_to_check() {
    // `^` is right-associative and binds tighter than unary minus:
    // T_ab^-1^2 is T_ab^-(1²) = inv(T_ab), which run accepted and check
    // refused (its exponent was not a plain literal)
    frames("T_ab^-1^2", &["b", "a"]);
    frames("T_ab^(1 - 2)", &["b", "a"]);
    frames("T_ab^(2 - 2)", &[]);
    frame_error("T_ab^(1 + 1)", "frames do not cancel in a power");
    frame_error("T_ab^(2^-1)", "frames do not cancel in a power");
    // an exponent that is a name has no number in check: refused, saying
    // why (it may be the −1 that run accepts)
    let e = last("given T_ab : SE3\nn = -1\nT_ab^n\n", Mode::Check);
    let Err((kind, msg)) = e else { panic!("{e:?}") };
    assert_eq!(kind, "frame");
    assert!(msg.contains("unless its exponent is −1, 0 or 1"), "{msg}");
}

#[test]
fn indexing_a_tuple_gives_each_part_its_own_frames() {
    // `t = (T_ab, T_cb)` holds a {a}←{b} and a {c}←{b}: `t[1] * t[2]` is
    // T_ab * T_cb, refused (the tuple's one tag, none, made both parts
    // untagged, so the product ran)
    frame_error("t = (T_ab, T_cb); t[1] * t[2]", "frames do not cancel");
    frame_error("(T_ab, T_cb)[1] * (T_ab, T_cb)[2]", "frames do not cancel");
    frames("t = (T_ab, T_bc); t[1] * t[2]", &["a", "c"]);
    frames("t = (T_ab, T_cb); t[2]", &["c", "b"]);
    frames("t = (2, p_b); t[2]", &["b"]);
    // an index written as literal arithmetic is known without numbers
    frame_error(
        "t = (T_ab, T_cb); t[2 - 1] * t[1 + 1]",
        "frames do not cancel",
    );
    // nested tuples, a bound tuple destructured later, a function's
    // parameter, a binding's name
    frame_error(
        "n = ((T_ab, 2), T_cb); n[1][1] * n[2]",
        "frames do not cancel",
    );
    frame_error(
        "t = (T_ab, T_cb); (A, B) = t; A * B",
        "frames do not cancel",
    );
    frame_error(
        "f(x) = x[1] * x[2]; f((T_ab, T_cb))",
        "frames do not cancel",
    );
    frame_error("t = (T_ab, T_cb); R_cd = t[1].R", "the name R_cd says");
    // a builtin's tuple: its parts take the parts of its tag, as when
    // destructured ((R, p) = TransToRp(T_ab): R is {a}←{b}, p in {a})
    frames("TransToRp(T_ab)[1]", &["a", "b"]);
    frames("TransToRp(T_ab)[2]", &["a"]);
}

#[test]
fn a_tuple_part_picked_by_a_name_is_checked_when_run() {
    // run knows k's number, so it checks the part it picks; check has no
    // number for k and says it cannot tell which part t[k] is
    let src = "T_ab = Trans((1, 0, 0))\nT_bc = RpToTrans(Rotz(0.3), (0, 1, 0))\nT_cb = inv(T_bc)\n\
               t = (T_ab, T_cb)\nk = 2\nt[1] * t[k]\n";
    let mut s = Session::new(Settings::default());
    let (_, err, errors) = s.run_to_strings("t.chs", src, Mode::Run, false);
    assert_eq!(errors, 1, "{err}");
    assert!(err.contains("frames do not cancel"), "{err}");
    let mut s = Session::new(Settings::default());
    let (_, err, errors) = s.run_to_strings("t.chs", src, Mode::Check, false);
    assert_eq!(errors, 0, "{err}");
    assert!(
        err.contains("warning: cannot tell which part of `t` `t[k]` is"),
        "{err}"
    );
    // parts alike: nothing to tell apart, no warning (k a number check
    // does not know; a given k has none, refused by both)
    let src = "given T_ab : SE3\nt = (T_ab, T_ab)\nk = len(t)\nt[k] * inv(T_ab)\n";
    let mut s = Session::new(Settings::default());
    let (_, err, errors) = s.run_to_strings("t.chs", src, Mode::Check, false);
    assert_eq!((errors, err.as_str()), (0, ""));
    // and the parts' numbers are the parts'
    let out = printed(
        "T_ab = RpToTrans(Rotz(1), (1, 2, 3))\nT_bc = RpToTrans(Rotx(1), (0, 2, 3))\n\
         t = (T_ab, T_bc);\nk = 2;\nt[1] * t[k] == T_ab * T_bc",
    );
    assert_eq!(out.lines().last(), Some("true"), "{out}");
}

#[test]
fn a_tuple_spread_over_arguments_keeps_its_parts_frames() {
    // `g((T_ab, T_cb))` with g(x, y) = x * y is T_ab * T_cb; the spread
    // parts were untagged, so it ran (and `T_cd = RpToTrans(TransToRp(T_ab))`
    // bound a {a}←{b} under the name {c}←{d})
    frame_error(
        "g(x, y) = x * y; t = (T_ab, T_cb); g(t)",
        "frames do not cancel",
    );
    frames("g(x, y) = x * y; g((T_ab, T_bc))", &["a", "c"]);
    frames("RpToTrans(TransToRp(T_ab))", &["a", "b"]);
    frame_error("T_cd = RpToTrans(TransToRp(T_ab))", "the name T_cd says");
}

#[test]
fn tuples_compare_part_by_part() {
    // each part with its own kind and frames, as the values compare:
    // check passed `(T_ab, T_cb) == (1, T_ab)` (it compared the lengths
    // only), which run refuses
    frame_error("(T_ab, 1) == (T_cb, 1)", "different frames");
    for r in both("(T_ab, T_cb) == (1, T_ab)") {
        match r {
            Err((kind, msg)) => {
                assert_eq!(kind, "type", "{msg}");
                assert!(
                    msg.contains("cannot compare an SE(3) with a scalar"),
                    "{msg}"
                );
            }
            Ok(x) => panic!("expected a type error, got {x:?}"),
        }
    }
    for r in both("(T_ab, 1) == (T_ab, 1)") {
        assert_eq!(r, Ok((vec![], "bool".to_string())));
    }
    let out = printed("T_ab = Trans((1, 0, 0));\n(T_ab, 1) == (T_ab, 1)\n(T_ab, 1) == (T_ab, 2)");
    assert_eq!(out.lines().collect::<Vec<_>>(), ["true", "false"], "{out}");
}
