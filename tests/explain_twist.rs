//! `explain` of twists from Ṫ, `inv(T) Td` and `Td inv(T)` (3.69)–(3.74).

use chasles::lie::{Mat4, Vec3, se3, so3};

mod common;
mod explain_common;
use explain_common::*;

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
