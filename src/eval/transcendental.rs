//! Proofs of identities between numbers made by exp and log (LANGUAGE.md
//! §7, issue 21): `exp(1)^2 == exp(2)`, `log(2) + log(3) == log(6)`,
//! `sqrt(exp(3)) == exp(3/2)`, `exp(log(2)/2) == sqrt(2)`. Such a number
//! has no exact form (e is a float), but it was made by operations over
//! exact numbers (its recipe, [`crate::values::exact::Exact::with_recipe`]),
//! and two normal forms cover what these operations make:
//!
//! - s·e^q, with s a nonzero real algebraic number and q a real algebraic
//!   number, both exact ([`Surd`]). The form is unique: s·e^q = s'·e^q'
//!   with q ≠ q' would make e^(q − q') algebraic, which the
//!   Lindemann–Weierstrass theorem forbids;
//! - a + Σ c_p ln p over primes p, a algebraic and the c_p rational.
//!   Unique too: by Baker's theorem 1 and the ln p (independent over ℚ by
//!   unique factorisation) are independent over the algebraic numbers.
//!
//! Sides with the same normal form are equal, proven; anything else proves
//! nothing here ([`super::certify`] then bounds the difference).

use std::collections::{BTreeMap, HashMap};

use super::value::Value;
use crate::sym::coef::{Coef, Rat, Surd};
use crate::syntax::ast::BinOp;
use crate::values::exact::Operation;

/// A number in one of the two normal forms (the module's doc).
#[derive(Debug, Clone, PartialEq)]
enum Form {
    /// s·e^q, s ≠ 0.
    Exp { s: Surd, q: Surd },
    /// a + Σ c_p ln p, every c_p ≠ 0.
    Log { a: Surd, c: BTreeMap<u64, Rat> },
    /// atan α of an exact real α: atan2(y, x) with x > 0 is atan(y/x),
    /// asin α is atan(α/√(1 − α²)), acos α for α > 0 is atan(√(1 − α²)/α)
    /// (atan is one to one: equal α, equal angles).
    Atan(Surd),
}

/// The largest integer factored into primes by trial division (its
/// square root is the last divisor tried).
const MAX_FACTORED: u64 = 1_000_000_000_000;

/// The largest integer power taken of a form.
const MAX_POWER: i64 = 64;

impl Form {
    /// An exact real number.
    fn exact(x: Surd) -> Form {
        if x.is_zero() {
            Form::Log {
                a: x,
                c: BTreeMap::new(),
            }
        } else {
            Form::Exp {
                s: x,
                q: Surd::ZERO,
            }
        }
    }

    /// The form as s·e^q, when it is one (an exact number is, with q = 0).
    fn as_exp(&self) -> Option<(Surd, Surd)> {
        match self {
            Form::Exp { s, q } => Some((s.clone(), q.clone())),
            Form::Log { a, c } if c.is_empty() && !a.is_zero() => Some((a.clone(), Surd::ZERO)),
            _ => None,
        }
    }

    /// The form as a + Σ c_p ln p, when it is one (an exact number is).
    fn as_log(&self) -> Option<(Surd, BTreeMap<u64, Rat>)> {
        match self {
            Form::Log { a, c } => Some((a.clone(), c.clone())),
            Form::Exp { s, q } if q.is_zero() => Some((s.clone(), BTreeMap::new())),
            _ => None,
        }
    }

    /// The exact real number the form is, if it is one.
    fn as_surd(&self) -> Option<Surd> {
        match self.as_exp() {
            Some((s, q)) if q.is_zero() => Some(s),
            None if matches!(self, Form::Log { a, c } if a.is_zero() && c.is_empty()) => {
                Some(Surd::ZERO)
            }
            _ => None,
        }
    }

    /// The exact rational the form is, if it is one.
    fn as_rat(&self) -> Option<Rat> {
        match self.as_exp() {
            Some((s, q)) if q.is_zero() => s.as_rat(),
            None if matches!(self, Form::Log { a, c } if a.is_zero() && c.is_empty()) => {
                Some(Rat::ZERO)
            }
            _ => None,
        }
    }

    /// The form of a sum a + Σ c_p ln p, s·e^q when no logarithm is left.
    fn log(a: Surd, mut c: BTreeMap<u64, Rat>) -> Form {
        c.retain(|_, r| !r.is_zero());
        if c.is_empty() {
            return Form::exact(a);
        }
        Form::Log { a, c }
    }

    fn neg(&self) -> Form {
        match self {
            Form::Atan(a) => Form::Atan(a.neg()),
            Form::Exp { s, q } => Form::Exp {
                s: s.neg(),
                q: q.clone(),
            },
            Form::Log { a, c } => {
                Form::log(a.neg(), c.iter().map(|(p, r)| (*p, r.neg())).collect())
            }
        }
    }

    fn add(&self, o: &Form) -> Option<Form> {
        if let (Some((s, q)), Some((t, r))) = (self.as_exp(), o.as_exp())
            && q == r
        {
            let sum = s.add(&t);
            return Some(if sum.is_zero() {
                Form::exact(sum)
            } else {
                Form::Exp { s: sum, q }
            });
        }
        let ((a, mut c), (b, d)) = (self.as_log()?, o.as_log()?);
        for (p, r) in d {
            let e = c.entry(p).or_insert(Rat::ZERO);
            *e = e.add(&r);
        }
        Some(Form::log(a.add(&b), c))
    }

    fn mul(&self, o: &Form) -> Option<Form> {
        if let (Some((s, q)), Some((t, r))) = (self.as_exp(), o.as_exp()) {
            return Some(Form::Exp {
                s: s.mul(&t)?,
                q: q.add(&r),
            });
        }
        // (a logarithm times a rational)
        let (k, (a, c)) = match (self.as_rat(), o.as_rat()) {
            (Some(k), _) => (k, o.as_log()?),
            (_, Some(k)) => (k, self.as_log()?),
            _ => return None,
        };
        Some(Form::log(
            a.scale(&k),
            c.into_iter().map(|(p, r)| (p, r.mul(&k))).collect(),
        ))
    }

    fn recip(&self) -> Option<Form> {
        let (s, q) = self.as_exp()?;
        Some(Form::Exp {
            s: s.inv()?,
            q: q.neg(),
        })
    }

    fn powi(&self, k: i64) -> Option<Form> {
        if k.abs() > MAX_POWER {
            return None;
        }
        let (s, q) = self.as_exp()?;
        let mut out = Surd::rat(Rat::ONE);
        for _ in 0..k.abs() {
            out = out.mul(&s)?;
        }
        let form = Form::Exp {
            s: out,
            q: q.scale(&Rat::int(k.abs())),
        };
        if k < 0 { form.recip() } else { Some(form) }
    }

    /// √x of s·e^q: √s·e^(q/2), s > 0 with an exact root.
    fn sqrt(&self) -> Option<Form> {
        let (s, q) = self.as_exp()?;
        if s.signum() <= 0.0 {
            return None;
        }
        Some(Form::Exp {
            s: s.sqrt()?,
            q: q.scale(&Rat::new(1, 2)?),
        })
    }

    /// e^x of a + Σ c_p ln p: Π p^c_p · e^a, each c_p an integer or a half.
    fn exp(&self) -> Option<Form> {
        let (a, c) = self.as_log()?;
        let mut s = Surd::rat(Rat::ONE);
        for (p, r) in c {
            let twice = r.mul(&Rat::int(2)).as_int()?;
            let p = Rat::int(i64::try_from(p).ok()?);
            let whole = Form::Exp {
                s: Surd::rat(p.clone()),
                q: Surd::ZERO,
            }
            .powi(twice.div_euclid(2))?
            .as_exp()?
            .0;
            s = s.mul(&whole)?;
            if twice.rem_euclid(2) == 1 {
                s = s.mul(&Surd::sqrt_of(&p)?)?;
            }
        }
        Some(Form::Exp { s, q: a })
    }

    /// ln x of s·e^q: q + ln s, s a positive rational whose numerator and
    /// denominator factor into primes.
    fn ln(&self) -> Option<Form> {
        let (s, q) = self.as_exp()?;
        let r = s.as_rat()?;
        if r.is_negative() || r.is_zero() {
            return None;
        }
        let (num, den) = r.small()?;
        let mut c = BTreeMap::new();
        for (n, sign) in [(num, 1), (den, -1)] {
            for (p, k) in factor(u64::try_from(n).ok()?)? {
                let e = c.entry(p).or_insert(Rat::ZERO);
                *e = e.add(&Rat::int(sign * i64::from(k)));
            }
        }
        Some(Form::log(q, c))
    }
}

/// The prime factors of n with their multiplicities, by trial division;
/// None above [`MAX_FACTORED`].
fn factor(mut n: u64) -> Option<Vec<(u64, u32)>> {
    if n > MAX_FACTORED || n == 0 {
        return None;
    }
    let mut out = Vec::new();
    let mut p = 2u64;
    while p * p <= n {
        let mut k = 0;
        while n.is_multiple_of(p) {
            n /= p;
            k += 1;
        }
        if k > 0 {
            out.push((p, k));
        }
        p += if p == 2 { 1 } else { 2 };
    }
    if n > 1 {
        out.push((n, 1));
    }
    Some(out)
}

/// True when `a` and `b`, numbers made by exp, log, sums, products,
/// quotients, integer powers and square roots over exact numbers, have
/// the same normal form (the module's doc): they are equal, proven.
pub fn proven_equal(a: &Value, b: &Value) -> bool {
    let mut memo = HashMap::new();
    match (form(a, &mut memo, 0), form(b, &mut memo, 0)) {
        (Some(Form::Atan(x)), Some(Form::Atan(y))) => x == y,
        (Some(x), Some(y)) => match (x.as_exp(), y.as_exp()) {
            (Some(p), Some(q)) => p == q,
            _ => x.as_log().is_some() && x.as_log() == y.as_log(),
        },
        _ => false,
    }
}

/// The deepest recipe read.
const MAX_DEPTH: u32 = 64;

/// The normal form of a scalar `v`: its exact form's, else its recipe's;
/// None outside the two forms.
fn form(v: &Value, memo: &mut HashMap<*const (), Option<Form>>, depth: u32) -> Option<Form> {
    let Value::Num { m, exact, .. } = v else {
        return None;
    };
    if m.shape() != (1, 1) || depth > MAX_DEPTH || !v.may_be_exact() {
        return None;
    }
    let key = exact.identity();
    if let Some(k) = key
        && let Some(found) = memo.get(&k)
    {
        return found.clone();
    }
    let out = match v.exact_form() {
        Some(e) => match e.data[0].as_const() {
            Some(Coef::Exact { re, im }) if im.is_zero() => Some(Form::exact(re)),
            _ => None,
        },
        None => exact.with_recipe(|p| of_recipe(p, memo, depth)).flatten(),
    };
    if let Some(k) = key {
        memo.insert(k, out.clone());
    }
    out
}

/// The normal form of a number made by recipe `p` (`form` of its
/// operands, then the operation).
fn of_recipe(
    p: &crate::values::exact::Pending,
    memo: &mut HashMap<*const (), Option<Form>>,
    depth: u32,
) -> Option<Form> {
    let args: Vec<&Value> = p.args.refs();
    let arg =
        |i: usize, memo: &mut HashMap<_, _>| args.get(i).and_then(|a| form(a, memo, depth + 1));
    match &p.op {
        Operation::Neg => Some(arg(0, memo)?.neg()),
        Operation::Arith(op) => {
            let (x, y) = (arg(0, memo)?, arg(1, memo)?);
            match op {
                BinOp::Add => x.add(&y),
                BinOp::Sub => x.add(&y.neg()),
                BinOp::Mul => x.mul(&y),
                BinOp::Div => x.mul(&y.recip()?),
                BinOp::Pow => x.powi(y.as_rat()?.as_int()?),
            }
        }
        Operation::Inverse => arg(0, memo)?.recip(),
        Operation::Call(name) => {
            let row = crate::builtins::lookup(name)?;
            if row.name == "atan2" && args.len() == 2 {
                let (y, x) = (arg(0, memo)?.as_surd()?, arg(1, memo)?.as_surd()?);
                if x.signum() <= 0.0 {
                    return None;
                }
                return Some(Form::Atan(y.mul(&x.inv()?)?));
            }
            let x = (args.len() == 1).then(|| arg(0, memo))??;
            match row.name {
                "exp" => x.exp(),
                "log" => x.ln(),
                "sqrt" => x.sqrt(),
                "atan" => Some(Form::Atan(x.as_surd()?)),
                "asin" | "acos" => {
                    let a = x.as_surd()?;
                    let c = Surd::rat(Rat::ONE).add(&a.mul(&a)?.neg());
                    if c.signum() <= 0.0 {
                        return None;
                    }
                    let c = c.sqrt()?;
                    if row.name == "asin" {
                        Some(Form::Atan(a.mul(&c.inv()?)?))
                    } else if a.signum() > 0.0 {
                        Some(Form::Atan(c.mul(&a.inv()?)?))
                    } else {
                        None
                    }
                }
                _ => None,
            }
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integers_factor_into_primes() {
        assert_eq!(factor(360), Some(vec![(2, 3), (3, 2), (5, 1)]));
        assert_eq!(factor(999_983), Some(vec![(999_983, 1)]));
        assert_eq!(factor(1), Some(vec![]));
        assert_eq!(factor(MAX_FACTORED + 1), None);
    }

    #[test]
    fn exp_and_log_are_inverse_on_the_forms() {
        let r = |n, d| Surd::rat(Rat::new(n, d).unwrap());
        let six = Form::exact(r(6, 1));
        let ln6 = six.ln().unwrap();
        let ln2_plus_ln3 = Form::exact(r(2, 1))
            .ln()
            .unwrap()
            .add(&Form::exact(r(3, 1)).ln().unwrap())
            .unwrap();
        assert_eq!(ln6, ln2_plus_ln3);
        assert_eq!(ln6.exp().unwrap().as_exp(), six.as_exp());
        // e^(ln 2 / 2) = √2
        let half_ln2 = Form::exact(r(2, 1))
            .ln()
            .unwrap()
            .mul(&Form::exact(r(1, 2)))
            .unwrap();
        let root2 = Surd::sqrt_of(&Rat::int(2)).unwrap();
        assert_eq!(half_ln2.exp().unwrap().as_exp(), Some((root2, Surd::ZERO)));
        // e¹·e¹ = e², and e² ≠ e³
        let e = Form::Exp {
            s: r(1, 1),
            q: r(1, 1),
        };
        let e2 = e.mul(&e).unwrap();
        assert_eq!(e2.as_exp(), Some((r(1, 1), r(2, 1))));
        assert_ne!(e2.as_exp(), e.powi(3).unwrap().as_exp());
    }
}
