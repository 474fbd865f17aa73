//! Tests of the closed forms on a branch: exact forms, and agreement
//! with the numeric maps at random points where the stated branch holds.

use super::*;
use crate::sym::matrix::rot_axis;

fn s(n: &str) -> Expr {
    Expr::symbol(Symbol::new(n))
}

#[test]
fn atan2_of_a_scaled_sine_and_cosine_is_the_angle() {
    let (a, b) = (s("a"), s("b"));
    let k = Expr::cos(&b);
    let (t, f) = atan2_angle(&Expr::sin(&a).mul(&k), &Expr::cos(&a).mul(&k)).unwrap();
    assert_eq!((t, f), (a.clone(), k));
    // sin(a + π/2) = cos a: the angle carries its quarter turn
    let (t, f) = atan2_angle(&Expr::cos(&a), &Expr::sin(&a).neg()).unwrap();
    assert_eq!(
        t,
        a.add(&Expr::pi().scale(&Coef::rat(crate::sym::coef::Rat::new(1, 2).unwrap())))
    );
    assert_eq!(f, Expr::one());
}

#[test]
fn log_and_euler_angles_of_symbolic_rotations() {
    let (a, b, c) = (s("a"), s("b"), s("c"));
    let (log, br) = log3(&rot_axis(2, &a)).unwrap();
    assert_eq!(log, skew(&[Expr::zero(), Expr::zero(), a.clone()]));
    assert_eq!(br.angles, vec![a.clone()]);
    let r = rot_axis(2, &a)
        .mul(&rot_axis(1, &b))
        .unwrap()
        .mul(&rot_axis(0, &c))
        .unwrap();
    let (angles, br) = euler(&r, true).unwrap();
    assert_eq!(angles, vec![a.clone(), b.clone(), c.clone()]);
    assert_eq!(br.positive, vec![Expr::cos(&b)]);
    let r = rot_axis(2, &a)
        .mul(&rot_axis(0, &b))
        .unwrap()
        .mul(&rot_axis(2, &c))
        .unwrap();
    let (angles, br) = euler(&r, false).unwrap();
    assert_eq!(angles, vec![a, b.clone(), c]);
    assert_eq!(br.positive, vec![Expr::sin(&b)]);
}

/// A small deterministic generator, uniform in [0, 1).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn pick(&mut self, n: usize) -> usize {
        ((self.next() * n as f64) as usize).min(n - 1)
    }
}

/// The number of a matrix of expressions at a point.
fn at(m: &Mat, p: &dyn Fn(&Symbol) -> Option<f64>) -> crate::lie::Mat3 {
    crate::lie::Mat3::from_fn(|i, j| m.get(i, j).eval(p).unwrap())
}

/// True where the branch holds at the point (with a margin): each factor
/// positive, each angle inside (−π, π).
fn holds(b: &Branch, p: &dyn Fn(&Symbol) -> Option<f64>) -> bool {
    let pi = std::f64::consts::PI;
    b.positive.iter().all(|k| k.eval(p).unwrap() > 1e-3)
        && b.angles
            .iter()
            .all(|a| a.eval(p).unwrap().abs() < pi - 1e-3)
}

/// Euler angles of random products of axis rotations (angles a, b, c, their
/// multiples and sums, π offsets, constants): wherever the stated branch
/// holds at a random point, the closed form is the numeric map's value.
#[test]
fn euler_closed_forms_agree_with_numbers_on_their_branch() {
    let (a, b, c) = (s("a"), s("b"), s("c"));
    let half = Expr::pi().scale(&Coef::rat(crate::sym::coef::Rat::new(1, 2).unwrap()));
    let angles = [
        a.clone(),
        b.clone(),
        c.clone(),
        a.neg(),
        b.scale(&Coef::int(2)),
        a.add(&b),
        Expr::pi().sub(&b),
        c.add(&half),
        Expr::pi().scale(&Coef::rat(crate::sym::coef::Rat::new(1, 3).unwrap())),
    ];
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let (mut reduced, mut checked) = (0, 0);
    for case in 0..100 {
        let n = 1 + rng.pick(3);
        let mut r = Mat::identity(3);
        for _ in 0..n {
            let f = rot_axis(rng.pick(3), &angles[rng.pick(angles.len())]);
            r = r.mul(&f).unwrap();
        }
        for zyx in [true, false] {
            let Some((v, br)) = euler(&r, zyx) else {
                continue;
            };
            reduced += usize::from(!br.positive.is_empty() || !br.angles.is_empty());
            for _ in 0..20 {
                let pt: Vec<f64> = (0..3).map(|_| (2.0 * rng.next() - 1.0) * 3.1).collect();
                let p = |x: &Symbol| {
                    ["a", "b", "c"]
                        .iter()
                        .position(|n| &*x.name == *n)
                        .map(|i| pt[i])
                };
                if !holds(&br, &p) {
                    continue;
                }
                let num = at(&r, &p);
                let want = if zyx {
                    crate::lie::repr::euler_zyx(&num)
                } else {
                    crate::lie::repr::euler_zxz(&num)
                };
                if want.note.is_some() {
                    continue;
                }
                checked += 1;
                for (i, e) in v.iter().enumerate() {
                    let got = e.eval(&p).unwrap();
                    assert!(
                        (got - want.angles[i]).abs() < 1e-9,
                        "case {case} ({}) at {pt:?}: angle {i} {e:?} = {got}, numbers {}",
                        if zyx { "zyx" } else { "zxz" },
                        want.angles[i]
                    );
                }
            }
        }
    }
    assert!(
        reduced > 50 && checked > 500,
        "{reduced} reduced, {checked} checked"
    );
}

/// atan2 of k sin θ and k cos θ with k a positive constant is θ where θ is
/// in (−π, π), at random points; with a factor of unknown sign it is kept.
#[test]
fn atan2_closed_forms_agree_with_numbers_on_their_branch() {
    let (a, b) = (s("a"), s("b"));
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let th = a.add(&b.scale(&Coef::int(2)));
    for k in [Expr::int(2), Expr::num(0.5), Expr::int(-3)] {
        let (y, x) = (Expr::sin(&th).mul(&k), Expr::cos(&th).mul(&k));
        let (t, br) = atan2(&y, &x).unwrap();
        for _ in 0..200 {
            let pt = [rng.next() * 6.0 - 3.0, rng.next() * 6.0 - 3.0];
            let p = |x: &Symbol| {
                ["a", "b"]
                    .iter()
                    .position(|n| &*x.name == *n)
                    .map(|i| pt[i])
            };
            if !holds(&br, &p) {
                continue;
            }
            let want = y.eval(&p).unwrap().atan2(x.eval(&p).unwrap());
            assert!((t.eval(&p).unwrap() - want).abs() < 1e-9, "{k:?} at {pt:?}");
        }
    }
    // cos(b) of either sign: no closed form without a branch
    let k = Expr::cos(&b);
    assert!(atan2(&Expr::sin(&a).mul(&k), &Expr::cos(&a).mul(&k)).is_none());
    assert!(atan2(&Expr::zero(), &k).is_none());
}
