//! A fraction held inline in an exact form ([`super::Exact::Ratio`]).

use crate::sym::coef::Rat;

/// A reduced fraction num/den (den > 0) small enough to sit inline in an
/// [`Exact`] (a denominator below 2³²: the value stays 104 bytes), with
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
