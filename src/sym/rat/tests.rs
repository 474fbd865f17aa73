//! Fractions inline and big, their remainders, decimals and the typed mark.

use super::*;

#[test]
fn remainders_are_exact_at_any_size() {
    let r = |n: i128, d: i128| Rat::new(n, d).unwrap();
    assert_eq!(r(7, 1).rem_euclid(2), Rat::ONE);
    assert_eq!(r(-7, 6).rem_euclid(2), r(5, 6));
    assert_eq!(r(13, 6).rem_euclid(2), r(1, 6));
    // 3·10³⁰ + 1/6 (big): 1/6; −2⁷⁰ − 1/2: 3/2
    let big = Rat::new(3 * 10i128.pow(30), 1).unwrap().add(&r(1, 6));
    assert!(matches!(big, Rat::Big(_)));
    assert_eq!(big.rem_euclid(2), r(1, 6));
    let neg = Rat::new(-(1i128 << 70), 1).unwrap().add(&r(-1, 2));
    assert_eq!(neg.rem_euclid(2), r(3, 2));
    assert_eq!(
        Rat::new(i128::from(i64::MAX), 1).unwrap().rem_euclid(2),
        Rat::ONE
    );
}

#[test]
fn small_and_big_agree() {
    let big = Rat::new(1i128 << 100, 3).unwrap();
    assert!(matches!(big, Rat::Big(_)));
    let back = big.mul(&Rat::new(3, 1i128 << 100).unwrap());
    assert_eq!(back, Rat::ONE);
    assert!(matches!(back, Rat::Small { .. }));
    // 2^62 + 2^62 leaves i64 and comes back by subtraction.
    let x = Rat::int(1 << 62);
    let y = x.add(&x);
    assert!(matches!(y, Rat::Big(_)));
    assert_eq!(y.add(&x.neg()), x);
    assert_eq!(
        Rat::int(i64::MIN).neg().add(&Rat::int(-1)),
        Rat::int(i64::MAX)
    );
    assert_eq!(big.to_string(), format!("{}/3", 1u128 << 100));
}

#[test]
fn binomials_stay_exact() {
    // C(120, 60) / 2^120 and back.
    let mut c = Rat::ONE;
    for k in 0..60i64 {
        c = c.mul(&Rat::new(i128::from(120 - k), i128::from(k + 1)).unwrap());
    }
    assert_eq!(c.to_string(), "96614908840363322603893139521372656");
    let half = Rat::new(1, 2).unwrap();
    let mut d = c.clone();
    for _ in 0..120 {
        d = d.mul(&half);
    }
    assert!((d.to_f64() - 0.0726).abs() < 1e-3, "{}", d.to_f64());
}

#[test]
fn the_typed_mark_is_kept_and_costs_no_size() {
    assert_eq!(std::mem::size_of::<Rat>(), 24);
    let typed = Rat::typed(0.425).unwrap();
    let eighth = Rat::new(1, 8).unwrap();
    assert!(typed.is_typed() && !eighth.is_typed());
    // equal values, equal hashes, whatever the mark
    assert_eq!(Rat::typed(0.125).unwrap(), eighth);
    let hash = |r: &Rat| {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        r.hash(&mut h);
        h.finish()
    };
    assert_eq!(hash(&Rat::typed(0.125).unwrap()), hash(&eighth));
    // arithmetic with a typed operand is typed; integers are not marked
    assert!(typed.mul(&Rat::int(2)).is_typed());
    assert!(eighth.add(&typed).is_typed());
    assert!(typed.neg().is_typed() && typed.inv().unwrap().is_typed());
    assert!(!typed.mul(&Rat::int(40)).is_typed());
    assert!(!eighth.mul(&eighth).is_typed());
}

#[test]
fn floats_and_decimals() {
    assert_eq!(Rat::from_f64_exact(0.5), Rat::new(1, 2));
    assert_eq!(Rat::from_f64_exact(-3.0), Some(Rat::int(-3)));
    assert_eq!(Rat::from_f64_exact(f64::NAN), None);
    assert_eq!(
        Rat::decimal(&BigInt::from(866), -3),
        Rat::new(433, 500).unwrap()
    );
    assert_eq!(
        Rat::decimal(&BigInt::from(1), -13),
        Rat::new(1, 10_000_000_000_000).unwrap()
    );
    assert_eq!(Rat::decimal(&BigInt::from(15), 2), Rat::int(1500));
}

#[test]
fn typed_quick_agrees_with_typed() {
    let mut xs = vec![
        0.1,
        0.2,
        0.3,
        0.866,
        -2.5,
        123.456,
        1e-5,
        0.30000000000000004,
        1.0 / 3.0,
        0.1 + 0.2,
        2.0,
        -7.0,
        1e-13,
        12345.678901234,
        0.999999999999999,
        1e20,
        5.4321,
    ];
    for k in 1..3000 {
        xs.push(f64::from(k) / 100.0);
        xs.push(f64::from(k) / 1000.0);
        xs.push(f64::from(k) * 0.1);
        xs.push(-f64::from(k) / 7.0);
        xs.push(f64::from(k) * 0.001 + 0.5);
    }
    let mut found = 0;
    for x in xs {
        if let Some(q) = Rat::typed_quick(x) {
            found += 1;
            let t = Rat::typed(x).expect("finite");
            assert_eq!(q, t, "{x}");
            assert_eq!(q.is_typed(), t.is_typed(), "{x}");
        }
    }
    // (most of them are decimals it reads at once)
    assert!(found > 10_000, "{found}");
    assert_eq!(Rat::typed_quick(0.37), Rat::new(37, 100));
    assert!(Rat::typed_quick(0.37).is_some_and(|r| r.is_typed()));
    assert_eq!(Rat::typed_quick(1.0 / 3.0), None);
    assert_eq!(Rat::typed_quick(f64::NAN), None);
}
