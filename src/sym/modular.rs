//! Arithmetic modulo a 128-bit integer, for the primality test and the
//! factoring behind [`super::squarefree`] (the square-free part of a
//! radicand, LANGUAGE.md §7).
//!
//! An odd modulus below 2¹²⁷ is worked in Montgomery form (R = 2¹²⁸): a
//! product is a 256-bit multiplication and one reduction, with no division.
//! Other moduli multiply by doubling, every step reduced — exact, slower,
//! and reached only by an even modulus or one above 2¹²⁷.

/// The integers modulo m, in the form that multiplies them fastest.
/// Elements are `u128` below m in the ring's own form: enter a number with
/// [`Ring::enter`] and read it with [`Ring::leave`]. Zero is zero in every
/// form, and a difference of two elements has the same gcd with m as the
/// difference of the numbers they stand for (R is a unit mod m).
pub struct Ring {
    m: u128,
    mont: Option<Mont>,
}

/// Montgomery's constants for an odd m < 2¹²⁷.
struct Mont {
    /// −m⁻¹ mod 2¹²⁸.
    neg_inv: u128,
    /// R² mod m, to enter a number.
    r2: u128,
}

impl Ring {
    /// The ring of integers modulo m (m ≥ 2).
    pub fn new(m: u128) -> Ring {
        let mont = (m % 2 == 1 && m < 1 << 127).then(|| {
            // Newton's iteration for m⁻¹ mod 2¹²⁸: each step doubles the
            // correct low bits, from 3 (m·m ≡ 1 mod 8 for odd m)
            let mut inv = m;
            for _ in 0..6 {
                inv = inv.wrapping_mul(2u128.wrapping_sub(m.wrapping_mul(inv)));
            }
            let r = (u128::MAX % m + 1) % m;
            Mont {
                neg_inv: inv.wrapping_neg(),
                r2: mul_slow(r, r, m),
            }
        });
        Ring { m, mont }
    }

    /// The modulus.
    pub fn modulus(&self) -> u128 {
        self.m
    }

    /// x (any u128) as an element.
    pub fn enter(&self, x: u128) -> u128 {
        let x = x % self.m;
        match &self.mont {
            Some(k) => self.redc(wide(x, k.r2)),
            None => x,
        }
    }

    /// The number an element stands for.
    pub fn leave(&self, x: u128) -> u128 {
        match self.mont {
            Some(_) => self.redc((0, x)),
            None => x,
        }
    }

    /// a + b.
    pub fn add(&self, a: u128, b: u128) -> u128 {
        add_mod(a, b, self.m)
    }

    /// a·b.
    pub fn mul(&self, a: u128, b: u128) -> u128 {
        match self.mont {
            Some(_) => self.redc(wide(a, b)),
            None => mul_slow(a, b, self.m),
        }
    }

    /// a^e.
    pub fn pow(&self, mut a: u128, mut e: u128) -> u128 {
        let mut acc = self.enter(1);
        while e > 0 {
            if e & 1 == 1 {
                acc = self.mul(acc, a);
            }
            a = self.mul(a, a);
            e >>= 1;
        }
        acc
    }

    /// Montgomery's reduction of t = (hi, lo) < m·2¹²⁸: t·R⁻¹ mod m.
    fn redc(&self, (hi, lo): (u128, u128)) -> u128 {
        let k = self.mont.as_ref().expect("a Montgomery ring");
        let u = lo.wrapping_mul(k.neg_inv);
        let (uh, ul) = wide(u, self.m);
        // lo + ul ≡ 0 mod 2¹²⁸: it carries exactly when lo ≠ 0
        debug_assert_eq!(lo.wrapping_add(ul), 0);
        let carry = u128::from(lo != 0);
        // hi < m and uh < m, so t < 2m + 1 ≤ 2¹²⁸ for m < 2¹²⁷
        let t = hi + uh + carry;
        if t >= self.m { t - self.m } else { t }
    }
}

/// The 256-bit product a·b as (high, low) halves.
fn wide(a: u128, b: u128) -> (u128, u128) {
    const LOW: u128 = (1 << 64) - 1;
    let (a1, a0) = (a >> 64, a & LOW);
    let (b1, b0) = (b >> 64, b & LOW);
    let (p00, p01, p10, p11) = (a0 * b0, a0 * b1, a1 * b0, a1 * b1);
    let mid = (p00 >> 64) + (p01 & LOW) + (p10 & LOW);
    let lo = (p00 & LOW) | (mid << 64);
    let hi = p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64);
    (hi, lo)
}

/// a + b mod m (a, b < m), without overflow.
fn add_mod(a: u128, b: u128, m: u128) -> u128 {
    if a >= m - b { a - (m - b) } else { a + b }
}

/// a·b mod m (a, b < m) by a direct product when it fits, else by
/// doubling and adding, every step reduced.
fn mul_slow(a: u128, b: u128, m: u128) -> u128 {
    if let Some(p) = a.checked_mul(b) {
        return p % m;
    }
    let (mut acc, mut a, mut b) = (0u128, a, b);
    while b > 0 {
        if b & 1 == 1 {
            acc = add_mod(acc, a, m);
        }
        a = add_mod(a, a, m);
        b >>= 1;
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Products in Montgomery form agree with the doubling product, for
    /// moduli of every size up to 2¹²⁷ and operands near m.
    #[test]
    fn montgomery_products_agree_with_doubling() {
        let moduli = [
            3u128,
            1_000_000_007,
            (1 << 61) - 1,
            (1 << 64) + 13,
            (1 << 100) + 277,
            (1 << 127) - 1,
            170_141_183_460_469_231_731_687_303_715_884_105_703,
        ];
        let mut seed = 0x9e37_79b9_7f4a_7c15_u128;
        for &m in &moduli {
            let ring = Ring::new(m);
            assert!(ring.mont.is_some(), "{m} is odd and below 2^127");
            let mut picks = vec![0, 1, 2, m - 1, m - 2, m / 2];
            for _ in 0..200 {
                seed = seed
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                picks.push(seed % m);
            }
            for &a in &picks {
                assert_eq!(ring.leave(ring.enter(a)), a);
                for &b in picks.iter().take(20) {
                    let got = ring.leave(ring.mul(ring.enter(a), ring.enter(b)));
                    assert_eq!(got, mul_slow(a, b, m), "{a}·{b} mod {m}");
                }
            }
            // Fermat for the primes among them
            if m == (1 << 127) - 1 || m == 1_000_000_007 {
                assert_eq!(ring.leave(ring.pow(ring.enter(3), m - 1)), 1);
            }
        }
    }

    /// An even modulus and one above 2¹²⁷ take the doubling product.
    #[test]
    fn other_moduli_multiply_by_doubling() {
        for m in [1u128 << 100, u128::MAX - 2] {
            let ring = Ring::new(m);
            assert!(ring.mont.is_none());
            let (a, b) = (m - 1, m - 3);
            assert_eq!(
                ring.leave(ring.mul(ring.enter(a), ring.enter(b))),
                mul_slow(a, b, m)
            );
            // (−1)(−3) = 3
            assert_eq!(ring.mul(a, b), 3);
        }
    }

    #[test]
    fn wide_products() {
        assert_eq!(wide(u128::MAX, u128::MAX), (u128::MAX - 1, 1));
        assert_eq!(wide(1 << 64, 1 << 64), (1, 0));
        assert_eq!(wide(12345, 678), (0, 12345 * 678));
    }
}
