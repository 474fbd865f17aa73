//! Expressions as a ring for generic algorithms (`num_traits`' `Zero` and
//! `One`, `+` and `*`): the symbolic matrix product and determinant start
//! from 0 and 1 as they do for numbers.

use super::Expr;
use crate::sym::coef::Coef;
use num_traits::{One, Zero};

/// Expressions form a commutative ring: `num_traits`' `Zero` and `One`
/// (with `+` and `*`) let ring algorithms, such as the symbolic matrix
/// product and determinant, start from 0 and 1 as for numbers.
impl Zero for Expr {
    /// 0 (no terms).
    fn zero() -> Expr {
        Expr::default()
    }
    /// True for 0 (no terms).
    fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
}

impl One for Expr {
    /// 1.
    fn one() -> Expr {
        Expr::constant(Coef::one())
    }
}

impl std::ops::Add for Expr {
    type Output = Expr;
    fn add(self, o: Expr) -> Expr {
        Expr::add(&self, &o)
    }
}

impl std::ops::Mul for Expr {
    type Output = Expr;
    fn mul(self, o: Expr) -> Expr {
        Expr::mul(&self, &o)
    }
}
