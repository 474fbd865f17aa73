//! `explain` of the logarithms, `log(R)`, `MatrixLog3`, `log(T)`,
//! `MatrixLog6` (§3.2.3.3, §3.3.3.2): each step against the book's
//! formulas, the branch and equation named, the hard cases θ → 0, θ → π.

use chasles::lie::steps::{self, Quantity};
use chasles::lie::{Mat3, Vec3, se3, so3};
use chasles::values::value::Value;
use proptest::prelude::*;
use std::f64::consts::PI;

mod common;
mod explain_common;
use explain_common::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// The steps of log T (§3.3.3.2) against the book's formulas.
    #[test]
    fn log6_steps_agree_with_the_book(w in unit_axis(), theta in angle(), p in point()) {
        let r = so3::exp(&(w * theta));
        let t = se3::from_rp(&r, &p);
        let steps = steps::log::log6(&t, None);
        // the last step is the value, bit for bit
        prop_assert_eq!(&steps.last().unwrap().value, &Quantity::Se3(se3::hat(&se3::log(&t))));
        // tr R (3.54)
        prop_assert_eq!(scalar(step(&steps, "trace")), r.trace());
        let th = scalar(step(&steps, "theta"));
        // θ = cos⁻¹((tr R − 1)/2) where cos⁻¹ is accurate (away from ±1)
        if (0.1..PI - 0.1).contains(&th) {
            let book = ((r.trace() - 1.0) / 2.0).acos();
            prop_assert!((th - book).abs() < 1e-12, "θ {th} vs {book}");
        }
        prop_assert!((th - theta).abs() < 1e-7, "θ {th} vs {theta}");
        // ω̂ from (3.61) where sin θ is not small
        let wh = vector(step(&steps, "omega_hat"));
        if th.sin() > 0.1 {
            let book = so3::vee(&((r - r.transpose()) / (2.0 * th.sin())));
            prop_assert!((wh - book).amax() < 1e-12, "ω̂ {wh} vs {book}");
        }
        prop_assert!((wh.norm() - 1.0).abs() < 1e-12);
        // G⁻¹(θ) (3.94) and v (3.93) where 1/θ is not huge
        if th > 1e-3 {
            let g = matrix(step(&steps, "G_inv"));
            let book = book_g_inv(&wh, th);
            prop_assert!((g - book).amax() < 1e-11 * book.amax(), "G⁻¹ {g} vs {book}");
            let v = vector(step(&steps, "v"));
            let want = book * p;
            prop_assert!((v - want).amax() < 1e-10 * (1.0 + want.amax()), "v {v} vs {want}");
        }
    }

    /// The steps of MatrixLog3 and of log R end with the value bit for bit,
    /// and a half turn cites the sub-case of (3.58)–(3.60) the book picks.
    #[test]
    fn log3_steps_end_with_the_value(w in unit_axis(), theta in angle()) {
        let r = so3::exp(&(w * theta));
        let s = steps::log::matrix_log3(&r, None);
        prop_assert_eq!(&s.last().unwrap().value, &Quantity::Vector3(so3::log(&r)));
        let s = steps::log::log3(&r, None);
        prop_assert_eq!(&s.last().unwrap().value, &Quantity::So3(so3::hat(&so3::log(&r))));
        if so3::is_half_turn(&r) {
            let w = step(&s, "omega_hat");
            let want = if 1.0 + r[(2, 2)] >= 1e-6 {
                "3.58"
            } else if 1.0 + r[(1, 1)] >= 1e-6 {
                "3.59"
            } else {
                "3.60"
            };
            prop_assert_eq!(w.reference, want);
        }
    }
}

/// `--json`: the statement's object carries `steps`, each with `ref`,
/// `name`, `text` and `value` (LANGUAGE.md §14), for each branch of the
/// logs as the book's library takes them: the general case, R = I, and
/// θ = π with the sub-cases (3.58), (3.59), (3.60).
#[test]
fn json_steps_name_the_branch_and_the_equation() {
    let cases = [
        ("explain log(Rotz(1))", "general", "3.61", [0.0, 0.0, 1.0]),
        (
            "explain log(Rotz(pi))",
            "half_turn_3.58",
            "3.58",
            [0.0, 0.0, 1.0],
        ),
        (
            "explain log(Roty(pi))",
            "half_turn_3.59",
            "3.59",
            [0.0, 1.0, 0.0],
        ),
        (
            "explain log(Rotx(pi))",
            "half_turn_3.60",
            "3.60",
            [1.0, 0.0, 0.0],
        ),
    ];
    for (src, case, eq, w) in cases {
        let lines = common::json(src);
        let steps = lines[0]["steps"].as_array().expect("steps");
        for s in steps {
            for key in ["ref", "name", "text", "value"] {
                assert!(s.get(key).is_some(), "{src}: {s} has no {key}");
            }
        }
        let by = |name: &str| {
            steps
                .iter()
                .find(|s| s["name"] == name)
                .unwrap_or_else(|| panic!("{src}: no {name}"))
        };
        assert_eq!(by("case")["value"], case, "{src}");
        assert_eq!(by("omega_hat")["ref"], eq, "{src}");
        assert_eq!(
            common::numbers(&by("omega_hat")["value"]),
            w.to_vec(),
            "{src}"
        );
        assert_eq!(by("trace")["ref"], "3.54");
        // the last step is the statement's value
        assert_eq!(steps.last().unwrap()["value"], lines[0]["value"], "{src}");
    }
    // R = I: case (i); a pure translation: θ = ‖p‖, v = p/‖p‖ (§3.3.3.2)
    let lines = common::json("explain MatrixLog6(Trans((3, 0, 4)))");
    let steps = lines[0]["steps"].as_array().unwrap();
    let by = |name: &str| steps.iter().find(|s| s["name"] == name).unwrap();
    assert_eq!(by("case")["value"], "pure_translation");
    assert_eq!(by("theta")["value"], 5);
    assert_eq!(common::numbers(&by("v")["value"]), vec![0.6, 0.0, 0.8]);
    // G⁻¹ (3.94) and v (3.93) of the book's MatrixLog6 docstring
    let lines =
        common::json("explain MatrixLog6([1, 0, 0, 0; 0, 0, -1, 0; 0, 1, 0, 3; 0, 0, 0, 1])");
    let steps = lines[0]["steps"].as_array().unwrap();
    let by = |name: &str| steps.iter().find(|s| s["name"] == name).unwrap();
    assert_eq!(by("G_inv")["ref"], "3.94");
    assert_eq!(by("v")["ref"], "3.93");
    let v = common::numbers(&by("v")["value"]);
    assert!(
        (v[1] - 1.5).abs() < 1e-12 && (v[2] - 1.5).abs() < 1e-12,
        "{v:?}"
    );
    // screw axis from q, ŝ, h and Grübler's dof
    let lines = common::json(
        "explain ScrewToAxis((3, 0, 0), (0, 0, 1), 2)\nexplain mech < links 4; joints 4R; planar >",
    );
    let names: Vec<&str> = lines[0]["steps"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    assert!(
        ["q", "s_hat", "h"].iter().all(|n| names.contains(n)),
        "{names:?}"
    );
    let dof = lines[1]["steps"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["name"] == "dof")
        .unwrap();
    assert_eq!(
        (dof["ref"].as_str(), dof["value"].as_i64()),
        (Some("2.4"), Some(1))
    );
}

/// θ = π − 1e-9: tr R rounds to −1 exactly, yet R ≠ Rᵀ and the logarithm
/// takes case (iii) (§3.2.3.3). The shown trace −1 and the case's "tr R ≠
/// −1" would contradict each other; the case says why both hold. And a
/// half turn whose float trace is not −1 says why case (ii) holds.
#[test]
fn the_case_explains_a_trace_that_rounds_against_it() {
    let lines = common::json("explain log(Rot((1, 2, 3), pi - 1e-9))");
    let steps = lines[0]["steps"].as_array().unwrap();
    assert_eq!(steps[0]["name"], "trace");
    assert_eq!(steps[0]["value"].as_f64(), Some(-1.0));
    assert_eq!(steps[1]["value"], "general");
    let note = steps[1]["note"].as_str().unwrap_or_default();
    assert!(note.contains("R ≠ Rᵀ"), "{:?}", steps[1]);
    // 2ω̂ω̂ᵀ − I for ω̂ = (1, 1, 1)/√3 in floats: symmetric, tr R = −1 + 6e-16
    let lines = common::json(
        "explain log([-0.33333333333333315, 0.6666666666666669, 0.6666666666666669; \
         0.6666666666666669, -0.33333333333333315, 0.6666666666666669; \
         0.6666666666666669, 0.6666666666666669, -0.33333333333333315])",
    );
    let steps = lines[0]["steps"].as_array().unwrap();
    assert_ne!(steps[0]["value"].as_f64(), Some(-1.0));
    assert_eq!(steps[1]["value"], "half_turn_3.58");
    let note = steps[1]["note"].as_str().unwrap_or_default();
    assert!(note.contains("R = Rᵀ"), "{:?}", steps[1]);
}

/// Rotz(π − 1e-12) Roty(π − 1e-12) turns by π − 1e-24: its floats are a
/// half turn, and certified arithmetic on its recipe tells MatrixLog3 the
/// sign of ω̂. explain decides θ = π the same way, so it shows case (iii)
/// with the value's ω̂, not case (ii) with −ω̂ and a value of the other sign.
#[test]
fn half_turn_decided_by_the_recipe_matches_the_value() {
    let lines = common::json("R = Rotz(pi - 1e-12) Roty(pi - 1e-12)\nexplain MatrixLog3(R)");
    let steps = lines[1]["steps"].as_array().unwrap();
    let by = |name: &str| steps.iter().find(|s| s["name"] == name).unwrap();
    assert_eq!(by("case")["value"], "general", "{steps:?}");
    let (theta, w) = (
        by("theta")["value"].as_f64().unwrap(),
        common::numbers(&by("omega_hat")["value"]),
    );
    let value = common::numbers(&lines[1]["value"]);
    for (wi, vi) in w.iter().zip(&value) {
        assert!(
            (wi * theta - vi).abs() < 1e-15,
            "ω̂θ {w:?}·{theta} vs {value:?}"
        );
    }
}

/// The `case` step that decides the SO(3) logarithm (the last one), with
/// its note.
fn rotation_case(o: &chasles::eval::interp::Outcome) -> (String, Option<String>) {
    let s = o.steps().iter().rfind(|s| s.name == "case").expect("case");
    match &s.value {
        Value::Str(c) => (c.to_string(), s.note.clone()),
        other => panic!("case is {other:?}"),
    }
}

/// The relations between the shown steps of a logarithm of `r` (§3.2.3.3,
/// and §3.3.3.2 when `p` is the translation): θ is the angle of R to
/// rounding (atan2(sin θ, cos θ), accurate also where cos⁻¹ of (3.54) is
/// not), case (ii) only for R = Rᵀ to rounding, a trace that rounds to −1
/// in case (iii) explained, ω̂ a unit vector with e^{[ω̂]θ} = R, and
/// v = G⁻¹(θ)p (3.93) with the book's G⁻¹ (3.94).
fn check_log_steps(o: &chasles::eval::interp::Outcome, r: &Mat3, p: Option<&Vec3>, what: &str) {
    let num = |name: &str| floats(shown(o, name));
    let (case, note) = rotation_case(o);
    if case == "identity" || case == "pure_translation" {
        assert!((r - Mat3::identity()).amax() <= 1e-15, "{what}: {case}");
        return;
    }
    let tr = num("trace")[0];
    assert!((tr - r.trace()).abs() <= 4e-16, "{what}: tr {tr}");
    let th = num("theta")[0];
    let sin = so3::vee(&(r - r.transpose())).norm() / 2.0;
    let reference = sin.atan2((tr - 1.0) / 2.0);
    assert!(
        (th - reference).abs() <= 4e-15,
        "{what}: θ {th} vs {reference}"
    );
    if case.starts_with("half_turn") {
        // (sin θ = ‖vee(R − Rᵀ)‖/2 at most 4ε, so3::HALF_TURN_SKEW)
        assert!(sin <= 1e-15, "{what}: {case} with sin θ = {sin:e}");
        // "θ = π": exactly, or a note says by how much the value's θ is not
        let said = o.steps().iter().find(|s| s.name == "theta").unwrap();
        assert!(
            th == PI || said.note.is_some(),
            "{what}: θ = π shown as {th}"
        );
    } else {
        assert_eq!(case, "general", "{what}");
        assert!(
            tr > -1.0 || note.is_some(),
            "{what}: tr R = {tr} in case (iii)"
        );
    }
    let w = Vec3::from_column_slice(&num("omega_hat"));
    assert!((w.norm() - 1.0).abs() <= 1e-14, "{what}: ‖ω̂‖ {}", w.norm());
    let tol = if th == PI { 1e-9 } else { 1e-13 };
    assert!(
        (so3::exp(&(w * th)) - r).amax() <= tol,
        "{what}: e^[ω̂]θ ≠ R"
    );
    if let (Some(p), true) = (p, th > 1e-6) {
        let g = Mat3::from_column_slice(&num("G_inv"));
        let book = book_g_inv(&w, th);
        assert!((g - book).amax() <= 1e-12 * book.amax(), "{what}: G⁻¹");
        let v = Vec3::from_column_slice(&num("v"));
        let want = book * p;
        assert!(
            (v - want).amax() <= 1e-12 / th * (1.0 + want.amax()),
            "{what}: v {v} vs {want}"
        );
    }
}

/// Seeded random rotations and transforms at the hard cases (θ → 0,
/// θ → π, θ = π exactly, a float half turn 2ω̂ω̂ᵀ − I, R = I) through the
/// language: the steps of explain log R, log T, MatrixExp6 and rpy agree
/// with each other by the book's equations, and end with the value.
#[test]
fn explained_steps_agree_with_each_other_at_the_hard_cases() {
    let mut rng = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 11) as f64 / (1u64 << 53) as f64
    };
    for i in 0..240 {
        let w = Vec3::new(next() - 0.5, next() - 0.5, next() - 0.5).normalize();
        let small = 10f64.powf(-12.0 + 9.0 * next());
        let theta = [next() * PI, small, PI - small, PI, 0.0, PI - 1e-15][i % 6];
        let r = if i % 12 == 3 {
            2.0 * w * w.transpose() - Mat3::identity()
        } else {
            so3::exp(&(w * theta))
        };
        let p = Vec3::new(next() - 0.5, next() - 0.5, next() - 0.5) * 10.0;
        let t = se3::from_rp(&r, &p);
        let setup = format!("T = {}\nR = T.R", matrix_literal(&t));
        let what = format!("case {i}: θ = {theta:e}");
        let o = last_outcome(&format!("{setup}\nexplain log(R)"));
        check_log_steps(&o, &r, None, &what);
        let o = last_outcome(&format!("{setup}\nexplain log(T)"));
        check_log_steps(&o, &r, Some(&p), &what);
        // (3.89): p = G(θ)v with the shown G and v, back to T
        let o = last_outcome(&format!("{setup}\nexplain MatrixExp6(MatrixLog6(T))"));
        if o.steps().iter().any(|s| s.name == "G") {
            let g = Mat3::from_column_slice(&floats(shown(&o, "G")));
            let v = Vec3::from_column_slice(&floats(shown(&o, "v")));
            let got = Vec3::from_column_slice(&floats(shown(&o, "p")));
            assert!(
                (g * v - got).amax() <= 1e-12 * (1.0 + got.amax()),
                "{what}: G v ≠ p"
            );
        }
        let back = floats(shown(&o, "T"));
        let want: Vec<f64> = t.as_slice().to_vec();
        let err = back
            .iter()
            .zip(&want)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(err <= 1e-9, "{what}: exp(log T) off by {err}");
        // App. B: the shown angles are the value's and give R back
        let o = last_outcome(&format!("{setup}\nexplain rpy(R)"));
        let a: Vec<f64> = ["roll", "pitch", "yaw"]
            .iter()
            .map(|n| floats(shown(&o, n))[0])
            .collect();
        assert_eq!(a, floats(&o.steps().last().unwrap().value), "{what}");
        let back = so3::rotz(a[2]) * so3::roty(a[1]) * so3::rotx(a[0]);
        assert!((back - r).amax() <= 1e-7, "{what}: rpy does not give R");
    }
}
