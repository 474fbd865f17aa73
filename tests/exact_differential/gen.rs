//! Random exact numbers as chasles source, with the oracle's value of
//! each: integers, decimals as typed, fractions, π, degrees, square roots
//! (nested, in products), large integers and tiny decimals, powers,
//! sin/cos/tan of rational multiples of π, and floats with no exact form
//! (sin 1, √(1 + √2)) — and pairs of them equal by an identity, differing by a
//! tiny exact amount, or unrelated.

use super::hp::H;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;

/// The π content of an exact value, as far as the model follows it: none,
/// one power of π times a number, or a polynomial in π.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pi {
    Free,
    Mono,
    Poly,
}

/// A value as the oracle knows it.
#[derive(Debug, Clone)]
pub struct V {
    /// The value to 640 binary places.
    pub h: H,
    /// A bound on the rounding error of the engine's float of it.
    pub err: f64,
    /// True when the language keeps it exact (§7): integers, decimals,
    /// fractions, π, square roots of rationals, the 15° family of sin/cos/tan,
    /// and arithmetic on them (a quotient only by a number free of π or a
    /// power of π).
    pub exact: bool,
    pub pi: Pi,
    /// The value exactly, when it is rational.
    pub rat: Option<BigRational>,
    /// m when the value is exactly m·π, m rational.
    pub pim: Option<BigRational>,
}

const EPS: f64 = f64::EPSILON;

/// The oracle's ball of a value known exactly as a rational `rat` or as
/// `pim`·π: made from that (within a unit of the last place) rather than
/// by the arithmetic that led there, whose radius may be wide.
fn exactly(h: H, rat: &Option<BigRational>, pim: &Option<BigRational>) -> H {
    match (rat, pim) {
        (Some(r), _) => H::frac(r.numer(), r.denom()),
        (None, Some(m)) => H::pi()
            .mul(&H::big(m.numer()))
            .div(&H::big(m.denom()))
            .unwrap_or(h),
        _ => h,
    }
}

impl V {
    fn of_rat(r: BigRational) -> V {
        let h = H::frac(r.numer(), r.denom());
        let f = h.to_f64().abs();
        V {
            h,
            err: f * EPS,
            exact: true,
            pi: Pi::Free,
            pim: r.is_zero().then(BigRational::zero),
            rat: Some(r),
        }
    }
    fn float(h: H) -> V {
        let f = h.to_f64().abs();
        V {
            h,
            err: 2.0 * f * EPS,
            exact: false,
            pi: Pi::Poly,
            rat: None,
            pim: None,
        }
    }
    /// |value| as a float.
    pub fn size(&self) -> f64 {
        self.h.to_f64().abs()
    }
    /// True when `self` and `o` are the same real: exactly when both are
    /// rational, else as the oracle's balls tell ([`super::hp::same`]).
    pub fn same(&self, o: &V) -> bool {
        match (&self.rat, &o.rat) {
            (Some(a), Some(b)) => a == b,
            _ => super::hp::same(&self.h, &o.h),
        }
    }
}

/// A random exact (or deliberately inexact) scalar expression.
#[derive(Debug, Clone)]
pub enum E {
    Int(i64),
    /// 10^k typed as a power.
    Big(u32),
    /// 1ek typed as a decimal.
    Sci(u32),
    /// 1e-k.
    Tiny(u32),
    /// m / 10^k typed as a decimal.
    Dec(i64, u32),
    Frac(i64, i64),
    Pi,
    /// k deg.
    Deg(i64),
    /// sin (0), cos (1), tan (2) of p/q π, or of p·15 deg (`deg` true).
    Trig(u8, i64, i64, bool),
    /// sin(1), cos(2), sqrt(1 + sqrt(2)), sqrt(sqrt(7)): no exact form.
    Float(u8),
    /// sqrt(n/d).
    Root(i64, i64),
    Neg(Box<E>),
    Add(Box<E>, Box<E>),
    Sub(Box<E>, Box<E>),
    Mul(Box<E>, Box<E>),
    Div(Box<E>, Box<E>),
    Pow(Box<E>, i32),
    Sqrt(Box<E>),
    /// sin (0), cos (1), tan (2) of an expression.
    Fn(u8, Box<E>),
    /// Any text with a value (identities write their other side so).
    Text(String, Box<E>),
}

fn decimal_text(m: i64, k: u32) -> String {
    let neg = m < 0;
    let digits = format!("{:0>width$}", m.unsigned_abs(), width = k as usize + 1);
    let (int, frac) = digits.split_at(digits.len() - k as usize);
    let s = if k == 0 {
        int.to_string()
    } else {
        format!("{int}.{frac}")
    };
    if neg { format!("(-{s})") } else { s }
}

impl E {
    /// The source text.
    pub fn src(&self) -> String {
        match self {
            E::Int(n) if *n < 0 => format!("({n})"),
            E::Int(n) => n.to_string(),
            E::Big(k) => format!("(10^{k})"),
            E::Sci(k) => format!("1e{k}"),
            E::Tiny(k) => format!("1e-{k}"),
            E::Dec(m, k) => decimal_text(*m, *k),
            E::Frac(p, q) => format!("({p}/{q})"),
            E::Pi => "pi".into(),
            E::Deg(k) => format!("({k} deg)"),
            E::Trig(f, p, q, deg) => {
                let name = ["sin", "cos", "tan"][*f as usize];
                if *deg {
                    format!("{name}({} deg)", p * 180 / q)
                } else {
                    format!("{name}({p}*pi/{q})")
                }
            }
            E::Float(i) => {
                ["sin(1)", "cos(2)", "sqrt(1 + sqrt(2))", "sqrt(sqrt(7))"][*i as usize % 4].into()
            }
            E::Root(n, d) => format!("sqrt({n}/{d})"),
            E::Neg(a) => format!("(-{})", a.src()),
            E::Add(a, b) => format!("({} + {})", a.src(), b.src()),
            E::Sub(a, b) => format!("({} - {})", a.src(), b.src()),
            E::Mul(a, b) => format!("({} * {})", a.src(), b.src()),
            E::Div(a, b) => format!("({} / {})", a.src(), b.src()),
            E::Pow(a, n) if *n < 0 => format!("({}^({n}))", a.src()),
            E::Pow(a, n) => format!("({}^{n})", a.src()),
            E::Sqrt(a) => format!("sqrt({})", a.src()),
            E::Fn(f, a) => format!("{}({})", ["sin", "cos", "tan"][*f as usize % 3], a.src()),
            E::Text(t, _) => t.clone(),
        }
    }

    /// The oracle's value; None where the expression is undefined or too
    /// close to a singularity for its float to be checked.
    pub fn eval(&self) -> Option<V> {
        // (the oracle keeps 640 binary places: below 1e-120, or beyond
        // 1e120, where a quotient would lose them, a case is left out)
        let v = self.value()?;
        let size = v.size();
        // (a zero is one when it is known exactly: 1e-216 is 0 to the
        // oracle's places)
        let zero = v.h.is_zero() && v.rat.as_ref().is_some_and(Zero::is_zero);
        let within = zero || (1e-120..1e120).contains(&size);
        if !within && !v.h.resolved() {
            // (out of range by a centre the oracle is unsure of)
            super::hp::unsure();
        }
        within.then_some(v)
    }

    fn value(&self) -> Option<V> {
        let r = |p: BigInt, q: BigInt| BigRational::new(p, q);
        Some(match self {
            E::Int(n) => V::of_rat(r((*n).into(), 1.into())),
            E::Big(k) | E::Sci(k) => V::of_rat(r(BigInt::from(10).pow(*k), 1.into())),
            E::Tiny(k) => V::of_rat(r(1.into(), BigInt::from(10).pow(*k))),
            E::Dec(m, k) => V::of_rat(r((*m).into(), BigInt::from(10).pow(*k))),
            E::Frac(p, q) => V::of_rat(r((*p).into(), (*q).into())),
            E::Pi => {
                let h = H::pi();
                V {
                    err: EPS * 4.0,
                    h,
                    exact: true,
                    pi: Pi::Mono,
                    rat: None,
                    pim: Some(BigRational::one()),
                }
            }
            E::Deg(k) => {
                let h = H::pi().mul(&H::int(*k)).div(&H::int(180))?;
                V {
                    err: 4.0 * EPS * h.to_f64().abs(),
                    h,
                    exact: true,
                    pi: if *k == 0 { Pi::Free } else { Pi::Mono },
                    rat: (*k == 0).then(BigRational::zero),
                    pim: Some(BigRational::new((*k).into(), 180.into())),
                }
            }
            E::Trig(f, p, q, _) => {
                let (s, c) = H::sin_cos_pi(*p, *q);
                let arg = (std::f64::consts::PI * *p as f64 / *q as f64).abs();
                let in_family = (12 * p) % q == 0;
                let h = match f {
                    0 => s,
                    1 => c,
                    _ => {
                        if c.abs().to_f64() < 1e-6 {
                            return None;
                        }
                        s.div(&c)?
                    }
                };
                let mut v = V::float(h);
                // the argument's rounding, times the slope (≤ 1 + tan²)
                let slope = if *f == 2 {
                    1.0 + v.size() * v.size()
                } else {
                    1.0
                };
                v.err = (8.0 * EPS * (arg + 1.0)) * slope + 4.0 * EPS * v.size();
                v.exact = in_family;
                v.pi = Pi::Free;
                snap_zero(v)
            }
            E::Float(i) => {
                let h = match i % 4 {
                    0 => H::int(1).sin_cos().0,
                    1 => H::int(2).sin_cos().1,
                    2 => H::int(1).add(&H::int(2).sqrt()?).sqrt()?,
                    _ => H::int(7).sqrt()?.sqrt()?,
                };
                V::float(h)
            }
            E::Root(n, d) => sqrt(&V::of_rat(r((*n).into(), (*d).into())))?,
            E::Neg(a) => {
                let a = a.eval()?;
                V {
                    h: a.h.neg(),
                    rat: a.rat.map(|x| -x),
                    pim: a.pim.map(|x| -x),
                    ..a
                }
            }
            E::Add(a, b) => add(&a.eval()?, &b.eval()?, false),
            E::Sub(a, b) => add(&a.eval()?, &b.eval()?, true),
            E::Mul(a, b) => mul(&a.eval()?, &b.eval()?),
            E::Div(a, b) => div(&a.eval()?, &b.eval()?)?,
            E::Pow(a, n) => {
                let a = a.eval()?;
                let p = (1..n.unsigned_abs()).fold(a.clone(), |acc, _| mul(&acc, &a));
                if *n < 0 {
                    div(&V::of_rat(BigRational::one()), &p)?
                } else {
                    p
                }
            }
            E::Sqrt(a) => sqrt(&a.eval()?)?,
            E::Fn(f, a) => {
                let a = a.eval()?;
                if a.size() > 100.0 {
                    return None;
                }
                let (s, c) = a.h.sin_cos();
                let h = match f % 3 {
                    0 => s,
                    1 => c,
                    _ => {
                        if c.abs().to_f64() < 1e-6 {
                            return None;
                        }
                        s.div(&c)?
                    }
                };
                let mut v = V::float(h);
                let slope = if f % 3 == 2 {
                    1.0 + v.size() * v.size()
                } else {
                    1.0
                };
                v.err = (a.err + 4.0 * EPS * a.size()) * slope + 4.0 * EPS * v.size().max(1e-300);
                let twelfths = a
                    .pim
                    .as_ref()
                    .map(|m| m * BigRational::from_integer(12.into()));
                v.exact = a.exact
                    && (a.rat.as_ref().is_some_and(Zero::is_zero)
                        || twelfths.is_some_and(|t| t.is_integer()));
                v.pi = Pi::Free;
                snap_zero(v)
            }
            E::Text(_, a) => a.eval()?,
        })
    }
}

/// −a.
pub fn neg(a: &V) -> V {
    V {
        h: a.h.neg(),
        rat: a.rat.clone().map(|x| -x),
        pim: a.pim.clone().map(|x| -x),
        ..a.clone()
    }
}

/// An exact sin/cos/tan that is 0 within the oracle's rounding is 0
/// (cos(−5π/2)), so that a root of it is 0 too.
fn snap_zero(mut v: V) -> V {
    if v.exact && super::hp::same(&v.h, &H::int(0)) {
        v.h = H::int(0);
        v.rat = Some(BigRational::zero());
        v.pim = Some(BigRational::zero());
    }
    v
}

/// a + b (a − b when `minus`).
pub fn add(a: &V, b: &V, minus: bool) -> V {
    let h = if minus { a.h.sub(&b.h) } else { a.h.add(&b.h) };
    let size = a.size() + b.size();
    let rat = match (&a.rat, &b.rat) {
        (Some(x), Some(y)) => Some(if minus { x - y } else { x + y }),
        _ => None,
    };
    let pi = match (a.pi, b.pi) {
        (Pi::Free, Pi::Free) => Pi::Free,
        _ if rat.is_some() => Pi::Free,
        _ => Pi::Poly,
    };
    let pim = match (&a.pim, &b.pim) {
        (Some(x), Some(y)) => Some(if minus { x - y } else { x + y }),
        _ => None,
    };
    V {
        h: exactly(h, &rat, &pim),
        err: a.err + b.err + EPS * size,
        exact: a.exact && b.exact,
        pi,
        rat,
        pim,
    }
}

/// a · b.
pub fn mul(a: &V, b: &V) -> V {
    let h = a.h.mul(&b.h);
    let rat = match (&a.rat, &b.rat) {
        (Some(x), Some(y)) => Some(x * y),
        _ => None,
    };
    let pi = match (a.pi, b.pi) {
        _ if rat.is_some() => Pi::Free,
        (Pi::Free, p) | (p, Pi::Free) => p,
        (Pi::Mono, Pi::Mono) => Pi::Mono,
        _ => Pi::Poly,
    };
    let (x, y) = (a.size(), b.size());
    let pim = match (&a.pim, &b.pim, &a.rat, &b.rat) {
        (Some(m), _, _, Some(r)) | (_, Some(m), Some(r), _) => Some(m * r),
        _ => None,
    };
    V {
        h: exactly(h, &rat, &pim),
        pim,
        err: a.err * y + b.err * x + a.err * b.err + EPS * x * y,
        exact: a.exact && b.exact,
        pi,
        rat,
    }
}

fn div(a: &V, b: &V) -> Option<V> {
    let y = b.size();
    // too close to 0 to say anything about the float
    if b.h.is_zero() || y <= 8.0 * b.err || y < 1e-200 {
        return None;
    }
    let Some(h) = a.h.div(&b.h) else {
        // (a divisor away from 0 whose ball still holds 0)
        super::hp::unsure();
        return None;
    };
    let rat = match (&a.rat, &b.rat) {
        (Some(x), Some(y)) => Some(x / y),
        _ => None,
    };
    let pi = match (a.pi, b.pi) {
        _ if rat.is_some() => Pi::Free,
        (p, Pi::Free) => p,
        (Pi::Free | Pi::Mono, Pi::Mono) => Pi::Mono,
        _ => Pi::Poly,
    };
    let q = h.to_f64().abs();
    let pim = match (&a.pim, &b.rat) {
        (Some(m), Some(r)) if !r.is_zero() => Some(m / r),
        _ => None,
    };
    Some(V {
        h: exactly(h, &rat, &pim),
        pim,
        err: (a.err + q * b.err) / (y - b.err) + EPS * q,
        exact: a.exact && b.exact && b.pi != Pi::Poly,
        pi,
        rat,
    })
}

/// √a; exact when a is a rational (LANGUAGE.md §7: the square root of
/// any exact rational is exact; the engine finds the square-free part of
/// numerators and denominators below 2⁶⁰ always).
fn sqrt(a: &V) -> Option<V> {
    if a.h.holds_zero() && !a.h.is_zero() {
        // (0 or near it, not known to be 0: out of the oracle's range
        // when it is 0 to its places, else ask at more places)
        if super::hp::cmp(&a.h, &H::int(0)) == super::hp::Cmp::Unknown {
            super::hp::unsure();
        }
        return None;
    }
    let h = a.h.sqrt()?;
    let s = h.to_f64();
    let err = if s > 0.0 {
        (a.err / (2.0 * s)).min(a.err.sqrt()) + EPS * s
    } else {
        a.err.sqrt()
    };
    let in_field = a.exact
        && a.rat
            .as_ref()
            .is_some_and(|r| r.numer().bits() < 60 && r.denom().bits() < 60);
    let rat = a.rat.as_ref().and_then(|r| {
        let (p, q) = (r.numer().sqrt(), r.denom().sqrt());
        (&p * &p == *r.numer() && &q * &q == *r.denom() && !r.is_negative())
            .then(|| BigRational::new(p, q))
    });
    let pim = rat.as_ref().filter(|r| r.is_zero()).cloned();
    Some(V {
        h: exactly(h, &rat, &pim),
        pim,
        err,
        exact: in_field,
        pi: Pi::Free,
        rat,
    })
}

/// A leaf: mostly exact numbers of every kind, some floats.
pub fn leaf() -> impl Strategy<Value = E> {
    prop_oneof![
        4 => (-12i64..=12).prop_map(E::Int),
        1 => (13u32..=30).prop_map(E::Big),
        1 => (10u32..=22).prop_map(E::Sci),
        2 => (10u32..=20).prop_map(E::Tiny),
        3 => (-9999i64..=9999, 1u32..=5).prop_map(|(m, k)| E::Dec(m, k)),
        3 => (-24i64..=24, 1i64..=12).prop_map(|(p, q)| E::Frac(p, q)),
        2 => Just(E::Pi),
        2 => (-360i64..=360).prop_map(E::Deg),
        4 => (0u8..3, -24i64..=24, 1i64..=12, any::<bool>())
            .prop_map(|(f, p, q, d)| E::Trig(f, p, q, d && (p * 180) % q == 0)),
        1 => (0u8..4).prop_map(E::Float),
        4 => (1i64..=50, 1i64..=12, 0usize..4)
            .prop_map(|(s, d, k)| E::Root(s * s * [1, 2, 3, 6][k], d)),
        1 => (1i64..=60, 1i64..=12).prop_map(|(n, d)| E::Root(n, d)),
    ]
}

/// A random expression over the leaves.
pub fn expr() -> BoxedStrategy<E> {
    leaf().prop_recursive(3, 12, 2, |inner| {
        prop_oneof![
            1 => inner.clone().prop_map(|a| E::Neg(Box::new(a))),
            3 => (inner.clone(), inner.clone()).prop_map(|(a, b)| E::Add(Box::new(a), Box::new(b))),
            2 => (inner.clone(), inner.clone()).prop_map(|(a, b)| E::Sub(Box::new(a), Box::new(b))),
            3 => (inner.clone(), inner.clone()).prop_map(|(a, b)| E::Mul(Box::new(a), Box::new(b))),
            2 => (inner.clone(), inner.clone()).prop_map(|(a, b)| E::Div(Box::new(a), Box::new(b))),
            2 => (inner.clone(), prop_oneof![2 => 2i32..=4, 1 => -2i32..=-1])
                .prop_map(|(a, n)| E::Pow(Box::new(a), n)),
            1 => inner.prop_map(|a| E::Sqrt(Box::new(a))),
        ]
    })
    .boxed()
}

fn b(e: E) -> Box<E> {
    Box::new(e)
}

/// cos(k·15°) as roots, k in 0..24.
fn cos15(k: i64) -> &'static str {
    let k = k.rem_euclid(24);
    let k = if k > 12 { 24 - k } else { k };
    [
        "1",
        "((sqrt(6) + sqrt(2))/4)",
        "(sqrt(3)/2)",
        "(sqrt(2)/2)",
        "(1/2)",
        "((sqrt(6) - sqrt(2))/4)",
        "0",
        "(-(sqrt(6) - sqrt(2))/4)",
        "(-1/2)",
        "(-sqrt(2)/2)",
        "(-sqrt(3)/2)",
        "(-(sqrt(6) + sqrt(2))/4)",
        "(-1)",
    ][k as usize]
}

/// An angle: exact (p/q π, k deg) or a float (a decimal in radians).
pub fn angle() -> impl Strategy<Value = E> {
    prop_oneof![
        3 => (-24i64..=24, 1i64..=12).prop_map(|(p, q)| E::Mul(b(E::Frac(p, q)), b(E::Pi))),
        1 => (-360i64..=360).prop_map(E::Deg),
        1 => (-999i64..=999).prop_map(|m| E::Dec(m, 3)),
    ]
}

/// sin or cos of an angle expression.
fn trig_of(f: &str, a: &E) -> E {
    E::Fn(u8::from(f == "cos"), b(a.clone()))
}

/// Pairs of numbers: equal by an identity, differing by a tiny exact
/// amount, or unrelated (the oracle says which).
pub fn pair() -> impl Strategy<Value = (E, E)> {
    let e = expr();
    prop_oneof![
        // rearranged: a + b = b + a, (a − b) + b = a, a(b + c) = ab + ac,
        // (a/b)·b = a, (a + b)² = a² + 2ab + b²
        3 => (e.clone(), e.clone(), e.clone(), 0u8..5).prop_map(|(x, y, z, k)| match k {
            0 => (E::Add(b(x.clone()), b(y.clone())), E::Add(b(y), b(x))),
            1 => (E::Add(b(E::Sub(b(x.clone()), b(y.clone()))), b(y)), x),
            2 => (
                E::Mul(b(x.clone()), b(E::Add(b(y.clone()), b(z.clone())))),
                E::Add(b(E::Mul(b(x.clone()), b(y))), b(E::Mul(b(x), b(z)))),
            ),
            3 => (E::Mul(b(E::Div(b(x.clone()), b(y.clone()))), b(y)), x),
            _ => (
                E::Pow(b(E::Add(b(x.clone()), b(y.clone()))), 2),
                E::Add(
                    b(E::Add(b(E::Pow(b(x.clone()), 2)), b(E::Mul(b(E::Int(2)), b(E::Mul(b(x), b(y.clone()))))))),
                    b(E::Pow(b(y), 2)),
                ),
            ),
        }),
        // roots: √(s²k/d²) = (s/d)√k, √a √b = √(ab), 1/√k = √k/k
        2 => (1i64..=40, 1i64..=12, 0usize..4, 1i64..=30, 1i64..=30, 0u8..3).prop_map(
            |(s, d, k, m, n, which)| {
                let k = [1, 2, 3, 6][k];
                match which {
                    0 => (
                        E::Root(s * s * k, d * d),
                        E::Mul(b(E::Frac(s, d)), b(E::Root(k, 1))),
                    ),
                    1 => (
                        E::Mul(b(E::Root(m, 1)), b(E::Root(n, 1))),
                        E::Root(m * n, 1),
                    ),
                    _ => (
                        E::Div(b(E::Int(1)), b(E::Root(k * s * s, 1))),
                        E::Div(b(E::Root(k * s * s, 1)), b(E::Int(k * s * s))),
                    ),
                }
            }
        ),
        // the 15° table: sin/cos/tan(m π/12) as roots
        2 => (-30i64..=30, 0u8..3, any::<bool>()).prop_map(|(m, f, deg)| {
            let c = cos15(m);
            let s = cos15(m - 6);
            let text = match f {
                0 => s.to_string(),
                1 => c.to_string(),
                _ => format!("({s}/{c})"),
            };
            let lhs = E::Trig(f, m, 12, deg);
            if f == 2 && m.rem_euclid(12) == 6 {
                return (E::Trig(0, m, 12, deg), E::Text(s.into(), b(E::Trig(0, m, 12, false))));
            }
            (lhs.clone(), E::Text(text, b(lhs)))
        }),
        // trigonometric identities at exact and float angles
        2 => (angle(), angle(), 0u8..4).prop_map(|(a, c, k)| {
            let (sa, ca) = (trig_of("sin", &a), trig_of("cos", &a));
            match k {
                0 => (
                    E::Add(b(E::Pow(b(sa), 2)), b(E::Pow(b(ca), 2))),
                    E::Int(1),
                ),
                1 => {
                    let (sc, cc) = (trig_of("sin", &c), trig_of("cos", &c));
                    (
                        trig_of("cos", &E::Add(b(a), b(c))),
                        E::Sub(b(E::Mul(b(ca), b(cc))), b(E::Mul(b(sa), b(sc)))),
                    )
                }
                2 => (
                    trig_of("sin", &E::Mul(b(E::Int(2)), b(a))),
                    E::Mul(b(E::Int(2)), b(E::Mul(b(sa), b(ca)))),
                ),
                _ => (E::Fn(2, b(a)), E::Div(b(sa), b(ca))),
            }
        }),
        // decimals as typed, degrees, powers of ten
        2 => (-99999i64..=99999, 1u32..=6, -720i64..=720, 10u32..=22, 0u8..4).prop_map(
            |(m, k, d, p, which)| match which {
                0 => (E::Dec(m, k), E::Frac(m, 10i64.pow(k))),
                1 => (E::Deg(d), E::Mul(b(E::Frac(d, 180)), b(E::Pi))),
                2 => (E::Tiny(p), E::Pow(b(E::Int(10)), -(p as i32))),
                _ => (E::Sci(p), E::Big(p)),
            }
        ),
        // a tiny exact difference: x + δ against x, 10^k + 1 against 10^k
        3 => (e.clone(), 0u8..5, 13u32..=30).prop_map(|(x, k, p)| {
            let d = match k {
                0 => E::Tiny(13),
                1 => E::Tiny(20),
                2 => E::Pow(b(E::Int(10)), -(p as i32)),
                3 => E::Mul(b(x.clone()), b(E::Tiny(15))),
                _ => return (E::Add(b(E::Big(p)), b(E::Int(1))), E::Big(p)),
            };
            (E::Add(b(x.clone()), b(d)), x)
        }),
        // unrelated, and a number against itself
        2 => (e.clone(), e.clone()).prop_map(|(x, y)| (x, y)),
        1 => e.prop_map(|x| (x.clone(), x)),
    ]
}
