//! The book's numbers: Examples 3.1–3.4, the MatrixLog3 of §3.2.3.3,
//! and the docstring examples of the Modern Robotics software library for
//! each function of §3.6.

// The book's printed numbers (e.g. 1.57079632 for π/2) are used verbatim.
#![allow(clippy::approx_constant)]

use chasles::lie::{Mat3, Mat4, Mat6, Vec3, Vec6, near_zero, project, se2, se3, so3};
use std::f64::consts::PI;

fn close3(a: &Mat3, b: &Mat3, tol: f64) {
    assert!((a - b).amax() <= tol, "\n{a}\n!=\n{b}");
}

fn close4(a: &Mat4, b: &Mat4, tol: f64) {
    assert!((a - b).amax() <= tol, "\n{a}\n!=\n{b}");
}

fn closev<const N: usize>(a: &nalgebra::SVector<f64, N>, b: &[f64; N], tol: f64) {
    for i in 0..N {
        assert!((a[i] - b[i]).abs() <= tol, "{a} != {b:?}");
    }
}

/// The transform used by several docstrings: R = Rot(x̂, 90°), p = (0, 0, 3).
fn t_doc() -> Mat4 {
    Mat4::new(
        1.0, 0.0, 0.0, 0.0, //
        0.0, 0.0, -1.0, 0.0, //
        0.0, 1.0, 0.0, 3.0, //
        0.0, 0.0, 0.0, 1.0,
    )
}

#[test]
fn example_3_1_rodrigues() {
    let w = Vec3::new(0.0, 3f64.sqrt() / 2.0, 0.5);
    let theta = PI / 6.0;
    let r = so3::exp(&(w * theta));
    let want = Mat3::new(
        0.866, -0.250, 0.433, //
        0.250, 0.967, 0.058, //
        -0.433, 0.058, 0.900,
    );
    close3(&r, &want, 6e-4);
    // Exponential coordinates ω̂θ = (0, 0.453, 0.262).
    closev(&so3::log(&r), &[0.0, 0.453, 0.262], 6e-4);
    // Rotating back about the same fixed axis gives the identity.
    close3(&(so3::exp(&(-w * theta)) * r), &Mat3::identity(), 1e-15);
}

#[test]
fn matrix_log3_of_cyclic_permutation() {
    // §3.2.3.3 / MatrixLog3 docstring: θ = 2π/3 about (1,1,1)/√3.
    let r = Mat3::new(0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    let l = so3::log(&r);
    closev(&l, &[1.20919958; 3], 1e-8);
    let (axis, theta) = so3::axis_angle(&l);
    assert!((theta - 2.0 * PI / 3.0).abs() < 1e-15);
    closev(&axis, &[1.0 / 3f64.sqrt(); 3], 1e-15);
    close3(
        &so3::hat(&l),
        &Mat3::new(
            0.0,
            -1.20919958,
            1.20919958, //
            1.20919958,
            0.0,
            -1.20919958, //
            -1.20919958,
            1.20919958,
            0.0,
        ),
        1e-8,
    );
}

/// Example 3.2 (Figure 3.15): T_ce = (T_ad T_db T_bc)⁻¹ T_ad T_de, with the
/// book's intermediate products. The book prints (T_ce)₃₄ = 130/√2; the
/// product is 160/√2 (a slip: see examples/ch3_ex3_2_camera.chs), which the
/// chain T_bc⁻¹ T_db⁻¹ T_de that avoids {a} confirms.
#[test]
fn example_3_2_camera() {
    let r = std::f64::consts::FRAC_1_SQRT_2;
    let t = |rot: &Mat3, x: f64, y: f64, z: f64| se3::from_rp(rot, &Vec3::new(x, y, z));
    // T_db, T_de and T_ad share one rotation.
    let flip = Mat3::new(0.0, 0.0, -1.0, 0.0, -1.0, 0.0, -1.0, 0.0, 0.0);
    let t_db = t(&flip, 250.0, -150.0, 200.0);
    let t_de = t(&flip, 300.0, 100.0, 120.0);
    let t_ad = t(&flip, 400.0, 50.0, 300.0);
    let r_bc = Mat3::new(0.0, -r, -r, 0.0, r, -r, 1.0, 0.0, 0.0);
    let t_bc = t(&r_bc, 30.0, -40.0, 25.0);

    close4(
        &(t_ad * t_de),
        &t(&Mat3::identity(), 280.0, -50.0, 0.0),
        1e-13,
    );
    let t_ac = t_ad * t_db * t_bc;
    close4(&t_ac, &t(&r_bc, 230.0, 160.0, 75.0), 1e-13);
    let t_ca = se3::inv(&t_ac);
    let r_cb = r_bc.transpose();
    close4(&t_ca, &t(&r_cb, -75.0, 70.0 * r, 390.0 * r), 1e-13);
    // (T_ce)₃₄ = 160/√2, where the book prints 130/√2.
    let want_ce = t(&r_cb, -75.0, -260.0 * r, 160.0 * r);
    close4(&(t_ca * t_ad * t_de), &want_ce, 1e-12);
    close4(&(se3::inv(&t_bc) * se3::inv(&t_db) * t_de), &want_ce, 1e-12);
}

#[test]
fn example_3_3_car_twist() {
    let tsb = Mat4::new(
        -1.0, 0.0, 0.0, 4.0, //
        0.0, 1.0, 0.0, 0.4, //
        0.0, 0.0, -1.0, 0.0, //
        0.0, 0.0, 0.0, 1.0,
    );
    let vb = Vec6::new(0.0, 0.0, -2.0, 2.8, 4.0, 0.0);
    let vs = se3::adjoint(&tsb) * vb;
    closev(&vs, &[0.0, 0.0, 2.0, -2.0, -4.0, 0.0], 1e-15);
    // The screw: a pure rotation (h = 0) about the axis through r_s = (2, −1, 0).
    let (q, s, h) = se3::screw_params(&vs);
    closev(&q, &[2.0, -1.0, 0.0], 1e-15);
    closev(&s, &[0.0, 0.0, 1.0], 0.0);
    assert_eq!(h, 0.0);
}

#[test]
fn example_3_4_se2_log() {
    let d = PI / 180.0;
    let tsb = se2::from_theta_xy(30.0 * d, 1.0, 2.0);
    let tsc = se2::from_theta_xy(60.0 * d, 2.0, 1.0);
    let st = se2::log(&(tsc * se2::inv(&tsb)));
    assert!((st.x - PI / 6.0).abs() < 1e-15);
    let s = st / st.x;
    closev(&s, &[1.0, 3.37, -3.37], 5e-3);
    // [S] as printed in the book.
    close3(
        &se2::hat(&s),
        &Mat3::new(0.0, -1.0, 3.37, 1.0, 0.0, -3.37, 0.0, 0.0, 0.0),
        5e-3,
    );
}

// ------------------------------------------- §3.6 software docstrings

#[test]
fn rot_inv() {
    let r = Mat3::new(0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    assert_eq!(
        so3::inv(&r),
        Mat3::new(0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0)
    );
}

#[test]
fn vec_to_so3_and_back() {
    let m = Mat3::new(0.0, -3.0, 2.0, 3.0, 0.0, -1.0, -2.0, 1.0, 0.0);
    assert_eq!(so3::hat(&Vec3::new(1.0, 2.0, 3.0)), m);
    assert_eq!(so3::vee(&m), Vec3::new(1.0, 2.0, 3.0));
}

#[test]
fn axis_ang3() {
    let (w, t) = so3::axis_angle(&Vec3::new(1.0, 2.0, 3.0));
    closev(&w, &[0.26726124, 0.53452248, 0.80178373], 1e-8);
    assert!((t - 3.7416573867739413).abs() < 1e-15);
}

#[test]
fn matrix_exp3() {
    let r = so3::exp(&Vec3::new(1.0, 2.0, 3.0));
    let want = Mat3::new(
        -0.69492056,
        0.71352099,
        0.08929286, //
        -0.19200697,
        -0.30378504,
        0.93319235, //
        0.69297817,
        0.6313497,
        0.34810748,
    );
    close3(&r, &want, 1e-8);
}

#[test]
fn rp_to_trans_and_back() {
    let r = Mat3::new(1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0);
    let t = se3::from_rp(&r, &Vec3::new(1.0, 2.0, 5.0));
    assert_eq!(
        t,
        Mat4::new(
            1.0, 0.0, 0.0, 1.0, //
            0.0, 0.0, -1.0, 2.0, //
            0.0, 1.0, 0.0, 5.0, //
            0.0, 0.0, 0.0, 1.0,
        )
    );
    let (r2, p2) = se3::to_rp(&t_doc());
    assert_eq!(r2, r);
    assert_eq!(p2, Vec3::new(0.0, 0.0, 3.0));
}

#[test]
fn trans_inv() {
    let want = Mat4::new(
        1.0, 0.0, 0.0, 0.0, //
        0.0, 0.0, 1.0, -3.0, //
        0.0, -1.0, 0.0, 0.0, //
        0.0, 0.0, 0.0, 1.0,
    );
    assert_eq!(se3::inv(&t_doc()), want);
}

#[test]
fn vec_to_se3_and_back() {
    let v = Vec6::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0);
    let m = Mat4::new(
        0.0, -3.0, 2.0, 4.0, //
        3.0, 0.0, -1.0, 5.0, //
        -2.0, 1.0, 0.0, 6.0, //
        0.0, 0.0, 0.0, 0.0,
    );
    assert_eq!(se3::hat(&v), m);
    assert_eq!(se3::vee(&m), v);
}

#[test]
fn adjoint() {
    #[rustfmt::skip]
    let want = Mat6::from_row_slice(&[
        1.0, 0.0, 0.0, 0.0, 0.0, 0.0,
        0.0, 0.0, -1.0, 0.0, 0.0, 0.0,
        0.0, 1.0, 0.0, 0.0, 0.0, 0.0,
        0.0, 0.0, 3.0, 1.0, 0.0, 0.0,
        3.0, 0.0, 0.0, 0.0, 0.0, -1.0,
        0.0, 0.0, 0.0, 0.0, 1.0, 0.0,
    ]);
    assert_eq!(se3::adjoint(&t_doc()), want);
}

#[test]
fn small_adjoint() {
    #[rustfmt::skip]
    let want = Mat6::from_row_slice(&[
        0.0, -3.0, 2.0, 0.0, 0.0, 0.0,
        3.0, 0.0, -1.0, 0.0, 0.0, 0.0,
        -2.0, 1.0, 0.0, 0.0, 0.0, 0.0,
        0.0, -6.0, 5.0, 0.0, -3.0, 2.0,
        6.0, 0.0, -4.0, 3.0, 0.0, -1.0,
        -5.0, 4.0, 0.0, -2.0, 1.0, 0.0,
    ]);
    assert_eq!(se3::ad(&Vec6::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0)), want);
}

#[test]
fn screw_to_axis() {
    let s = se3::screw_to_axis(&Vec3::new(3.0, 0.0, 0.0), &Vec3::new(0.0, 0.0, 1.0), 2.0);
    assert_eq!(s, Vec6::new(0.0, 0.0, 1.0, 0.0, -3.0, 2.0));
}

#[test]
fn axis_ang6() {
    let e = Vec6::new(1.0, 0.0, 0.0, 1.0, 2.0, 3.0);
    assert_eq!(se3::axis_angle(&e), (e, 1.0));
    // Pure translation: θ = ‖v‖.
    let (s, t) = se3::axis_angle(&Vec6::new(0.0, 0.0, 0.0, 0.0, 3.0, 4.0));
    assert_eq!((s, t), (Vec6::new(0.0, 0.0, 0.0, 0.0, 0.6, 0.8), 5.0));
    assert_eq!(se3::axis_angle(&Vec6::zeros()), (Vec6::zeros(), 0.0));
}

#[test]
fn matrix_exp6() {
    let e = Vec6::new(1.57079632, 0.0, 0.0, 0.0, 2.35619449, 2.35619449);
    // The docstring input has 8 decimals: agreement to ~1e-8.
    close4(&se3::exp(&e), &t_doc(), 3e-8);
    close4(&se3::exp(&se3::log(&t_doc())), &t_doc(), 1e-15);
}

#[test]
fn matrix_log6() {
    let l = se3::log(&t_doc());
    closev(
        &l,
        &[1.57079633, 0.0, 0.0, 0.0, 2.35619449, 2.35619449],
        1e-8,
    );
    // Exactly: θ = π/2 about x̂, v = G⁻¹(π/2)p with p = (0, 0, 3).
    assert!((l[0] - PI / 2.0).abs() < 1e-15);
    assert!((l[4] - 3.0 * PI / 4.0).abs() < 1e-15);
    assert!((l[5] - 3.0 * PI / 4.0).abs() < 1e-15);
}

#[test]
fn project_to_so3_and_se3() {
    let m = Mat3::new(
        0.675, 0.150, 0.720, //
        0.370, 0.771, -0.511, //
        -0.630, 0.619, 0.472,
    );
    let want = Mat3::new(
        0.67901136,
        0.14894516,
        0.71885945, //
        0.37320708,
        0.77319584,
        -0.51272279, //
        -0.63218672,
        0.61642804,
        0.46942137,
    );
    close3(&project::project_to_so3(&m), &want, 1e-8);
    let m4 = Mat4::new(
        0.675, 0.150, 0.720, 1.2, //
        0.370, 0.771, -0.511, 5.4, //
        -0.630, 0.619, 0.472, 3.6, //
        0.003, 0.002, 0.010, 0.9,
    );
    let want4 = se3::from_rp(&want, &Vec3::new(1.2, 5.4, 3.6));
    close4(&project::project_to_se3(&m4), &want4, 1e-8);
}

#[test]
fn distance_and_test_so3_se3() {
    let m = Mat3::new(1.0, 0.0, 0.0, 0.0, 0.1, -0.95, 0.0, 1.0, 0.1);
    assert!((project::distance_to_so3(&m) - 0.08835).abs() < 1e-5);
    assert!(!project::test_if_so3(&m));
    let m4 = Mat4::new(
        1.0, 0.0, 0.0, 1.2, //
        0.0, 0.1, -0.95, 1.5, //
        0.0, 1.0, 0.1, -0.9, //
        0.0, 0.0, 0.1, 0.98,
    );
    assert!((project::distance_to_se3(&m4) - 0.134931).abs() < 1e-6);
    assert!(!project::test_if_se3(&m4));
    assert!(project::test_if_so3(&Mat3::identity()));
    assert!(project::test_if_se3(&t_doc()));
    // det ≤ 0: the software's "large number".
    assert_eq!(project::distance_to_so3(&(-Mat3::identity())), 1e9);
}

#[test]
fn near_zero_doc() {
    assert!(near_zero(-1e-7));
}
