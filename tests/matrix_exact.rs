//! Decisions on matrices and vectors by their exact forms (LANGUAGE.md §3,
//! §5, §7; issue 21: never a wrong answer). A branch chosen by comparing
//! floats with a threshold — the θ = π case of the matrix logarithm
//! (§3.2.3.3), the zero vector of `Normalize`, membership of SO(3) and
//! SE(3), the book's `NearZero` and `TestIfSO3` tolerances — is chosen by
//! the exact form when the operands have one: the floats of an exact
//! matrix may be on the other side of the threshold (a skew part of
//! exactly −1e-20 is 0 as floats, so a rotation by π − 1e-20 about −ẑ read
//! as a half turn gave +ẑπ, 2π away in the coordinates).

mod common;

use common::{error, outputs, printed};

/// The numbers `src`'s last statement prints.
fn numbers(src: &str) -> Vec<f64> {
    common::last_numbers(src)
}

fn close(x: &[f64], want: &[f64]) -> bool {
    x.len() == want.len()
        && x.iter()
            .zip(want)
            .all(|(a, b)| (a - b).abs() <= 1e-15 * b.abs().max(1.0))
}

/// A rotation by π − 1e-20 about −ẑ, typed exactly (rational: cosθ =
/// (1 − u²)/(1 + u²), sinθ = 2u/(1 + u²) with u = tan(θ/2) = −2·10²⁰): its
/// skew part is (0, 0, −1e-20) exactly, far below the rounding of its
/// floats, and tr R = −1 + 1e-40.
const NEAR_HALF_TURN: &str =
    "u = -2e20\nc = (1 - u^2)/(1 + u^2)\ns = 2*u/(1 + u^2)\nR = [c, -s, 0; s, c, 0; 0, 0, 1]\n";

/// Just off θ = π, exactly: not a half turn. The log is −ẑ(π − 1e-20)
/// (the skew part fixes the sign), with no note that −ω̂ is as valid.
#[test]
fn log_just_off_pi_is_not_a_half_turn() {
    let pi = std::f64::consts::PI;
    let src = format!("{NEAR_HALF_TURN}MatrixLog3(R)");
    assert!(
        close(&numbers(&src), &[0.0, 0.0, -pi]),
        "{:?}",
        numbers(&src)
    );
    let (_, err) = outputs(&src);
    assert!(!err.contains("θ = π"), "{err}");
    // the same rotation block in a transform: ω = −ẑπ, v = G⁻¹(θ)p
    let src = format!("{NEAR_HALF_TURN}MatrixLog6([R, (1, 2, 3); 0, 0, 0, 1])");
    let s = numbers(&src);
    assert!(close(&s[..3], &[0.0, 0.0, -pi]), "{s:?}");
    // v = p − ½[φ]p + k(π)[φ]²p with k(π) = 1/π²: (π/2·2·… ) — check by
    // exp: the round trip gives the transform back
    let back = format!(
        "{NEAR_HALF_TURN}T = [R, (1, 2, 3); 0, 0, 0, 1]\nMatrixExp6(VecTose3(MatrixLog6(T))) - T"
    );
    let d = numbers(&back);
    assert!(d.iter().all(|x| x.abs() <= 1e-14), "{d:?}");
}

/// Just off θ = π with no exact form (cos(π − 1e-20) has none), made
/// from exact numbers: certified arithmetic on how the rotation was made
/// finds its skew part nonzero, and its sign. `Rotz(−π + 1e-20)` has a
/// skew part of −1.2e-16 in floats (rounding), so it was read as a half
/// turn: +ẑπ with the note (answer −ẑ(π − 1e-20)).
#[test]
fn log_just_off_pi_without_an_exact_form() {
    let pi = std::f64::consts::PI;
    for (src, want) in [
        ("MatrixLog3(Rotz(-pi + 1e-20))", vec![0.0, 0.0, -pi]),
        (
            "MatrixLog3(Rotz(pi/3) Rotz(2*pi/3 - 1e-20))",
            vec![0.0, 0.0, pi],
        ),
        (
            "MatrixLog3(Rot((0.8, 0, -0.6), pi - 1e-20))",
            vec![0.8 * pi, 0.0, -0.6 * pi],
        ),
    ] {
        assert!(close(&numbers(src), &want), "{src}: {:?}", numbers(src));
        let (_, err) = outputs(src);
        assert!(!err.contains("θ = π"), "{src}: {err}");
    }
    for src in [
        "MatrixLog6([Rotz(-pi + 1e-20), (1, 2, 3); 0, 0, 0, 1])",
        "MatrixLog6(RpToTrans(Rotz(-pi + 1e-20), (1, 2, 3)))",
    ] {
        let s = numbers(src);
        assert!(close(&s[..3], &[0.0, 0.0, -pi]), "{src}: {s:?}");
        let (_, err) = outputs(src);
        assert!(!err.contains("θ = π"), "{src}: {err}");
    }
    // (RpToTrans bounded in certified arithmetic: == sees 8.4e-21 too)
    let (out, err) =
        outputs("RpToTrans(Rotz(1), (1, 2, 3)) == RpToTrans(Rotz(1 + 1e-20), (1, 2, 3))");
    assert_eq!(out, "false\n");
    assert!(err.contains("below double precision"), "{err}");
    // exactly π: the book's axis (3.58), ω̂₃ > 0, and the note
    let (out, err) = outputs("MatrixLog3(Rotz(-pi))");
    assert!(out.starts_with("(0, 0, 3.1416)"), "{out}");
    assert!(err.contains("θ = π"), "{err}");
}

/// Exactly at θ = π: the half-turn branch, whatever the rounding of the
/// skew part, with the book's sign (3.58) and the note.
#[test]
fn log_at_pi_is_a_half_turn_exactly() {
    let pi = std::f64::consts::PI;
    for (src, axis) in [
        ("Rot((1,2,2)/3, pi)", [1.0, 2.0, 2.0]),
        ("Rot((-1,2,-2)/3, pi)", [1.0, -2.0, 2.0]),
        ("[-1, 0, 0; 0, -1, 0; 0, 0, 1]", [0.0, 0.0, 3.0]),
        // 2ŵŵᵀ − I for ŵ = (1, 2, 2)/3, with exact entries
        (
            "[2/9 - 1, 4/9, 4/9; 4/9, 8/9 - 1, 8/9; 4/9, 8/9, 8/9 - 1]",
            [1.0, 2.0, 2.0],
        ),
    ] {
        let want: Vec<f64> = axis.iter().map(|a| a / 3.0 * pi).collect();
        let src = format!("MatrixLog3({src})");
        assert!(close(&numbers(&src), &want), "{src}: {:?}", numbers(&src));
        let (_, err) = outputs(&src);
        assert!(err.contains("θ = π"), "{src}: {err}");
    }
}

/// `Normalize` refuses a vector that is exactly zero, whatever its floats,
/// and normalizes one that is tiny or huge but not zero.
#[test]
fn normalize_decides_zero_exactly() {
    for src in [
        "Normalize((1, 2, 3) - (1, 2, 3))",
        // 0.1 + 0.2 − 0.3 is 5.6e-17 as floats, 0 as decimals
        "Normalize((0.1 + 0.2, 0, 0) - (0.3, 0, 0))",
        "normalize((sin(pi), 0))",
    ] {
        let e = error(src);
        assert!(e.contains("zero vector"), "{src}: {e}");
    }
    assert_eq!(
        printed("Normalize((1e-200, 0, 0))"),
        "(1, 0, 0)  : 3-vector\n"
    );
    let h = std::f64::consts::FRAC_1_SQRT_2;
    assert!(close(
        &numbers("Normalize((1e-200, 1e-200, 0))"),
        &[h, h, 0.0]
    ));
    assert!(close(&numbers("Normalize((3e200, 4e200))"), &[0.6, 0.8]));
    // nonzero exactly, its floats cancelling to 0: the direction of
    // (√2 − 1.4142135623730951) x̂, which is −x̂
    assert!(close(
        &numbers("Normalize((sqrt(2) - 1.4142135623730951, 0))"),
        &[-1.0, 0.0]
    ));
}

/// An axis or exponential coordinates exactly zero are zero, whatever
/// their floats: no direction is read from rounding (`AxisAng3` gave the
/// axis x̂ of (5.6e-17, 0, 0), `Rot` rotated about it).
#[test]
fn zero_axes_are_decided_exactly() {
    let zero = "(0.1 + 0.2, 0, 0) - (0.3, 0, 0)";
    let (out, _) = outputs(&format!("(w, theta) = AxisAng3({zero})"));
    assert_eq!(out, "w = (0, 0, 0)  : 3-vector\ntheta = 0\n");
    let e = error(&format!("Rot({zero}, pi/2)"));
    assert!(e.contains("the rotation axis is the zero vector"), "{e}");
    let (out, _) = outputs("(S, theta) = AxisAng6((0, 0, 0, 0.1 + 0.2 - 0.3, 0, 0))");
    assert!(out.starts_with("S = (0, 0, 0, 0, 0, 0)"), "{out}");
    let t = numbers("(S, theta) = AxisAng6((0, 0, 0, 0.1 + 0.2 - 0.3, 0, 0))\ntheta");
    assert_eq!(t, [0.0]);
    // tiny but not zero: a direction
    let r = numbers("Rot((1e-200, 0, 0), pi/2)");
    let want = [1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0];
    assert!(
        r.iter().zip(want).all(|(x, w)| (x - w).abs() < 1e-15),
        "{r:?}"
    );
}

/// Membership of SO(3) by the exact form (LANGUAGE.md §5): an exact
/// rotation is one however far its floats have strayed (the identity
/// below, whose floats are 18.4 off), and is computed with at the floats
/// nearest its entries; the contract's tolerances (1e-9 taken as it is,
/// 1e-2 projected) are measured on the exact matrix.
#[test]
fn membership_is_decided_exactly() {
    let out = printed(&format!("{NEAR_HALF_TURN}R"));
    assert!(out.ends_with(": SO(3)\n"), "{out}");
    let out = printed("[0.6, -0.8, 0; 0.8, 0.6, 0; 0, 0, 1]");
    assert!(out.ends_with(": SO(3)\n"), "{out}");
    // cos(3π/2)/1e-17 is 0 exactly and −18.37 in floats
    let z = "Z = [1, cos(3*pi/2)/1e-17, 0; 0, 1, 0; 0, 0, 1]\n";
    let (out, err) = outputs(&format!("{z}MatrixLog3(Z)"));
    assert!(out.ends_with("(0, 0, 0)  : 3-vector\n"), "{out}");
    assert!(err.is_empty(), "{err}");
    let (out, err) = outputs(&format!("{z}R_ab = Z\nR_ab"));
    assert!(out.ends_with("0, 0, 1]  : SO(3) {a}←{b}\n"), "{out}");
    assert!(err.is_empty(), "{err}");
    // exactly 1e-2 + √2·1e-20 off once the floats are put right: the
    // distance is the exact one
    let (_, err) = outputs("MatrixLog3([1, 1e-20 + cos(3*pi/2)/1e-17, 0; 0, 1, 0; 0, 0, 1])");
    assert!(err.is_empty(), "{err}");
    let e = error("MatrixLog3([2, cos(3*pi/2)/1e-17, 0; 0, 1, 0; 0, 0, 1])");
    assert!(e.contains("distance from SO(3) is 3"), "{e}");
    // a typed matrix within 1e-9 is a rotation (printed values read back,
    // §10), and its distance is its own
    let out = printed("A = [1, 1e-20, 0; 0, 1, 0; 0, 0, 1]");
    assert!(out.ends_with(": SO(3)\n"), "{out}");
    let d = numbers("DistanceToSO3([1, 1e-20, 0; 0, 1, 0; 0, 0, 1])");
    assert!((d[0] / (2f64.sqrt() * 1e-20) - 1.0).abs() < 1e-12, "{d:?}");
    // an exact rotation is at distance 0 (its floats' is rounding)
    assert_eq!(numbers("DistanceToSO3(Rot((1, 2, 2)/3, pi/3))"), [0.0]);
}

/// The book's tolerances (`NearZero`: |z| < 1e-6; `TestIfSO3`: distance
/// < 1e-3) decided by the exact value at the boundary.
#[test]
fn book_tolerances_are_decided_exactly() {
    assert_eq!(printed("NearZero(1e-6 - 1e-30)"), "true\n");
    assert_eq!(printed("NearZero(-1e-6 + 1e-30)"), "true\n");
    assert_eq!(printed("NearZero(1e-6 * (sqrt(3)^2/3))"), "false\n");
    assert_eq!(printed("NearZero(sin(pi) * 1e10)"), "true\n");
    // distance exactly 1e-3 (its float is 0.000999…): not below 1e-3
    let m = "[1, 0, 0; 0, 1, 0; 0, 0, sqrt(1 + 1e-3)]";
    assert_eq!(printed(&format!("TestIfSO3({m})")), "false\n");
    assert_eq!(printed(&format!("TestIfSO3({m} * (1 - 1e-30))")), "true\n");
    let t = "[1, 0, 0, 5; 0, 1, 0, 6; 0, 0, sqrt(1 + 1e-3), 7; 0, 0, 0, 1]";
    assert_eq!(printed(&format!("TestIfSE3({t})")), "false\n");
    assert_eq!(printed("TestIfSO3(Rotz(1))"), "true\n");
}

/// Vectors are decided entry by entry: first entries exact and different
/// is no rounding, whatever the second entries are.
#[test]
fn vectors_are_compared_entry_by_entry() {
    let (out, err) = outputs("(1, exp(0)) == (1 + 1e-13, 1)");
    assert_eq!((out.as_str(), err.as_str()), ("false\n", ""));
    let (out, err) = outputs("(1 + 1e-13, 1) == (1, exp(0))");
    assert_eq!((out.as_str(), err.as_str()), ("false\n", ""));
    // the floats are equal, the first entries exactly are not
    assert_eq!(printed("(1, exp(0)) == (1 + 1e-20, 1)"), "false\n");
    assert_eq!(printed("(1, exp(0)) == (1, 1)"), "true\n");
    // matrices written entry by entry too
    assert_eq!(
        printed("[1, exp(0); 0, 1] == [1 + 1e-20, 1; 0, 1]"),
        "false\n"
    );
    assert_eq!(printed("[1, exp(0); 0, 1] == [1, 1; 0, 1]"), "true\n");
    // floats with no recipe still get the note (a column of a matrix
    // exponential: its squared length y is 1 but for rounding); exp(1)
    // keeps a recipe since session 13, so exp(1) + 1e-14 certainly differs
    let unit = "x = exp([(0.1, 0.2, 0.3)])\ny = x[1,1]^2 + x[2,1]^2 + x[3,1]^2\n";
    let (out, err) = outputs(&format!("{unit}(y, 2) == (1, 2)"));
    assert!(out.ends_with("false\n"), "{out}");
    assert!(err.contains("rounding only"), "{err}");
    let (out, err) = outputs("(exp(1), 2) == (exp(1) + 1e-14, 2)");
    assert_eq!((out.as_str(), err.as_str()), ("false\n", ""));
}

/// Euler angles near gimbal lock (cos b = 0 for ZYX and roll–pitch–yaw,
/// sin b = 0 for ZXZ): b = π/2 − 1e-20 is no lock, though cos b = 1e-20 is
/// below rounding in floats, which gave (0.1, π/2, 0) and a gimbal-lock
/// warning for Rotz(0.3) Roty(π/2 − 1e-20) Rotx(0.2); the lock is decided
/// by the certified entries of how the rotation was made, or its exact
/// form, and the angles read from them.
#[test]
fn gimbal_lock_is_decided_exactly() {
    let h = std::f64::consts::FRAC_PI_2;
    for (src, want) in [
        (
            "euler_zyx(Rotz(0.3) Roty(pi/2 - 1e-20) Rotx(0.2))",
            [0.3, h, 0.2],
        ),
        (
            "rpy(Rotz(0.3) Roty(-pi/2 + 1e-20) Rotx(0.2))",
            [0.2, -h, 0.3],
        ),
        (
            "euler_zxz(Rotz(0.3) Rotx(1e-20) Rotz(0.2))",
            [0.3, 0.0, 0.2],
        ),
    ] {
        let x = numbers(src);
        assert!(
            x.iter().zip(want).all(|(a, b)| (a - b).abs() <= 1e-15),
            "{src}: {x:?}"
        );
        let (_, err) = outputs(src);
        assert!(!err.contains("gimbal"), "{src}: {err}");
    }
    // at the lock exactly: c set to 0, with the warning
    let src = "euler_zyx(Rotz(0.3) Roty(pi/2) Rotx(0.2))";
    let x = numbers(src);
    assert!((x[0] - 0.1).abs() <= 1e-15 && x[2] == 0.0, "{x:?}");
    let (_, err) = outputs(src);
    assert!(err.contains("gimbal lock (b = π/2)"), "{err}");
    let (_, err) = outputs("euler_zxz([1, 0, 0; 0, 1, 0; 0, 0, 1])");
    assert!(err.contains("gimbal lock (b = 0)"), "{err}");
}
