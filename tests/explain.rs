//! `explain` (LANGUAGE.md §14, issue 37): every step's value agrees with an
//! independent computation of that quantity by the book's own formula
//! where it is accurate — tr R (3.54), θ = cos⁻¹((tr R − 1)/2), ω̂ from
//! (R − Rᵀ)/(2 sin θ) (3.61), G⁻¹(θ) from (3.94), v = G⁻¹(θ)p (3.93), G(θ)
//! from (3.88) — and the last step is the expression's value bit for bit,
//! in the library and through the language.
//!
//! This file: the last step through the language, for every algorithm;
//! each function explained has its own file (`explain_log.rs`,
//! `explain_exp.rs`, `explain_twist.rs`, `explain_euler.rs`,
//! `explain_diff.rs`, `explain_grubler.rs`).

use chasles::eval::env::Mode;
use chasles::lie::{Vec3, se3, so3};
use chasles::session::{Session, Settings};

mod explain_common;
use explain_common::*;

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
