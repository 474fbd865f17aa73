//! `explain` (LANGUAGE.md §14, issue 37): every step's value agrees with an
//! independent computation of that quantity by the book's own formula
//! where it is accurate — tr R (3.54), θ = cos⁻¹((tr R − 1)/2), ω̂ from
//! (R − Rᵀ)/(2 sin θ) (3.61), G⁻¹(θ) from (3.94), v = G⁻¹(θ)p (3.93), G(θ)
//! from (3.88) — and the last step is the expression's value bit for bit,
//! in the library and through the language.

use chasles::eval::env::Mode;
use chasles::lie::steps::{self, Quantity, Step};
use chasles::lie::{Mat3, Mat4, Vec3, Vec6, se3, so3};
use chasles::session::{Session, Settings};
use chasles::values::value::Value;
use proptest::prelude::*;
use std::f64::consts::PI;

fn unit_axis() -> impl Strategy<Value = Vec3> {
    (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64)
        .prop_filter("axis not too short", |(x, y, z)| {
            x * x + y * y + z * z > 0.01
        })
        .prop_map(|(x, y, z)| Vec3::new(x, y, z).normalize())
}

/// θ: uniform on (0, π), near 0, near π, or exactly π.
fn angle() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => 1e-9..PI,
        1 => 1e-12..1e-5f64,
        1 => (1e-12..1e-5f64).prop_map(|d| PI - d),
        1 => Just(PI),
    ]
}

fn point() -> impl Strategy<Value = Vec3> {
    (-5.0..5.0f64, -5.0..5.0f64, -5.0..5.0f64).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn step<'a>(steps: &'a [Step], name: &str) -> &'a Step {
    steps
        .iter()
        .find(|s| s.name == name)
        .unwrap_or_else(|| panic!("no step {name} in {steps:#?}"))
}

fn scalar(s: &Step) -> f64 {
    match s.value {
        Quantity::Scalar(x) => x,
        ref q => panic!("{} is {q:?}", s.name),
    }
}

fn vector(s: &Step) -> Vec3 {
    match s.value {
        Quantity::Vector3(v) => v,
        ref q => panic!("{} is {q:?}", s.name),
    }
}

fn matrix(s: &Step) -> Mat3 {
    match s.value {
        Quantity::Matrix3(m) | Quantity::So3(m) | Quantity::Rotation(m) => m,
        ref q => panic!("{} is {q:?}", s.name),
    }
}

/// G⁻¹(θ) of (3.94), written as the book writes it.
fn book_g_inv(w: &Vec3, theta: f64) -> Mat3 {
    let wm = so3::hat(w);
    Mat3::identity() / theta - 0.5 * wm + (1.0 / theta - 0.5 / (theta / 2.0).tan()) * wm * wm
}

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

    /// The steps of exp([S]θ) (Prop. 3.16): G(θ) of (3.88) and p = G(θ)v
    /// (3.89), and the last step is the value bit for bit.
    #[test]
    fn exp6_steps_agree_with_the_book(w in unit_axis(), theta in 1e-2..3.0f64, v in point()) {
        let s = Vec6::new(w.x, w.y, w.z, v.x, v.y, v.z) * theta;
        let steps = steps::exp::exp6(&s);
        let t = se3::exp(&s);
        prop_assert_eq!(&steps.last().unwrap().value, &Quantity::Transform(t));
        let wm = so3::hat(&w);
        let g = Mat3::identity() * theta + (1.0 - theta.cos()) * wm + (theta - theta.sin()) * wm * wm;
        let got = matrix(step(&steps, "G"));
        prop_assert!((got - g).amax() < 1e-12 * (1.0 + g.amax()));
        let p = vector(step(&steps, "p"));
        prop_assert!((p - g * v).amax() < 1e-10 * (1.0 + p.amax()));
    }
}

/// A float as the language reads it back exactly.
fn lit(x: f64) -> String {
    format!("{x:?}")
}

fn matrix_literal(t: &Mat4) -> String {
    let rows: Vec<String> = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| lit(t[(i, j)]))
                .collect::<Vec<_>>()
                .join(", ")
        })
        .collect();
    format!("[{}]", rows.join("; "))
}

/// The numbers of a value.
fn numbers(v: &Value) -> Vec<u64> {
    match v {
        Value::Num { m, .. } => m.as_slice().iter().map(|x| (x + 0.0).to_bits()).collect(),
        Value::Tuple(vs) => vs.iter().flat_map(numbers).collect(),
        other => panic!("not numbers: {other:?}"),
    }
}

/// Through the language: `explain X`'s last step is the value of `X`
/// typed as a plain statement, bit for bit, for every algorithm.
#[test]
fn last_step_is_the_statement_value_bit_for_bit() {
    let mut rng = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    for _ in 0..20 {
        let w = Vec3::new(next(), next(), next());
        let t = se3::from_rp(
            &so3::exp(&(w * 1.5)),
            &(Vec3::new(next(), next(), next()) * 4.0),
        );
        let setup = format!(
            "T = {0}\nT_ab = {0}\nT_bc = {0}\nR = T.R\nF = wrench((1, 2, 3), (4, 5, 6))",
            matrix_literal(&t)
        );
        for e in [
            "log(T)",
            "MatrixLog6(T)",
            "log(R)",
            "MatrixLog3(R)",
            "exp(log(T))",
            "MatrixExp3(MatrixLog3(R))",
            "inv(T)",
            "Ad(T)",
            "Ad(T).T * F",
            "euler_zyx(R)",
            "rpy(R)",
            "quat(R)",
            "screw_params(MatrixLog6(T))",
            "inv(T_ab) T_ab T_bc",
        ] {
            let src = format!("{setup}\nexplain {e}\n{e}");
            let mut session = Session::new(Settings::default());
            let mut outs = Vec::new();
            let errors = session.run(&src, Mode::Run, false, |r| outs.push(r.result.clone()));
            assert_eq!(errors, 0, "{src}");
            let n = outs.len();
            let explained = outs[n - 2].as_ref().unwrap();
            let plain = outs[n - 1].as_ref().unwrap();
            let last = explained
                .steps()
                .last()
                .unwrap_or_else(|| panic!("no steps: {e}"));
            let value = plain.val.as_deref().unwrap();
            assert_eq!(numbers(&last.value), numbers(value), "{e}");
            assert!(explained.steps().len() >= 2, "{e}");
            assert!(
                explained.steps().iter().all(|s| !s.reference.is_empty()),
                "{e}"
            );
        }
    }
}

/// The outcome of the last statement of `src`.
fn last_outcome(src: &str) -> chasles::eval::interp::Outcome {
    let mut session = Session::new(Settings::default());
    let mut outs = Vec::new();
    let errors = session.run(src, Mode::Run, false, |r| outs.push(r.result.clone()));
    assert_eq!(errors, 0, "{src}");
    outs.pop().unwrap().unwrap()
}

fn shown<'a>(o: &'a chasles::eval::interp::Outcome, name: &str) -> &'a Value {
    &o.steps()
        .iter()
        .find(|s| s.name == name)
        .unwrap_or_else(|| panic!("no step {name}"))
        .value
}

fn floats(v: &Value) -> Vec<f64> {
    match v {
        Value::Num { m, .. } => m.as_slice().to_vec(),
        other => panic!("not numbers: {other:?}"),
    }
}

/// Twists from Ṫ (3.69)–(3.74): ω_b = vee(RᵀṘ), v_b = Rᵀṗ, ω_s =
/// vee(ṘRᵀ), v_s = ṗ − ω_s × p, computed here independently.
#[test]
fn twists_from_t_dot_agree_with_the_book() {
    let r = so3::exp(&Vec3::new(0.3, -0.2, 0.9));
    let p = Vec3::new(1.0, -2.0, 0.5);
    let w = Vec3::new(0.4, 0.1, -0.7);
    let pdot = Vec3::new(0.2, 0.3, -1.0);
    let rdot = so3::hat(&w) * r;
    let t = se3::from_rp(&r, &p);
    let mut tdot = Mat4::zeros();
    tdot.fixed_view_mut::<3, 3>(0, 0).copy_from(&rdot);
    tdot.fixed_view_mut::<3, 1>(0, 3).copy_from(&pdot);
    let setup = format!("T = {}\nTd = {}", matrix_literal(&t), matrix_literal(&tdot));
    let body = last_outcome(&format!("{setup}\nexplain inv(T) Td"));
    let wb = so3::vee(&(r.transpose() * rdot));
    let vb = r.transpose() * pdot;
    for (got, want) in floats(shown(&body, "omega_b")).iter().zip(wb.iter()) {
        assert!((got - want).abs() < 1e-12, "ω_b {got} vs {want}");
    }
    for (got, want) in floats(shown(&body, "v_b")).iter().zip(vb.iter()) {
        assert!((got - want).abs() < 1e-12, "v_b {got} vs {want}");
    }
    let space = last_outcome(&format!("{setup}\nexplain Td inv(T)"));
    let vs = pdot - w.cross(&p);
    for (got, want) in floats(shown(&space, "omega_s")).iter().zip(w.iter()) {
        assert!((got - want).abs() < 1e-12, "ω_s {got} vs {want}");
    }
    for (got, want) in floats(shown(&space, "v_s")).iter().zip(vs.iter()) {
        assert!((got - want).abs() < 1e-12, "v_s {got} vs {want}");
    }
}

/// `diff`: a step per node, bottom up, ending with the derivative itself.
#[test]
fn diff_steps_end_with_the_derivative() {
    let src = "given q(t) : scalar\nx = diff(sin(q)^2 + 3 q, t)\nexplain diff(sin(q)^2 + 3 q, t)";
    let mut session = Session::new(Settings::default());
    let mut outs = Vec::new();
    assert_eq!(
        session.run(src, Mode::Run, false, |r| outs.push(r.result.clone())),
        0
    );
    let explained = outs.pop().unwrap().unwrap();
    let plain = outs.pop().unwrap().unwrap();
    let texts: Vec<&str> = explained.steps().iter().map(|s| s.text.as_str()).collect();
    assert_eq!(explained.steps().len(), 7, "{texts:?}");
    assert!(texts[1].contains("chain rule"), "{texts:?}");
    assert!(texts[2].contains("power rule"), "{texts:?}");
    assert!(texts[6].contains("sum rule"), "{texts:?}");
    assert_eq!(&explained.steps()[6].value, plain.val.as_deref().unwrap());
}

/// Grübler (2.4): the counts and dof as numbers (Example 2.1, the four-bar).
#[test]
fn grubler_steps_have_the_counts() {
    let o = last_outcome("explain dof(mech < links 4; joints R R R R; planar >)");
    let n = |name| shown(&o, name).as_scalar().unwrap();
    assert_eq!(
        (n("m"), n("N"), n("J"), n("f_i"), n("dof")),
        (3.0, 4.0, 4.0, 4.0, 1.0)
    );
    assert_eq!(o.steps().last().unwrap().reference, "2.4");
}

mod common;

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

/// The exponential of a matrix that is not in so(3) or se(3) is not
/// Rodrigues' formula or Prop. 3.16: explain refuses rather than show the
/// wrong algorithm's steps; the value itself is still computed by `exp`.
#[test]
fn exp_of_a_general_matrix_is_not_explained_as_rodrigues() {
    let err = common::error("explain exp([1, 2, 0; 0, 1, 0; 0, 0, 1])");
    assert!(err.contains("no book algorithm"), "{err}");
    assert!(common::try_json("exp([1, 2, 0; 0, 1, 0; 0, 0, 1])").is_ok());
    let err = common::error("explain exp([1, 0, 0, 1; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1])");
    assert!(err.contains("no book algorithm"), "{err}");
}

/// T⁻¹A with A not a derivative of T whose product is not in se(3) is not
/// a twist (3.72): it is shown as the product it is, never as ω_b and v_b.
#[test]
fn a_product_that_is_not_a_twist_is_not_explained_as_one() {
    let src = "T = [Rotz(1), (1, 2, 3); 0, 1]\nA = [1, 2, 0, 1; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 0]\nexplain inv(T) A";
    let lines = common::json(src);
    let steps = lines[2]["steps"].as_array().unwrap();
    assert!(steps.iter().all(|s| s["name"] != "omega_b"), "{steps:?}");
    assert_eq!(steps.last().unwrap()["name"], "chain");
}

/// Near gimbal lock (cos b = 1e-16, not 0: r₁₁ and r₂₁ are typed as
/// nonzero) rpy decides the lock by R's exact entries; explain takes the
/// same branch (App. B), so its yaw, pitch and roll steps are the angles
/// of the value, not those of a lock the value did not take.
#[test]
fn euler_steps_take_the_gimbal_branch_of_the_value() {
    let r = "R = [-9.61014653969206e-17, 0.7654818453520746, -0.6434574923305988; \
             5.559190581948764e-17, -0.6434574923305988, -0.7654818453520746; \
             -1.0, -1.0933495538555965e-16, 1.9282613280258205e-17]";
    for (f, names) in [
        ("rpy", ["roll", "pitch", "yaw"]),
        ("euler_zyx", ["c", "b", "a"]),
    ] {
        let lines = common::json(&format!("{r}\nexplain {f}(R)"));
        let steps = lines[1]["steps"].as_array().unwrap();
        let by = |name: &str| steps.iter().find(|s| s["name"] == name).unwrap();
        assert_eq!(by("case")["value"], "general", "{f}: {steps:?}");
        let value = common::numbers(&lines[1]["value"]);
        let shown: Vec<f64> = names
            .iter()
            .map(|n| by(n)["value"].as_f64().unwrap())
            .collect();
        let shown = if f == "rpy" {
            shown
        } else {
            shown.into_iter().rev().collect()
        };
        assert_eq!(shown, value, "{f}");
    }
}

/// At small θ the shown G(θ) (3.88) and (1 − cos θ)[ω̂]² (3.51) keep
/// their (1 − cos θ) = 2 sin²(θ/2) and θ − sin θ terms: p = G(θ)v (3.89)
/// holds with the shown G and v (v = vθ/θ is large, so a G that lost
/// (1 − cos θ) = 3e-19 to cancellation was off by 1e-8 in G(θ)v).
#[test]
fn small_angle_g_and_rodrigues_terms_keep_their_digits() {
    let s = Vec6::new(
        3.690818798153363e-10,
        6.804176418606463e-10,
        -5.7700577213906866e-11,
        -26.725970898898634,
        17.31817383181878,
        28.894629513963952,
    );
    let steps = steps::exp::exp6(&s);
    let (g, v, p) = (
        matrix(step(&steps, "G")),
        vector(step(&steps, "v")),
        vector(step(&steps, "p")),
    );
    assert!((g * v - p).amax() < 1e-13 * p.amax(), "{} vs {p}", g * v);
    for theta in [1e-9, 1e-6, 1e-3] {
        let w = Vec3::new(0.0, 0.6, 0.8);
        let steps = steps::exp::exp3(&(w * theta));
        let got = matrix(step(&steps, "cos_term"));
        let half = (theta / 2.0).sin();
        let want = 2.0 * half * half * so3::hat(&w) * so3::hat(&w);
        assert!(
            (got - want).amax() <= 1e-15 * want.amax(),
            "θ {theta}: {got} vs {want}"
        );
    }
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
