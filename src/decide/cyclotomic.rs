//! Cyclotomic fields for the proofs of [`super::lift`]: the minimal
//! polynomial Φ_n of a primitive n-th root of unity z = e^{2πi/n}, and the
//! square roots and i written as polynomials in z, so that a number with
//! roots of unity (cos π/5) and one with square roots ((1 + √5)/4) are
//! written in one field, ℚ(z), where equal numbers have equal canonical
//! forms. Every √k with k square-free lies in such a field (Gauss sums:
//! for an odd prime p, Σ_{a=1}^{p−1} (a/p) z_p^a = √p*, p* = ±p ≡ 1 mod 4;
//! √2 = z_8 + z_8⁻¹; i = z_4), the least such n being k's conductor.

use crate::sym::coef::Coef;
use crate::sym::rat::Rat;
use crate::sym::surd::Surd;

/// The cyclotomic polynomial Φ_n (integer coefficients, lowest power
/// first): the minimal polynomial over ℚ of a primitive n-th root of
/// unity, by Φ_n = (zⁿ − 1) / Π Φ_d over the divisors d < n.
pub fn cyclotomic(n: usize) -> Vec<i64> {
    let mut p = vec![0i64; n + 1];
    p[0] = -1;
    p[n] = 1;
    for d in (1..n).filter(|d| n.is_multiple_of(*d)) {
        let q = cyclotomic(d);
        // (exact division by the monic q, highest power first)
        let mut out = vec![0i64; p.len() - q.len() + 1];
        for i in (0..out.len()).rev() {
            let c = p[i + q.len() - 1];
            out[i] = c;
            for (j, qj) in q.iter().enumerate() {
                p[i + j] -= c * qj;
            }
        }
        p = out;
    }
    p
}

/// The conductor of √k for a square-free k > 1: the least n with √k in
/// ℚ(e^{2πi/n}) — k when k ≡ 1 (mod 4), else 4k. None when too large to
/// matter (above 720, the widest field the proofs use).
pub fn conductor(k: u128) -> Option<usize> {
    let n = if k % 4 == 1 { k } else { k.checked_mul(4)? };
    usize::try_from(n).ok().filter(|n| *n <= 720)
}

/// The least n whose field holds every square root among `c`'s
/// coefficients (1 when there is none; None when one is too large).
pub fn conductor_of(c: &Coef) -> Option<usize> {
    let Coef::Exact { re, im } = c else {
        return Some(1);
    };
    let mut n = 1;
    for (k, _) in re.terms().chain(im.terms()) {
        if k > 1 {
            n = num_integer::Integer::lcm(&n, &conductor(k)?);
        }
    }
    Some(n)
}

/// The product of two polynomials in z modulo zⁿ − 1 (z is an n-th root
/// of unity).
fn times(a: &[Rat], b: &[Rat], n: usize) -> Vec<Rat> {
    let mut out = vec![Rat::ZERO; n];
    for (i, x) in a.iter().enumerate().filter(|(_, x)| !x.is_zero()) {
        for (j, y) in b.iter().enumerate().filter(|(_, y)| !y.is_zero()) {
            let at = (i + j) % n;
            out[at] = out[at].add(&x.mul(y));
        }
    }
    out
}

/// z^e modulo zⁿ − 1, as a polynomial.
fn power(e: usize, n: usize) -> Vec<Rat> {
    let mut out = vec![Rat::ZERO; n];
    out[e % n] = Rat::ONE;
    out
}

/// a^e mod m.
fn pow_mod(a: usize, mut e: usize, m: usize) -> usize {
    let (mut base, mut out) = (a % m, 1 % m);
    while e > 0 {
        if e & 1 == 1 {
            out = out * base % m;
        }
        base = base * base % m;
        e >>= 1;
    }
    out
}

/// √k (k square-free, its conductor dividing n) as a polynomial in
/// z = e^{2πi/n}, modulo zⁿ − 1: the product over k's primes of √2 =
/// z_8 + z_8⁻¹ and of the Gauss sums Σ (a/p) z_p^a, which are √p
/// (p ≡ 1 mod 4) or i√p (p ≡ 3 mod 4), z_m = z^{n/m}, times i^−m for
/// the m primes ≡ 3 (mod 4).
fn sqrt_poly(k: u128, n: usize) -> Option<Vec<Rat>> {
    let k = usize::try_from(k).ok()?;
    if !n.is_multiple_of(conductor(k as u128)?) {
        return None;
    }
    let mut out = power(0, n);
    let (mut rest, mut p, mut threes) = (k, 2, 0usize);
    while rest > 1 {
        if !rest.is_multiple_of(p) {
            p += 1;
            continue;
        }
        rest /= p;
        let root = if p == 2 {
            let mut r = power(n / 8, n);
            r[7 * n / 8] = Rat::ONE;
            r
        } else {
            let mut gauss = vec![Rat::ZERO; n];
            for a in 1..p {
                let sign = if pow_mod(a, (p - 1) / 2, p) == 1 {
                    1
                } else {
                    -1
                };
                gauss[a * n / p] = Rat::int(sign);
            }
            threes += usize::from(p % 4 == 3);
            gauss
        };
        out = times(&out, &root, n);
    }
    // (each Gauss sum of a p ≡ 3 is i√p: the product is i^m √k, and
    // i^m is ±1 or ±i, the latter only when 4 | n)
    if threes % 2 == 1 {
        out = times(&out, &power(3 * n / 4, n), n);
    }
    if threes % 4 >= 2 {
        out.iter_mut().for_each(|c| *c = c.neg());
    }
    Some(out)
}

/// A surd as a polynomial in z = e^{2πi/n} (None when a root's conductor
/// does not divide n).
fn surd_poly(s: &Surd, n: usize) -> Option<Vec<Rat>> {
    let mut out = vec![Rat::ZERO; n];
    for (k, c) in s.terms() {
        let root = if k == 1 {
            power(0, n)
        } else {
            sqrt_poly(k, n)?
        };
        for (o, r) in out.iter_mut().zip(root) {
            *o = o.add(&r.mul(c));
        }
    }
    Some(out)
}

/// The exact coefficient `c` as a polynomial in z = e^{2πi/n}, lowest
/// power first, with rational coefficients when 4 | n (i = z^{n/4}); when
/// 4 ∤ n, i stays in the coefficients (ℚ(i) meets ℚ(z) in ℚ only, so the
/// forms stay canonical). None for a float or a root outside ℚ(z).
pub fn coef_poly(c: &Coef, n: usize) -> Option<Vec<Coef>> {
    let Coef::Exact { re, im } = c else {
        return None;
    };
    let re = surd_poly(re, n)?;
    let im = surd_poly(im, n)?;
    let out = if n.is_multiple_of(4) {
        let turned = times(&im, &power(n / 4, n), n);
        re.iter()
            .zip(&turned)
            .map(|(a, b)| Coef::rat(a.add(b)))
            .collect()
    } else {
        re.into_iter()
            .zip(im)
            .map(|(a, b)| Coef::rat(a).add(&Coef::i().mul(&Coef::rat(b))))
            .collect()
    };
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The polynomial at z = e^{2πi/n}, as floats.
    fn at(p: &[Rat], n: usize) -> (f64, f64) {
        p.iter().enumerate().fold((0.0, 0.0), |(re, im), (j, c)| {
            let t = std::f64::consts::TAU * j as f64 / n as f64;
            (re + c.to_f64() * t.cos(), im + c.to_f64() * t.sin())
        })
    }

    #[test]
    fn square_roots_are_their_gauss_sums() {
        let squarefree = |k: u128| (2..=k).all(|d| d * d > k || !k.is_multiple_of(d * d));
        for k in (2u128..=180).filter(|k| squarefree(*k)) {
            let Some(c) = conductor(k) else { continue };
            for n in (c..=720).step_by(c).filter(|n| n.is_multiple_of(2)).take(3) {
                let p = sqrt_poly(k, n).expect("in the field");
                let (re, im) = at(&p, n);
                let want = (k as f64).sqrt();
                assert!(
                    (re - want).abs() < 1e-9 && im.abs() < 1e-9,
                    "√{k} at n = {n}: {re} {im}"
                );
            }
            assert!(sqrt_poly(k, 2 * c + 2).is_none());
        }
    }

    #[test]
    fn i_and_cyclotomic_degrees() {
        let p = coef_poly(&Coef::i(), 20).expect("exact");
        assert_eq!(p[5], Coef::int(1));
        assert_eq!(cyclotomic(10), vec![1, -1, 1, -1, 1]);
        assert_eq!(cyclotomic(720).len() - 1, 192);
    }
}
