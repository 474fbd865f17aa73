//! Helpers shared by the tests of `explain` (tests/explain*.rs, one file
//! per function explained): random axes, angles and points for the
//! property tests, a step's value by name, the book's G⁻¹(θ) (3.94), a
//! transform as a literal the language reads back exactly, and the
//! outcome of a script with its shown steps.
//!
//! Each test file uses only a part of these, hence the `dead_code`
//! allowance.

#![allow(dead_code)]

use chasles::eval::env::Mode;
use chasles::lie::steps::{Quantity, Step};
use chasles::lie::{Mat3, Mat4, Vec3, so3};
use chasles::session::{Session, Settings};
use chasles::values::value::Value;
use proptest::prelude::*;
use std::f64::consts::PI;

pub fn unit_axis() -> impl Strategy<Value = Vec3> {
    (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64)
        .prop_filter("axis not too short", |(x, y, z)| {
            x * x + y * y + z * z > 0.01
        })
        .prop_map(|(x, y, z)| Vec3::new(x, y, z).normalize())
}

/// θ: uniform on (0, π), near 0, near π, or exactly π.
pub fn angle() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => 1e-9..PI,
        1 => 1e-12..1e-5f64,
        1 => (1e-12..1e-5f64).prop_map(|d| PI - d),
        1 => Just(PI),
    ]
}

pub fn point() -> impl Strategy<Value = Vec3> {
    (-5.0..5.0f64, -5.0..5.0f64, -5.0..5.0f64).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

pub fn step<'a>(steps: &'a [Step], name: &str) -> &'a Step {
    steps
        .iter()
        .find(|s| s.name == name)
        .unwrap_or_else(|| panic!("no step {name} in {steps:#?}"))
}

pub fn scalar(s: &Step) -> f64 {
    match s.value {
        Quantity::Scalar(x) => x,
        ref q => panic!("{} is {q:?}", s.name),
    }
}

pub fn vector(s: &Step) -> Vec3 {
    match s.value {
        Quantity::Vector3(v) => v,
        ref q => panic!("{} is {q:?}", s.name),
    }
}

pub fn matrix(s: &Step) -> Mat3 {
    match s.value {
        Quantity::Matrix3(m) | Quantity::So3(m) | Quantity::Rotation(m) => m,
        ref q => panic!("{} is {q:?}", s.name),
    }
}

/// G⁻¹(θ) of (3.94), written as the book writes it.
pub fn book_g_inv(w: &Vec3, theta: f64) -> Mat3 {
    let wm = so3::hat(w);
    Mat3::identity() / theta - 0.5 * wm + (1.0 / theta - 0.5 / (theta / 2.0).tan()) * wm * wm
}

/// A float as the language reads it back exactly.
pub fn lit(x: f64) -> String {
    format!("{x:?}")
}

pub fn matrix_literal(t: &Mat4) -> String {
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
pub fn numbers(v: &Value) -> Vec<u64> {
    match v {
        Value::Num { m, .. } => m.as_slice().iter().map(|x| (x + 0.0).to_bits()).collect(),
        Value::Tuple(vs) => vs.iter().flat_map(numbers).collect(),
        other => panic!("not numbers: {other:?}"),
    }
}

/// The outcome of the last statement of `src`.
pub fn last_outcome(src: &str) -> chasles::eval::interp::Outcome {
    let mut session = Session::new(Settings::default());
    let mut outs = Vec::new();
    let errors = session.run(src, Mode::Run, false, |r| outs.push(r.result.clone()));
    assert_eq!(errors, 0, "{src}");
    outs.pop().unwrap().unwrap()
}

pub fn shown<'a>(o: &'a chasles::eval::interp::Outcome, name: &str) -> &'a Value {
    &o.steps()
        .iter()
        .find(|s| s.name == name)
        .unwrap_or_else(|| panic!("no step {name}"))
        .value
}

pub fn floats(v: &Value) -> Vec<f64> {
    match v {
        Value::Num { m, .. } => m.as_slice().to_vec(),
        other => panic!("not numbers: {other:?}"),
    }
}
