//! Issue 36, numbers at their limits: no finite input is refused because
//! a norm √Σx² under- or overflowed in floats (quaternions, axes, Cayley
//! parameters, exponential coordinates, screw axes), and the values are
//! the rotations the inputs mean.

mod common;

use common::{json_lines, run};

/// The numbers of the last JSON object of `src` (flattened), or the error.
fn numbers(src: &str) -> Vec<f64> {
    let (code, out, err) = run(&["--json", "-e", src]);
    assert_eq!(code, 0, "{src}: {out}{err}");
    let last = json_lines(&out).pop().expect("a value");
    let mut xs = Vec::new();
    fn walk(v: &serde_json::Value, xs: &mut Vec<f64>) {
        match v {
            serde_json::Value::Array(a) => a.iter().for_each(|v| walk(v, xs)),
            v => xs.push(v.as_f64().unwrap_or(f64::NAN)),
        }
    }
    walk(&last["value"], &mut xs);
    xs
}

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol)
}

const RZ90: [f64; 9] = [0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];

#[test]
fn a_tiny_or_huge_quaternion_is_its_rotation() {
    // (1, 0, 0, 1)/√2 is Rot(ẑ, π/2), at any scale
    for s in ["1e-170", "1e200", "1e-310", "1e307"] {
        let src = format!("rot_quat(({s}, 0, 0, {s}))");
        let r = numbers(&src);
        assert!(close(&r, &RZ90, 1e-15), "{src}: {r:?}");
    }
}

#[test]
fn a_tiny_or_huge_axis_is_its_direction() {
    // Rot((1, 1, 0), 1) at any scale of the axis
    let want = numbers("Rot((1, 1, 0), 1)");
    for s in ["1e-170", "1e170", "1e300", "1e-320"] {
        let src = format!("Rot(({s}, {s}, 0), 1)");
        assert!(close(&numbers(&src), &want, 1e-15), "{src}");
    }
    // AxisAng3 of tiny and huge coordinates: the unit axis and the angle
    let r = numbers("AxisAng3((1e-170, 1e-170, 0))");
    let h = std::f64::consts::FRAC_1_SQRT_2;
    assert!(close(&r[..3], &[h, h, 0.0], 1e-15), "{r:?}");
    assert!((r[3] / 1e-170 - 2f64.sqrt()).abs() < 1e-15, "{r:?}");
    let r = numbers("AxisAng3((3e200, 4e200, 0))");
    assert!(close(&r[..3], &[0.6, 0.8, 0.0], 1e-15), "{r:?}");
    assert!((r[3] / 5e200 - 1.0).abs() < 1e-15, "{r:?}");
    // the norm itself
    assert!((numbers("norm((3e200, 4e200, 0))")[0] / 5e200 - 1.0).abs() < 1e-15);
    assert!((numbers("norm((3e-170, 4e-170))")[0] / 5e-170 - 1.0).abs() < 1e-15);
}

#[test]
fn huge_cayley_parameters_are_a_half_turn() {
    // r = ẑ tan(θ/2) → ∞ as θ → π: Rot(ẑ, π) (to 2/1e200)
    let r = numbers("rot_cayley((0, 0, 1e200))");
    assert!(
        close(&r, &[-1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0], 1e-15),
        "{r:?}"
    );
    // and a tiny r is the identity to first order: R = I + 2[r] + O(r²)
    let r = numbers("rot_cayley((1e-170, 0, 0))");
    assert_eq!(r, [1.0, 0.0, 0.0, 0.0, 1.0, -2e-170, 0.0, 2e-170, 1.0]);
    // an ordinary r as before: r = ẑ tan(π/4) is Rot(ẑ, π/2)
    let r = numbers("rot_cayley((0, 0, 1))");
    assert!(close(&r, &RZ90, 1e-15), "{r:?}");
}

#[test]
fn huge_exponential_coordinates_are_a_rotation() {
    // exp([(1e170, 0, 0)]) is Rotx of the float 1e170 (its sine and cosine
    // are those of that number), not inf or NaN
    let r = numbers("exp([(1e170, 0, 0)])");
    let (s, c) = 1e170f64.sin_cos();
    assert!(
        close(&r, &[1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c], 1e-15),
        "{r:?}"
    );
}

#[test]
fn screw_parameters_of_a_huge_twist() {
    // V = (ω, v) = 1e200 (x̂, ŷ): q = ω × v/‖ω‖² = ẑ, ŝ = x̂, h = 0
    let r = numbers("screw_params((1e200, 0, 0, 0, 1e200, 0))");
    assert!(
        close(&r, &[0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0], 1e-15),
        "{r:?}"
    );
}

/// The text of `src` run: (stdout, stderr).
fn texts(src: &str) -> (String, String) {
    let (_, out, err) = run(&["-e", src]);
    (out, err)
}

#[test]
fn a_whole_number_of_radians_beyond_a_turn_gets_a_note() {
    let (out, err) = texts("Rotz(30)");
    assert!(
        err.contains("note: 30 rad = 1718.9°; did you mean `30 deg`?"),
        "{err}"
    );
    // the value is still 30 radians: cos 30 = 0.1543
    assert!(out.starts_with("[ 0.1543, 0.988,  0"), "{out}");
    // in JSON too, on the statement's object
    let (_, out, _) = run(&["--json", "-e", "Rot((0, 0, 1), -45)"]);
    let j = &json_lines(&out)[0];
    assert_eq!(
        j["warnings"][0]["message"],
        "-45 rad = -2578.3°; did you mean `-45 deg`?"
    );
    // said explicitly, within a turn, or in degrees: no note
    for src in [
        "Rotz(30 rad)",
        "Rotz(6)",
        "Rotz(30 deg)",
        "Rotx(pi)",
        "Rotz(2.5)",
    ] {
        let (_, err) = texts(src);
        assert!(err.is_empty(), "{src}: {err}");
    }
}

#[test]
fn a_misspelled_degree_unit_suggests_deg() {
    for src in ["Rotz(30 dgr)", "Rotz(30 degree)", "Rotz(30 degrees)"] {
        let (_, err) = texts(src);
        assert!(err.contains("30 deg or 30°"), "{src}: {err}");
    }
}

#[test]
fn a_printed_picture_never_replaces_a_users_file() {
    let dir = common::scratch("edges-pictures");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("draw-2.svg"), "mine").unwrap();
    let src = "T_ab = Trans((1, 0, 0))\ndraw(T_ab)\n";
    let (code, out, err) = common::run_in(&["-e", src], &dir);
    assert_eq!(code, 0, "{err}");
    // the user's file is kept, the picture takes the next free name, and
    // the statement says so (in text and in JSON)
    assert_eq!(
        std::fs::read_to_string(dir.join("draw-2.svg")).unwrap(),
        "mine"
    );
    let svg = std::fs::read_to_string(dir.join("draw-2_2.svg")).unwrap();
    assert!(svg.starts_with("<svg"), "{svg}");
    assert!(out.contains("→ draw-2_2.svg"), "{out}");
    assert!(
        err.contains("note: 'draw-2.svg' exists and is not a picture chasles printed: it is kept, and this picture is 'draw-2_2.svg'"),
        "{err}"
    );
    // a rerun replaces its own picture, not the user's, and adds no file
    let (_, out, _) = common::run_in(&["--json", "-e", src], &dir);
    let j = &json_lines(&out)[1];
    assert_eq!(j["value"]["file"], "draw-2_2.svg", "{j}");
    assert!(
        j["warnings"][0]["message"]
            .as_str()
            .unwrap()
            .contains("'draw-2.svg' exists"),
        "{j}"
    );
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["draw-2.svg", "draw-2_2.svg"]);
    // a picture chasles printed there before is replaced, with no note
    std::fs::remove_file(dir.join("draw-2.svg")).unwrap();
    for _ in 0..2 {
        let (_, out, err) = common::run_in(&["-e", src], &dir);
        assert!(out.contains("→ draw-2.svg"), "{out}");
        assert!(err.is_empty(), "{err}");
    }
    assert!(!dir.join("draw-2_3.svg").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_books_point_v_of_figure_3_13() {
    // §3.3.1.2, Fig. 3.13: v_b = (0, 0, 1.5), v_a = T_ab v_b with v a point
    let src = "T_ab = [1, 0, 0, 1; 0, 1, 0, 2; 0, 0, 1, 0; 0, 0, 0, 1]\nv_b = (0, 0, 1.5)\nv_a = T_ab v_b\n";
    assert_eq!(numbers(src), [1.0, 2.0, 1.5]);
    // a value that is a linear velocity (a twist's v) is still refused
    let (code, _, err) = run(&[
        "-e",
        "T_ab = Trans((1, 2, 0))\nV_b = (0, 0, 1, 1, 0, 0)\nv_b = V_b.v\nT_ab * v_b\n",
    ]);
    assert_eq!(code, 1);
    assert!(
        err.contains("v_b is a linear velocity, not a point"),
        "{err}"
    );
    // and a rotation still acts on a literal v as on any vector
    assert!(close(
        &numbers("R_ab = Rotz(pi/2)\nv_b = (1, 0, 0)\nR_ab v_b"),
        &[0.0, 1.0, 0.0],
        1e-15
    ));
}

#[test]
fn a_user_function_may_shadow_a_builtin_with_a_note() {
    let (code, out, err) = run(&["-e", "trans(n) = n + 1\ntrans(2)\nrot(n) = 2 n\nrot(3)\n"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out, "3\n6\n");
    assert!(
        err.contains("note: trans is now your function: it hides the builtin Trans"),
        "{err}"
    );
    // the builtin under its other names is untouched
    assert_eq!(
        numbers("trans(n) = n\nTrans((1, 2, 3))")[3],
        1.0,
        "Trans keeps its meaning"
    );
}

#[test]
fn contact_words_suggest_rolling_or_sliding() {
    for (src, want) in [
        (
            "mech < links 8; joints 6 contact, 4R; planar >",
            "say which point contact, `rolling` or `sliding`",
        ),
        (
            "mech < links 3; joints 2R 1 point; planar >",
            "say which point contact",
        ),
        (
            "mech < links 3; joints 2R 1 roll; planar >",
            "did you mean `rolling`?",
        ),
        (
            "mech < links 3; joints 2R 1 slide; spatial >",
            "did you mean `sliding`?",
        ),
    ] {
        let (code, _, err) = run(&["-e", src]);
        assert_eq!(code, 1, "{src}");
        assert!(err.contains(want), "{src}: {err}");
        assert!(!err.contains("cylindrical"), "{src}: {err}");
    }
    // the words themselves work: 2R and a rolling contact in the plane,
    // 3(3 − 1 − 3) + 2 + 1 = 0
    assert_eq!(
        numbers("dof(mech < links 3; joints 2R 1 rolling; planar >)"),
        [0.0]
    );
}

/// A count written as a decimal is a number like any other count (§9:
/// counts may be expressions): `links 2.0` is 2 links, `links 2.5` the
/// domain error `links n` with n = 2.5 gives. Both were a syntax error at
/// the point whose help said to write "2.0 or 2" — what was written; in
/// `joints 2.5R` the help now says a count is a whole number.
#[test]
fn a_decimal_count_is_read_as_a_number() {
    assert_eq!(
        numbers("dof(mech < links 4.0; joints 4R; planar >)"),
        numbers("dof(mech < links 4; joints 4R; planar >)")
    );
    assert_eq!(numbers("dof(mech < legs 6.0 UPS; spatial >)"), [6.0]);
    for src in [
        "mech < links 2.5; joints R; planar >",
        "n = 2.5\nmech < links n; joints R; planar >",
    ] {
        let (code, _, err) = run(&["-e", src]);
        assert_eq!(code, 1, "{src}");
        assert!(
            err.contains("domain error: a count must be a whole number, not 2.5"),
            "{src}: {err}"
        );
    }
    let (code, _, err) = run(&["-e", "mech < links 4; joints 2.5R; planar >"]);
    assert_eq!(code, 1);
    assert!(err.contains("syntax error"), "{err}");
    assert!(
        err.contains("help: a count is a whole number: 2, not 2.5"),
        "{err}"
    );
    assert!(!err.contains("2.0 or 2"), "{err}");
    // (a number with no digit after its point keeps that help)
    let (_, _, err) = run(&["-e", "x = (2., 1)"]);
    assert!(!err.contains("a count is a whole number"), "{err}");
}

#[test]
fn identity_takes_the_size_a_call_fixes() {
    // frame(I, p) is Trans(p); Ad(I) the 6×6 identity; RotInv(I) = I
    assert_eq!(numbers("frame(I, (1, 2, 3))"), numbers("Trans((1, 2, 3))"));
    let ad = numbers("Ad(I)");
    assert_eq!(ad.len(), 36);
    assert!((0..36).all(|k| ad[k] == if k % 7 == 0 { 1.0 } else { 0.0 }));
    assert_eq!(numbers("RotInv(I)").len(), 9);
    // frame(R) is [R, 0; 0, 1], so frame(I) is the identity transform
    let id = numbers("frame(I)");
    assert!(
        (0..16).all(|k| id[k] == if k % 5 == 0 { 1.0 } else { 0.0 }),
        "{id:?}"
    );
    assert_eq!(
        numbers("frame(Rotz(pi/3))"),
        numbers("RpToTrans(Rotz(pi/3), (0, 0, 0))")
    );
    let (_, out, _) = run(&["-e", "given t : scalar\nframe(Rotz(t))"]);
    assert!(out.starts_with("[cos(t), -sin(t), 0, 0"), "{out}");
    // a call that leaves the size open still asks for it
    let (code, _, err) = run(&["-e", "inv(I)"]);
    assert_eq!(code, 1);
    assert!(err.contains("`I` has no size here"), "{err}");
}

#[test]
fn axis_angle_of_the_books_bracket_form() {
    // AxisAng3([ω̂]θ) reads the so(3) matrix as its vector ω̂θ (§3.2.3.3)
    assert!(close(
        &numbers("R = Rotz(1)\nAxisAng3(log(R))"),
        &[0.0, 0.0, 1.0, 1.0],
        1e-15
    ));
    assert_eq!(
        numbers("AxisAng3(log(Rot((1, 2, 2)/3, 0.5)))"),
        numbers("AxisAng3(MatrixLog3(Rot((1, 2, 2)/3, 0.5)))")
    );
    // and AxisAng6([S]θ) as AxisAng6 of the vector Sθ
    assert_eq!(
        numbers("AxisAng6(log(RpToTrans(Rotz(1), (1, 2, 3))))"),
        numbers("AxisAng6(MatrixLog6(RpToTrans(Rotz(1), (1, 2, 3))))")
    );
    // a matrix that is not skew-symmetric is still refused
    let (code, _, _) = run(&["-e", "AxisAng3([1, 0, 0; 0, 1, 0; 0, 0, 1])"]);
    assert_eq!(code, 1);
}

#[test]
fn hostile_numbers_get_answers_not_panics() {
    // huge and tiny angles and axes: values or clear refusals, exit 0 or 1
    for src in [
        "Rotz(1e308)",
        "Rot((1e308, 1e308, 1e308), 1)",
        "rot_quat((1e308, 1e308, 0, 0))",
        "rot_cayley((1e308, 1e308, 1e308))",
        "AxisAng3((1e-320, 0, 0))",
        "exp([(1e-300, 0, 0)])",
        "acos(-1.0000000000000002)",
        "sqrt(-0.0)",
    ] {
        let (code, out, err) = run(&["-e", src]);
        assert!(code == 0 || code == 1, "{src}: {code}");
        assert!(!err.contains("panicked"), "{src}: {err}");
        assert!(code == 1 || !out.is_empty(), "{src}");
    }
    // no note for an angle beyond what degrees are written as
    let (_, _, err) = run(&["-e", "Rotz(1e308)"]);
    assert!(!err.contains("did you mean"), "{err}");
    // rot_cayley of huge parameters along (1, 1, 1) is the half turn about it
    let r = numbers("rot_cayley((1e308, 1e308, 1e308))");
    let h = numbers("Rot((1, 1, 1), pi)");
    assert!(close(&r, &h, 1e-15), "{r:?} vs {h:?}");
}

/// The JSON warnings' messages of the last statement of `src`.
fn notes(src: &str) -> Vec<String> {
    let (code, out, err) = run(&["--json", "-e", src]);
    assert_eq!(code, 0, "{src}: {out}{err}");
    let last = json_lines(&out).pop().expect("a value");
    last["warnings"]
        .as_array()
        .map(|ws| {
            ws.iter()
                .map(|w| w["message"].as_str().unwrap_or_default().to_owned())
                .collect()
        })
        .unwrap_or_default()
}

#[test]
fn a_zero_angle_has_no_axis_and_says_so() {
    // θ = 0: ω̂ is undefined (§3.2.3.3, case (i)); the zero vector stands
    // in for it, with a note (the book's Python gives NaN)
    assert_eq!(numbers("axis_ang3((0, 0, 0))"), [0.0, 0.0, 0.0, 0.0]);
    let n = notes("axis_ang3((0, 0, 0))");
    assert!(
        n.len() == 1 && n[0].starts_with("θ = 0: no rotation, so the axis ω̂ is undefined"),
        "{n:?}"
    );
    assert_eq!(numbers("AxisAng6((0, 0, 0, 0, 0, 0))"), [0.0; 7]);
    let n = notes("AxisAng6((0, 0, 0, 0, 0, 0))");
    assert!(
        n.len() == 1 && n[0].starts_with("θ = 0: no motion, so the screw axis S is undefined"),
        "{n:?}"
    );
    // any θ > 0 has its axis, however small θ is, and no note: a tiny
    // rotation, a pure translation
    assert_eq!(
        numbers("axis_ang3((1e-300, 0, 0))"),
        [1.0, 0.0, 0.0, 1e-300]
    );
    assert!(notes("axis_ang3((1e-300, 0, 0))").is_empty());
    assert_eq!(
        numbers("axis_ang6((0, 0, 0, 3, 0, 4))"),
        [0.0, 0.0, 0.0, 0.6, 0.0, 0.8, 5.0]
    );
    assert!(notes("axis_ang6((0, 0, 0, 3, 0, 4))").is_empty());
}

#[test]
fn a_subnormal_axis_is_a_unit_axis() {
    // θ = ‖(1e-320, 1e-320, 0)‖ is subnormal: ω̂ = ω̂θ/θ kept three digits
    // (0.70719776…); scaled first, it is (1, 1, 0)/√2 to the last digit
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let r = numbers("AxisAng3((1e-320, 1e-320, 0))");
    assert!(close(&r[..3], &[h, h, 0.0], 2e-16), "{r:?}");
    let r = numbers("AxisAng6((1e-320, 1e-320, 0, 0, 0, 0))");
    assert!(close(&r[..6], &[h, h, 0.0, 0.0, 0.0, 0.0], 2e-16), "{r:?}");
    let r = numbers("AxisAng6((0, 0, 0, 1e-320, 0, 1e-320))");
    assert!(close(&r[..6], &[0.0, 0.0, 0.0, h, 0.0, h], 2e-16), "{r:?}");
}

#[test]
fn a_slow_turn_is_a_turn_not_a_pure_translation() {
    // V = (1e-7 x̂, ẑ): ω ≠ 0, so a turn about x̂ through q = ω × v/‖ω‖² =
    // (0, −1e7, 0) with pitch 0 (§3.3.2.2), not the pure translation along
    // ẑ (q = 0, h = ∞) that NearZero(‖ω‖) made of it
    let r = numbers("screw_params((1e-7, 0, 0, 0, 0, 1))");
    assert!(
        close(&r, &[0.0, -1e7, 0.0, 1.0, 0.0, 0.0, 0.0], 1e-8),
        "{r:?}"
    );
    let n = notes("screw_params((1e-7, 0, 0, 0, 0, 1))");
    assert!(
        n.len() == 1 && n[0].contains("not a pure translation") && n[0].contains("h = ∞"),
        "{n:?}"
    );
    // AxisAng6 keeps the book's software's reading (θ = ‖v‖), and says
    // that S is then no unit screw axis, and what the turn is
    assert_eq!(
        numbers("AxisAng6((1e-7, 0, 0, 0, 0, 1))"),
        [1e-7, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0]
    );
    let n = notes("AxisAng6((1e-7, 0, 0, 0, 0, 1))");
    assert!(
        n.len() == 1 && n[0].contains("not a unit screw axis") && n[0].contains("-10000000"),
        "{n:?}"
    );
    // ω = 0 exactly is the pure translation, with no note
    assert_eq!(
        numbers("screw_params((0, 0, 0, 0, 3, 4))")[3..6],
        [0.0, 0.6, 0.8]
    );
    assert!(notes("screw_params((0, 0, 0, 0, 3, 4))").is_empty());
}

#[test]
fn the_point_of_a_screw_of_large_pitch_keeps_its_digits() {
    // S = ScrewToAxis(q, ŝ, 1e8) rounded: v is nearly 1e8 ŝ, and
    // ŝ × v/‖ω‖ cancelled to q right to 1e-9 only. Reference: mpmath at 40
    // digits of the typed decimals (q = ω × v/‖ω‖², h = ωᵀv/‖ω‖²).
    let r = numbers(
        "screw_params((0.16132283906425882, 0.912466834400418, 0.37600427885268467, \
         16132286.961491106, 91246683.72653003, 37600425.87927317))",
    );
    let q = [-1.9381249808177318, 1.4723304532401601, -2.7414285992643113];
    assert!(close(&r[..3], &q, 4e-16 * 3.0), "{r:?}");
    assert!((r[6] - 99_999_999.999_999_99).abs() <= 1.5e-8, "{r:?}");
}

#[test]
fn the_distance_of_a_computed_matrix_near_so3_keeps_its_digits() {
    // M = Rotx(0.7) Rotz(0.3) (1 + 3e-12) in floats: the plain product
    // RᵀR − I cancelled to five digits of ‖MᵀM − I‖_F (1.0392459e-11).
    // Reference: mpmath at 50 digits of M's floats as --json prints them.
    let m = "M = untag(Rotx(0.7) * Rotz(0.3)) * (1 + 3e-12)";
    assert_eq!(
        numbers(m),
        [
            0.955336489128472,
            -0.2955202066622261,
            0.0,
            0.22602632125030112,
            0.7306816499377045,
            -0.6442176872396237,
            0.1903793440679438,
            0.6154446635601198,
            0.7648421872867831
        ]
    );
    let want = 1.039_243_251_086_133_7e-11;
    let d = numbers(&format!("{m}; DistanceToSO3(M)"))[0];
    assert!((d / want - 1.0).abs() < 1e-15, "{d} vs {want}");
    let t = numbers(&format!("{m}; DistanceToSE3([M, (1, 2, 3); 0, 0, 0, 1])"))[0];
    assert!((t / want - 1.0).abs() < 1e-15, "{t} vs {want}");
}

/// Exponential coordinates whose angle θ = ‖ω̂θ‖ is rounded far enough to
/// move the rotation (θ·2⁻⁵³ > 1e-9) warn that the rotation is known only
/// so far: at (1, 2, 3)·10²⁰ no digit is left, and the value was printed
/// as if exact. One nonzero component is an exact angle (no warning), and
/// so is a turn of ordinary size.
#[test]
fn exponential_coordinates_too_large_for_their_angle_warn() {
    for src in [
        "MatrixExp3(VecToso3((1e20, 2e20, 3e20)))",
        "exp([(1e12, 2e12, 3e12)])",
        "MatrixExp6(VecTose3((3e7, 4e7, 0, 1, 2, 3)))",
        "exp([(0, 3e7, 4e7, 1, 2, 3)])",
    ] {
        let (_, err) = texts(src);
        assert!(
            err.contains("is rounded to the nearest float: the angle, and so the rotation, is known only to about"),
            "{src}: {err}"
        );
    }
    for src in [
        "exp([(1e12, 0, 0)])",
        "MatrixExp3(VecToso3((0.1, 0.2, 0.3)))",
        "exp([(0, 0, 1, 0, 2, 0)] 0.1)",
        "exp([(3e6, 4e6, 0)])",
    ] {
        let (_, err) = texts(src);
        assert!(err.is_empty(), "{src}: {err}");
    }
}

/// ProjectToSO3 of a matrix with many nearest rotations gives one of them
/// and says it is not unique: 0 (every rotation), −I (det < 0 and equal
/// singular values: every half turn; chasles gave diag(1, −1, −1),
/// modern_robotics gives diag(−1, −1, 1), now both), a rank-1 matrix (every
/// rotation taking its row direction to its column direction). A rank-1
/// matrix whose determinant was rounding noise (4.7e-19) got a reflection,
/// det −1, labelled SO(3). A unique nearest rotation says nothing.
#[test]
fn projection_ties_are_said_and_answered_with_a_nearest_rotation() {
    let tie = "the nearest rotation is not unique";
    for (src, want) in [
        (
            "ProjectToSO3(zeros(3, 3))",
            "the matrix is 0, and every rotation is as near",
        ),
        (
            "ProjectToSO3(-eye(3))",
            "det < 0 and the two smallest singular values of the matrix are equal (σ₂ = σ₃ = 1)",
        ),
        (
            "ProjectToSO3([0, 2, 0; 0, 0, 0; 0, 0, 0])",
            "has rank 1 (singular values 2, 0, 0)",
        ),
        (
            "ProjectToSE3([-1, 0, 0, 1; 0, -1, 0, 2; 0, 0, -1, 3; 0, 0, 0, 1])",
            "singular values of the rotation block are equal",
        ),
    ] {
        let (_, err) = texts(src);
        assert!(err.contains(tie) && err.contains(want), "{src}: {err}");
    }
    let r = numbers("ProjectToSO3(-eye(3))");
    assert_eq!(r, [-1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0]);
    let t = numbers("ProjectToSE3([-1, 0, 0, 1; 0, -1, 0, 2; 0, 0, -1, 3; 0, 0, 0, 1])");
    assert_eq!(
        &t[..12],
        [-1.0, 0.0, 0.0, 1.0, 0.0, -1.0, 0.0, 2.0, 0.0, 0.0, 1.0, 3.0]
    );
    // [0, 2, 0; 0, 0, 0; 0, 0, 0] = 2 x̂ ŷᵀ: the nearest rotations take ŷ to
    // x̂ (‖R − M‖² = ‖M‖² + 3 − 2·2 = 3)
    let r = numbers("ProjectToSO3([0, 2, 0; 0, 0, 0; 0, 0, 0])");
    assert!((r[1] - 1.0).abs() < 1e-15, "{r:?}");
    let m = "[0.1366963853729478, 0.8500276686476482, -1.1714031011733639; \
             -0.02899153119641787, -0.18027984870398495, 0.24843941160984825; \
             0.01915951075732261, 0.11914078208464096, -0.16418510450630905]";
    let d = numbers(&format!("det(ProjectToSO3({m}))"))[0];
    assert!((d - 1.0).abs() < 1e-14, "{d}");
    let (_, err) = texts(&format!("ProjectToSO3({m})"));
    assert!(
        err.contains("has rank 1 (singular values 1.5, 0, 0)"),
        "{err}"
    );
    // det < 0 with σ₂ > σ₃ is unique: turned about the smallest, no warning
    let (out, err) = texts("ProjectToSO3([-1, 0, 0; 0, -1, 0; 0, 0, -0.999])");
    assert!(err.is_empty(), "{err}");
    assert!(
        out.starts_with("[-1,  0, 0\n  0, -1, 0\n  0,  0, 1]"),
        "{out}"
    );
    for src in [
        "ProjectToSO3([0.675, 0.150, 0.720; 0.370, 0.771, -0.511; -0.630, 0.619, 0.472])",
        "ProjectToSO3([1, 0, 0; 0, 1, 0; 0, 0, 0])",
    ] {
        let (_, err) = texts(src);
        assert!(err.is_empty(), "{src}: {err}");
    }
}
