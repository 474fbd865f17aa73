//! The oracle's numbers: balls of reals. Each is a centre n / 2^P (a big
//! integer n at a precision of P binary places, [`prec`]) and a radius r
//! (in units of 2^-P) that bounds, rigorously, how far the real it stands
//! for is from the centre: every operation widens the radius by what it
//! rounds and by what the operands' radii can do. Independent of the
//! engine's exact forms: π by Machin's formula, square roots by the integer
//! square root, sin and cos by their Taylor series after reduction by 2π.
//!
//! Two balls are [`Cmp::Differ`] when they are disjoint — a proof; they
//! are [`Cmp::Same`] when they overlap and both are narrower than
//! 2^-[`REL`] of the larger (or 2^-[`ABS`] absolutely) — not a proof, but
//! the generator never makes a nonzero difference anywhere near that small
//! (its smallest are 10^-30 on numbers below 10^120). Otherwise the oracle
//! cannot tell ([`Cmp::Unknown`]): [`same`] then raises a flag
//! ([`take_unsure`]) and the caller asks again at a higher precision
//! ([`PRECISIONS`]) or leaves the case out, counted.
//!
//! (The first oracle was fixed point at 640 places, and "the same" was
//! agreement to 400 of them: 10^116 + 12 + 10^-19 was "the same" as
//! 10^116 + 12, and a/B·B with B = 10^90 was not a — false failures.)

use num_bigint::{BigInt, Sign};
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cell::{Cell, RefCell};
use std::collections::HashMap;

/// The precisions a case is tried at, in order.
pub const PRECISIONS: [u32; 4] = [2048, 4096, 8192, 16384];

/// Balls that overlap are the same real when they are narrower than
/// 2^-REL of the larger…
pub const REL: u32 = 1024;
/// … or than 2^-ABS absolutely (a real that is 0).
pub const ABS: u32 = 1536;

thread_local! {
    static PREC: Cell<u32> = const { Cell::new(PRECISIONS[0]) };
    static UNSURE: Cell<bool> = const { Cell::new(false) };
    static PI: RefCell<HashMap<u32, BigInt>> = RefCell::new(HashMap::new());
}

/// The precision now: binary places of every new ball.
pub fn prec() -> u32 {
    PREC.with(Cell::get)
}

/// Runs `f` with balls of `p` binary places (restored after).
pub fn with_prec<T>(p: u32, f: impl FnOnce() -> T) -> T {
    let old = PREC.with(|c| c.replace(p));
    let out = f();
    PREC.with(|c| c.set(old));
    out
}

/// Whether the oracle could not tell something since the last call (and
/// clears the flag).
pub fn take_unsure() -> bool {
    UNSURE.with(|c| c.replace(false))
}

/// Marks that the oracle could not tell something at this precision.
pub fn unsure() {
    UNSURE.with(|c| c.set(true));
}

/// A real: the centre `n` / 2^`p` within `r` / 2^`p`.
#[derive(Clone, Debug, PartialEq)]
pub struct H {
    n: BigInt,
    r: BigInt,
    p: u32,
}

fn ball(n: BigInt, r: BigInt) -> H {
    H { n, r, p: prec() }
}

/// ⌈a / b⌉ for a ≥ 0, b > 0.
fn div_up(a: &BigInt, b: &BigInt) -> BigInt {
    (a + b - BigInt::one()) / b
}

impl H {
    /// The integer n.
    pub fn int(n: i64) -> H {
        H::big(&BigInt::from(n))
    }
    /// The big integer n.
    pub fn big(n: &BigInt) -> H {
        ball(n << prec(), BigInt::zero())
    }
    /// p / q (q ≠ 0).
    pub fn frac(p: &BigInt, q: &BigInt) -> H {
        let num = p << prec();
        let r = if (&num % q).is_zero() { 0 } else { 1 };
        ball(num / q, BigInt::from(r))
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
    fn same_prec(&self, o: &H) {
        assert_eq!(self.p, o.p, "balls of two precisions mixed");
    }
    pub fn add(&self, o: &H) -> H {
        self.same_prec(o);
        ball(&self.n + &o.n, &self.r + &o.r)
    }
    pub fn sub(&self, o: &H) -> H {
        self.add(&o.neg())
    }
    pub fn neg(&self) -> H {
        H {
            n: -&self.n,
            ..self.clone()
        }
    }
    pub fn mul(&self, o: &H) -> H {
        self.same_prec(o);
        let p = self.p;
        let n = (&self.n * &o.n) >> p;
        // (n1 + δ1)(n2 + δ2) − n1 n2, over 2^p, and the floor
        let spread = self.n.abs() * &o.r + o.n.abs() * &self.r + &self.r * &o.r;
        H {
            n,
            r: (spread >> p) + 2,
            p,
        }
    }
    /// self / o; None when the ball of `o` holds 0.
    pub fn div(&self, o: &H) -> Option<H> {
        self.same_prec(o);
        let p = self.p;
        let d = o.n.abs();
        if d <= o.r {
            return None;
        }
        let n = (&self.n << p) / &o.n;
        // |(n1 + δ1)/(n2 + δ2) − n1/n2| ≤ (r1|n2| + |n1| r2) / (|n2| (|n2| − r2))
        let top = (&self.r * &d + self.n.abs() * &o.r) << p;
        let r = div_up(&top, &(&d * (&d - &o.r))) + 1;
        Some(H { n, r, p })
    }
    /// √self; None when the ball is below 0.
    pub fn sqrt(&self) -> Option<H> {
        let p = self.p;
        let hi = &self.n + &self.r;
        if hi.is_negative() {
            return None;
        }
        let lo = &self.n - &self.r;
        if !lo.is_positive() {
            // the root is in [0, √hi]
            let n = (self.n.clone().max(BigInt::zero()) << p).sqrt();
            let r = (hi << p).sqrt() + 1;
            return Some(H { n, r, p });
        }
        let n = (&self.n << p).sqrt();
        let lo_root = (lo << p).sqrt();
        // |√a − √b| = |a − b| / (√a + √b)
        let r = div_up(&(&self.r << p), &(&lo_root + &n)) + 1;
        Some(H { n, r, p })
    }
    pub fn powi(&self, n: u32) -> H {
        (0..n).fold(H::int(1), |acc, _| acc.mul(self))
    }
    pub fn abs(&self) -> H {
        H {
            n: self.n.abs(),
            ..self.clone()
        }
    }
    /// True when the ball is exactly the point 0.
    pub fn is_zero(&self) -> bool {
        self.n.is_zero() && self.r.is_zero()
    }
    /// True when the ball holds 0.
    pub fn holds_zero(&self) -> bool {
        self.n.abs() <= self.r
    }
    /// True when the ball is narrow enough for [`cmp`] to say `Same` of
    /// it and a ball as narrow (2^8 below the thresholds).
    pub fn resolved(&self) -> bool {
        let rel = self.n.abs() >> (REL + 8);
        let abs = BigInt::one() << self.p.saturating_sub(ABS + 8);
        self.r <= rel.max(abs)
    }
    /// The nearest f64 to the centre (to within an ulp).
    pub fn to_f64(&self) -> f64 {
        let bits = self.n.bits();
        let (n, shift) = if bits > 100 {
            (&self.n >> (bits - 100), bits as i64 - 100)
        } else {
            (self.n.clone(), 0)
        };
        let x = n.to_f64().unwrap_or(f64::NAN);
        let e = shift - i64::from(self.p);
        // (in two steps: 2^e alone may be out of an f64's range)
        x * 2f64.powi((e / 2) as i32) * 2f64.powi((e - e / 2) as i32)
    }
    /// π (within 2 units of the last place).
    pub fn pi() -> H {
        let p = prec();
        let n = PI.with(|m| m.borrow_mut().entry(p).or_insert_with(|| machin(p)).clone());
        ball(n, BigInt::from(2))
    }
    /// (sin x, cos x) by Taylor series after reducing x by a multiple of
    /// 2π (any x: sin and cos are 1-Lipschitz, so the radius carries over).
    pub fn sin_cos(&self) -> (H, H) {
        let p = self.p;
        // guard bits: the reduction multiplies π's error by m
        let m = {
            let two_pi = H::pi().mul(&H::int(2));
            let q = self.div(&two_pi).map_or(0.0, |q| q.to_f64().round());
            BigInt::from(q as i64)
        };
        let g = 64 + m.bits() as u32;
        let w = p + g;
        let (s, c) = with_prec(w, || {
            let x = H {
                n: &self.n << g,
                r: BigInt::zero(),
                p: w,
            };
            let two_pi = H::pi().mul(&H::int(2));
            let x = x.sub(&two_pi.mul(&H::big(&m)));
            series(&x)
        });
        let down = |v: H| H {
            n: &v.n >> g,
            r: (v.r >> g) + 1 + &self.r,
            p,
        };
        (down(s), down(c))
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
    /// The sign of the centre: −1, 0 or 1 (of the real, when the ball is
    /// away from 0).
    pub fn signum(&self) -> i32 {
        match self.n.sign() {
            Sign::Minus => -1,
            Sign::NoSign => 0,
            Sign::Plus => 1,
        }
    }
}

/// π·2^p by Machin's formula, π = 16 atan(1/5) − 4 atan(1/239), with 32
/// guard bits (within 1 of the true value).
fn machin(p: u32) -> BigInt {
    let g = p + 32;
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
}

/// (sin x, cos x) of a small x (|x| ≤ 4) by their series, each term
/// within a unit of the last place, the radius the terms' count plus the
/// input's radius and the tail.
fn series(x: &H) -> (H, H) {
    let p = x.p;
    assert!(
        x.to_f64().abs() <= 4.0,
        "series of a large x: reduce it first"
    );
    let (mut s, mut c) = (BigInt::zero(), BigInt::zero());
    let mut term = BigInt::one() << p; // x^k / k!, within k units
    let mut k = 0u32;
    while !term.is_zero() {
        let signed = if (k / 2).is_multiple_of(2) {
            term.clone()
        } else {
            -&term
        };
        if k.is_multiple_of(2) {
            c += signed;
        } else {
            s += signed;
        }
        k += 1;
        term = ((&term * &x.n) >> p) / BigInt::from(k);
    }
    // term j is within 2j + 4 units (each step rounds twice and |x| ≤ 4
    // shrinks the error it carries from j ≥ 4 on): the sum within
    // k² + 3k; the tail after a zero term (ratio below 1/2) within
    // 2(2k + 5); and x's own radius
    let k = u64::from(k);
    let err = BigInt::from(k * k + 7 * k + 10) + &x.r;
    (
        H {
            n: s,
            r: err.clone(),
            p,
        },
        H { n: c, r: err, p },
    )
}

/// What the oracle says of two reals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Cmp {
    /// Disjoint balls: certainly different.
    Differ,
    /// Overlapping balls narrower than the thresholds.
    Same,
    /// Overlapping balls too wide to tell.
    Unknown,
}

/// Compares two reals.
pub fn cmp(a: &H, b: &H) -> Cmp {
    a.same_prec(b);
    let d = (&a.n - &b.n).abs();
    let r = &a.r + &b.r;
    if d > r {
        return Cmp::Differ;
    }
    let rel = a.n.abs().max(b.n.abs()) >> REL;
    let abs = BigInt::one() << a.p.saturating_sub(ABS);
    if d + r <= rel.max(abs) {
        Cmp::Same
    } else {
        Cmp::Unknown
    }
}

/// True when `a` and `b` are the same real (as [`cmp`] tells); false when
/// they differ, and false with the [`unsure`] flag raised when the oracle
/// cannot tell.
pub fn same(a: &H, b: &H) -> bool {
    match cmp(a, b) {
        Cmp::Same => true,
        Cmp::Differ => false,
        Cmp::Unknown => {
            unsure();
            false
        }
    }
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
        assert!(!take_unsure());
    }

    /// The first oracle's false failures: a tiny difference on a huge
    /// number, and a quotient by a huge number multiplied back.
    #[test]
    fn relative_not_absolute() {
        let big = H::pow10(116).add(&H::int(12));
        assert_eq!(cmp(&big.add(&H::pow10(-19)), &big), Cmp::Differ);
        let r2 = H::int(2).sqrt().unwrap();
        let b = H::pow10(90).add(&H::frac(&3.into(), &7.into()));
        assert_eq!(cmp(&r2.div(&b).unwrap().mul(&b), &r2), Cmp::Same);
        let tiny = H::pow10(-300);
        let near = tiny.add(&tiny.mul(&H::pow10(-20)));
        assert_eq!(cmp(&tiny, &near), Cmp::Differ);
        let (s, _) = H::int(1000).sin_cos();
        assert!((s.to_f64() - 1000f64.sin()).abs() < 1e-13);
        // disjoint balls differ however close
        let hair = H::int(1).add(&H::frac(&1.into(), &(BigInt::one() << 1100u32)));
        assert_eq!(cmp(&hair, &H::int(1)), Cmp::Differ);
        // 1/x·x with x = 10^-600, 2^55 units of the last place at 2048
        // places: too wide to tell; at 4096, the same
        let back = || {
            let x = H::pow10(-600);
            cmp(&H::int(1).div(&x).unwrap().mul(&x), &H::int(1))
        };
        assert_eq!(back(), Cmp::Unknown);
        assert_eq!(with_prec(4096, back), Cmp::Same);
        assert!(!take_unsure());
    }
}
