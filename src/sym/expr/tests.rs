//! The canonical form's own tests: identities that need no rule, the chain
//! rule, and evaluation at numbers.

use super::*;

fn s(n: &str) -> Expr {
    Expr::symbol(Symbol::new(n))
}

#[test]
fn pythagoras_and_angle_sums_need_no_rule() {
    let t = s("t");
    let one = Expr::cos(&t)
        .powi(2)
        .unwrap()
        .add(&Expr::sin(&t).powi(2).unwrap());
    assert_eq!(one, Expr::one());
    let (a, b) = (s("a"), s("b"));
    let lhs = Expr::cos(&a)
        .mul(&Expr::cos(&b))
        .sub(&Expr::sin(&a).mul(&Expr::sin(&b)));
    assert_eq!(lhs, Expr::cos(&a.add(&b)));
    assert_eq!(
        Expr::cos(&t.add(&Expr::pi().scale(&Coef::rat(Rat::new(1, 2).unwrap())))),
        Expr::sin(&t).neg()
    );
}

#[test]
fn time_derivative_by_the_chain_rule() {
    let th = Expr::symbol(Symbol::timed("theta"));
    let d = Expr::sin(&th).diff(&Wrt::Time(Symbol::new("t")));
    let want = Expr::cos(&th).mul(&Expr::symbol(Symbol::timed("theta").dot()));
    assert_eq!(d, want);
}

#[test]
fn evaluation_matches_numbers() {
    let (a, b) = (s("a"), s("b"));
    let e = Expr::cos(&a.add(&b))
        .mul(&b)
        .add(&Expr::sqrt(&a.mul(&a).add(&Expr::one())));
    let at = |x: &Symbol| Some(if &*x.name == "a" { 0.3 } else { -1.2 });
    let want = (0.3f64 - 1.2).cos() * -1.2 + (0.09f64 + 1.0).sqrt();
    assert!((e.eval(&at).unwrap() - want).abs() < 1e-14);
}
