//! Exact coefficients of symbolic expressions: complex numbers whose real
//! and imaginary parts lie in ℚ(√2, √3) (basis 1, √2, √3, √6), so that the
//! book's constants (½, 1/√2, √3/2, the lengths typed as decimals) stay
//! exact and e^{iθ} = cos θ + i sin θ needs no special case. A coefficient
//! that overflows or comes from a number with no simple closed form is kept
//! as a complex `f64` pair ([`Coef::Approx`]).

#![allow(clippy::should_implement_trait, clippy::needless_range_loop)]

use std::cmp::Ordering;

/// A reduced fraction `num/den` with `den > 0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Rat {
    pub num: i128,
    pub den: i128,
}

fn gcd(a: i128, b: i128) -> i128 {
    let (a, b) = (a.unsigned_abs(), b.unsigned_abs());
    // Word-sized operands (the usual case) divide in hardware.
    if let (Ok(mut x), Ok(mut y)) = (u64::try_from(a), u64::try_from(b)) {
        while y != 0 {
            (x, y) = (y, x % y);
        }
        return x as i128;
    }
    // Binary gcd: no 128-bit division.
    let (mut x, mut y) = (a, b);
    if x == 0 || y == 0 {
        return (x | y) as i128;
    }
    let shift = (x | y).trailing_zeros();
    x >>= x.trailing_zeros();
    while y != 0 {
        y >>= y.trailing_zeros();
        if x > y {
            std::mem::swap(&mut x, &mut y);
        }
        y -= x;
    }
    (x << shift) as i128
}

/// Magnitude beyond which a fraction is given up for a float (products of
/// two stay inside `i128`).
const LIMIT: i128 = 1 << 60;

impl Rat {
    /// 0.
    pub const ZERO: Rat = Rat { num: 0, den: 1 };
    /// 1.
    pub const ONE: Rat = Rat { num: 1, den: 1 };

    /// `num/den` reduced; None when it does not fit.
    pub fn new(num: i128, den: i128) -> Option<Rat> {
        if den == 0 {
            return None;
        }
        let g = gcd(num, den).max(1);
        let (mut n, mut d) = (num / g, den / g);
        if d < 0 {
            n = -n;
            d = -d;
        }
        (n.abs() < LIMIT && d < LIMIT).then_some(Rat { num: n, den: d })
    }
    /// The integer n.
    pub fn int(n: i64) -> Rat {
        Rat {
            num: n as i128,
            den: 1,
        }
    }
    /// True for 0.
    pub fn is_zero(self) -> bool {
        self.num == 0
    }
    /// The sum; None when it does not fit.
    pub fn add(self, o: Rat) -> Option<Rat> {
        if o.num == 0 {
            return Some(self);
        }
        if self.num == 0 {
            return Some(o);
        }
        if self.den == 1 && o.den == 1 {
            let n = self.num + o.num;
            return (n.abs() < LIMIT).then_some(Rat { num: n, den: 1 });
        }
        let g = gcd(self.den, o.den);
        let (a, b) = (self.den / g, o.den / g);
        Rat::new(self.num * b + o.num * a, self.den * b)
    }
    /// The product; None when it does not fit.
    pub fn mul(self, o: Rat) -> Option<Rat> {
        if self.num == 0 || o.num == 0 {
            return Some(Rat::ZERO);
        }
        if self.den == 1 && o.den == 1 {
            let n = self.num * o.num;
            return (n.abs() < LIMIT).then_some(Rat { num: n, den: 1 });
        }
        let g1 = gcd(self.num, o.den).max(1);
        let g2 = gcd(o.num, self.den).max(1);
        Rat::new(
            (self.num / g1) * (o.num / g2),
            (self.den / g2) * (o.den / g1),
        )
    }
    /// −x.
    pub fn neg(self) -> Rat {
        Rat {
            num: -self.num,
            den: self.den,
        }
    }
    /// 1/x; None for 0.
    pub fn inv(self) -> Option<Rat> {
        Rat::new(self.den, self.num)
    }
    /// The nearest float.
    pub fn to_f64(self) -> f64 {
        self.num as f64 / self.den as f64
    }
    /// The integer, when the fraction is one.
    pub fn as_int(self) -> Option<i64> {
        (self.den == 1)
            .then(|| i64::try_from(self.num).ok())
            .flatten()
    }
    /// The fraction nearest `x` with a denominator at most `max_den`
    /// (continued fractions), when it is within 1e-12 (relative) of `x`;
    /// below 1e-14 a number is rounding noise and reads as 0.
    pub fn approximate(x: f64, max_den: i128) -> Option<Rat> {
        if !x.is_finite() || x.abs() > 1e15 {
            return None;
        }
        // rounding noise of a computed zero (cos(π/2) = 6e-17)
        if x.abs() < 1e-14 {
            return Some(Rat::ZERO);
        }
        let (mut h0, mut h1, mut k0, mut k1) = (0i128, 1i128, 1i128, 0i128);
        let mut y = x;
        for _ in 0..40 {
            let a = y.floor();
            if a.abs() > 1e15 {
                break;
            }
            let a = a as i128;
            let (h2, k2) = (a * h1 + h0, a * k1 + k0);
            if k2 > max_den {
                break;
            }
            (h0, h1, k0, k1) = (h1, h2, k1, k2);
            let r = h1 as f64 / k1 as f64;
            if (r - x).abs() <= 1e-12 * x.abs() {
                return Rat::new(h1, k1);
            }
            let f = y - a as f64;
            if f.abs() < 1e-300 {
                break;
            }
            y = 1.0 / f;
        }
        None
    }
}

/// An element a + b√2 + c√3 + d√6 of the real field ℚ(√2, √3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Surd(pub [Rat; 4]);

/// The basis roots 1, √2, √3, √6.
pub const ROOTS: [i64; 4] = [1, 2, 3, 6];

impl Surd {
    /// 0.
    pub const ZERO: Surd = Surd([Rat::ZERO; 4]);
    /// A rational as a field element.
    pub fn rat(r: Rat) -> Surd {
        Surd([r, Rat::ZERO, Rat::ZERO, Rat::ZERO])
    }
    /// True for 0.
    pub fn is_zero(&self) -> bool {
        self.0.iter().all(|r| r.is_zero())
    }
    /// The sum; None on overflow.
    pub fn add(&self, o: &Surd) -> Option<Surd> {
        let mut out = [Rat::ZERO; 4];
        for i in 0..4 {
            out[i] = self.0[i].add(o.0[i])?;
        }
        Some(Surd(out))
    }
    /// −x.
    pub fn neg(&self) -> Surd {
        Surd(self.0.map(Rat::neg))
    }
    /// The product; None on overflow.
    pub fn mul(&self, o: &Surd) -> Option<Surd> {
        // √a √b = k √c over the basis 1, √2, √3, √6.
        const TABLE: [[(i64, usize); 4]; 4] = [
            [(1, 0), (1, 1), (1, 2), (1, 3)],
            [(1, 1), (2, 0), (1, 3), (2, 2)],
            [(1, 2), (1, 3), (3, 0), (3, 1)],
            [(1, 3), (2, 2), (3, 1), (6, 0)],
        ];
        let mut out = [Rat::ZERO; 4];
        for i in 0..4 {
            if self.0[i].is_zero() {
                continue;
            }
            for j in 0..4 {
                if o.0[j].is_zero() {
                    continue;
                }
                let (k, c) = TABLE[i][j];
                let t = self.0[i].mul(o.0[j])?.mul(Rat::int(k))?;
                out[c] = out[c].add(t)?;
            }
        }
        Some(Surd(out))
    }
    /// The conjugate under √2 → −√2 (`s2`) and/or √3 → −√3 (`s3`).
    fn conj(&self, s2: bool, s3: bool) -> Surd {
        let [a, b, c, d] = self.0;
        let b = if s2 { b.neg() } else { b };
        let c = if s3 { c.neg() } else { c };
        let d = if s2 != s3 { d.neg() } else { d };
        Surd([a, b, c, d])
    }
    /// 1/x: multiplying by the three conjugates leaves a rational norm.
    pub fn inv(&self) -> Option<Surd> {
        if self.is_zero() {
            return None;
        }
        let others = [
            self.conj(true, false),
            self.conj(false, true),
            self.conj(true, true),
        ];
        let mut num = others[0];
        num = num.mul(&others[1])?.mul(&others[2])?;
        let norm = self.mul(&num)?;
        let n = norm.0[0].inv()?;
        num.mul(&Surd::rat(n))
    }
    /// The nearest float.
    pub fn to_f64(&self) -> f64 {
        self.0
            .iter()
            .zip(ROOTS)
            .map(|(r, k)| r.to_f64() * (k as f64).sqrt())
            .sum()
    }
    /// The sign of the value (exactly 0 only for zero).
    pub fn signum(&self) -> f64 {
        if self.is_zero() {
            0.0
        } else {
            self.to_f64().signum()
        }
    }
    /// The rational, when only the rational part is present.
    pub fn as_rat(&self) -> Option<Rat> {
        self.0[1..].iter().all(|r| r.is_zero()).then_some(self.0[0])
    }
    /// A closed form of `x`: p/q, or p/q times √2, √3 or √6.
    pub fn recognize(x: f64) -> Option<Surd> {
        if x == 0.0 {
            return Some(Surd::ZERO);
        }
        if let Some(r) = Rat::approximate(x, 10_000) {
            return Some(Surd::rat(r));
        }
        for (i, k) in ROOTS.iter().enumerate().skip(1) {
            if let Some(r) = Rat::approximate(x / (*k as f64).sqrt(), 1000) {
                let mut s = [Rat::ZERO; 4];
                s[i] = r;
                return Some(Surd(s));
            }
        }
        // A decimal as typed: 0.425, 0.0823 (a denominator of 2s and 5s only).
        Rat::approximate(x, 1_000_000_000)
            .filter(|r| 1_000_000_000 % r.den == 0)
            .map(Surd::rat)
    }
}

/// A coefficient: an exact complex number over ℚ(√2, √3), or a complex
/// `f64` pair when no exact form is known.
#[derive(Debug, Clone, Copy, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub enum Coef {
    Exact { re: Surd, im: Surd },
    Approx { re: f64, im: f64 },
}

impl Eq for Coef {}

impl Ord for Coef {
    fn cmp(&self, other: &Coef) -> Ordering {
        match (self, other) {
            (Coef::Exact { re: a, im: b }, Coef::Exact { re: c, im: d }) => (a, b).cmp(&(c, d)),
            (Coef::Approx { re: a, im: b }, Coef::Approx { re: c, im: d }) => {
                a.total_cmp(c).then(b.total_cmp(d))
            }
            (Coef::Exact { .. }, Coef::Approx { .. }) => Ordering::Less,
            (Coef::Approx { .. }, Coef::Exact { .. }) => Ordering::Greater,
        }
    }
}

impl PartialOrd for Coef {
    fn partial_cmp(&self, other: &Coef) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Coef {
    /// 0.
    pub const ZERO: Coef = Coef::Exact {
        re: Surd::ZERO,
        im: Surd::ZERO,
    };
    /// A rational coefficient.
    pub fn rat(r: Rat) -> Coef {
        Coef::real(Surd::rat(r))
    }
    /// An integer coefficient.
    pub fn int(n: i64) -> Coef {
        Coef::rat(Rat::int(n))
    }
    /// 1.
    pub fn one() -> Coef {
        Coef::int(1)
    }
    /// The imaginary unit i.
    pub fn i() -> Coef {
        Coef::Exact {
            re: Surd::ZERO,
            im: Surd::rat(Rat::ONE),
        }
    }
    /// A real coefficient.
    pub fn real(s: Surd) -> Coef {
        Coef::Exact {
            re: s,
            im: Surd::ZERO,
        }
    }
    /// A number as a coefficient: exact when it is a simple closed form.
    pub fn from_f64(x: f64) -> Coef {
        match Surd::recognize(x) {
            Some(s) => Coef::real(s),
            None => Coef::Approx { re: x, im: 0.0 },
        }
    }
    /// True for 0.
    pub fn is_zero(&self) -> bool {
        match self {
            Coef::Exact { re, im } => re.is_zero() && im.is_zero(),
            Coef::Approx { re, im } => *re == 0.0 && *im == 0.0,
        }
    }
    /// True for 1.
    pub fn is_one(&self) -> bool {
        *self == Coef::one()
    }
    /// (re, im) as floats.
    pub fn to_c64(&self) -> (f64, f64) {
        match self {
            Coef::Exact { re, im } => (re.to_f64(), im.to_f64()),
            Coef::Approx { re, im } => (*re, *im),
        }
    }
    fn approx(&self) -> Coef {
        let (re, im) = self.to_c64();
        Coef::Approx { re, im }
    }
    /// A float result; a value that rounds to 0 is dropped exactly.
    fn settle(re: f64, im: f64) -> Coef {
        let re = if re.abs() < 1e-300 { 0.0 } else { re };
        let im = if im.abs() < 1e-300 { 0.0 } else { im };
        if im == 0.0 && re == 0.0 {
            Coef::ZERO
        } else {
            Coef::Approx { re, im }
        }
    }
    /// The sum (a float pair when exact arithmetic overflows).
    pub fn add(&self, o: &Coef) -> Coef {
        if let (Coef::Exact { re: a, im: b }, Coef::Exact { re: c, im: d }) = (self, o)
            && let (Some(re), Some(im)) = (a.add(c), b.add(d))
        {
            return Coef::Exact { re, im };
        }
        let ((a, b), (c, d)) = (self.to_c64(), o.to_c64());
        Coef::settle(a + c, b + d)
    }
    /// −c.
    pub fn neg(&self) -> Coef {
        match self {
            Coef::Exact { re, im } => Coef::Exact {
                re: re.neg(),
                im: im.neg(),
            },
            Coef::Approx { re, im } => Coef::Approx { re: -re, im: -im },
        }
    }
    /// The product (a float pair when exact arithmetic overflows).
    pub fn mul(&self, o: &Coef) -> Coef {
        if let (Coef::Exact { re: a, im: b }, Coef::Exact { re: c, im: d }) = (self, o) {
            let exact = || -> Option<Coef> {
                let re = a.mul(c)?.add(&b.mul(d)?.neg())?;
                let im = a.mul(d)?.add(&b.mul(c)?)?;
                Some(Coef::Exact { re, im })
            };
            if let Some(c) = exact() {
                return c;
            }
        }
        let ((a, b), (c, d)) = (self.to_c64(), o.to_c64());
        Coef::settle(a * c - b * d, a * d + b * c)
    }
    /// The complex conjugate.
    pub fn conj(&self) -> Coef {
        match self {
            Coef::Exact { re, im } => Coef::Exact {
                re: *re,
                im: im.neg(),
            },
            Coef::Approx { re, im } => Coef::Approx { re: *re, im: -im },
        }
    }
    /// 1/c; None for zero.
    pub fn inv(&self) -> Option<Coef> {
        if self.is_zero() {
            return None;
        }
        if let Coef::Exact { re, im } = self {
            let exact = || -> Option<Coef> {
                let norm = re.mul(re)?.add(&im.mul(im)?)?;
                let n = norm.inv()?;
                Some(Coef::Exact {
                    re: re.mul(&n)?,
                    im: im.neg().mul(&n)?,
                })
            };
            if let Some(c) = exact() {
                return Some(c);
            }
        }
        let (a, b) = self.approx().to_c64();
        let n = a * a + b * b;
        Some(Coef::settle(a / n, -b / n))
    }
    /// The real k with Re(k·c) = `to` (Im(k·c) = `to` when the real part is
    /// 0): the scale that makes a real expression's first coefficient
    /// print as 1. None for 0.
    pub fn real_scale(&self, to: Rat) -> Option<Coef> {
        match self {
            Coef::Exact { re, im } => {
                let part = if re.is_zero() { im } else { re };
                Some(Coef::real(part.inv()?.mul(&Surd::rat(to))?))
            }
            Coef::Approx { re, im } => {
                let part = if *re == 0.0 { *im } else { *re };
                (part != 0.0).then(|| Coef::settle(to.to_f64() / part, 0.0))
            }
        }
    }
    /// The rational, when the coefficient is one.
    pub fn as_rat(&self) -> Option<Rat> {
        match self {
            Coef::Exact { re, im } if im.is_zero() => re.as_rat(),
            _ => None,
        }
    }
    /// The real part exactly, when the imaginary part is 0.
    pub fn as_real(&self) -> Option<Surd> {
        match self {
            Coef::Exact { re, im } if im.is_zero() => Some(*re),
            _ => None,
        }
    }
    /// e^{iπ p} exactly for p a multiple of 1/12 (cos and sin of multiples
    /// of 15° lie in ℚ(√2, √3)).
    pub fn unit_root(p: Rat) -> Option<Coef> {
        let twelfths = p.mul(Rat::int(12))?.as_int()?.rem_euclid(24);
        // cos(k·15°) for k = 0..=6, as (rational part, √2 part, √3 part, √6 part) / 4.
        const COS: [[i64; 4]; 7] = [
            [4, 0, 0, 0],
            [0, 1, 0, 1],
            [0, 0, 2, 0],
            [0, 2, 0, 0],
            [2, 0, 0, 0],
            [0, -1, 0, 1],
            [0, 0, 0, 0],
        ];
        let cos_of = |k: i64| -> Surd {
            // cos is even and cos(180° - x) = -cos x.
            let k = k.rem_euclid(24);
            let k = if k > 12 { 24 - k } else { k };
            let (k, sign) = if k > 6 { (12 - k, -1) } else { (k, 1) };
            Surd(COS[k as usize].map(|n| Rat::new((sign * n) as i128, 4).unwrap_or(Rat::ZERO)))
        };
        Some(Coef::Exact {
            re: cos_of(twelfths),
            im: cos_of(twelfths - 6),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn surd_arithmetic_is_exact() {
        let r2 = Surd([Rat::ZERO, Rat::ONE, Rat::ZERO, Rat::ZERO]);
        let two = r2.mul(&r2).unwrap();
        assert_eq!(two, Surd::rat(Rat::int(2)));
        let x = Surd([Rat::ONE, Rat::ONE, Rat::ONE, Rat::ZERO]);
        let one = x.mul(&x.inv().unwrap()).unwrap();
        assert_eq!(one, Surd::rat(Rat::ONE));
    }

    #[test]
    fn recognizes_closed_forms() {
        let h = Surd::recognize(std::f64::consts::FRAC_1_SQRT_2).unwrap();
        assert_eq!(h.0[1], Rat::new(1, 2).unwrap());
        assert_eq!(
            Surd::recognize(0.425).unwrap(),
            Surd::rat(Rat::new(17, 40).unwrap())
        );
        assert!(Surd::recognize(std::f64::consts::PI).is_none());
    }

    #[test]
    fn unit_roots_match_cos_and_sin() {
        for k in -30..30 {
            let p = Rat::new(k, 12).unwrap();
            let (re, im) = Coef::unit_root(p).unwrap().to_c64();
            let a = std::f64::consts::PI * k as f64 / 12.0;
            assert!(
                (re - a.cos()).abs() < 1e-14 && (im - a.sin()).abs() < 1e-14,
                "{k} {re} {im}"
            );
        }
    }
}
