//! The exact forms of results: the table of exact calls, recipes that
//! keep their operands, and vectors of fractions held at once.

use super::*;
use crate::builtins::{lookup, table};

#[test]
fn the_table_of_exact_calls_agrees_with_the_names() {
    for b in table() {
        assert_eq!(exact_call(b), exact_name(b.name), "{}", b.name);
        assert_eq!(call_keeps(b), Keeps::of(b.name), "{}", b.name);
    }
    let keeps = |n| call_keeps(lookup(n).expect("a builtin"));
    assert_eq!(keeps("exp"), Keeps::OfNumberOrMotion);
    assert_eq!(keeps("log"), Keeps::OfNumber);
    assert_eq!(keeps("atan2"), Keeps::OfNumber);
    assert_eq!(keeps("Rotz"), Keeps::Always);
    assert_eq!(keeps("MatrixLog6"), Keeps::Never);
    let row = |n| lookup(n).expect("a builtin");
    assert!(exact_call(row("sqrt")) && exact_call(row("Rotz")));
    assert!(exact_call(row("exp")) && exact_call(row("Ad")));
    assert!(!exact_call(row("MatrixLog6")));
}

/// A 3-vector of fractions held inline and numbers as typed has the
/// form its recipe makes, at once: the same fractions with the same
/// typed marks (0.1 typed prints as a decimal, 7/1000 computed as a
/// fraction). A float entry, a decimal past 9 places, one too large
/// to pack or another length keeps the recipe.
#[test]
fn a_vector_of_fractions_has_its_recipes_form_at_once() {
    use crate::sym::coef::Rat;
    use crate::values::num::Num;
    let typed = |x: f64| {
        let mut v = Value::scalar(x);
        v.set_exact(Exact::Typed);
        v
    };
    let ratio = |r: Rat| Value::Num {
        kind: Kind::Scalar,
        m: Num::Scalar(r.to_f64()),
        exact: Exact::Ratio(Fraction::of(&r).expect("inline")),
    };
    let r = |p, q| Rat::new(p, q).expect("a fraction");
    let kind = Kind::Vector(Some(3));
    let cases = [
        [ratio(r(7, 1000)), typed(0.0), typed(0.0)],
        [ratio(r(-7, 3)), typed(0.1), typed(2.5)],
        [ratio(r(37, 100).marked(true)), ratio(r(1, 8)), typed(-3.0)],
        [ratio(r(1, 3)), typed(12.345), ratio(r(99_999, 1000))],
    ];
    for entries in &cases {
        let e = Op::Vector.exact_of(entries, &kind);
        assert!(matches!(e, Exact::Ratios(_)), "{e:?}");
        let recipe = Op::Vector.pending(Operands::of(entries), &kind);
        let floats: Vec<f64> = entries.iter().filter_map(Value::as_scalar).collect();
        let m = Num::vector(&floats);
        let (at_once, made) = (e.form(&m).expect("exact"), recipe.form(&m).expect("exact"));
        assert_eq!(at_once, made);
        let marks = |f: &Mat| -> Vec<bool> {
            f.data
                .iter()
                .map(|x| {
                    x.as_const()
                        .and_then(|c| c.as_rat())
                        .is_some_and(|q| q.is_typed())
                })
                .collect()
        };
        assert_eq!(marks(&at_once), marks(&made), "{entries:?}");
        assert_eq!((at_once.rows, at_once.cols), (3, 1));
    }
    // (a float entry, a decimal of more places than held inline, a
    // denominator past 1024, four entries: a recipe)
    for entries in [
        vec![ratio(r(1, 3)), Value::scalar(0.5), typed(0.0)],
        vec![ratio(r(1, 3)), typed(123.456789), typed(0.0)],
        vec![ratio(r(1, 3)), typed(1e-13), typed(0.0)],
        vec![ratio(r(1, 3)), typed(0.0), typed(0.0), typed(0.0)],
    ] {
        let e = Op::Vector.exact_of(&entries, &Kind::Vector(Some(entries.len())));
        assert!(!matches!(e, Exact::Ratios(_)), "{e:?}");
    }
}

/// A product of numbers as typed keeps its operands, not copies, and
/// its exact form is the product of theirs (`[S] 0.1` as in issue
/// 14's benchmark).
#[test]
fn a_product_keeps_its_operands_and_is_exact() {
    let as_typed = |mut v: Value| {
        v.set_exact(Exact::Typed);
        v
    };
    let typed = |x: f64| as_typed(Value::scalar(x));
    let m = Box::new(as_typed(Value::vector(Kind::Vector(Some(2)), &[1.0, 3.0])));
    let e = Op::Arith(crate::syntax::ast::BinOp::Mul).exact_of_pair(
        m,
        Box::new(typed(0.1)),
        &Kind::Vector(Some(2)),
    );
    let Exact::Later(_) = &e else {
        panic!("a recipe: {e:?}")
    };
    let form = e
        .form(&crate::values::num::Num::vector(&[
            0.1,
            0.30000000000000004,
        ]))
        .expect("exact");
    let tenth = |n| {
        crate::sym::Expr::constant(crate::sym::coef::Coef::rat(
            crate::sym::coef::Rat::new(n, 10).expect("a fraction"),
        ))
    };
    assert_eq!(form.data, vec![tenth(1), tenth(3)]);
    // A float operand: no recipe.
    let f = Op::Arith(crate::syntax::ast::BinOp::Mul).exact_of_pair(
        Box::new(Value::scalar(0.1)),
        Box::new(typed(2.0)),
        &Kind::Scalar,
    );
    assert!(f.is_float());
}
