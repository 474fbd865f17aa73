//! The logarithm of an exponential (the book's §3.2.3.3 and §3.3.3.2;
//! LANGUAGE.md §7): `log(exp([ω̂] 0.5))` is [ω̂] 0.5 exactly, so
//! `log(exp([ω̂] 0.5)) == [ω̂] 0.5` and `MatrixLog6(MatrixExp6(V)) == V` are
//! true, not floats that differ by rounding.
//!
//! The book's logarithms are principal: θ ∈ [0, π] (the algorithm of
//! §3.2.3.3; for a transform, v = G⁻¹(θ)p, (3.92)). For X in so(3) or
//! se(3) whose rotation part ω has ‖ω‖ < π, e^X is the rotation by
//! θ = ‖ω‖ about ω̂ (with its translation), and the logarithm's one answer
//! with θ in [0, π) is X itself. So when X has an exact form of that
//! shape (skew, its bottom row 0) and the bound is certified by ball
//! arithmetic, the logarithm's exact form is X's, in the logarithm's
//! shape (the 3- or 6-vector of `MatrixLog3` and `MatrixLog6`), and every
//! proof of `==` reads it as it reads X.
//!
//! Past π, a rotation's logarithm is X turned back by whole turns,
//! ω(1 − 2πk/θ) ([`turned_back`]), when θ is certified between odd
//! multiples of π; a transform's translation would change too
//! (G⁻¹(θ′)G(θ)v), and stays a float. At an odd multiple of π the
//! logarithm has two answers (±ω̂, the θ = π note) and stays a float.
//! Whatever made it, a group element that is exactly I (a whole turn,
//! `Rotz(2 pi)`), or a transform whose rotation is, has the logarithm 0 or
//! [0, p; 0, 0] ([`identity_log`]); its floats are rounding's, which no
//! tolerance relative to 0 could call rounding. An X with no exact form,
//! and so(2) and se(2) (whose exponentials keep no recipe), stay floats.

use super::ball;
use super::certify::PRECISIONS;
use crate::check::ty::Kind;
use crate::sym::coef::{Coef, Rat};
use crate::sym::matrix::{skew, twist_matrix, unskew};
use crate::sym::{Expr, Mat};
use crate::values::exact::deref;
use crate::values::exact::{Exact, Operation, is_exact};
use crate::values::value::Value;

/// The exact form of `out`, the result of builtin `name` on `args`, when
/// it is the logarithm of an exponential on the principal branch (the
/// module's doc): X in `out`'s shape. None for any other call (the
/// caller asks only for results of a Lie algebra's kinds).
pub(crate) fn exact_of(name: &str, args: &[Value], out: &Value) -> Option<Exact> {
    if !matches!(name, "log" | "MatrixLog3" | "MatrixLog6") {
        return None;
    }
    let ([arg], Value::Num { m, .. }) = (args, out) else {
        return None;
    };
    let of_exponent = |(group, x): (Kind, Value)| {
        let v = algebra_vector(&x.exact_form()?, group)?;
        if principal(&v[..3]) {
            Some(v)
        } else if v.len() == 3 {
            // (past π: a rotation's X turned back by whole turns)
            turned_back(&v)
        } else {
            // (a transform's translation would change too, G⁻¹(θ′)G(θ)v:
            // a float, unless its rotation is I)
            None
        }
    };
    let v = exponent(arg)
        .and_then(of_exponent)
        .or_else(|| identity_log(arg))?;
    let (rows, cols) = m.shape();
    // (the logarithm's shape is its group's: a vector of v's length, or
    // that vector's matrix)
    let side = if v.len() == 3 { 3 } else { 4 };
    let fits = (rows, cols) == (v.len(), 1) || (rows, cols) == (side, side);
    fits.then(|| Exact::known(in_shape(&v, rows, cols)))
}

/// The logarithm of a rotation that is exactly I (§3.2.3.3, case (a):
/// θ = 0, log R = 0), or of a transform whose rotation is exactly I
/// (§3.3.3.2, case (a): ω = 0, so [S]θ = [0, p; 0, 0]): the vector 0, or
/// (0, p). Its floats are rounding's (`Rotz(2π)`'s sin 2π is −2.4e-16),
/// so without this `log(Rotz(2 pi)) == zeros(3, 3)` compared noise with
/// 0, where no relative tolerance can say "rounding". Only a rotation
/// whose trace is within 1e-9 of 3 in floats has its exact form asked for.
fn identity_log(e: &Value) -> Option<Vec<Expr>> {
    let Value::Num { m, kind, .. } = e else {
        return None;
    };
    let n = match kind {
        Kind::SO3 => 3,
        Kind::SE3 => 4,
        _ => return None,
    };
    // (a rotation's trace is 1 + 2 cos θ: within 1e-9 of 3 only near I;
    // the exact form below decides)
    if m.shape() != (n, n) || (m[(0, 0)] + m[(1, 1)] + m[(2, 2)] - 3.0).abs() > 1e-9 {
        return None;
    }
    let x = e.exact_form()?;
    let is = |i: usize, j: usize, k: i64| *x.get(i, j) == Expr::int(k);
    let rotation_is_one = (0..3).all(|i| (0..3).all(|j| is(i, j, i64::from(i == j))));
    if !rotation_is_one {
        return None;
    }
    let mut v = vec![Expr::default(); 3];
    if n == 4 {
        if !(0..3).all(|j| is(3, j, 0)) || !is(3, 3, 1) {
            return None;
        }
        v.extend((0..3).map(|i| x.get(i, 3).clone()));
    }
    Some(v)
}

/// The principal logarithm of e^[ω] for ‖ω‖ = θ past π (§3.2.3.3): the
/// rotation by θ about ω̂ is the rotation by θ − 2πk, k the whole turns
/// nearest θ/2π, so its logarithm is ω̂(θ − 2πk) = ω(1 − 2πk/θ) (about −ω̂
/// when θ − 2πk < 0). None unless |θ − 2πk| < π is certified by ball
/// arithmetic — at an odd multiple of π the logarithm has two answers (the
/// θ = π note) — or when θ has no exact form (a square root the exact
/// numbers do not hold; then the product is no exact form either, and
/// [`Exact::known`] keeps none).
fn turned_back(omega: &[Expr]) -> Option<Vec<Expr>> {
    let square = norm_squared(omega);
    let prec = PRECISIONS[0];
    let pi = ball::pi(prec);
    let pi2 = ball::mul(&pi, &pi, prec)?;
    let s = ball::exact(&square, prec)?;
    // θ/2π from the floats, then certified: (2k − 1)²π² < θ² < (2k + 1)²π²
    let turns = (ball::floats(&ball::div(&s, &pi2, prec)?).0.sqrt() / 2.0).round();
    if !(1.0..=1e6).contains(&turns) {
        return None;
    }
    let k = turns as i64;
    let odd_squared = |j: i64| ball::mul(&ball::int(&(j * j).into()), &pi2, prec);
    let below = ball::sub(&s, &odd_squared(2 * k - 1)?, prec)?;
    let above = ball::sub(&odd_squared(2 * k + 1)?, &s, prec)?;
    let inside = |d: &ball::Ball| ball::nonzero(d) && ball::floats(d).0 > 0.0;
    if !inside(&below) || !inside(&above) {
        return None;
    }
    // θ = √(θ²), or √(θ²/π²)·π for an angle in turns of π (`[ẑ] 5 pi/2`)
    let pi_squared = Expr::pi().mul(&Expr::pi());
    let theta = match square.div(&pi_squared)? {
        turns if turns.as_const().is_some() => Expr::sqrt(&turns).mul(&Expr::pi()),
        _ => Expr::sqrt(&square),
    };
    let whole = Expr::pi().scale(&Coef::rat(Rat::new(2 * i128::from(k), 1)?));
    let factor = Expr::int(1).sub(&whole.div(&theta)?);
    let v: Vec<Expr> = omega.iter().map(|w| w.mul(&factor)).collect();
    // (an angle a + bπ, or a root the exact numbers do not hold, gives no
    // exact form: the caller then tries whether e^X is exactly I)
    is_exact(&Mat::column(v.clone())).then_some(v)
}

/// The group of e^X and the argument X, when `e` was made by an
/// exponential (`exp`, `MatrixExp3`, `MatrixExp6`) of X and still keeps
/// that recipe (read without working out any form: `log(T_ac)` of a
/// product reads one operation name, no more).
fn exponent(e: &Value) -> Option<(Kind, Value)> {
    let Value::Num { exact, kind, .. } = e else {
        return None;
    };
    let x = exact
        .peek_recipe(|p| {
            let Operation::Call(name) = p.op else {
                return None;
            };
            let exp = crate::builtins::lookup(name)?.name;
            if !matches!(exp, "exp" | "MatrixExp3" | "MatrixExp6") {
                return None;
            }
            match deref(&p.args.refs()).as_slice() {
                [x] => Some((*x).clone()),
                _ => None,
            }
        })
        .flatten()?;
    Some((*kind, x))
}

/// The vector of X, an exact element of the Lie algebra of `group`: ω
/// (so(3)) or (ω, v) (se(3)), of the vector itself or of the matrix
/// (3.30, 3.70); None when X is not exactly of that form (not skew, a
/// bottom row that is not 0, another shape).
fn algebra_vector(x: &Mat, group: Kind) -> Option<Vec<Expr>> {
    let v = match (x.rows, x.cols) {
        (3 | 6, 1) => x.data.clone(),
        (3, 3) => unskew(x),
        (4, 4) => {
            let mut v = unskew(x);
            v.extend((0..3).map(|i| x.get(i, 3).clone()));
            v
        }
        _ => return None,
    };
    let fits = matches!((group, v.len()), (Kind::SO3, 3) | (Kind::SE3, 6));
    (fits && (x.cols == 1 || in_shape(&v, x.rows, x.cols) == *x)).then_some(v)
}

/// The vector `v` of an element of so(3) or se(3) in a logarithm's shape:
/// as it is (`MatrixLog3`, `MatrixLog6`), or its matrix [ω] (3.30) or
/// [V] (3.70) (`log`).
fn in_shape(v: &[Expr], rows: usize, cols: usize) -> Mat {
    match (rows, cols) {
        (3, 3) => skew(v),
        (4, 4) => twist_matrix(v),
        _ => Mat::column(v.to_vec()),
    }
}

/// ‖ω‖² = Σ ωᵢ², exactly.
fn norm_squared(omega: &[Expr]) -> Expr {
    omega.iter().fold(Expr::default(), |s, w| s.add(&w.mul(w)))
}

/// True when ‖ω‖ < π is certified: π² − Σ ωᵢ² is a ball that excludes 0
/// and lies above it.
fn principal(omega: &[Expr]) -> bool {
    let square = norm_squared(omega);
    let prec = PRECISIONS[0];
    let pi = ball::pi(prec);
    let Some(pi2) = ball::mul(&pi, &pi, prec) else {
        return false;
    };
    let Some(s) = ball::exact(&square, prec) else {
        return false;
    };
    ball::sub(&pi2, &s, prec).is_some_and(|d| ball::nonzero(&d) && ball::floats(&d).0 > 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i128, d: i128) -> Expr {
        Expr::constant(Coef::rat(Rat::new(n, d).expect("a fraction")))
    }

    #[test]
    fn the_vector_of_each_algebra() {
        // [(1, 2, 3)] with v = (4, 5, 6) beside it, row by row
        let m = Mat {
            rows: 4,
            cols: 4,
            data: [0, -3, 2, 4, 3, 0, -1, 5, -2, 1, 0, 6, 0, 0, 0, 0]
                .iter()
                .map(|&k| q(k, 1))
                .collect(),
        };
        let v: Vec<Expr> = (1..=6).map(|k| q(k, 1)).collect();
        assert_eq!(algebra_vector(&m, Kind::SE3), Some(v.clone()));
        assert_eq!(in_shape(&v, 4, 4), m);
        assert_eq!(in_shape(&v, 6, 1).data, v);
        // not skew, or a bottom row that is not 0: not of se(3)
        let mut bent = m.clone();
        bent.data[0] = q(1, 1);
        assert_eq!(algebra_vector(&bent, Kind::SE3), None);
        let mut bent = m.clone();
        bent.data[15] = q(1, 1);
        assert_eq!(algebra_vector(&bent, Kind::SE3), None);
        // the same 4×4 is no element of so(3); a 3-vector is, and its [ω]
        assert_eq!(algebra_vector(&m, Kind::SO3), None);
        let hat = in_shape(&v[..3], 3, 3);
        assert_eq!(algebra_vector(&hat, Kind::SO3), Some(v[..3].to_vec()));
        assert_eq!(
            algebra_vector(&Mat::column(v[..3].to_vec()), Kind::SE3),
            None
        );
    }

    #[test]
    fn the_principal_branch_is_strict() {
        // ‖(3, 0, 0)‖ = 3 < π; 3.15 > π; π itself is not strictly inside
        assert!(principal(&[q(3, 1), q(0, 1), q(0, 1)]));
        assert!(!principal(&[q(315, 100), q(0, 1), q(0, 1)]));
        assert!(!principal(&[Expr::pi(), q(0, 1), q(0, 1)]));
        assert!(principal(&[q(0, 1), q(0, 1), q(0, 1)]));
    }

    #[test]
    fn past_pi_whole_turns_come_off() {
        // (0, 0, 4): θ = 4, one turn off, (0, 0, 4 − 2π)
        let four = [q(0, 1), q(0, 1), q(4, 1)];
        let turned = turned_back(&four).expect("4 is between π and 3π");
        assert_eq!(turned[2], q(4, 1).sub(&Expr::pi().scale(&Coef::int(2))));
        assert_eq!(
            (&turned[0], &turned[1]),
            (&Expr::default(), &Expr::default())
        );
        // (0, 0, 5π/2): π/2; (0, 0, 3π): two answers, no form
        let angle = |k: i128| Expr::pi().scale(&Coef::rat(Rat::new(k, 2).expect("k/2")));
        let turned = turned_back(&[q(0, 1), q(0, 1), angle(5)]).expect("5π/2");
        assert_eq!(turned[2], angle(1));
        assert_eq!(turned_back(&[q(0, 1), q(0, 1), angle(6)]), None);
        // (3, 4, 0)·(7/5): θ = 7, k = 1, ω(1 − 2π/7)
        let w = [q(21, 5), q(28, 5), q(0, 1)];
        let turned = turned_back(&w).expect("7 is between π and 3π");
        let two_pi_seventh = Expr::pi().scale(&Coef::rat(Rat::new(2, 7).expect("2/7")));
        assert_eq!(turned[0], q(21, 5).sub(&q(21, 5).mul(&two_pi_seventh)));
    }
}
