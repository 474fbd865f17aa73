//! Exact real numbers with square roots (LANGUAGE.md §7: "square roots of
//! exact numbers and what arithmetic makes of them" stay exact): a
//! rational plus rational multiples of √k for distinct square-free
//! integers k > 1 — an element of ℚ(√k₁, √k₂, …). Such roots are linearly
//! independent over ℚ, so each number has one form and is 0 only when
//! every coefficient is: `==` on it is exact. √2·√3 = √6, √8 = 2√2,
//! 1/(√2 + √3) = √3 − √2; the book's √2/2 and √3/2 are the common case.
//!
//! A rational alone (the usual coefficient) holds no list and allocates
//! nothing beyond its [`Rat`].

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed};

use super::rat::Rat;
use super::squarefree;

/// a + Σ cₖ√k: a rational part and the roots' coefficients, by increasing
/// square-free k > 1, none 0 (so the derived equality is the value's).
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Surd {
    rat: Rat,
    roots: Vec<(u128, Rat)>,
}

/// The most terms a reciprocal may make before it is given up (a float
/// then): 1/(√2 + √3 + √5 + … ) over n primes has 2ⁿ⁻¹ terms.
const MAX_TERMS: usize = 256;

fn gcd(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// An integer as a fraction (None above i128).
fn int(n: u128) -> Option<Rat> {
    Rat::new(i128::try_from(n).ok()?, 1)
}

impl Surd {
    /// 0.
    pub const ZERO: Surd = Surd {
        rat: Rat::ZERO,
        roots: Vec::new(),
    };
    /// A rational as a surd.
    pub fn rat(r: Rat) -> Surd {
        Surd {
            rat: r,
            roots: Vec::new(),
        }
    }
    /// c·√k for a square-free k (k = 1: the rational c).
    fn term(c: Rat, k: u128) -> Surd {
        match k {
            _ if c.is_zero() => Surd::ZERO,
            1 => Surd::rat(c),
            _ => Surd {
                rat: Rat::ZERO,
                roots: vec![(k, c)],
            },
        }
    }
    /// a + b√2 + c√3 + d√6 (the field of the book's angles, multiples of
    /// 15°).
    pub fn of_basis([a, b, c, d]: [Rat; 4]) -> Surd {
        let roots = [(2, b), (3, c), (6, d)]
            .into_iter()
            .filter(|(_, r)| !r.is_zero())
            .collect();
        Surd { rat: a, roots }
    }
    /// The terms as (k, cₖ) with k = 1 for the rational part, each
    /// coefficient non-zero, by increasing k.
    pub fn terms(&self) -> impl Iterator<Item = (u128, &Rat)> {
        (!self.rat.is_zero())
            .then_some((1u128, &self.rat))
            .into_iter()
            .chain(self.roots.iter().map(|(k, c)| (*k, c)))
    }
    /// True for 0.
    pub fn is_zero(&self) -> bool {
        self.roots.is_empty() && self.rat.is_zero()
    }
    /// The rational, when there is no root.
    pub fn as_rat(&self) -> Option<Rat> {
        self.roots.is_empty().then(|| self.rat.clone())
    }
    /// The rational, by reference, when there is no root.
    pub fn rational(&self) -> Option<&Rat> {
        self.roots.is_empty().then_some(&self.rat)
    }
    /// The sum.
    pub fn add(&self, o: &Surd) -> Surd {
        Surd {
            rat: self.rat.add(&o.rat),
            roots: merge(&self.roots, &o.roots),
        }
    }
    /// −x.
    pub fn neg(&self) -> Surd {
        Surd {
            rat: self.rat.neg(),
            roots: self.roots.iter().map(|(k, c)| (*k, c.neg())).collect(),
        }
    }
    /// r·x.
    pub fn scale(&self, r: &Rat) -> Surd {
        if r.is_zero() {
            return Surd::ZERO;
        }
        Surd {
            rat: self.rat.mul(r),
            roots: self.roots.iter().map(|(k, c)| (*k, c.mul(r))).collect(),
        }
    }
    /// The product, by √a·√b = g√(ab/g²) with g = gcd(a, b); None when a
    /// root's k passes 2¹²⁸.
    pub fn mul(&self, o: &Surd) -> Option<Surd> {
        if o.roots.is_empty() {
            return Some(self.scale(&o.rat));
        }
        if self.roots.is_empty() {
            return Some(o.scale(&self.rat));
        }
        let mut acc = Vec::with_capacity((self.roots.len() + 1) * (o.roots.len() + 1));
        for (a, x) in self.terms() {
            for (b, y) in o.terms() {
                let g = gcd(a, b);
                let k = (a / g).checked_mul(b / g)?;
                let c = x.mul(y);
                acc.push((k, if g == 1 { c } else { c.mul(&int(g)?) }));
            }
        }
        Some(Surd::collect(acc))
    }
    /// The sum of terms (k, cₖ) in any order, k square-free.
    fn collect(mut terms: Vec<(u128, Rat)>) -> Surd {
        terms.sort_by_key(|t| t.0);
        let mut out = Surd::ZERO;
        for (k, c) in terms {
            if k == 1 {
                out.rat = out.rat.add(&c);
            } else if let Some(last) = out.roots.last_mut().filter(|l| l.0 == k) {
                last.1 = last.1.add(&c);
            } else {
                out.roots.push((k, c));
            }
        }
        out.roots.retain(|(_, c)| !c.is_zero());
        out
    }
    /// A b > 1 that divides each root's k or is prime to it: the roots
    /// whose k it divides change sign together under an automorphism of
    /// the field (√p ↦ −√p for one prime p of b). None without roots.
    fn base(&self) -> Option<u128> {
        let mut b = self.roots.first()?.0;
        'again: loop {
            for (k, _) in &self.roots {
                let g = gcd(b, *k);
                if g != 1 && g != b {
                    b = g;
                    continue 'again;
                }
            }
            return Some(b);
        }
    }
    /// x = a + c√b with a and c free of b's primes.
    fn split(&self, b: u128) -> (Surd, Surd) {
        let (mut a, mut c) = (Surd::rat(self.rat.clone()), Vec::new());
        for (k, r) in &self.roots {
            if k % b == 0 {
                c.push((k / b, r.clone()));
            } else {
                a.roots.push((*k, r.clone()));
            }
        }
        (a, Surd::collect(c))
    }
    /// 1/x: 1/(a + c√b) = (a − c√b)/(a² − b c²), the denominator free of
    /// b's primes, until it is rational. None for 0, or when the terms
    /// pass `MAX_TERMS` (or a root 2¹²⁸).
    pub fn inv(&self) -> Option<Surd> {
        if self.roots.is_empty() {
            return Some(Surd::rat(self.rat.inv()?));
        }
        let b = self.base()?;
        let (a, c) = self.split(b);
        let cb = c.mul(&Surd::term(Rat::ONE, b))?;
        let d = a.mul(&a)?.add(&c.mul(&c)?.scale(&int(b)?).neg());
        if d.roots.len() > MAX_TERMS {
            return None;
        }
        let out = a.add(&cb.neg()).mul(&d.inv()?)?;
        (out.roots.len() <= MAX_TERMS).then_some(out)
    }
    /// Machine words beyond the inline ones that the fractions hold (0 for
    /// the usual small ones).
    pub fn words(&self) -> usize {
        self.terms().map(|(_, r)| r.words()).sum()
    }
    /// The nearest float, or nearly.
    pub fn to_f64(&self) -> f64 {
        self.terms()
            .map(|(k, r)| r.to_f64() * (k as f64).sqrt())
            .sum()
    }
    /// The sign of the value (0 only for zero): read off floats when they
    /// leave no doubt, else from bounds of every root, at a precision
    /// doubled until they settle it (they do: the value is not 0).
    pub fn signum(&self) -> f64 {
        if self.roots.is_empty() {
            return if self.rat.is_zero() {
                0.0
            } else if self.rat.is_negative() {
                -1.0
            } else {
                1.0
            };
        }
        let (mut v, mut size) = (0.0f64, 0.0f64);
        for (k, r) in self.terms() {
            let t = r.to_f64() * (k as f64).sqrt();
            v += t;
            size += t.abs();
        }
        if v.is_finite() && size.is_finite() && size > 1e-250 && v.abs() > 1e-9 * size {
            return v.signum();
        }
        let mut bits = 128usize;
        while bits <= 1 << 22 {
            let (lo, hi) = self.bounds(bits);
            if lo.is_positive() {
                return 1.0;
            }
            if hi.is_negative() {
                return -1.0;
            }
            bits *= 4;
        }
        v.signum()
    }
    /// Bounds on the value from each √k to `bits` binary places.
    fn bounds(&self, bits: usize) -> (BigRational, BigRational) {
        let scale = BigInt::one() << bits;
        let mut lo = self.rat.to_big();
        let mut hi = lo.clone();
        for (k, c) in &self.roots {
            let s = (BigInt::from(*k) << (2 * bits)).sqrt();
            let below = BigRational::new(s.clone(), scale.clone());
            let above = BigRational::new(s + 1, scale.clone());
            let c = c.to_big();
            if c.is_positive() {
                lo += &c * below;
                hi += &c * above;
            } else {
                lo += &c * above;
                hi += &c * below;
            }
        }
        (lo, hi)
    }
    /// √self as a surd: a rational's root ([`Surd::sqrt_of`]), or
    /// √(a + b√c) denested when d = a² − b²c is a rational square:
    /// √((a + √d)/2) ± √((a − √d)/2), the sign of b (√(2 + √3) =
    /// (√6 + √2)/2). None for a negative number or a root that does not
    /// denest (√(1 + √2)).
    pub fn sqrt(&self) -> Option<Surd> {
        if let Some(r) = self.rational() {
            return if r.is_negative() {
                None
            } else {
                Surd::sqrt_of(r)
            };
        }
        let [(c, b)] = self.roots.as_slice() else {
            return None;
        };
        let a = &self.rat;
        if self.signum() <= 0.0 || a.is_negative() {
            return None;
        }
        let d = a.mul(a).add(&b.mul(b).mul(&int(*c)?).neg());
        if d.is_negative() {
            return None;
        }
        let s = Surd::sqrt_of(&d)?.as_rat()?;
        let half = Rat::new(1, 2)?;
        let x = Surd::sqrt_of(&a.add(&s).mul(&half))?;
        let y = Surd::sqrt_of(&a.add(&s.neg()).mul(&half))?;
        Some(if b.is_negative() {
            x.add(&y.neg())
        } else {
            x.add(&y)
        })
    }
    /// √r exactly: r = s²·k/q² with k square-free (√8 = 2√2, √(3/4) =
    /// √3/2, √5); None for r < 0, or when the primes of r's numerator or
    /// denominator cannot be found for sure ([`squarefree`]).
    pub fn sqrt_of(r: &Rat) -> Option<Surd> {
        if r.is_negative() {
            return None;
        }
        if r.is_zero() {
            return Some(Surd::ZERO);
        }
        // √(p/q) = sp√kp/(sq√kq) = sp·g·√(kp kq/g²)/(sq·kq)
        let ((sp, kp), (sq, kq)) = match r.small() {
            Some((p, q)) => {
                let (sp, kp) = squarefree::split_u128(p.unsigned_abs().into())?;
                let (sq, kq) = squarefree::split_u128(q.unsigned_abs().into())?;
                ((BigInt::from(sp), kp), (BigInt::from(sq), kq))
            }
            None => {
                let (p, q) = r.parts();
                let (sp, kp) = squarefree::split(p.magnitude())?;
                let (sq, kq) = squarefree::split(q.magnitude())?;
                ((BigInt::from(sp), kp), (BigInt::from(sq), kq))
            }
        };
        let g = gcd(kp, kq);
        let k = (kp / g).checked_mul(kq / g)?;
        let c = BigRational::new(sp * BigInt::from(g), sq * BigInt::from(kq));
        Some(Surd::term(Rat::from_big(c), k))
    }
}

/// The sum of two lists of roots (by increasing k), zeros dropped.
fn merge(a: &[(u128, Rat)], b: &[(u128, Rat)]) -> Vec<(u128, Rat)> {
    if a.is_empty() {
        return b.to_vec();
    }
    if b.is_empty() {
        return a.to_vec();
    }
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match a[i].0.cmp(&b[j].0) {
            Ordering::Less => {
                out.push(a[i].clone());
                i += 1;
            }
            Ordering::Greater => {
                out.push(b[j].clone());
                j += 1;
            }
            Ordering::Equal => {
                let s = a[i].1.add(&b[j].1);
                if !s.is_zero() {
                    out.push((a[i].0, s));
                }
                i += 1;
                j += 1;
            }
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(p: i128, q: i128) -> Rat {
        Rat::new(p, q).unwrap()
    }
    fn root(n: i128) -> Surd {
        Surd::sqrt_of(&r(n, 1)).unwrap()
    }

    #[test]
    fn roots_multiply_and_cancel_exactly() {
        assert_eq!(root(5).mul(&root(5)), Some(Surd::rat(r(5, 1))));
        assert_eq!(root(2).mul(&root(3)), Some(root(6)));
        assert_eq!(root(8), Surd::term(r(2, 1), 2));
        assert_eq!(Surd::sqrt_of(&r(9, 4)), Some(Surd::rat(r(3, 2))));
        assert_eq!(Surd::sqrt_of(&r(1, 3)), Some(Surd::term(r(1, 3), 3)));
        assert_eq!(root(10).mul(&root(15)), Some(Surd::term(r(5, 1), 6)));
        assert!(root(2).add(&root(3)).add(&root(5).neg()).signum() > 0.0);
        assert_eq!(Surd::sqrt_of(&r(-4, 1)), None);
    }

    #[test]
    fn reciprocals_of_sums_of_roots() {
        let x = root(2).add(&root(3));
        assert_eq!(x.inv(), Some(root(3).add(&root(2).neg())));
        // 1/(1 + √2 + √3 + √5 + √7) · itself = 1
        let y = [2, 3, 5, 7]
            .iter()
            .fold(Surd::rat(Rat::ONE), |s, &k| s.add(&root(k)));
        let inv = y.inv().expect("within the limit");
        assert_eq!(y.mul(&inv), Some(Surd::rat(Rat::ONE)));
        assert!((inv.to_f64() * y.to_f64() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn signs_of_near_cancellations_are_exact() {
        // √(10¹⁶ + 1) − 10⁸ > 0 though floats make it 0
        let big = Surd::sqrt_of(&r(10_i128.pow(16) + 1, 1)).unwrap();
        assert_eq!(big.add(&Surd::rat(r(-(10_i128.pow(8)), 1))).signum(), 1.0);
        // 5√2 − √50 = 0
        assert!(Surd::term(r(5, 1), 2).add(&root(50).neg()).is_zero());
        // √2 + √3 − √(5 + 2√6) is not representable; √2 + √3 − √10 < 0? (3.146 − 3.162)
        assert_eq!(root(2).add(&root(3)).add(&root(10).neg()).signum(), -1.0);
    }
}
