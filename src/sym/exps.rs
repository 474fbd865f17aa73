//! The exponential of a symbolic scalar in the canonical form (LANGUAGE.md
//! §7; issue 35): exp(a) is kept as a call of a canonical argument, and a
//! product of such calls is one call, e^{a} e^{b} = e^{a + b} (true for
//! every real or complex a and b), so that each monomial holds at most one
//! exponential, to the first power: `exp(t) exp(-t)` is 1, `exp(t)^2` is
//! `exp(2 t)`, `1/exp(t)` is `exp(-t)`, and e⁰ = 1 exactly. The closed forms
//! of e^{At} (book §3.2.1, eq. 3.41–3.48; [`super::matexp`]) print short and
//! `==` proves them by comparing term maps.

use super::coef::Coef;
use super::expr::{Expr, Func, Mono, Var};
use num_traits::{One, Zero};

fn is_exp(v: &Var) -> bool {
    matches!(v, Var::Call(c) if c.f == Func::Exp)
}

/// True when the monomial holds an exponential to a power other than 1, or
/// two exponentials: a product [`Expr::fold_exps`] makes one call.
fn may_fold(m: &Mono) -> bool {
    let mut seen = false;
    for (v, e) in m {
        if is_exp(v) {
            if seen || *e != 1 {
                return true;
            }
            seen = true;
        }
    }
    false
}

impl Expr {
    /// eˣ: exactly 1 at x = 0 (what a fold e^{a} e^{−a} leaves), a float
    /// at another number (e has no exact form here), else the call exp(x)
    /// of the canonical x. (A typed `exp(0)` stays the float the numeric
    /// path computes: the scripts that need a float 1 with no exact form
    /// use it, `tests/errors/domain/near_domain.chs`.)
    pub fn exp(x: &Expr) -> Expr {
        if x.is_zero() {
            return Expr::one();
        }
        Expr::apply(Func::Exp, x, f64::exp)
    }

    /// `self` with each monomial that `may` holds replaced by `fold` of it
    /// and its coefficient, the others kept: the one walk of the product
    /// folds ([`Expr::fold_exps`], [`Expr::fold_halves`]); `self` unchanged
    /// when no monomial may fold.
    pub(super) fn fold_terms(
        self,
        may: fn(&Mono) -> bool,
        fold: impl Fn(Mono, Coef) -> Expr,
    ) -> Expr {
        if !self.terms.keys().any(may) {
            return self;
        }
        let mut out = Expr::zero();
        for (m, c) in self.terms {
            if may(&m) {
                for (m, c) in fold(m, c).terms {
                    out.push(m, c);
                }
            } else {
                out.push(m, c);
            }
        }
        out
    }
    /// e^{a}ᵐ e^{b}ⁿ = e^{m a + n b} in every monomial (the module's doc);
    /// the expression unchanged when no monomial holds such a product.
    pub(super) fn fold_exps(self) -> Expr {
        self.fold_terms(may_fold, |m, c| {
            let mut rest: Mono = Vec::with_capacity(m.len());
            let mut arg = Expr::zero();
            for (v, e) in m {
                match &v {
                    Var::Call(call) if call.f == Func::Exp => {
                        arg = arg.add(&call.args[0].scale(&Coef::int(i64::from(e))));
                    }
                    _ => rest.push((v, e)),
                }
            }
            let mut t = Expr::zero();
            t.push(rest, c);
            // (the product of t, which holds no exponential, with one call:
            // no further exponential fold)
            t.mul(&Expr::exp(&arg))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::Symbol;

    fn t() -> Expr {
        Expr::symbol(Symbol::new("t"))
    }

    #[test]
    fn products_of_exponentials_are_one_exponential() {
        let (a, b) = (Expr::exp(&t()), Expr::exp(&t().neg()));
        assert_eq!(a.mul(&b), Expr::one());
        let two = Expr::exp(&t().scale(&Coef::int(2)));
        assert_eq!(a.mul(&a), two);
        assert_eq!(a.mul(&two), Expr::exp(&t().scale(&Coef::int(3))));
        assert_eq!(a.recip(), Some(b.clone()));
        assert_eq!(a.powi(-2), Some(Expr::exp(&t().scale(&Coef::int(-2)))));
    }

    #[test]
    fn exp_of_zero_is_exactly_one() {
        assert_eq!(Expr::exp(&Expr::zero()), Expr::one());
        assert!(Expr::exp(&Expr::zero()).as_const().unwrap().is_exact());
        // e¹ has no exact form: a float
        assert!(!Expr::exp(&Expr::one()).as_const().unwrap().is_exact());
    }

    #[test]
    fn a_sum_times_an_exponential_folds_term_by_term() {
        let s = Expr::one().add(&Expr::exp(&t()));
        let p = s.mul(&Expr::exp(&t().neg()));
        assert_eq!(p, Expr::exp(&t().neg()).add(&Expr::one()));
    }
}
