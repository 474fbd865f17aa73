//! Half angles in the canonical form (LANGUAGE.md §7: "equal trigonometric
//! polynomials print alike"). An angle x whose double 2x is linear in the
//! symbols (x = t/2, (t1 + t2)/2) has no z = e^{ix} of its own, so sin x
//! and cos x are kept calls; a product of them is folded into the whole
//! angle, as the double-angle formulas say:
//!
//! sin x cos x = sin(2x)/2, sin² x = (1 − cos 2x)/2, cos² x = (1 + cos 2x)/2,
//!
//! so that `sin(t/2) cos(t/2)` is `sin(t)/2` and `2 cos(t/2)² − 1` is
//! `cos(t)`; what is left holds sin x or cos x to the first power at most,
//! and not both. (`==` also decides the rest: `together::unhalved`.)

use std::sync::Arc;

use super::coef::{Coef, Rat};
use super::expr::{Call, Expr, Func, Mono, Var};
use num_traits::{One, Zero};

/// The half angle x of a sine or cosine call, with the call's kind (true
/// for the sine), when 2x is linear.
fn half(v: &Var) -> Option<(&Expr, bool)> {
    match v {
        Var::Call(c) if matches!(c.f, Func::Sin | Func::Cos) => {
            Some((&c.args[0], c.f == Func::Sin))
        }
        _ => None,
    }
}

/// True when the monomial holds a square of a sine or cosine call, or a
/// sine and a cosine of one argument x, where 2x is linear: a product the
/// double-angle formulas fold.
fn may_fold(m: &Mono) -> bool {
    m.iter().enumerate().any(|(i, (v, e))| {
        let Some((x, sin)) = half(v) else {
            return false;
        };
        (*e >= 2
            || (*e >= 1
                && m[i + 1..]
                    .iter()
                    .any(|(w, f)| *f >= 1 && half(w).is_some_and(|(y, s)| s != sin && y == x))))
            && whole_has_z(x)
    })
}

fn twice(x: &Expr) -> Expr {
    x.scale(&Coef::int(2))
}

/// True when 2x has a z ([`Expr::expi`]): first, without forming 2x, that
/// every term of x is a symbol, π or a constant (any other term has no z
/// however scaled; x may be a large sum, the angle of `exp([S] θ)` with θ a
/// power of a sum, whose doubling in every product made a derivative take
/// most of its half second there — matrix differential seed 100072).
fn whole_has_z(x: &Expr) -> bool {
    let linear = x
        .terms
        .keys()
        .all(|m| matches!(m.as_slice(), [] | [(Var::Sym(_) | Var::Pi, 1)]));
    linear && Expr::expi(&twice(x)).is_some()
}

/// sin(x)^s cos(x)^c by the double-angle formulas: (the folded factor, the
/// powers of sin x and cos x left).
fn fold(x: &Expr, mut s: i32, mut c: i32) -> (Expr, i32, i32) {
    let half_coef = Coef::rat(Rat::new(1, 2).unwrap_or(Rat::ONE));
    let two_x = twice(x);
    let (sin2, cos2) = (Expr::sin(&two_x), Expr::cos(&two_x));
    let mut out = Expr::one();
    while s >= 1 && c >= 1 {
        out = out.mul(&sin2.scale(&half_coef));
        s -= 1;
        c -= 1;
    }
    while s >= 2 {
        out = out.mul(&Expr::one().sub(&cos2).scale(&half_coef));
        s -= 2;
    }
    while c >= 2 {
        out = out.mul(&Expr::one().add(&cos2).scale(&half_coef));
        c -= 2;
    }
    (out, s, c)
}

impl Expr {
    /// Products of sines and cosines of a half angle folded into its whole
    /// angle (module doc).
    pub(super) fn fold_halves(self) -> Expr {
        self.fold_terms(may_fold, fold_mono)
    }
}

/// One term with its half-angle products folded.
fn fold_mono(m: Mono, c: Coef) -> Expr {
    // (angle, sine call, its power, cosine call, its power)
    type Pair = (Expr, Option<Arc<Call>>, i32, Option<Arc<Call>>, i32);
    let mut pairs: Vec<Pair> = Vec::new();
    let mut rest: Mono = Vec::new();
    for (v, e) in m {
        let Var::Call(call) = &v else {
            rest.push((v, e));
            continue;
        };
        let Some((x, sin)) = half(&v).filter(|_| e > 0) else {
            rest.push((v, e));
            continue;
        };
        let i = match pairs.iter().position(|p| p.0 == *x) {
            Some(i) => i,
            None => {
                pairs.push((x.clone(), None, 0, None, 0));
                pairs.len() - 1
            }
        };
        if sin {
            (pairs[i].1, pairs[i].2) = (Some(call.clone()), e);
        } else {
            (pairs[i].3, pairs[i].4) = (Some(call.clone()), e);
        }
    }
    let mut t = Expr::constant(c);
    for (x, sc, s, cc, k) in pairs {
        // only where 2x is linear: the whole angle has its z
        let (f, s, k) = if whole_has_z(&x) {
            fold(&x, s, k)
        } else {
            (Expr::one(), s, k)
        };
        t = t.mul(&f);
        for (call, p) in [(sc, s), (cc, k)] {
            if let Some(call) = call
                && p != 0
            {
                rest.push((Var::Call(call), p));
            }
        }
    }
    rest.sort_by(|a, b| a.0.cmp(&b.0));
    let mut r = Expr::zero();
    r.push(rest, Coef::one());
    t.mul(&r)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::expr::Symbol;

    fn s(n: &str) -> Expr {
        Expr::symbol(Symbol::new(n))
    }

    #[test]
    fn products_of_half_angles_fold_into_the_whole_angle() {
        let t = s("t");
        let h = t.scale(&Coef::rat(Rat::new(1, 2).unwrap()));
        let (sh, ch) = (Expr::sin(&h), Expr::cos(&h));
        let half = Coef::rat(Rat::new(1, 2).unwrap());
        assert_eq!(sh.mul(&ch), Expr::sin(&t).scale(&half));
        assert_eq!(ch.mul(&ch).sub(&sh.mul(&sh)), Expr::cos(&t));
        assert_eq!(
            ch.mul(&ch).scale(&Coef::int(2)).sub(&Expr::one()),
            Expr::cos(&t)
        );
        // odd powers keep one factor: sin³(t/2) = sin(t/2)(1 − cos t)/2
        let cube = sh.mul(&sh).mul(&sh);
        assert_eq!(cube, sh.mul(&Expr::one().sub(&Expr::cos(&t))).scale(&half));
        // a third of an angle is no half: kept
        let third = Expr::sin(&t.scale(&Coef::rat(Rat::new(1, 3).unwrap())));
        assert_eq!(third.mul(&third).terms.len(), 1);
    }
}
