//! Exact forms: decimals as typed, recipes run once, what they weigh.

use super::*;

#[test]
fn decimals_are_read_as_typed() {
    assert_eq!(decimal(0.866), Rat::new(433, 500));
    assert_eq!(decimal(0.1), Rat::new(1, 10));
    assert_eq!(decimal(-2.5), Rat::new(-5, 2));
    assert_eq!(decimal(3.0), Some(Rat::int(3)));
    let tiny = decimal(1e-13).expect("finite");
    assert_eq!(tiny.mul(&Rat::int(10_000_000_000_000)), Rat::ONE);
    assert_eq!(decimal(f64::NAN), None);
    assert!(is_short_decimal(&Rat::new(433, 500).unwrap()));
    assert!(!is_short_decimal(&Rat::new(1, 3).unwrap()));
}

#[test]
fn a_recipe_weighs_its_node_its_operands_and_what_only_it_holds() {
    fn none(_: &Operation, _: &[&Value], _: &Kind) -> Option<Mat> {
        None
    }
    let value = std::mem::size_of::<Value>() as u64;
    let recipe = |args: Operands| {
        Exact::pending(Pending {
            op: Operation::Neg,
            args,
            kind: Kind::Scalar,
            run: none,
        })
    };
    assert_eq!(Exact::Float.weight(), 0);
    assert_eq!(Exact::Typed.weight(), 0);
    let half = Fraction::of(&Rat::new(1, 2).expect("1/2")).expect("inline");
    assert_eq!(Exact::Ratio(half).weight(), 0);
    // (a 3-vector's fractions, packed inline: nothing)
    let thirds = Exact::Ratios(Fractions3::of([half; 3]).expect("small"));
    assert_eq!(thirds.weight(), 0);
    let leaf = recipe(Operands::of(&[Value::scalar(0.5)]));
    assert_eq!(leaf.weight(), NODE_BYTES + value);
    let with = |e: Exact| Value::Num {
        kind: Kind::Scalar,
        m: Num::Scalar(0.5),
        exact: e,
    };
    // (an operand only this recipe holds counts with it; one held
    // elsewhere too, a binding's, is counted there)
    let owned = recipe(Operands::Pair(
        Box::new(with(leaf.clone())),
        Box::new(Value::scalar(1.0)),
    ));
    assert_eq!(owned.weight(), NODE_BYTES + 2 * value);
    drop(owned);
    let only = recipe(Operands::Pair(
        Box::new(with(leaf)),
        Box::new(Value::scalar(1.0)),
    ));
    assert_eq!(only.weight(), 2 * NODE_BYTES + 3 * value);
    let known = Exact::known(Mat::scalar(Expr::pi()));
    assert_eq!(
        known.weight(),
        NODE_BYTES + BOX_BYTES + form_bytes(&Mat::scalar(Expr::pi()))
    );
}

#[test]
fn a_recipe_runs_once_and_a_float_has_no_form() {
    thread_local!(static CALLS: Cell<u32> = const { Cell::new(0) });
    fn pi(_: &Operation, _: &[&Value], _: &Kind) -> Option<Mat> {
        CALLS.with(|c| c.set(c.get() + 1));
        Some(Mat::scalar(Expr::pi()))
    }
    let m = Num::Scalar(0.5);
    let e = Exact::pending(Pending {
        op: Operation::Neg,
        args: Operands::of(&[Value::scalar(0.5)]),
        kind: Kind::Scalar,
        run: pi,
    });
    assert_eq!(e.form(&m), Some(Mat::scalar(Expr::pi())));
    assert_eq!(e.clone().form(&m), Some(Mat::scalar(Expr::pi())));
    assert_eq!(CALLS.with(Cell::get), 1);
    assert_eq!(Exact::Float.form(&m), None);
    assert_eq!(
        Exact::Typed.form(&m),
        Some(Mat::scalar(Expr::constant(Coef::rat(
            Rat::new(1, 2).unwrap()
        ))))
    );
    // A float coefficient is no exact form.
    let approx = Mat::scalar(Expr::constant(Coef::Approx { re: 0.3, im: 0.0 }));
    assert_eq!(Exact::known(approx).form(&m), None);
}

/// Fractions in machine words are the fractions of [`Rat`], typed mark
/// and all: as typed, and their sums, differences, products, quotients.
#[test]
fn fractions_in_words_are_those_of_rat() {
    let mut xs = vec![
        0.0, 1.0, -3.0, 0.1, 0.37, -2.5, 0.5, 0.125, 0.4, 1e6, 7.0, 123.456,
    ];
    for k in 1..200 {
        xs.push(f64::from(k) * 0.01);
        xs.push(-f64::from(k) / 8.0);
    }
    let mut fractions = Vec::new();
    for &x in &xs {
        let quick = Fraction::typed(x);
        let slow = Rat::typed(x).expect("finite");
        if let Some(f) = quick {
            assert_eq!(f.rat(), slow, "{x}");
            assert_eq!(f.rat().is_typed(), slow.is_typed(), "{x}");
            fractions.push(f);
        }
    }
    assert!(fractions.len() > 350, "{}", fractions.len());
    // (and fractions from integers: 1/3, −2/7)
    fractions.push(Fraction::of(&Rat::new(1, 3).expect("1/3")).expect("inline"));
    fractions.push(Fraction::of(&Rat::new(-2, 7).expect("-2/7")).expect("inline"));
    let same = |f: Option<Fraction>, r: Option<Rat>, what: &str| {
        let Some(f) = f else { return };
        let r = r.expect(what);
        assert_eq!(f.rat(), r, "{what}");
        assert_eq!(f.rat().is_typed(), r.is_typed(), "{what}");
    };
    let pick = |i: usize| fractions[(i * 7919) % fractions.len()];
    for i in 0..3000 {
        let (a, b) = (pick(i), pick(i + 1 + i / 3));
        let (x, y) = (a.rat(), b.rat());
        same(a.plus(b), Some(x.add(&y)), "+");
        same(a.minus(b), Some(x.add(&y.neg())), "-");
        same(a.times(b), Some(x.mul(&y)), "*");
        if !y.is_zero() {
            same(a.over(b), y.inv().map(|v| x.mul(&v)), "/");
        } else {
            assert_eq!(a.over(b), None);
        }
    }
}

/// Three fractions packed inline are the three fractions, marks and signs
/// kept; one past the bounds (a numerator of 2²⁰, a denominator of 1025)
/// is not packed.
#[test]
fn three_fractions_pack_and_unpack_as_they_were() {
    let f = |p: i128, q: i128, typed: bool| {
        Fraction::of(&Rat::new(p, q).expect("a fraction").marked(typed)).expect("inline")
    };
    for rs in [
        [f(7, 1000, false), f(0, 1, false), f(-3, 1, false)],
        [
            f(-1_048_575, 1024, true),
            f(1_048_575, 1, false),
            f(37, 100, true),
        ],
        [f(-1, 3, false), f(99_999, 1000, false), f(1, 1024, true)],
    ] {
        let packed = Fractions3::of(rs).expect("small");
        assert_eq!(packed.get(), rs);
        assert_eq!(
            packed.get().map(|r| r.rat().is_typed()),
            rs.map(|r| r.rat().is_typed())
        );
    }
    assert_eq!(
        Fractions3::of([f(1_048_576, 1, false), f(0, 1, false), f(0, 1, false)]),
        None
    );
    assert_eq!(
        Fractions3::of([f(1, 1025, false), f(0, 1, false), f(0, 1, false)]),
        None
    );
    assert_eq!(
        Fractions3::of([f(-1_048_576, 3, false), f(0, 1, false), f(0, 1, false)]),
        None
    );
}

/// An exact form is 16 bytes, so that a value is 104 (`num.rs`), and a
/// recipe's node 112, a size class of 128 bytes with its counts (a 3-vector's
/// fractions packed inline, a form once known boxed).
#[test]
fn an_exact_form_and_a_node_keep_their_sizes() {
    assert_eq!(std::mem::size_of::<Exact>(), 16);
    assert_eq!(std::mem::size_of::<Later>(), 112);
}

/// A lone number as typed or a fraction held inline is kept in the
/// recipe's node (no box of a value): it weighs the node alone, and is
/// read back as the value it was, kind, float and exact form.
#[test]
fn a_lone_fraction_is_kept_in_the_node() {
    let third = Fraction::of(&Rat::new(1, 3).expect("1/3")).expect("inline");
    for exact in [Exact::Ratio(third), Exact::Typed] {
        let v = Value::Num {
            kind: Kind::Scalar,
            m: Num::Scalar(1.0 / 3.0),
            exact: exact.clone(),
        };
        let args = Operands::of(std::slice::from_ref(&v));
        assert!(matches!(args, Operands::Scalar(..)));
        let back = args.refs();
        let [b] = back.as_slice() else {
            panic!("one operand")
        };
        assert_eq!(&**b, &v);
        assert_eq!(
            format!("{:?}", b.exact_form()),
            format!("{:?}", v.exact_form())
        );
        assert_eq!(Operands::owned(vec![v]).under(), (0, 0));
    }
    // (a float, or more than one operand: copies)
    assert!(matches!(
        Operands::of(&[Value::scalar(0.5)]),
        Operands::Copied(_)
    ));
}
