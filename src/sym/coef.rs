//! Exact coefficients of symbolic expressions: complex numbers whose real
//! and imaginary parts are rationals plus rational multiples of square
//! roots ([`Surd`]: ½, 1/√2, √3/2, √5, the lengths typed as decimals), so
//! that the book's constants stay exact and e^{iθ} = cos θ + i sin θ needs
//! no special case. Fractions are exact however large ([`Rat`]); a
//! coefficient that comes from a number with no exact form (sin 1,
//! √(1 + √2)) is kept as a complex `f64` pair ([`Coef::Approx`]), and a
//! sum of such pairs that cancels to within rounding is 0, never a term of
//! noise.

#![allow(clippy::should_implement_trait, clippy::needless_range_loop)]

use std::cmp::Ordering;

pub use super::rat::Rat;
pub use super::surd::Surd;

/// A coefficient: an exact complex number with rational parts and square
/// roots ([`Surd`]), or a complex
/// `f64` pair when no exact form is known.
#[derive(Debug, Clone, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub enum Coef {
    /// re + i·im, each exact.
    Exact {
        /// The real part.
        re: Surd,
        /// The imaginary part.
        im: Surd,
    },
    /// re + i·im in floating point.
    Approx {
        /// The real part.
        re: f64,
        /// The imaginary part.
        im: f64,
    },
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

/// The hash of the order's equality: an approximate part by its bits (as
/// `total_cmp` compares it), so shared calls ([`super::intern`]) find
/// their equals.
impl std::hash::Hash for Coef {
    fn hash<H: std::hash::Hasher>(&self, h: &mut H) {
        match self {
            Coef::Exact { re, im } => (0u8, re, im).hash(h),
            Coef::Approx { re, im } => (1u8, re.to_bits(), im.to_bits()).hash(h),
        }
    }
}

impl PartialOrd for Coef {
    fn partial_cmp(&self, other: &Coef) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// A float sum `a + b`, 0 when it cancels to within rounding (a few units
/// in the last place of the larger summand): such a remainder is noise.
fn float_sum(a: f64, b: f64) -> f64 {
    let s = a + b;
    if s.abs() <= 8.0 * f64::EPSILON * a.abs().max(b.abs()) {
        0.0
    } else {
        s
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
    /// A float as a coefficient (LANGUAGE.md §7): exact only when the
    /// float is itself a simple fraction — an integer, or a fraction whose
    /// denominator is a power of two up to 1024 (0.5, 0.25) — else a float.
    /// No closed form is guessed: a number that has one (1/√2, π/9) enters
    /// a symbolic expression through its exact form, not through its float.
    pub fn from_f64(x: f64) -> Coef {
        let scaled = x * 1024.0;
        if x.is_finite() && scaled == scaled.trunc() && scaled.abs() < 9.0e15 {
            let r = Rat::new(scaled as i128, 1024);
            if let Some(r) = r {
                return Coef::rat(r);
            }
        }
        Coef::Approx { re: x, im: 0.0 }
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
        match self {
            Coef::Exact { re, im } => im.is_zero() && re.as_rat() == Some(Rat::ONE),
            Coef::Approx { .. } => false,
        }
    }
    /// Machine words beyond the inline ones that the exact parts hold (0
    /// for the usual small fractions): the weight of a term in the
    /// expression limit.
    pub fn words(&self) -> usize {
        match self {
            Coef::Exact { re, im } => re.words() + im.words(),
            Coef::Approx { .. } => 0,
        }
    }
    /// True for an exact coefficient.
    pub fn is_exact(&self) -> bool {
        matches!(self, Coef::Exact { .. })
    }
    /// (re, im) as floats.
    pub fn to_c64(&self) -> (f64, f64) {
        match self {
            Coef::Exact { re, im } => (re.to_f64(), im.to_f64()),
            Coef::Approx { re, im } => (*re, *im),
        }
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
    /// The sum (a float pair when either is one; a float sum that cancels
    /// to within rounding is 0).
    pub fn add(&self, o: &Coef) -> Coef {
        if let (Coef::Exact { re: a, im: b }, Coef::Exact { re: c, im: d }) = (self, o) {
            return Coef::Exact {
                re: a.add(c),
                im: b.add(d),
            };
        }
        let ((a, b), (c, d)) = (self.to_c64(), o.to_c64());
        Coef::settle(float_sum(a, c), float_sum(b, d))
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
    /// The product (a float pair when either is one, or when a root of
    /// the exact product passes 2¹²⁸).
    pub fn mul(&self, o: &Coef) -> Coef {
        if let (Coef::Exact { re: a, im: b }, Coef::Exact { re: c, im: d }) = (self, o) {
            let exact = || {
                if b.is_zero() && d.is_zero() {
                    return Some(Coef::real(a.mul(c)?));
                }
                Some(Coef::Exact {
                    re: a.mul(c)?.add(&b.mul(d)?.neg()),
                    im: a.mul(d)?.add(&b.mul(c)?),
                })
            };
            if let Some(p) = exact() {
                return p;
            }
        }
        let ((a, b), (c, d)) = (self.to_c64(), o.to_c64());
        Coef::settle(float_sum(a * c, -(b * d)), float_sum(a * d, b * c))
    }
    /// The complex conjugate.
    pub fn conj(&self) -> Coef {
        match self {
            Coef::Exact { re, im } => Coef::Exact {
                re: re.clone(),
                im: im.neg(),
            },
            Coef::Approx { re, im } => Coef::Approx { re: *re, im: -im },
        }
    }
    /// 1/c; None for zero. Exact for an exact c, unless its reciprocal
    /// passes the size of a [`Surd`] (a float pair then).
    pub fn inv(&self) -> Option<Coef> {
        if self.is_zero() {
            return None;
        }
        if let Coef::Exact { re, im } = self {
            let exact = || {
                if im.is_zero() {
                    return Some(Coef::real(re.inv()?));
                }
                let n = re.mul(re)?.add(&im.mul(im)?).inv()?;
                Some(Coef::Exact {
                    re: re.mul(&n)?,
                    im: im.neg().mul(&n)?,
                })
            };
            if let Some(c) = exact() {
                return Some(c);
            }
        }
        let (a, b) = self.to_c64();
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
                match part.inv() {
                    Some(p) => Some(Coef::real(p.scale(&to))),
                    None if part.is_zero() => None,
                    None => Some(Coef::settle(to.to_f64() / part.to_f64(), 0.0)),
                }
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
            Coef::Exact { re, im } if im.is_zero() => Some(re.clone()),
            _ => None,
        }
    }
    /// e^{iπ p} exactly for p a multiple of 1/12 (cos and sin of multiples
    /// of 15° lie in ℚ(√2, √3)).
    pub fn unit_root(p: Rat) -> Option<Coef> {
        let twelfths = p.mul(&Rat::int(12)).as_int()?.rem_euclid(24);
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
            Surd::of_basis(
                COS[k as usize].map(|n| Rat::new(i128::from(sign * n), 4).unwrap_or(Rat::ZERO)),
            )
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
        let r2 = Surd::of_basis([Rat::ZERO, Rat::ONE, Rat::ZERO, Rat::ZERO]);
        let two = r2.mul(&r2).unwrap();
        assert_eq!(two, Surd::rat(Rat::int(2)));
        let x = Surd::of_basis([Rat::ONE, Rat::ONE, Rat::ONE, Rat::ZERO]);
        let one = x.mul(&x.inv().unwrap()).unwrap();
        assert_eq!(one, Surd::rat(Rat::ONE));
    }

    #[test]
    fn square_roots_in_the_field_are_exact() {
        let r = |p, q| Rat::new(p, q).unwrap();
        let basis = |i: usize, c: Rat| {
            let mut b = [Rat::ZERO, Rat::ZERO, Rat::ZERO, Rat::ZERO];
            b[i] = c;
            Surd::of_basis(b)
        };
        assert_eq!(Surd::sqrt_of(&r(8, 1)), Some(basis(1, Rat::int(2))));
        assert_eq!(Surd::sqrt_of(&r(3, 4)), Some(basis(2, r(1, 2))));
        assert_eq!(Surd::sqrt_of(&r(1, 2)), Some(basis(1, r(1, 2))));
        assert_eq!(Surd::sqrt_of(&r(9, 4)), Some(Surd::rat(r(3, 2))));
        // any square-free part now: √5 is exact, its square is 5
        let five = Surd::sqrt_of(&Rat::int(5)).unwrap();
        assert_eq!(five.mul(&five), Some(Surd::rat(Rat::int(5))));
        assert_eq!(Surd::sqrt_of(&Rat::int(-4)), None);
    }

    #[test]
    fn floats_are_exact_only_as_themselves() {
        assert_eq!(Coef::from_f64(0.5), Coef::rat(Rat::new(1, 2).unwrap()));
        assert_eq!(Coef::from_f64(-3.0), Coef::int(-3));
        // No closed form is guessed from a float.
        for x in [
            std::f64::consts::FRAC_1_SQRT_2,
            0.1,
            std::f64::consts::PI / 9.0,
        ] {
            assert_eq!(Coef::from_f64(x), Coef::Approx { re: x, im: 0.0 });
        }
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
