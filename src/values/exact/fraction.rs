//! A fraction held inline in an exact form ([`super::Exact::Ratio`]).

use crate::sym::coef::Rat;

/// A reduced fraction num/den (den > 0) small enough to sit inline in an
/// [`super::Exact`] (a denominator below 2³²: the value stays 104 bytes), with
/// the typed mark its [`Rat`] carries (`0.37` as typed prints as a
/// decimal, `37/100` computed from integers as a fraction: the same form
/// the recipe would have made).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub struct Fraction {
    num: i64,
    den: u32,
    typed: bool,
}

impl Fraction {
    /// `r` inline, when it is a small fraction whose denominator fits.
    pub fn of(r: &Rat) -> Option<Fraction> {
        let (num, den) = r.small()?;
        Some(Fraction {
            num,
            den: u32::try_from(den).ok()?,
            typed: r.is_typed(),
        })
    }
    /// The fraction as a [`Rat`], its typed mark with it.
    pub fn rat(self) -> Rat {
        Rat::Small {
            num: self.num,
            den: i64::from(self.den),
            typed: self.typed,
        }
    }
}

/// The four operations on fractions at hand in machine words, as [`Rat`]
/// does them (the same reduced fraction and the same typed mark: a sum or
/// product is marked when an operand is, a quotient is the product by
/// the inverse, whose mark is the divisor's unless the inverse is whole),
/// with no 128-bit division; None where a word would overflow or the
/// denominator not fit (the caller then asks [`Rat`]).
impl Fraction {
    /// `x` as typed ([`Rat::typed`]), at once: an integer below 9·10¹⁵,
    /// or a decimal of at most 15 significant digits and 9 places, the one
    /// with the fewest places whose quotient n/10ʲ rounds to `x` (a
    /// correctly rounded division of exact floats, so it reads back as
    /// `x`; with 15 significant digits or fewer no other decimal of as few
    /// digits does, so it is the shortest `{:e}` prints). None otherwise.
    #[inline]
    pub fn typed(x: f64) -> Option<Fraction> {
        if let Some(f) = Fraction::whole(x) {
            return Some(f);
        }
        let (mut p, mut den) = (1.0_f64, 1_u64);
        for _ in 0..9 {
            p *= 10.0;
            den *= 10;
            let y = x * p;
            if y.is_nan() || y.abs() >= 1e15 {
                return None;
            }
            // (the nearest integer; a miss only gives None)
            let n = (y + 0.5_f64.copysign(y)) as i64;
            if n as f64 / p == x {
                return reduced(i128::from(n), u128::from(den), true);
            }
        }
        None
    }
    /// `x` as typed when it is a whole number below 9·10¹⁵ (no mark).
    #[inline]
    pub fn whole(x: f64) -> Option<Fraction> {
        let n = x as i64;
        (n as f64 == x && n.unsigned_abs() < 9_000_000_000_000_000).then_some(Fraction {
            num: n,
            den: 1,
            typed: false,
        })
    }
    /// `self + o`.
    #[inline]
    pub fn plus(self, o: Fraction) -> Option<Fraction> {
        let (p, q, r, s) = self.words(o);
        reduced(p * s + r * q, (q * s) as u128, self.typed || o.typed)
    }
    /// `self − o`.
    #[inline]
    pub fn minus(self, o: Fraction) -> Option<Fraction> {
        if o.num == i64::MIN {
            return None;
        }
        self.plus(Fraction { num: -o.num, ..o })
    }
    /// `self · o`.
    #[inline]
    pub fn times(self, o: Fraction) -> Option<Fraction> {
        let (p, q, r, s) = self.words(o);
        reduced(p * r, (q * s) as u128, self.typed || o.typed)
    }
    /// `self / o`; None for o = 0.
    #[inline]
    pub fn over(self, o: Fraction) -> Option<Fraction> {
        if o.num == 0 || o.num == i64::MIN {
            return None;
        }
        let (num, den) = (i64::from(o.den), o.num.unsigned_abs());
        let inverse = Fraction {
            num: if o.num < 0 { -num } else { num },
            den: u32::try_from(den).ok()?,
            typed: o.typed && den != 1,
        };
        self.times(inverse)
    }
    /// The numerators and denominators of two fractions, widened.
    #[inline]
    fn words(self, o: Fraction) -> (i128, i128, i128, i128) {
        (
            i128::from(self.num),
            i128::from(self.den),
            i128::from(o.num),
            i128::from(o.den),
        )
    }
}

/// num/den (den > 0) reduced, marked typed when `typed` and not whole;
/// None when the reduced fraction does not fit.
#[inline]
fn reduced(num: i128, den: u128, typed: bool) -> Option<Fraction> {
    let n = u64::try_from(num.unsigned_abs()).ok()?;
    let d = u64::try_from(den).ok()?;
    let g = gcd(n, d).max(1);
    let (n, d) = (n / g, d / g);
    let n = i64::try_from(n).ok()?;
    Some(Fraction {
        num: if num < 0 { -n } else { n },
        den: u32::try_from(d).ok()?,
        typed: typed && d != 1,
    })
}

/// The greatest common divisor (binary: shifts and subtractions).
#[inline]
fn gcd(mut a: u64, mut b: u64) -> u64 {
    if a == 0 || b == 0 {
        return a | b;
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

/// Three small fractions packed in the twelve bytes a [`Fraction`] leaves
/// beside its mark: the entries of a 3-vector held inline in an
/// [`super::Exact`] (`(k/1000, 0, 0)`, a position p of (3.62)), with no
/// allocation and nothing to drop. Each entry is a word: its numerator
/// (below 2²⁰ in size), its denominator (at most 1024) and its typed mark.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub struct Fractions3([u32; 3]);

/// The bits of an entry of [`Fractions3`] below the numerator: 10 for
/// the denominator less one, 1 for the mark.
const DEN_BITS: u32 = 10;

impl Fractions3 {
    /// `rs` packed, when each fits (a numerator below 2²⁰ in size, a
    /// denominator at most 1024).
    #[inline]
    pub fn of(rs: [Fraction; 3]) -> Option<Fractions3> {
        let word = |r: Fraction| -> Option<u32> {
            let den = r.den.checked_sub(1).filter(|d| *d < 1 << DEN_BITS)?;
            let num = i32::try_from(r.num)
                .ok()
                .filter(|n| n.unsigned_abs() < 1 << 20)?;
            Some(((num as u32) << (DEN_BITS + 1)) | (u32::from(r.typed) << DEN_BITS) | den)
        };
        Some(Fractions3([word(rs[0])?, word(rs[1])?, word(rs[2])?]))
    }
    /// The exact form of the 3-vector whose entries these are: what the
    /// recipe of `(a, b, c)` makes, the column of the entries' constants.
    pub fn form(self) -> crate::sym::Mat {
        use crate::sym::{coef::Coef, expr::Expr};
        let entry = |r: Fraction| Expr::constant(Coef::rat(r.rat()));
        crate::sym::Mat::column(self.get().map(entry).to_vec())
    }
    /// The three fractions, in order.
    #[inline]
    pub fn get(self) -> [Fraction; 3] {
        self.0.map(|w| Fraction {
            num: i64::from((w as i32) >> (DEN_BITS + 1)),
            den: (w & ((1 << DEN_BITS) - 1)) + 1,
            typed: w & (1 << DEN_BITS) != 0,
        })
    }
}
