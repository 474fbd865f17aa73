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

use crate::sym::Expr;
use crate::sym::coef::{Coef, Rat, Surd};
use crate::sym::expr::Var;
use crate::syntax::ast::BinOp;
use crate::values::exact::Operation;
use crate::values::value::Value;
use num_traits::Zero;

/// A number in one of the two normal forms (the module's doc). The
/// exponent q and the constant a are exact real constants of the canonical
/// form: square roots and powers of π (so e^π and ln 2 + π have forms too;
/// equal forms are then still equal numbers, though a difference proves
/// nothing there).
#[derive(Debug, Clone, PartialEq)]
enum Form {
    /// s·e^q, s ≠ 0 algebraic.
    Exp { s: Surd, q: Expr },
    /// a + Σ c_p ln p, every c_p ≠ 0.
    Log { a: Expr, c: BTreeMap<u64, Rat> },
    /// a + Σ cᵢ atan αᵢ: a an exact real constant (π and algebraic
    /// numbers), cᵢ ≠ 0 rational, the αᵢ distinct exact reals in (0, 1) —
    /// [`Form::atan`] puts any atan α so (atan(−α) = −atan α, atan α =
    /// π/2 − atan(1/α) for α > 1, atan 1 = π/4); atan2(y, x) with x > 0 is
    /// atan(y/x), asin α is atan(α/√(1 − α²)), acos α = π/2 − asin α. Equal
    /// forms are the same sum of the same terms, so equal numbers; unequal
    /// forms prove nothing (atan ½ + atan ⅓ = π/4).
    Arc { a: Expr, c: Vec<(Surd, Rat)> },
}

mod arcs;

/// The last divisor tried when factoring into primes: what is left above
/// it, if below its square, is prime.
const MAX_DIVISOR: u64 = 1_000_000;

/// The largest integer power taken of a form.
const MAX_POWER: i64 = 1024;

/// An exact real number as a constant expression.
fn constant(s: Surd) -> Expr {
    if s.is_zero() {
        Expr::zero()
    } else {
        Expr::constant(Coef::real(s))
    }
}

/// The algebraic number a constant expression is (None with π in it).
fn algebraic(e: &Expr) -> Option<Surd> {
    if e.terms.is_empty() {
        return Some(Surd::ZERO);
    }
    match e.as_const()? {
        Coef::Exact { re, im } if im.is_zero() => Some(re),
        _ => None,
    }
}

impl Form {
    /// An exact real algebraic number.
    fn exact(x: Surd) -> Form {
        if x.is_zero() {
            Form::Log {
                a: Expr::zero(),
                c: BTreeMap::new(),
            }
        } else {
            Form::Exp {
                s: x,
                q: Expr::zero(),
            }
        }
    }

    /// An exact real constant (with π: a + Σ c_p ln p with no logarithm).
    fn leaf(e: Expr) -> Form {
        match algebraic(&e) {
            Some(s) => Form::exact(s),
            None => Form::Log {
                a: e,
                c: BTreeMap::new(),
            },
        }
    }

    /// The form as s·e^q, when it is one (an algebraic number is, with
    /// q = 0).
    fn as_exp(&self) -> Option<(Surd, Expr)> {
        match self {
            Form::Exp { s, q } => Some((s.clone(), q.clone())),
            Form::Log { a, c } if c.is_empty() => {
                let s = algebraic(a)?;
                (!s.is_zero()).then(|| (s, Expr::zero()))
            }
            _ => None,
        }
    }

    /// The form as a + Σ c_p ln p, when it is one (an algebraic number is).
    fn as_log(&self) -> Option<(Expr, BTreeMap<u64, Rat>)> {
        match self {
            Form::Log { a, c } => Some((a.clone(), c.clone())),
            Form::Exp { s, q } if q.is_zero() => Some((constant(s.clone()), BTreeMap::new())),
            _ => None,
        }
    }

    /// The exact real algebraic number the form is, if it is one.
    fn as_surd(&self) -> Option<Surd> {
        match self {
            Form::Exp { s, q } if q.is_zero() => Some(s.clone()),
            Form::Log { a, c } if c.is_empty() => algebraic(a),
            _ => None,
        }
    }

    /// The exact rational the form is, if it is one.
    fn as_rat(&self) -> Option<Rat> {
        self.as_surd()?.as_rat()
    }

    /// The form of a sum a + Σ c_p ln p.
    fn log(a: Expr, mut c: BTreeMap<u64, Rat>) -> Form {
        c.retain(|_, r| !r.is_zero());
        if c.is_empty() {
            return Form::leaf(a);
        }
        Form::Log { a, c }
    }

    fn neg(&self) -> Form {
        match self {
            Form::Arc { a, c } => Form::arc(
                a.neg(),
                c.iter().map(|(x, r)| (x.clone(), r.neg())).collect(),
            ),
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
        if matches!(self, Form::Arc { .. }) || matches!(o, Form::Arc { .. }) {
            let ((a, mut c), (b, d)) = (self.as_arc()?, o.as_arc()?);
            c.extend(d);
            return Some(Form::arc(a.add(&b), c));
        }
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
        // (a sum of arcs times a rational)
        for (x, k) in [(self, o), (o, self)] {
            if let (Form::Arc { a, c }, Some(k)) = (x, k.as_rat()) {
                let terms = c.iter().map(|(x, r)| (x.clone(), r.mul(&k))).collect();
                return Some(Form::arc(a.scale(&Coef::rat(k)), terms));
            }
        }
        if let (Some((s, q)), Some((t, r))) = (self.as_exp(), o.as_exp()) {
            return Some(Form::Exp {
                s: s.mul(&t)?,
                q: q.add(&r),
            });
        }
        // (a logarithm times a rational; a constant times an algebraic)
        let by = |k: &Form, x: &Form| -> Option<Form> {
            let (a, c) = x.as_log()?;
            if let Some(k) = k.as_rat() {
                return Some(Form::log(
                    a.scale(&Coef::rat(k.clone())),
                    c.into_iter().map(|(p, r)| (p, r.mul(&k))).collect(),
                ));
            }
            let k = k.as_surd()?;
            c.is_empty().then(|| Form::leaf(a.scale(&Coef::real(k))))
        };
        by(self, o).or_else(|| by(o, self))
    }

    /// x / y: x·(1/y), or the rational k when x and y are logarithms with
    /// x = k·y (`log(4)/log(2)` is 2).
    fn div(&self, o: &Form) -> Option<Form> {
        if let (Some((a, c)), Some((b, d))) = (self.as_log(), o.as_log())
            && let Some((p, r)) = d.iter().next()
        {
            let k = c.get(p)?.mul(&r.inv()?);
            let scaled: BTreeMap<u64, Rat> = d.iter().map(|(p, r)| (*p, r.mul(&k))).collect();
            if c == scaled && a == b.scale(&Coef::rat(k.clone())) {
                return Some(Form::exact(Surd::rat(k)));
            }
        }
        self.mul(&o.recip()?)
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
            q: q.scale(&Coef::int(k.abs())),
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
            q: q.scale(&Coef::rat(Rat::new(1, 2)?)),
        })
    }

    /// e^x of a + Σ c_p ln p: Π p^c_p · e^a, each c_p an integer or a half.
    fn exp(&self) -> Option<Form> {
        let (a, c) = self.as_log()?;
        let mut s = Surd::rat(Rat::ONE);
        for (p, r) in c {
            let twice = r.mul(&Rat::int(2)).as_int()?;
            let p = Rat::int(i64::try_from(p).ok()?);
            let whole = Form::exact(Surd::rat(p.clone()))
                .powi(twice.div_euclid(2))?
                .as_surd()?;
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
        let (num, den) = r.parts();
        let mut c = BTreeMap::new();
        for (n, sign) in [(num, 1), (den, -1)] {
            for (p, k) in factor(&n)? {
                let e = c.entry(p).or_insert(Rat::ZERO);
                *e = e.add(&Rat::int(sign * i64::from(k)));
            }
        }
        Some(Form::log(q, c))
    }
}

/// The prime factors of n > 0 with their multiplicities, by trial
/// division up to [`MAX_DIVISOR`]; None when what is left may not be prime
/// (or n has more than 4096 bits).
fn factor(n: &num_bigint::BigInt) -> Option<Vec<(u64, u32)>> {
    use num_traits::{One, ToPrimitive};
    if n.sign() != num_bigint::Sign::Plus || n.bits() > 4096 {
        return None;
    }
    let mut n = n.clone();
    let mut out = Vec::new();
    let mut p = 2u64;
    while p <= MAX_DIVISOR && num_bigint::BigInt::from(p) * p <= n {
        let mut k = 0;
        loop {
            let (q, r) = num_integer::Integer::div_rem(&n, &num_bigint::BigInt::from(p));
            if !r.is_zero() {
                break;
            }
            n = q;
            k += 1;
        }
        if k > 0 {
            out.push((p, k));
        }
        p += if p == 2 { 1 } else { 2 };
    }
    if !n.is_one() {
        // (no divisor up to p left it: prime when below p²)
        if num_bigint::BigInt::from(p) * p <= n {
            return None;
        }
        out.push((n.to_u64()?, 1));
    }
    Some(out)
}

/// True when `a` and `b`, numbers made by exp, log, sums, products,
/// quotients, integer powers and square roots over exact numbers, have
/// the same normal form (the module's doc): they are equal, proven.
pub fn proven_equal(a: &Value, b: &Value) -> bool {
    let mut memo = HashMap::new();
    match (form(a, &mut memo, 0), form(b, &mut memo, 0)) {
        (Some(x @ Form::Arc { .. }), Some(y)) | (Some(y), Some(x @ Form::Arc { .. })) => {
            x.as_arc() == y.as_arc()
        }
        (Some(x), Some(y)) => match (x.as_exp(), y.as_exp()) {
            (Some(p), Some(q)) => p == q,
            _ => x.as_log().is_some() && x.as_log() == y.as_log(),
        },
        _ => false,
    }
}

/// True for an exact real constant: exact real coefficients times powers
/// of π.
fn exact_constant(e: &Expr) -> bool {
    e.terms.iter().all(|(m, c)| {
        matches!(c, Coef::Exact { im, .. } if im.is_zero())
            && m.iter().all(|(v, _)| matches!(v, Var::Pi))
    })
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
        Some(e) => exact_constant(&e.data[0]).then(|| Form::leaf(e.data[0].clone())),
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
    let owned = p.args.refs();
    let args: Vec<&Value> = crate::values::exact::deref(&owned);
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
                BinOp::Div => x.div(&y),
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
                return Form::atan(y.mul(&x.inv()?)?);
            }
            let x = (args.len() == 1).then(|| arg(0, memo))??;
            match row.name {
                "exp" => x.exp(),
                "log" => x.ln(),
                "sqrt" => x.sqrt(),
                "atan" => Form::atan(x.as_surd()?),
                "asin" | "acos" => {
                    // asin α = atan(α/√(1 − α²)), ±π/2 at α = ±1
                    let a = x.as_surd()?;
                    let c = Surd::rat(Rat::ONE).add(&a.mul(&a)?.neg());
                    let asin = match c.signum() {
                        0.0 => Form::leaf(Expr::pi().scale(&Coef::rat(Rat::new(
                            if a.signum() > 0.0 { 1 } else { -1 },
                            2,
                        )?))),
                        s if s > 0.0 => Form::atan(a.mul(&c.sqrt()?.inv()?)?)?,
                        _ => return None,
                    };
                    if row.name == "asin" {
                        Some(asin)
                    } else {
                        // acos α = π/2 − asin α
                        let half_pi = Form::leaf(Expr::pi().scale(&Coef::rat(Rat::new(1, 2)?)));
                        half_pi.add(&asin.neg())
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
        let f = |n: u64| factor(&n.into());
        assert_eq!(f(360), Some(vec![(2, 3), (3, 2), (5, 1)]));
        assert_eq!(f(999_983), Some(vec![(999_983, 1)]));
        assert_eq!(f(1), Some(vec![]));
        // (a prime above 10¹² may be a product of two above 10⁶)
        assert_eq!(f(1_000_003 * 1_000_033), None);
        assert_eq!(f(1 << 60), Some(vec![(2, 60)]));
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
        assert_eq!(
            half_ln2.exp().unwrap().as_exp(),
            Some((root2, Expr::zero()))
        );
        // e¹·e¹ = e², and e² ≠ e³
        let e = Form::Exp {
            s: r(1, 1),
            q: constant(r(1, 1)),
        };
        let e2 = e.mul(&e).unwrap();
        assert_eq!(e2.as_exp(), Some((r(1, 1), constant(r(2, 1)))));
        assert_ne!(e2.as_exp(), e.powi(3).unwrap().as_exp());
    }
}
