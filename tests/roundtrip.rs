//! Printed values parse back to the same value (LANGUAGE.md §10, as fend
//! tests it): a value printed with `--digits 17`, typed back in, is the
//! same f64s bit for bit — scalars, vectors, rows, matrices, group elements.

use chasles::check::ty::{Kind, Ty};
use chasles::eval::env::Mode;
use chasles::eval::value::Value;
use chasles::output::text;
use chasles::session::{Session, Settings};
use nalgebra::DMatrix;
use proptest::prelude::*;
use std::f64::consts::PI;

/// Prints `v` as `x = ...` with 17 digits, runs it, and returns the value bound to x.
fn reread(v: &Value) -> Value {
    let printed = text::show_value("x = ", &Ty::plain(v.kind()), v, 17);
    let src = printed.split("  :").next().unwrap().to_string();
    let mut s = Session::new(Settings::default());
    let (_, err, n) = s.run_to_strings("t", &src, Mode::Run, false);
    assert_eq!(n, 0, "{src}\n{err}");
    s.env.get("x").and_then(|b| b.val.clone()).expect("x bound")
}

fn finite() -> impl Strategy<Value = f64> {
    prop_oneof![
        -1e6..1e6f64,
        -1.0..1.0f64,
        (-300i32..300, -1.0..1.0f64).prop_map(|(e, m)| m * 10f64.powi(e)),
        Just(0.0),
        Just(-0.0),
        Just(f64::MIN_POSITIVE),
    ]
}

proptest! {
    #[test]
    fn matrices_read_back_exactly(r in 1usize..6, c in 1usize..6, xs in proptest::collection::vec(finite(), 36)) {
        let m = DMatrix::from_iterator(r, c, xs.into_iter().take(r * c));
        let v = Value::Num { kind: if c == 1 { Kind::Vector(Some(r)) } else { Kind::Matrix(Some(r), Some(c)) }, m: m.clone().into(), exact: Default::default() };
        let back = reread(&v);
        let bm = back.as_matrix().expect("numbers").clone();
        prop_assert_eq!(bm.shape(), m.shape());
        for (a, b) in bm.iter().zip(m.iter()) {
            prop_assert!(a == b, "{} read back as {}", b, a);
        }
    }

    /// Transforms over every θ ∈ [0, π] (θ = 0 and θ = π exactly, θ just
    /// below π) and pure translations.
    #[test]
    fn rotations_and_transforms_read_back(
        ax in -1.0..1.0f64,
        ay in -1.0..1.0f64,
        az in 0.1..1.0f64,
        th in prop_oneof![
            4 => (0.0..PI).prop_map(|t| t.to_string()),
            1 => Just("0".to_string()),
            1 => Just("pi".to_string()),
            1 => (1e-12..1e-3f64).prop_map(|d| format!("pi - {d}")),
        ],
        pure in proptest::bool::weighted(0.2),
        px in -100.0..100.0f64,
    ) {
        let src = if pure {
            format!("T = RpToTrans(eye(3), ({px}, 1, 2))")
        } else {
            format!("T = RpToTrans(Rot(({ax}, {ay}, {az}), {th}), ({px}, 1, 2))")
        };
        let mut s = Session::new(Settings::default());
        s.run_to_strings("t", &src, Mode::Run, false);
        let t = s.env.get("T").and_then(|b| b.val.clone()).unwrap();
        let back = reread(&t);
        prop_assert_eq!(back.kind(), Kind::SE3);
        prop_assert_eq!(back.as_matrix(), t.as_matrix());
    }
}
