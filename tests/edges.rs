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
