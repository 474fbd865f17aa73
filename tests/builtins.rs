//! The builtin table (LANGUAGE.md §8): every entry's runnable example runs
//! without error, every book name has its snake_case alias, and the
//! section-3.6 functions give the book's numbers.

use std::f64::consts::PI;

use chasles::builtins;
use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};

mod common;
use common::{json, last_numbers, numbers};

fn assert_close(src: &str, want: &[f64], tol: f64) {
    let got = last_numbers(src);
    assert_eq!(got.len(), want.len(), "{src}: {got:?}");
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() <= tol, "{src}: got {got:?}, want {want:?}");
    }
}

#[test]
fn every_example_runs() {
    for b in builtins::table() {
        let mut s = Session::new(Settings::default());
        let (_, err, n) = s.run_to_strings("example", b.example, Mode::Run, false);
        assert_eq!(n, 0, "{}: example `{}` failed:\n{err}", b.name, b.example);
        assert!(
            b.example.contains(b.name) || b.aliases.iter().any(|a| b.example.contains(a)),
            "{}",
            b.name
        );
    }
}

#[test]
fn book_names_have_snake_case_aliases() {
    let pairs = [
        ("RotInv", "rot_inv"),
        ("VecToso3", "vec_to_so3"),
        ("so3ToVec", "so3_to_vec"),
        ("AxisAng3", "axis_ang3"),
        ("MatrixExp3", "matrix_exp3"),
        ("MatrixLog3", "matrix_log3"),
        ("RpToTrans", "rp_to_trans"),
        ("TransToRp", "trans_to_rp"),
        ("TransInv", "trans_inv"),
        ("VecTose3", "vec_to_se3"),
        ("se3ToVec", "se3_to_vec"),
        ("Adjoint", "adjoint"),
        ("ScrewToAxis", "screw_to_axis"),
        ("AxisAng6", "axis_ang6"),
        ("MatrixExp6", "matrix_exp6"),
        ("MatrixLog6", "matrix_log6"),
        ("NearZero", "near_zero"),
        ("Normalize", "normalize"),
        ("ProjectToSO3", "project_to_so3"),
        ("ProjectToSE3", "project_to_se3"),
        ("DistanceToSO3", "distance_to_so3"),
        ("DistanceToSE3", "distance_to_se3"),
        ("TestIfSO3", "test_if_so3"),
        ("TestIfSE3", "test_if_se3"),
    ];
    for (book, snake) in pairs {
        let a = builtins::lookup(book).unwrap_or_else(|| panic!("{book} missing"));
        let b = builtins::lookup(snake).unwrap_or_else(|| panic!("{snake} missing"));
        assert_eq!(a.name, b.name);
    }
    for (alias, book) in [
        ("skew", "VecToso3"),
        ("vee", "vee"),
        ("Ad", "Adjoint"),
        ("unskew", "so3ToVec"),
    ] {
        assert_eq!(builtins::lookup(alias).unwrap().name, book);
    }
}

#[test]
fn section_3_6_numbers() {
    let tol = 1e-4;
    assert_close(
        "RotInv([0, 0, 1; 1, 0, 0; 0, 1, 0])",
        &[0., 1., 0., 0., 0., 1., 1., 0., 0.],
        tol,
    );
    assert_close(
        "VecToso3((1, 2, 3))",
        &[0., -3., 2., 3., 0., -1., -2., 1., 0.],
        tol,
    );
    assert_close(
        "so3ToVec([0, -3, 2; 3, 0, -1; -2, 1, 0])",
        &[1., 2., 3.],
        tol,
    );
    assert_close(
        "(w, t) = AxisAng3((1, 2, 3))",
        &[0.26726124, 0.53452248, 0.80178373, 3.74165739],
        tol,
    );
    assert_close(
        "MatrixExp3((1, 2, 3))",
        &[
            -0.69492056,
            0.71352099,
            0.08929286,
            -0.19200697,
            -0.30378504,
            0.93319235,
            0.69297817,
            0.6313497,
            0.34810748,
        ],
        tol,
    );
    assert_close(
        "MatrixLog3([0, 0, 1; 1, 0, 0; 0, 1, 0])",
        &[1.20919958, 1.20919958, 1.20919958],
        tol,
    );
    assert_close(
        "TransInv([1, 0, 0, 0; 0, 0, -1, 0; 0, 1, 0, 3; 0, 0, 0, 1])",
        &[
            1., 0., 0., 0., 0., 0., 1., -3., 0., -1., 0., 0., 0., 0., 0., 1.,
        ],
        tol,
    );
    assert_close(
        "ScrewToAxis((3, 0, 0), (0, 0, 1), 2)",
        &[0., 0., 1., 0., -3., 2.],
        tol,
    );
    assert_close(
        "(S, th) = AxisAng6((1, 0, 0, 1, 2, 3))",
        &[1., 0., 0., 1., 2., 3., 1.],
        tol,
    );
    assert_close(
        "MatrixExp6((pi/2, 0, 0, 0, 3 pi/4, 3 pi/4))",
        &[
            1., 0., 0., 0., 0., 0., -1., 0., 0., 1., 0., 3., 0., 0., 0., 1.,
        ],
        tol,
    );
    assert_close(
        "MatrixLog6([1, 0, 0, 0; 0, 0, -1, 0; 0, 1, 0, 3; 0, 0, 0, 1])",
        &[PI / 2.0, 0., 0., 0., 0.75 * PI, 0.75 * PI],
        tol,
    );
    assert_close(
        "DistanceToSO3([1, 0, 0; 0, 0.1, -0.95; 0, 1, 0.1])",
        &[0.08835],
        tol,
    );
    assert_close(
        "Adjoint([1, 0, 0, 0; 0, 0, -1, 0; 0, 1, 0, 3; 0, 0, 0, 1])",
        &[
            1., 0., 0., 0., 0., 0., 0., 0., -1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 0., 0., 3.,
            1., 0., 0., 3., 0., 0., 0., 0., -1., 0., 0., 0., 0., 1., 0.,
        ],
        tol,
    );
}

#[test]
fn exp_and_log_are_the_matrix_maps() {
    // log returns the Lie-algebra matrix; exp of any square matrix is e^A.
    assert_close(
        "log([0, 0, 1; 1, 0, 0; 0, 1, 0])",
        &[
            0., -1.2092, 1.2092, 1.2092, 0., -1.2092, -1.2092, 1.2092, 0.,
        ],
        1e-4,
    );
    assert_close("exp([0, 1; 0, 0])", &[1., 1., 0., 1.], 1e-12);
    assert_close(
        "exp([-1, 0; 0, -2])",
        &[(-1f64).exp(), 0., 0., (-2f64).exp()],
        1e-12,
    );
    assert_close("exp([(0, 0, 1)] (pi/2)) * (1, 0, 0)", &[0., 1., 0.], 1e-12);
    assert_close(
        "exp(log(Rot((1, 2, 3), pi))) - Rot((1, 2, 3), pi)",
        &[0.; 9],
        1e-14,
    );
}

#[test]
fn representations_round_trip() {
    assert_close("euler_zyx(rot_zyx(0.1, 0.2, 0.3))", &[0.1, 0.2, 0.3], 1e-12);
    assert_close("euler_zxz(rot_zxz(0.1, 0.2, 0.3))", &[0.1, 0.2, 0.3], 1e-12);
    assert_close("rpy(rot_rpy(0.1, 0.2, 0.3))", &[0.1, 0.2, 0.3], 1e-12);
    assert_close(
        "quat(Rotz(pi/2))",
        &[
            std::f64::consts::FRAC_1_SQRT_2,
            0.,
            0.,
            std::f64::consts::FRAC_1_SQRT_2,
        ],
        1e-12,
    );
    assert_close("cayley(Rotz(pi/2))", &[0., 0., 1.], 1e-12);
    assert_close(
        "rot_quat(quat_mul(quat(Rotz(0.3)), quat(Rotx(0.2)))) - Rotz(0.3) * Rotx(0.2)",
        &[0.; 9],
        1e-14,
    );
}

#[test]
fn screw_params_of_a_pure_translation() {
    let lines = json("(q, s, h) = screw_params((0, 0, 0, 0, 0, 2))");
    let v = &lines[0]["value"];
    assert_eq!(v[2], "inf");
    assert_eq!(numbers(&v[1]), vec![0., 0., 1.]);
    assert_close(
        "(q, s, h) = screw_params(ScrewToAxis((3, 0, 0), (0, 0, 1), 2))",
        &[3., 0., 0., 0., 0., 1., 2.],
        1e-12,
    );
}

#[test]
fn screw_to_axis_of_an_infinite_pitch_is_the_pure_translation() {
    // h = ∞: S = (0, ŝ) (§3.3.2.2), wherever q is; no NaN.
    assert_close(
        "ScrewToAxis((1, 0, 0), (0, 0, 1), inf)",
        &[0., 0., 0., 0., 0., 1.],
        0.0,
    );
    // screw_params gives h = inf and q = 0 for a pure translation, and
    // ScrewToAxis takes them back, as `screw` does.
    for f in ["ScrewToAxis", "screw"] {
        assert_close(
            &format!("{f}(screw_params((0, 0, 0, 1, 0, 0)))"),
            &[0., 0., 0., 1., 0., 0.],
            0.0,
        );
        // h = −∞: the limit of the normalized axis as h → −∞, (0, −ŝ).
        assert_close(
            &format!("{f}((1, 2, 3), (0, 0, 2), -inf)"),
            &[0., 0., 0., 0., 0., -1.],
            0.0,
        );
    }
    // explain shows the case and ends with the same value.
    let lines = json("explain ScrewToAxis((1, 0, 0), (0, 0, 1), inf)");
    let steps = lines[0]["steps"].as_array().expect("steps");
    let last = steps.last().expect("a step");
    assert!(
        last["text"].as_str().is_some_and(|t| t.contains("h = ∞")),
        "{last}"
    );
    assert_eq!(numbers(&last["value"]), vec![0., 0., 0., 0., 0., 1.]);
    // A NaN pitch (inf − inf) is NaN entries with the NaN warning.
    let mut s = Session::new(Settings::default());
    let (out, err, n) = s.run_to_strings(
        "t",
        "ScrewToAxis((1, 0, 0), (0, 0, 1), inf - inf)\n",
        Mode::Run,
        false,
    );
    assert_eq!(n, 0, "{err}");
    assert!(
        out.contains("NaN") && err.contains("NaN entries"),
        "{out}{err}"
    );
}
