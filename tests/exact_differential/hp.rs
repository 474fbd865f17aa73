//! The oracle's numbers: reals to 640 binary places (about 190 decimal
//! digits), as a big integer n standing for n / 2^640. Independent of the
//! engine's exact forms: π by Machin's formula, square roots by the
//! integer square root, sin and cos by their Taylor series. A difference
//! below 2^-400 of the larger side is taken as zero; the generator never
//! makes a nonzero difference anywhere near that small.

use num_bigint::{BigInt, Sign};
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::sync::OnceLock;

/// Binary places kept.
pub const P: u32 = 640;

/// A real number to [`P`] binary places.
#[derive(Clone, Debug, PartialEq)]
pub struct H(pub BigInt);

impl H {
    /// The integer n.
    pub fn int(n: i64) -> H {
        H(BigInt::from(n) << P)
    }
    /// The big integer n.
    pub fn big(n: &BigInt) -> H {
        H(n << P)
    }
    /// p / q.
    pub fn frac(p: &BigInt, q: &BigInt) -> H {
        H((p << P) / q)
    }
    /// 10^k (k may be negative).
    pub fn pow10(k: i32) -> H {
        let t = BigInt::from(10).pow(k.unsigned_abs());
        if k >= 0 {
            H::big(&t)
        } else {
            H::frac(&BigInt::one(), &t)
        }
    }
    pub fn add(&self, o: &H) -> H {
        H(&self.0 + &o.0)
    }
    pub fn sub(&self, o: &H) -> H {
        H(&self.0 - &o.0)
    }
    pub fn neg(&self) -> H {
        H(-&self.0)
    }
    pub fn mul(&self, o: &H) -> H {
        H((&self.0 * &o.0) >> P)
    }
    /// self / o; None for o = 0.
    pub fn div(&self, o: &H) -> Option<H> {
        (!o.0.is_zero()).then(|| H((&self.0 << P) / &o.0))
    }
    /// √self; None below 0.
    pub fn sqrt(&self) -> Option<H> {
        (!self.0.is_negative()).then(|| H((&self.0 << P).sqrt()))
    }
    pub fn powi(&self, n: u32) -> H {
        (0..n).fold(H::int(1), |acc, _| acc.mul(self))
    }
    pub fn abs(&self) -> H {
        H(self.0.abs())
    }
    pub fn is_zero(&self) -> bool {
        self.0.is_zero()
    }
    /// The nearest f64 (to within an ulp).
    pub fn to_f64(&self) -> f64 {
        let bits = self.0.bits();
        let (n, shift) = if bits > 100 {
            (&self.0 >> (bits - 100), bits as i64 - 100)
        } else {
            (self.0.clone(), 0)
        };
        let x = n.to_f64().unwrap_or(f64::NAN);
        x * 2f64.powi((shift - i64::from(P)) as i32)
    }
    /// π.
    pub fn pi() -> H {
        static PI: OnceLock<BigInt> = OnceLock::new();
        H(PI.get_or_init(|| {
            // π = 16 atan(1/5) − 4 atan(1/239), with 32 guard bits
            let g = P + 32;
            let atan_inv = |m: i64| {
                let m = BigInt::from(m);
                let m2 = &m * &m;
                let mut power = (BigInt::one() << g) / &m; // 1/m^(2k+1)
                let mut sum = BigInt::zero();
                let mut k = 0u32;
                while !power.is_zero() {
                    let term = &power / BigInt::from(2 * k + 1);
                    if k.is_multiple_of(2) {
                        sum += term;
                    } else {
                        sum -= term;
                    }
                    power /= &m2;
                    k += 1;
                }
                sum
            };
            (atan_inv(5) * 16 - atan_inv(239) * 4) >> 32
        })
        .clone())
    }
    /// (sin x, cos x) by Taylor series (x of moderate size: the series
    /// converges for any x, slowly for large ones).
    pub fn sin_cos(&self) -> (H, H) {
        let (mut s, mut c) = (H(BigInt::zero()), H(BigInt::zero()));
        // sin: x − x³/3! + …; cos: 1 − x²/2! + …
        let mut term = H::int(1); // x^k / k!
        let mut k = 0u32;
        while !term.is_zero() || k < 4 {
            let signed = if (k / 2).is_multiple_of(2) {
                term.clone()
            } else {
                term.neg()
            };
            if k.is_multiple_of(2) {
                c = c.add(&signed);
            } else {
                s = s.add(&signed);
            }
            k += 1;
            term = H((&term.mul(self).0) / BigInt::from(k));
            if k > 4000 {
                break;
            }
        }
        (s, c)
    }
    /// sin and cos of (p/q)·π, reduced exactly first.
    pub fn sin_cos_pi(p: i64, q: i64) -> (H, H) {
        // p/q mod 2 into (−1, 1]
        let two_q = 2 * q;
        let mut r = p.rem_euclid(two_q);
        if r > q {
            r -= two_q;
        }
        let x = H::pi().mul(&H::int(r)).div(&H::int(q)).unwrap_or(H::int(0));
        x.sin_cos()
    }
    /// The sign: −1, 0 or 1.
    pub fn signum(&self) -> i32 {
        match self.0.sign() {
            Sign::Minus => -1,
            Sign::NoSign => 0,
            Sign::Plus => 1,
        }
    }
}

/// True when `a` and `b` agree to 400 binary places of the larger (or of
/// 1): the same real, up to the oracle's own rounding.
pub fn same(a: &H, b: &H) -> bool {
    let d = (&a.0 - &b.0).abs();
    let scale = a.0.abs().max(b.0.abs()).max(BigInt::one() << P);
    (d << 400u32) <= scale
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants() {
        assert!((H::pi().to_f64() - std::f64::consts::PI).abs() < 1e-15);
        let (s, c) = H::int(1).sin_cos();
        assert!((s.to_f64() - 1f64.sin()).abs() < 1e-15);
        assert!((c.to_f64() - 1f64.cos()).abs() < 1e-15);
        let (s, c) = H::sin_cos_pi(1, 6);
        assert!(same(&s, &H::frac(&1.into(), &2.into())));
        assert!(same(&c.mul(&c), &H::frac(&3.into(), &4.into())));
        let r2 = H::int(2).sqrt().unwrap();
        assert!(same(&r2.mul(&r2), &H::int(2)));
        assert!(!same(&H::pow10(20).add(&H::int(1)), &H::pow10(20)));
    }
}
