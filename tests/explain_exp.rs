//! `explain` of the exponentials, `exp([S]θ)`, `MatrixExp6`, `exp([ω]θ)`
//! (Prop. 3.16, (3.51)): G(θ) of (3.88) and p = G(θ)v (3.89), digits kept
//! at small θ, and no Rodrigues' steps for a matrix outside so(3), se(3).

use chasles::lie::steps::{self, Quantity};
use chasles::lie::{Mat3, Vec3, Vec6, se3, so3};
use proptest::prelude::*;

mod common;
mod explain_common;
use explain_common::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

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
