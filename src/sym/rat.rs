//! Exact fractions for the coefficients of symbolic expressions (LANGUAGE.md
//! §7: "however large, an integer coefficient is never rounded"). A
//! fraction that fits two machine words is held inline and computed with
//! 128-bit intermediates; a larger one is a big rational (`num-rational`),
//! so `(sin a + cos b)^60` keeps its binomial coefficients exact.

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive};

/// A reduced fraction num/den with den > 0: inline while both fit an
/// `i64` (the usual case), a big rational otherwise. Each value has one
/// form, so equality, order and hash are those of the value's
/// representation (a consistent total order, not the numeric one).
///
/// An inline fraction also remembers whether it was made from a number
/// typed as a decimal (`0.425`, LANGUAGE.md §7), so that the printer shows
/// the book's lengths as typed while ⅛ computed from integers stays a
/// fraction: the mark is kept by arithmetic (a sum or product with a
/// marked operand is marked), lives in the tag's padding (the size is
/// unchanged) and takes no part in equality, order or hash.
#[derive(Clone)]
pub enum Rat {
    /// num/den, reduced, den > 0; `typed`: made from a typed decimal.
    Small {
        /// The numerator.
        num: i64,
        /// The denominator, > 0.
        den: i64,
        /// Made from a typed decimal: printed as one (`0.425`).
        typed: bool,
    },
    /// A fraction too large for [`Rat::Small`].
    Big(Box<BigRational>),
}

/// The value's equality: the typed mark is not part of it.
impl PartialEq for Rat {
    fn eq(&self, o: &Rat) -> bool {
        match (self, o) {
            (Rat::Small { num: a, den: b, .. }, Rat::Small { num: c, den: d, .. }) => {
                a == c && b == d
            }
            (Rat::Big(x), Rat::Big(y)) => x == y,
            _ => false,
        }
    }
}

impl Eq for Rat {}

/// The representation's order (inline fractions first, then by numerator
/// and denominator): a consistent total order, not the numeric one.
impl Ord for Rat {
    fn cmp(&self, o: &Rat) -> std::cmp::Ordering {
        match (self, o) {
            (Rat::Small { num: a, den: b, .. }, Rat::Small { num: c, den: d, .. }) => {
                (a, b).cmp(&(c, d))
            }
            (Rat::Big(x), Rat::Big(y)) => x.cmp(y),
            (Rat::Small { .. }, Rat::Big(_)) => std::cmp::Ordering::Less,
            (Rat::Big(_), Rat::Small { .. }) => std::cmp::Ordering::Greater,
        }
    }
}

impl PartialOrd for Rat {
    fn partial_cmp(&self, o: &Rat) -> Option<std::cmp::Ordering> {
        Some(self.cmp(o))
    }
}

/// The hash of the equality (the typed mark left out).
impl std::hash::Hash for Rat {
    fn hash<H: std::hash::Hasher>(&self, h: &mut H) {
        match self {
            Rat::Small { num, den, .. } => (0u8, num, den).hash(h),
            Rat::Big(b) => (1u8, b).hash(h),
        }
    }
}

impl std::fmt::Debug for Rat {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Rat::Small { num, den, .. } => f
                .debug_struct("Small")
                .field("num", num)
                .field("den", den)
                .finish(),
            Rat::Big(b) => f.debug_tuple("Big").field(b).finish(),
        }
    }
}

fn gcd(a: u128, b: u128) -> u128 {
    // Word-sized operands (the usual case) divide in hardware.
    if let (Ok(mut x), Ok(mut y)) = (u64::try_from(a), u64::try_from(b)) {
        while y != 0 {
            (x, y) = (y, x % y);
        }
        return u128::from(x);
    }
    // Binary gcd: no 128-bit division.
    let (mut x, mut y) = (a, b);
    if x == 0 || y == 0 {
        return x | y;
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
    x << shift
}

impl Rat {
    /// 0.
    pub const ZERO: Rat = Rat::Small {
        num: 0,
        den: 1,
        typed: false,
    };
    /// 1.
    pub const ONE: Rat = Rat::Small {
        num: 1,
        den: 1,
        typed: false,
    };

    /// `num/den` reduced; None for a zero denominator.
    pub fn new(num: i128, den: i128) -> Option<Rat> {
        if den == 0 {
            return None;
        }
        let neg = (num < 0) != (den < 0);
        let (n, d) = (num.unsigned_abs(), den.unsigned_abs());
        let g = gcd(n, d).max(1);
        Some(Rat::from_parts(neg, n / g, d / g))
    }
    /// A reduced fraction ±n/d from magnitudes.
    fn from_parts(neg: bool, n: u128, d: u128) -> Rat {
        if let (Ok(a), Ok(b)) = (i64::try_from(n), i64::try_from(d)) {
            return Rat::Small {
                num: if neg { -a } else { a },
                den: b,
                typed: false,
            };
        }
        let n = BigInt::from(n);
        let n = if neg { -n } else { n };
        Rat::Big(Box::new(BigRational::new_raw(n, BigInt::from(d))))
    }
    /// A reduced big rational, inline when it fits.
    pub fn from_big(r: BigRational) -> Rat {
        if let (Some(num), Some(den)) = (r.numer().to_i64(), r.denom().to_i64()) {
            return Rat::Small {
                num,
                den,
                typed: false,
            };
        }
        Rat::Big(Box::new(r))
    }
    /// The value as a big rational.
    pub fn to_big(&self) -> BigRational {
        match self {
            Rat::Small { num, den, .. } => {
                BigRational::new_raw(BigInt::from(*num), BigInt::from(*den))
            }
            Rat::Big(b) => (**b).clone(),
        }
    }
    /// Numerator and denominator (reduced, denominator > 0).
    pub fn parts(&self) -> (BigInt, BigInt) {
        match self {
            Rat::Small { num, den, .. } => (BigInt::from(*num), BigInt::from(*den)),
            Rat::Big(b) => (b.numer().clone(), b.denom().clone()),
        }
    }
    /// Numerator and denominator when both fit an `i64`.
    pub fn small(&self) -> Option<(i64, i64)> {
        match self {
            Rat::Small { num, den, .. } => Some((*num, *den)),
            Rat::Big(_) => None,
        }
    }
    /// 64-bit words of a big fraction's numerator and denominator (0 when
    /// inline).
    pub fn words(&self) -> usize {
        match self {
            Rat::Small { .. } => 0,
            Rat::Big(b) => (b.numer().bits() + b.denom().bits()).div_ceil(64) as usize,
        }
    }
    /// The remainder of this fraction by the positive integer `m`, in
    /// [0, m): r − m⌊r/m⌋, exactly however large r is (an angle's
    /// multiple of π reduced by its period: 3·10⁷³ mod 2 is 0).
    pub fn rem_euclid(&self, m: i64) -> Rat {
        if let Rat::Small { num, den, typed } = self
            && let Some(md) = m.checked_mul(*den)
        {
            return Rat::Small {
                num: num.rem_euclid(md),
                den: *den,
                typed: *typed,
            };
        }
        let r = self.to_big();
        let m = BigRational::from_integer(BigInt::from(m));
        let q = (&r / &m).floor();
        Rat::from_big(r - q * m)
    }
    /// True when the fraction was made from a number typed as a decimal
    /// (its printed form is then a decimal: `0.425`, not `17/40`).
    pub fn is_typed(&self) -> bool {
        matches!(self, Rat::Small { typed: true, .. })
    }
    /// The fraction, marked as made from a typed decimal when `typed`
    /// (an integer or a big fraction is never marked).
    pub fn marked(mut self, typed: bool) -> Rat {
        if typed && let Rat::Small { den, typed: t, .. } = &mut self {
            *t = *den != 1;
        }
        self
    }
    /// The integer n.
    pub fn int(n: i64) -> Rat {
        Rat::Small {
            num: n,
            den: 1,
            typed: false,
        }
    }
    /// True for 0.
    pub fn is_zero(&self) -> bool {
        matches!(self, Rat::Small { num: 0, .. })
    }
    /// True below 0.
    pub fn is_negative(&self) -> bool {
        match self {
            Rat::Small { num, .. } => *num < 0,
            Rat::Big(b) => b.is_negative(),
        }
    }
    /// The sum (marked as typed when an operand is).
    pub fn add(&self, o: &Rat) -> Rat {
        self.add_unmarked(o).marked(self.is_typed() || o.is_typed())
    }
    fn add_unmarked(&self, o: &Rat) -> Rat {
        match (self, o) {
            (x, y) if y.is_zero() => x.clone(),
            (x, y) if x.is_zero() => y.clone(),
            (Rat::Small { num: a, den: b, .. }, Rat::Small { num: c, den: d, .. }) => {
                let (a, b, c, d) = (
                    i128::from(*a),
                    i128::from(*b),
                    i128::from(*c),
                    i128::from(*d),
                );
                if b == 1 && d == 1 {
                    return Rat::new(a + c, 1).unwrap_or(Rat::ZERO);
                }
                let g = gcd(b as u128, d as u128) as i128;
                let (p, q) = (b / g, d / g);
                // |a q + c p| < 2^127 and b q < 2^126: no overflow.
                Rat::new(a * q + c * p, b * q).unwrap_or(Rat::ZERO)
            }
            _ => big_add(self, o),
        }
    }
    /// The product (marked as typed when an operand is).
    pub fn mul(&self, o: &Rat) -> Rat {
        self.mul_unmarked(o).marked(self.is_typed() || o.is_typed())
    }
    fn mul_unmarked(&self, o: &Rat) -> Rat {
        match (self, o) {
            _ if self.is_zero() || o.is_zero() => Rat::ZERO,
            (Rat::Small { num: a, den: b, .. }, Rat::Small { num: c, den: d, .. }) => {
                let (a, b, c, d) = (
                    i128::from(*a),
                    i128::from(*b),
                    i128::from(*c),
                    i128::from(*d),
                );
                if b == 1 && d == 1 {
                    return Rat::new(a * c, 1).unwrap_or(Rat::ZERO);
                }
                Rat::new(a * c, b * d).unwrap_or(Rat::ZERO)
            }
            _ => big_mul(self, o),
        }
    }
    /// −x.
    pub fn neg(&self) -> Rat {
        match self {
            Rat::Small { num, den, typed } if *num != i64::MIN => Rat::Small {
                num: -num,
                den: *den,
                typed: *typed,
            },
            _ => Rat::from_big(-self.to_big()),
        }
    }
    /// 1/x; None for 0.
    pub fn inv(&self) -> Option<Rat> {
        match self {
            _ if self.is_zero() => None,
            Rat::Small { num, den, typed } => {
                Rat::new(i128::from(*den), i128::from(*num)).map(|r| r.marked(*typed))
            }
            Rat::Big(b) => Some(Rat::from_big(b.recip())),
        }
    }
    /// The nearest float (±inf beyond the range of `f64`).
    pub fn to_f64(&self) -> f64 {
        match self {
            // both exact in an f64: one rounding, the nearest float
            Rat::Small { num, den, .. } if num.unsigned_abs() <= 1 << 53 && *den <= 1 << 53 => {
                *num as f64 / *den as f64
            }
            Rat::Small { .. } => self.to_big().to_f64().unwrap_or(f64::NAN),
            Rat::Big(b) => b.to_f64().unwrap_or(f64::NAN),
        }
    }
    /// Every digit of a decimal (a denominator of 2s and 5s only):
    /// `99999.999999999999`, `100000000000000000001`, `-0.00561`; None for
    /// any other fraction.
    pub fn decimal_text(&self) -> Option<String> {
        let (p, q) = self.parts();
        let ten = BigInt::from(10);
        // q divides 10^k for the least such k
        let (mut k, mut d) = (0usize, q.clone());
        while !d.is_one() {
            let g = d.gcd(&ten);
            if g.is_one() {
                return None;
            }
            d /= g;
            k += 1;
        }
        let scaled = &p * num_traits::pow(ten, k) / &q;
        let digits = scaled.magnitude().to_string();
        let sign = if scaled.is_negative() { "-" } else { "" };
        if k == 0 {
            return Some(format!("{sign}{digits}"));
        }
        let padded = format!("{digits:0>width$}", width = k + 1);
        let (int, frac) = padded.split_at(padded.len() - k);
        Some(format!("{sign}{int}.{frac}"))
    }
    /// The integer, when the fraction is one that fits an `i64`.
    pub fn as_int(&self) -> Option<i64> {
        match self {
            Rat::Small { num, den: 1, .. } => Some(*num),
            _ => None,
        }
    }
    /// True when the fraction is an integer.
    pub fn is_integer(&self) -> bool {
        match self {
            Rat::Small { den, .. } => *den == 1,
            Rat::Big(b) => b.denom().is_one(),
        }
    }
    /// The exact value of a finite float (every float is a dyadic
    /// fraction); None for NaN and infinities.
    pub fn from_f64_exact(x: f64) -> Option<Rat> {
        if x == x.trunc() && x.abs() < 9.2e18 {
            return Some(Rat::int(x as i64));
        }
        BigRational::from_float(x).map(Rat::from_big)
    }
    /// The decimal a float was typed as: the shortest digits that read back
    /// as it (`0.1` is 1/10, `1e-13` is 1/10¹³); None for inf or NaN.
    pub fn typed(x: f64) -> Option<Rat> {
        if !x.is_finite() {
            return None;
        }
        if x == x.trunc() && x.abs() < 9.0e15 {
            return Some(Rat::int(x as i64));
        }
        // `{:e}` is the shortest round-trip form: `-8.66e-1`.
        let text = format!("{x:e}");
        let (mantissa, exp) = text.split_once('e')?;
        let exp: i32 = exp.parse().ok()?;
        let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        let digits: BigInt = format!("{int}{frac}").parse().ok()?;
        Some(Rat::decimal(&digits, exp - frac.len() as i32))
    }
    /// [`Rat::typed`] without text or big integers, for the usual
    /// numbers: an integer below 9·10¹⁵, or a decimal of at most 15
    /// significant digits and 15 places (`0.1`, `0.866`, `123.456`). None
    /// when it cannot tell at once (ask [`Rat::typed`]). The decimal found
    /// is the one with the fewest places whose quotient n/10ʲ rounds to
    /// `x` (a correctly rounded division of exact floats), so it reads back
    /// as `x`; with 15 significant digits or fewer no other decimal of as
    /// few digits does, so it is the shortest that `{:e}` prints.
    #[inline]
    pub fn typed_quick(x: f64) -> Option<Rat> {
        if x == x.trunc() && x.abs() < 9.0e15 {
            return Some(Rat::int(x as i64));
        }
        if !x.is_finite() {
            return None;
        }
        let mut p = 1.0_f64;
        let mut den: i64 = 1;
        for _ in 0..15 {
            p *= 10.0;
            den *= 10;
            let n = (x * p).round();
            if n.abs() >= 1e15 {
                return None;
            }
            if n / p == x {
                return Rat::new(n as i128, i128::from(den)).map(|r| r.marked(true));
            }
        }
        None
    }
    /// The decimal `digits · 10^exp` exactly (a number as typed: `0.866`
    /// is 866/1000, `1e-13` is 1/10¹³), marked as typed.
    pub fn decimal(digits: &BigInt, exp: i32) -> Rat {
        let ten = BigInt::from(10);
        let p = num_traits::pow(ten, exp.unsigned_abs() as usize);
        if exp >= 0 {
            Rat::from_big(BigRational::from_integer(digits * p))
        } else {
            Rat::from_big(BigRational::new(digits.clone(), p)).marked(true)
        }
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

/// `a/b` reduced, with `b > 0` (no gcd when `b` is 1: integers are the
/// common big case, binomial coefficients, and a gcd with 1 costs as much as
/// a long division).
fn reduced(a: BigInt, b: BigInt) -> Rat {
    if b.is_one() {
        return Rat::from_big(BigRational::from_integer(a));
    }
    let g = a.gcd(&b);
    if g.is_one() {
        Rat::from_big(BigRational::new_raw(a, b))
    } else {
        Rat::from_big(BigRational::new_raw(a / &g, b / g))
    }
}

/// The sum of fractions at least one of which is big.
fn big_add(x: &Rat, y: &Rat) -> Rat {
    let ((a, b), (c, d)) = (x.parts(), y.parts());
    if b == d {
        return reduced(a + c, b);
    }
    reduced(a * &d + c * &b, b * d)
}

/// The product of fractions at least one of which is big: cross gcds
/// keep the parts small, and none is taken with a denominator of 1.
fn big_mul(x: &Rat, y: &Rat) -> Rat {
    let ((a, b), (c, d)) = (x.parts(), y.parts());
    let cross = |n: BigInt, m: BigInt| -> (BigInt, BigInt) {
        if m.is_one() || n.is_one() {
            return (n, m);
        }
        let g = n.gcd(&m);
        if g.is_one() { (n, m) } else { (n / &g, m / g) }
    };
    let (a, d) = cross(a, d);
    let (c, b) = cross(c, b);
    let n = a * c;
    let m = b * d;
    if m.is_one() {
        Rat::from_big(BigRational::from_integer(n))
    } else {
        Rat::from_big(BigRational::new_raw(n, m))
    }
}

impl std::fmt::Display for Rat {
    /// `p` or `p/q`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (p, q) = self.parts();
        if q.is_one() {
            write!(f, "{p}")
        } else {
            write!(f, "{p}/{q}")
        }
    }
}

/// p/q (digits of a fraction in lowest terms) as typed in scientific notation, when that is much shorter: a
/// long power of ten in it (`1e300`, `1e-13`), at most 15 digits.
pub fn scientific(p: &str, q: &str) -> Option<String> {
    let digits = |m: &str| -> Option<String> {
        (m.len() <= 15).then(|| match m.len() {
            1 => m.to_string(),
            _ => format!("{}.{}", &m[..1], &m[1..]),
        })
    };
    if q == "1" && p.len() > 15 {
        let m = p.trim_end_matches('0');
        if p.len() - m.len() < 10 {
            return None;
        }
        return Some(format!("{}e{}", digits(m)?, p.len() - 1));
    }
    let zeros = q.strip_prefix('1')?;
    if zeros.len() > 12 && zeros.bytes().all(|b| b == b'0') && p.len() <= 15 {
        // p / 10^n = m · 10^(len(p) - 1 - n), m = p.ddd (a number of
        // more than 12 places above 1 too: 11 + 1e-13 is 1.10000000000001e1)
        let m = p.trim_end_matches('0');
        let exp = p.len() as i64 - 1 - zeros.len() as i64;
        return Some(format!("{}e{exp}", digits(m)?));
    }
    None
}

#[cfg(test)]
mod tests;
