//! Issue 21, `log` of a symbolic transform (§3.3.3.2): `log(exp([S] t))` is
//! `[S] t` for a numeric screw axis, `log([R, p; 0, 1])` is `[ω̂]θ` with
//! vθ = θ G⁻¹(θ) p (3.94) where R = Rot(ω̂, θ) has a numeric axis, and
//! `[0, p; 0, 0]` for R = I; each with the branch it holds on named, each
//! agreeing with the numeric `log` at random points to 1e-12. Where no
//! closed form is found the call is kept — never a wrong value.

use chasles::lie::se3;
use chasles::sym::branch::log6;
use chasles::sym::coef::{Coef, Rat};
use chasles::sym::matrix::{self, Mat};
use chasles::sym::{Expr, Symbol};
use nalgebra::Matrix4;
use num_traits::One;

mod common;
use common::{Rng, outputs as run};

fn t() -> Expr {
    Expr::symbol(Symbol::new("t"))
}

/// The numbers of a symbolic matrix at t.
fn at(m: &Mat, x: f64) -> Matrix4<f64> {
    let lookup = |s: &Symbol| (&*s.name == "t").then_some(x);
    Matrix4::from_fn(|i, j| m.get(i, j).eval(&lookup).expect("only t"))
}

/// A screw axis of exact fractions p/q.
fn screw(s: &[(i64, i64)]) -> Vec<Expr> {
    s.iter()
        .map(|&(p, q)| Expr::constant(Coef::rat(Rat::new(i128::from(p), i128::from(q)).unwrap())))
        .collect()
}

/// The screw's numbers.
fn numbers(s: &[(i64, i64)]) -> Vec<f64> {
    s.iter().map(|&(p, q)| p as f64 / q as f64).collect()
}

fn exps(s: &[(i64, i64)]) -> Mat {
    let st: Vec<Expr> = screw(s).iter().map(|x| x.mul(&t())).collect();
    matrix::exp6(&matrix::twist_matrix(&st)).expect("a closed form")
}

/// The largest difference between the closed form of log at t and the
/// numeric log of the transform at t, over random t in (−π, π).
fn worst(tr: &Mat, log: &Mat, rng: &mut Rng) -> f64 {
    let mut worst = 0.0f64;
    for _ in 0..100 {
        let x = 3.1 * rng.next();
        if x.abs() < 1e-3 {
            continue;
        }
        let want = se3::hat(&se3::log(&at(tr, x)));
        worst = worst.max((at(log, x) - want).amax());
    }
    worst
}

#[test]
fn the_log_of_a_screw_motion_is_the_screw_times_the_angle() {
    let mut rng = Rng(0x10a6_0000_0000_0001);
    for s in [
        [(0, 1), (0, 1), (1, 1), (0, 1), (-2, 1), (1, 2)],
        [(1, 3), (2, 3), (2, 3), (0, 1), (-2, 1), (1, 2)],
        [(0, 1), (3, 5), (4, 5), (1, 1), (0, 1), (-3, 1)],
    ] {
        let tr = exps(&s);
        let (log, branch) = log6(&tr).expect("a closed form");
        let st: Vec<Expr> = screw(&s).iter().map(|x| x.mul(&t())).collect();
        assert_eq!(log, matrix::twist_matrix(&st), "{s:?}");
        assert_eq!(branch.angles, vec![t()]);
        assert!(branch.positive.is_empty());
        let w = worst(&tr, &log, &mut rng);
        assert!(w < 1e-12, "{s:?}: largest difference {w:e}");
    }
    // random screws of finite pitch: rational unit axes from Pythagorean
    // quadruples a² + b² + c² = d², signs and order at random; v in eighths
    let quads = [
        [1, 2, 2, 3],
        [2, 3, 6, 7],
        [1, 4, 8, 9],
        [4, 4, 7, 9],
        [2, 6, 9, 11],
        [3, 4, 12, 13],
    ];
    for i in 0..30 {
        let [a, b, c, d] = quads[i % quads.len()];
        let mut w = [a, b, c].map(|x| (i64::from(x), i64::from(d)));
        w.rotate_left(i % 3);
        for x in &mut w {
            if rng.next() < 0.0 {
                x.0 = -x.0;
            }
        }
        let v = [0; 3].map(|_| ((rng.next() * 24.0).round() as i64, 8));
        let s = [w[0], w[1], w[2], v[0], v[1], v[2]];
        let tr = exps(&s);
        let (log, _) = log6(&tr).expect("a closed form");
        let d = worst(&tr, &log, &mut rng);
        assert!(d < 1e-12, "{:?}: largest difference {d:e}", numbers(&s));
    }
}

#[test]
fn the_log_of_a_rotation_and_a_fixed_position_has_cot_half_theta() {
    let mut rng = Rng(0x10a6_0000_0000_0002);
    let r = matrix::rot_axis(2, &t());
    let p = Mat::column(vec![Expr::int(1), Expr::int(2), Expr::int(3)]);
    let tr = matrix::rp_to_trans(&r, &p);
    let (log, branch) = log6(&tr).expect("a closed form");
    // 1 − cos t > 0 (t ≠ 0) where the quotient is left
    assert_eq!(branch.positive, vec![Expr::one().sub(&Expr::cos(&t()))]);
    let d = worst(&tr, &log, &mut rng);
    assert!(d < 1e-12, "largest difference {d:e}");
    let (out, err) = run("given t : scalar\nlog([Rotz(t), (1, 2, 3); 0, 0, 0, 1])");
    assert!(out.contains("t + (1/2) t sin(t)/(1 - cos(t))"), "{out}");
    assert!(
        err.contains("log of a symbolic transform: the closed form on the branch 1 - cos(t) > 0 and t in (−π, π)"),
        "{err}"
    );
}

#[test]
fn logs_in_the_language_with_their_branch() {
    let (out, err) = run("given t, L : scalar\nS = (0, 0, 1, 0, -2, 0.5)\n\
         log(exp([S] t)) == [S] t\nMatrixLog6(exp([S] t)) == S t\n\
         log([eye(3), (t, 2, L); 0, 0, 0, 1])\n");
    assert_eq!(
        out.lines().skip(1).collect::<Vec<_>>(),
        [
            "true",
            "true",
            "[0, 0, 0, t",
            " 0, 0, 0, 2",
            " 0, 0, 0, L",
            " 0, 0, 0, 0]  : se(3)"
        ],
        "{out}"
    );
    assert!(
        err.contains("log of a symbolic transform: the closed form on the branch t in (−π, π)"),
        "{err}"
    );
    assert!(
        err.contains(
            "MatrixLog6 of a symbolic transform: the closed form on the branch t in (−π, π)"
        ),
        "{err}"
    );
    // R = I needs no branch: one note per log above, none for it
    assert_eq!(err.matches("note:").count(), 2, "{err}");
}

#[test]
fn symbolic_axes_have_logs_on_the_branch() {
    let (out, err) = run("given w : vec3\ngiven S : screw\ngiven t : scalar\n\
         log(exp([w] t)) == [w] t\nMatrixLog3(Rot(w, t)) == w t\nlog(exp([S] t)) == [S] t\n");
    assert_eq!(out, "true\ntrue\ntrue\n");
    for note in [
        "log of a symbolic rotation: the closed form on the branch t in (−π, π)",
        "MatrixLog3 of a symbolic rotation: the closed form on the branch t in (−π, π)",
        "log of a symbolic transform: the closed form on the branch t in (−π, π)",
        "w is assumed to be a unit vector",
        "S = (ω, v) is assumed to have ‖ω‖ = 1",
    ] {
        assert!(err.contains(note), "{note}\n{err}");
    }
}

#[test]
fn no_closed_form_keeps_the_call() {
    // a rotation about an axis that is not the exponential's: no angle
    let (out, _) = run("given w : vec3\ngiven t : scalar\nlog(exp([w] t) Rotx(t))\n");
    assert!(out.starts_with("log("), "{out}");
    // two angles about different axes: no Rot(ω̂, θ) found
    let (out, _) = run("given a, b : scalar\nlog([Rotz(a) Rotx(b), (1, 2, 3); 0, 0, 0, 1])\n");
    assert!(out.starts_with("log("), "{out}");
}
