//! e^{As} in closed form for a small square matrix A of exact numbers times
//! one scalar expression s (book §3.2.1, eq. 3.41–3.48; Exercise 3.34;
//! LANGUAGE.md §7: "`exp(A t)` of a small matrix with exact eigenvalues has
//! its closed form").
//!
//! For a 2×2 A with characteristic polynomial z² − σz + π, every matrix
//! that the polynomial annihilates has e^{As} = g₀(s) I + g₁(s) A, where
//! g₀ + g₁z interpolates e^{zs} at the eigenvalues:
//!
//! - real distinct μ₁ ≠ μ₂: g₁ = (e^{μ₁s} − e^{μ₂s})/(μ₁ − μ₂), g₀ = (μ₁e^{μ₂s} − μ₂e^{μ₁s})/(μ₁ − μ₂);
//! - repeated μ: g₁ = s e^{μs}, g₀ = (1 − μs) e^{μs};
//! - complex α ± iβ: g₁ = e^{αs} sin(βs)/β, g₀ = e^{αs}(cos βs − α sin(βs)/β),
//!   the book's e^{αt}(cos βt, sin βt) form.
//!
//! A 3×3 A needs one rational eigenvalue λ (the others are then the roots
//! of a quadratic q, p(z) = (z − λ)q(z)). With λ simple, P = q(A)/q(λ) is
//! the projector on its eigenvector and e^{As} = e^{λs}P + (g₀I + g₁A)(I − P)
//! with g from q; a triple λ gives e^{λs}(I + Ns + N²s²/2), N = A − λI.
//! Eigenvalues that are not exact (a square root with no exact form, a
//! cubic with no rational root) give None: the call is kept.

use super::coef::{Coef, Rat};
use super::expr::Expr;
use super::matrix::{Mat, common_factor};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// The largest |coefficient| of the integer characteristic polynomial whose
/// divisors are searched for a rational eigenvalue.
const MAX_COEFFICIENT: u64 = 1_000_000_000_000;

/// The most candidates p/q the rational root theorem may try (each an
/// exact evaluation of the cubic).
const MAX_CANDIDATES: usize = 4096;

/// e^{M} for a square matrix M = A s, 1×1 to 3×3, with A exact rational
/// and s one expression (the module's doc); None otherwise.
pub fn exp_square(m: &Mat) -> Option<Mat> {
    let n = m.rows;
    if m.cols != n || !(1..=3).contains(&n) {
        return None;
    }
    if m.data.iter().all(Expr::is_zero) {
        return Some(Mat::identity(n));
    }
    let (ks, s) = common_factor(&m.data)?;
    let rats: Vec<Rat> = ks.iter().map(Coef::as_rat).collect::<Option<_>>()?;
    let a = Mat {
        rows: n,
        cols: n,
        data: rats
            .iter()
            .map(|r| Expr::constant(Coef::rat(r.clone())))
            .collect(),
    };
    let big: Vec<BigRational> = rats.iter().map(Rat::to_big).collect();
    match n {
        1 => Some(Mat::scalar(Expr::exp(&s.scale(&ks[0])))),
        2 => {
            let (sigma, pi) = (a.trace(), a.det()?);
            let (g0, g1) = quadratic(&sigma, &pi, &s)?;
            Some(combine(&g0, &g1, &a))
        }
        _ => cubic(&a, &big, &s),
    }
}

/// g₀ I + g₁ A.
fn combine(g0: &Expr, g1: &Expr, a: &Mat) -> Mat {
    let mut out = a.scale(g1);
    for i in 0..a.rows {
        let d = out.get(i, i).add(g0);
        out.set(i, i, d);
    }
    out
}

/// (g₀, g₁) of the module's doc for the eigenvalues of z² − σz + π (σ and π
/// exact constants): e^{Bs} = g₀I + g₁B for every B with B² − σB + πI = 0.
fn quadratic(sigma: &Expr, pi: &Expr, s: &Expr) -> Option<(Expr, Expr)> {
    let half = Coef::rat(Rat::new(1, 2)?);
    let disc = sigma.mul(sigma).sub(&pi.scale(&Coef::int(4)));
    let d = disc.as_const()?.as_rat()?;
    let mid = sigma.scale(&half); // (μ₁ + μ₂)/2, or α
    let e_mid = Expr::exp(&s.mul(&mid));
    if d.is_zero() {
        let g1 = s.mul(&e_mid);
        let g0 = Expr::one().sub(&mid.mul(s)).mul(&e_mid);
        return Some((g0, g1));
    }
    let root = exact_sqrt(&abs(&d))?; // √|disc|
    if d.is_negative() {
        let beta = root.scale(&half);
        let (c, sn) = (Expr::cos(&beta.mul(s)), Expr::sin(&beta.mul(s)));
        let sn_over = sn.mul(&beta.recip()?);
        let g1 = e_mid.mul(&sn_over);
        let g0 = e_mid.mul(&c.sub(&mid.mul(&sn_over)));
        return Some((g0, g1));
    }
    let m1 = mid.add(&root.scale(&half));
    let m2 = mid.sub(&root.scale(&half));
    let (e1, e2) = (Expr::exp(&s.mul(&m1)), Expr::exp(&s.mul(&m2)));
    let inv = root.recip()?; // 1/(μ₁ − μ₂)
    let g1 = e1.sub(&e2).mul(&inv);
    let g0 = m1.mul(&e2).sub(&m2.mul(&e1)).mul(&inv);
    Some((g0, g1))
}

/// √r as an exact constant (a surd), None when it has no exact form.
fn exact_sqrt(r: &Rat) -> Option<Expr> {
    let e = Expr::sqrt(&Expr::constant(Coef::rat(r.clone())));
    e.as_const().filter(Coef::is_exact)?;
    Some(e)
}

fn abs(r: &Rat) -> Rat {
    if r.is_negative() { r.neg() } else { r.clone() }
}

fn rat_expr(r: &BigRational) -> Expr {
    Expr::constant(Coef::rat(Rat::from_big(r.clone())))
}

/// p(z) = z³ + b₂z² + b₁z + b₀ of a 3×3 matrix: b₂ = −tr A, b₁ the sum of
/// the principal 2×2 minors, b₀ = −det A.
fn char_poly3(a: &[BigRational]) -> [BigRational; 3] {
    let g = |i: usize, j: usize| &a[i * 3 + j];
    let minor = |i: usize, j: usize| g(i, i) * g(j, j) - g(i, j) * g(j, i);
    let tr = g(0, 0) + g(1, 1) + g(2, 2);
    let m = minor(0, 1) + minor(0, 2) + minor(1, 2);
    let det = g(0, 0) * minor(1, 2) - g(0, 1) * (g(1, 0) * g(2, 2) - g(1, 2) * g(2, 0))
        + g(0, 2) * (g(1, 0) * g(2, 1) - g(1, 1) * g(2, 0));
    [-det, m, -tr]
}

/// The positive divisors of n (n ≤ [`MAX_COEFFICIENT`]).
fn divisors(n: u64) -> Vec<u64> {
    let mut out = Vec::new();
    let mut d = 1;
    while d * d <= n {
        if n.is_multiple_of(d) {
            out.push(d);
            if d * d != n {
                out.push(n / d);
            }
        }
        d += 1;
    }
    out
}

/// A rational root of z³ + b₂z² + b₁z + b₀ (rational root theorem on the
/// polynomial times the common denominator), None when it has none or its
/// coefficients are too large to search.
fn rational_root(b: &[BigRational; 3]) -> Option<BigRational> {
    let p = |z: &BigRational| ((z + &b[2]) * z + &b[1]) * z + &b[0];
    if b[0].is_zero() {
        return Some(BigRational::zero());
    }
    let den = b.iter().fold(BigInt::one(), |acc, c| {
        let d = c.denom();
        num_integer::Integer::lcm(&acc, d)
    });
    let a0 = (&b[0] * BigRational::from_integer(den.clone())).to_integer();
    let (a0, a3) = (a0.abs().to_u64()?, den.to_u64()?);
    if a0 > MAX_COEFFICIENT || a3 > MAX_COEFFICIENT {
        return None;
    }
    let (ps, qs) = (divisors(a0), divisors(a3));
    if ps.len().saturating_mul(qs.len()) > MAX_CANDIDATES {
        return None;
    }
    for q in &qs {
        for num in &ps {
            for sign in [1i64, -1] {
                let z = BigRational::new(BigInt::from(*num) * sign, BigInt::from(*q));
                if p(&z).is_zero() {
                    return Some(z);
                }
            }
        }
    }
    None
}

/// e^{As} of a 3×3 A with a rational eigenvalue (the module's doc).
fn cubic(a: &Mat, big: &[BigRational], s: &Expr) -> Option<Mat> {
    let b = char_poly3(big);
    let lambda = rational_root(&b)?;
    // p(z) = (z − λ)(z² + q₁z + q₀)
    let q1 = &b[2] + &lambda;
    let q0 = &b[1] + &lambda * &q1;
    let q_at = |z: &BigRational| (z + &q1) * z + &q0;
    let id = Mat::identity(3);
    let shifted = |z: &BigRational| a.add(&id.scale(&rat_expr(z)), true);
    if q_at(&lambda).is_zero() {
        // λ at least double; μ = tr A − 2λ the third
        let mu = -&b[2] - &lambda * BigRational::from_integer(2.into());
        if mu == lambda {
            let nil = shifted(&lambda)?;
            let n2 = nil.mul(&nil)?;
            let half = Expr::constant(Coef::rat(Rat::new(1, 2)?));
            let poly = id
                .add(&nil.scale(s), false)?
                .add(&n2.scale(&s.mul(s).mul(&half)), false)?;
            return Some(poly.scale(&Expr::exp(&s.mul(&rat_expr(&lambda)))));
        }
        // μ simple, the quadratic (z − λ)²
        let nil = shifted(&lambda)?;
        let gap = &mu - &lambda;
        let proj = nil.mul(&nil)?.scale(&rat_expr(&(&gap * &gap)).recip()?);
        let two_l = rat_expr(&(&lambda * BigRational::from_integer(2.into())));
        let l2 = rat_expr(&(&lambda * &lambda));
        return split(a, &proj, &mu, &two_l, &l2, s);
    }
    let q_mat = a
        .mul(a)?
        .add(&a.scale(&rat_expr(&q1)), false)?
        .add(&id.scale(&rat_expr(&q0)), false)?;
    let proj = q_mat.scale(&rat_expr(&q_at(&lambda)).recip()?);
    split(a, &proj, &lambda, &rat_expr(&-q1), &rat_expr(&q0), s)
}

/// e^{λs}P + (g₀I + g₁A)(I − P) for the projector P on the simple
/// eigenvalue λ and the other eigenvalues' quadratic z² − σz + π.
fn split(
    a: &Mat,
    proj: &Mat,
    lambda: &BigRational,
    sigma: &Expr,
    pi: &Expr,
    s: &Expr,
) -> Option<Mat> {
    let (g0, g1) = quadratic(sigma, pi, s)?;
    let rest = Mat::identity(3).add(proj, true)?;
    let on_rest = combine(&g0, &g1, a).mul(&rest)?;
    proj.scale(&Expr::exp(&s.mul(&rat_expr(lambda))))
        .add(&on_rest, false)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::Symbol;

    fn t() -> Expr {
        Expr::symbol(Symbol::new("t"))
    }

    fn mat(n: usize, v: &[i64]) -> Mat {
        Mat {
            rows: n,
            cols: n,
            data: v.iter().map(|x| t().scale(&Coef::int(*x))).collect(),
        }
    }

    fn exp_t(k: i64) -> Expr {
        Expr::exp(&t().scale(&Coef::int(k)))
    }

    #[test]
    fn distinct_real_eigenvalues_give_exponentials() {
        // A = [0, 1; -2, -3]: eigenvalues −1, −2
        let e = exp_square(&mat(2, &[0, 1, -2, -3])).unwrap();
        let two = Coef::int(2);
        assert_eq!(*e.get(0, 0), exp_t(-1).scale(&two).sub(&exp_t(-2)));
        assert_eq!(*e.get(0, 1), exp_t(-1).sub(&exp_t(-2)));
        assert_eq!(*e.get(1, 0), exp_t(-2).sub(&exp_t(-1)).scale(&two));
        assert_eq!(*e.get(1, 1), exp_t(-2).scale(&two).sub(&exp_t(-1)));
    }

    #[test]
    fn complex_eigenvalues_give_sines_and_cosines() {
        // A = [0, 1; -1, 0]: e^{At} = [cos t, sin t; −sin t, cos t]
        let e = exp_square(&mat(2, &[0, 1, -1, 0])).unwrap();
        assert_eq!(*e.get(0, 0), Expr::cos(&t()));
        assert_eq!(*e.get(0, 1), Expr::sin(&t()));
        assert_eq!(*e.get(1, 0), Expr::sin(&t()).neg());
    }

    #[test]
    fn a_repeated_eigenvalue_gives_t_times_the_exponential() {
        // A = [1, 1; 0, 1]: e^{At} = e^t [1, t; 0, 1]
        let e = exp_square(&mat(2, &[1, 1, 0, 1])).unwrap();
        assert_eq!(*e.get(0, 0), exp_t(1));
        assert_eq!(*e.get(0, 1), t().mul(&exp_t(1)));
        assert!(e.get(1, 0).is_zero());
    }

    #[test]
    fn three_by_three_with_a_triple_and_a_simple_eigenvalue() {
        // a Jordan block of 2: e^{2t}[1, t, t²/2; 0, 1, t; 0, 0, 1]
        let e = exp_square(&mat(3, &[2, 1, 0, 0, 2, 1, 0, 0, 2])).unwrap();
        let half = Coef::rat(Rat::new(1, 2).unwrap());
        assert_eq!(*e.get(0, 2), t().mul(&t()).mul(&exp_t(2)).scale(&half));
        // diag(1, 2, 3)
        let d = exp_square(&mat(3, &[1, 0, 0, 0, 2, 0, 0, 0, 3])).unwrap();
        assert_eq!(*d.get(2, 2), exp_t(3));
        assert!(d.get(0, 1).is_zero());
    }

    #[test]
    fn a_cubic_with_too_many_candidate_roots_keeps_the_call() {
        // p(z) = z³ − 963761198400 (6720 divisors): not searched, the call kept
        let m = mat(3, &[0, 1, 0, 0, 0, 1, 963_761_198_400, 0, 0]);
        assert_eq!(exp_square(&m), None);
        // (few divisors: 2³·3·5·7 = 840, z = 2 a root of z³ − 8)
        let m = mat(3, &[0, 1, 0, 0, 0, 1, 8, 0, 0]);
        assert!(exp_square(&m).is_some());
    }

    #[test]
    fn inexact_eigenvalues_keep_the_call() {
        // z³ − 2 has no rational root
        assert_eq!(exp_square(&mat(3, &[0, 1, 0, 0, 0, 1, 2, 0, 0])), None);
        let sym = Mat {
            rows: 2,
            cols: 2,
            data: vec![t(), t().mul(&t()), Expr::zero(), t()],
        };
        assert_eq!(exp_square(&sym), None);
    }
}
