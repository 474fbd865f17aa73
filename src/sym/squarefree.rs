//! The square-free part of an integer (LANGUAGE.md §7: a square root of an
//! exact number stays exact): n = s²·k with k square-free, so that √n =
//! s√k and two roots √k, √k' of distinct square-free k, k' are never
//! rational multiples of each other — the condition under which a sum of
//! roots is 0 only when every coefficient is ([`super::surd::Surd`]).
//!
//! The primes of n are found by trial division, a deterministic
//! Miller–Rabin test and Pollard's rho within a fixed budget. Where they
//! cannot be found for sure (a cofactor above 3·10²⁴ that is not shown
//! composite and split, or n beyond 2¹²⁸), the answer is None: the root
//! then has no exact form and is a float, compared as one — never a
//! wrongly split root.

use num_bigint::BigUint;
use num_traits::ToPrimitive;

use super::modular::Ring;

/// Trial division runs below this bound: a cofactor left is a product of
/// primes at least this large.
const TRIAL: u128 = 1 << 12;

/// Below this the Miller–Rabin test with the first 13 primes as bases is
/// exact (ψ₁₃ > 3.3·10²⁴).
const MR_EXACT: u128 = 3_317_044_064_679_887_385_961_981;

/// Steps of Pollard's rho tried on one cofactor before giving up: enough
/// for any cofactor below 2⁶⁴ (its least prime is below 2³², found in
/// about 2¹⁶ steps), fewer above, where a step is dearer.
fn rho_steps(m: u128) -> u32 {
    if m < 1 << 64 { 1 << 20 } else { 1 << 16 }
}

/// n = s²·k with k square-free, as (s, k); None when the primes of n
/// cannot be found for sure (see the module's comment). n = 0 gives (0, 1).
pub fn split(n: &BigUint) -> Option<(BigUint, u128)> {
    if let Some(n) = n.to_u128() {
        let (s, k) = split_u128(n)?;
        return Some((BigUint::from(s), k));
    }
    // beyond 2¹²⁸: a perfect square, or small square factors taken out
    // until the rest fits
    let r = n.sqrt();
    if &r * &r == *n {
        return Some((r, 1));
    }
    let (mut s, mut m) = (BigUint::from(1u8), n.clone());
    let mut f = 2u32;
    while u128::from(f) < TRIAL {
        let ff = BigUint::from(f) * f;
        while (&m % &ff).to_u32() == Some(0) {
            m /= &ff;
            s *= f;
        }
        f += 1;
    }
    let (s2, k) = split_u128(m.to_u128()?)?;
    Some((s * s2, k))
}

/// [`split`] of a 128-bit integer.
pub fn split_u128(n: u128) -> Option<(u128, u128)> {
    if n == 0 {
        return Some((0, 1));
    }
    let mut primes = Vec::new();
    let mut m = n;
    let mut f = 2u128;
    while f < TRIAL && f * f <= m {
        while m.is_multiple_of(f) {
            m /= f;
            primes.push(f);
        }
        f += if f == 2 { 1 } else { 2 };
    }
    if m > 1 {
        large_primes(m, &mut primes)?;
    }
    primes.sort_unstable();
    let (mut s, mut k) = (1u128, 1u128);
    let mut i = 0;
    while i < primes.len() {
        let p = primes[i];
        let j = primes[i..].iter().take_while(|&&q| q == p).count();
        for _ in 0..j / 2 {
            s *= p;
        }
        if j % 2 == 1 {
            k *= p;
        }
        i += j;
    }
    Some((s, k))
}

/// The primes of m (every prime of m at least [`TRIAL`], or m below
/// TRIAL²), with multiplicity; None when they cannot be found for sure.
fn large_primes(m: u128, out: &mut Vec<u128>) -> Option<()> {
    if m == 1 {
        return Some(());
    }
    if m < TRIAL * TRIAL || is_prime(m)? {
        out.push(m);
        return Some(());
    }
    let r = m.isqrt();
    if r * r == m {
        large_primes(r, out)?;
        return large_primes(r, out);
    }
    let d = rho(m)?;
    large_primes(d, out)?;
    large_primes(m / d, out)
}

/// Whether m (odd, without prime factors below [`TRIAL`]) is prime, by the
/// Miller–Rabin test, exact below [`MR_EXACT`]; None above it for a
/// number the test does not show composite.
fn is_prime(m: u128) -> Option<bool> {
    let ring = Ring::new(m);
    let (one, minus_one) = (ring.enter(1), ring.enter(m - 1));
    let (mut d, mut r) = (m - 1, 0u32);
    while d % 2 == 0 {
        d /= 2;
        r += 1;
    }
    for a in [2u128, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41] {
        let mut x = ring.pow(ring.enter(a), d);
        if x == one || x == minus_one {
            continue;
        }
        let mut composite = true;
        for _ in 1..r {
            x = ring.mul(x, x);
            if x == minus_one {
                composite = false;
                break;
            }
        }
        if composite {
            return Some(false);
        }
    }
    (m < MR_EXACT).then_some(true)
}

/// Steps of Pollard's rho whose differences are multiplied together
/// before one gcd is taken.
const BATCH: u32 = 64;

/// A proper factor of the composite m (Pollard's rho with Brent's cycle
/// search, the differences of a batch multiplied before one gcd), None
/// past [`rho_steps`] steps for each of a few constants. A batch whose
/// product shares all of m is walked again a step at a time.
fn rho(m: u128) -> Option<u128> {
    let gcd = |mut a: u128, mut b: u128| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    let ring = Ring::new(m);
    for c in 1..=4u128 {
        let c = ring.enter(c);
        // one step of Brent's search: y moves on, x is kept at powers of 2
        let step = |(x, y, power, lam): (u128, u128, u32, u32)| {
            let (x, power, lam) = if power == lam {
                (y, power * 2, 0)
            } else {
                (x, power, lam)
            };
            (x, ring.add(ring.mul(y, y), c), power, lam + 1)
        };
        let mut walk = (ring.enter(2), ring.enter(2), 1u32, 0u32);
        let (mut q, mut steps) = (ring.enter(1), 0u32);
        let mut saved = walk;
        let mut in_batch = 0u32;
        loop {
            walk = step(walk);
            steps += 1;
            in_batch += 1;
            q = ring.mul(q, walk.0.abs_diff(walk.1));
            if in_batch == BATCH || steps > rho_steps(m) {
                let g = gcd(q, m);
                if g == m {
                    // walk the batch again, one gcd a step
                    walk = saved;
                    for _ in 0..in_batch {
                        walk = step(walk);
                        match gcd(walk.0.abs_diff(walk.1), m) {
                            g if g == m => break,
                            g if g > 1 => return Some(g),
                            _ => {}
                        }
                    }
                    break;
                }
                if g > 1 {
                    return Some(g);
                }
                if steps > rho_steps(m) {
                    break;
                }
                saved = walk;
                in_batch = 0;
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_free_parts() {
        assert_eq!(split_u128(8), Some((2, 2)));
        assert_eq!(split_u128(12), Some((2, 3)));
        assert_eq!(split_u128(1), Some((1, 1)));
        assert_eq!(split_u128(5), Some((1, 5)));
        assert_eq!(split_u128(360), Some((6, 10)));
        // primes above the trial bound, squared and not
        let p = 1_000_000_007u128;
        let q = 998_244_353u128;
        assert_eq!(split_u128(p * p), Some((p, 1)));
        assert_eq!(split_u128(p * p * q), Some((p, q)));
        assert_eq!(split_u128(p * q), Some((1, p * q)));
        assert_eq!(split_u128(p * p * 12), Some((2 * p, 3)));
        // a Mersenne prime, and its square times 2
        let m61 = (1u128 << 61) - 1;
        assert_eq!(split_u128(m61), Some((1, m61)));
        assert_eq!(split_u128(2 * m61 * m61), Some((m61, 2)));
        // beyond 2¹²⁸: a square
        let big = BigUint::from(10u8).pow(40);
        assert_eq!(split(&big), Some((BigUint::from(10u8).pow(20), 1)));
    }

    #[test]
    fn primes_by_miller_rabin() {
        assert_eq!(is_prime((1u128 << 61) - 1), Some(true));
        assert_eq!(is_prime(1_000_000_007 * 998_244_353), Some(false));
    }
}
