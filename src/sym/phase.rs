//! Constant angle offsets in the canonical form (LANGUAGE.md §7: "sums of
//! angles folded … so that equal trigonometric polynomials print alike").
//! An offset φ that is not a multiple of π/12 (π/5, π/7, a decimal 0.3)
//! has a cosine outside the exact coefficients, so e^{iφ} enters as a
//! *phase variable*, an angle whose value is known: e^{i(t + π/5)} is
//! z_t·u^k with u = e^{iπ/27720} (27720 = lcm(1, …, 12)) and k = 5544, and
//! e^{i(t + 0.3)} is z_t·v^300000 with v = e^{i/10⁶}. Offsets then add as
//! angles do, and cos(t1 + 0.3) cos t2 − sin(t1 + 0.3) sin t2 prints
//! cos(t1 + t2 + 0.3).
//!
//! The form stays canonical: a π-phase keeps only its part within
//! (−π/6, π/6) that is no multiple of π/12 (the rest, e^{iπ m/12}, is an
//! exact coefficient, [`Coef::unit_root`]); radians are no rational
//! multiple of π, and e^{ir} is transcendental for a rational r ≠ 0
//! (Lindemann), so distinct decimal phases are independent of each other
//! and of the exact coefficients. A phase with no angle left beside it is
//! a number (cos(π/5) is 0.809…, as typed).

use super::coef::{Coef, Rat};
use super::expr::{Expr, Mono, Symbol, Var, mono_mul};

/// π-phases are multiples of π/PI_DEN (lcm of 1..=12: π/5, π/7, π/8, …).
pub const PI_DEN: i64 = 27720;
/// Radian phases are multiples of 1/RAD_DEN (decimals of up to six digits).
pub const RAD_DEN: i64 = 1_000_000;
/// π/12 in units of π/PI_DEN: multiples of it are exact coefficients.
const TWELFTH: i64 = PI_DEN / 12;
/// π/24 in units: the π-phase of a canonical form lies in (−π/24, π/24].
pub const PI_EDGE: i32 = (TWELFTH / 2) as i32;
/// The largest radian exponent kept (beyond, the phase is a float factor:
/// the exponents of a product of two never overflow).
const RAD_LIMIT: i64 = 1 << 28;
/// The first character of a phase's name: no name a user can declare.
const MARK: char = '\u{10FFFD}';

/// Which phase variable a symbol is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unit {
    /// u = e^{iπ/PI_DEN}.
    Pi,
    /// v = e^{i/RAD_DEN}.
    Rad,
}

impl Unit {
    /// The angle of one unit, in radians.
    pub fn radians(self) -> f64 {
        match self {
            Unit::Pi => std::f64::consts::PI / PI_DEN as f64,
            Unit::Rad => 1.0 / RAD_DEN as f64,
        }
    }
    /// The phase variable's symbol (sorted after every declared angle, the
    /// π-phase before the radian one: `t + π/5 + 0.3`).
    pub fn symbol(self) -> Symbol {
        Symbol::new(&match self {
            Unit::Pi => format!("{MARK}1pi"),
            Unit::Rad => format!("{MARK}2rad"),
        })
    }
}

impl Symbol {
    /// The phase variable this symbol is, if it is one.
    pub fn phase(&self) -> Option<Unit> {
        let rest = self.name.strip_prefix(MARK)?;
        Some(if rest.ends_with("pi") {
            Unit::Pi
        } else {
            Unit::Rad
        })
    }
    /// True for a phase variable (a constant, not a declared angle).
    pub fn is_phase(&self) -> bool {
        self.name.starts_with(MARK)
    }
}

/// The phase monomial of the offset π·pi + rad, with the exact part of the
/// π-offset as a coefficient; None when an offset does not fit a unit (π/13,
/// 1/3 rad: the caller keeps a call).
pub fn offset(pi: &Rat, rad: &Rat) -> Option<(Mono, Coef)> {
    let mut m: Mono = Vec::new();
    let mut c = Coef::one();
    if !pi.is_zero() {
        let k = pi.mul(&Rat::int(PI_DEN)).as_int()?;
        let (r, exact) = reduce_pi(k.rem_euclid(2 * PI_DEN));
        c = Coef::unit_root(exact)?;
        if r != 0 {
            m.push((Var::Z(Unit::Pi.symbol()), i32::try_from(r).ok()?));
        }
    }
    if !rad.is_zero() {
        let k = rad.mul(&Rat::int(RAD_DEN)).as_int()?;
        if k.abs() > RAD_LIMIT / 4 {
            return None;
        }
        m = mono_mul(
            &m,
            &vec![(Var::Z(Unit::Rad.symbol()), i32::try_from(k).ok()?)],
        );
    }
    Some((m, c))
}

/// k units of π/PI_DEN as r units in (−π/24, π/24] and an exact multiple
/// of π/12, as a fraction of π: one form for each value (u^TWELFTH is the
/// exact e^{iπ/12}, so r is taken modulo it).
fn reduce_pi(k: i64) -> (i64, Rat) {
    let mut r = k.rem_euclid(TWELFTH);
    if 2 * r > TWELFTH {
        r -= TWELFTH;
    }
    let exact = Rat::new(i128::from(k - r), i128::from(PI_DEN)).unwrap_or(Rat::ZERO);
    (r, exact)
}

/// e^{ikx} for k units as a float pair.
fn float_phase(unit: Unit, k: i32) -> Coef {
    let a = unit.radians() * f64::from(k);
    Coef::Approx {
        re: a.cos(),
        im: a.sin(),
    }
}

impl Expr {
    /// True when a monomial holds a phase variable.
    pub fn has_phase(&self) -> bool {
        self.terms
            .keys()
            .flatten()
            .any(|(v, _)| matches!(v, Var::Z(s) if s.is_phase()))
    }

    /// The canonical form of phases (after a product, a conjugate or a
    /// substitution): a π-phase reduced to (−π/24, π/24] with the rest an
    /// exact coefficient; a radian phase past its limit, or any phase
    /// with no declared angle beside it, a float factor.
    pub(super) fn fold_phases(self) -> Expr {
        if !self.has_phase() {
            return self;
        }
        let mut out = Expr::default();
        for (m, mut c) in self.terms {
            let angle = m
                .iter()
                .any(|(v, _)| matches!(v, Var::Z(s) if !s.is_phase()));
            let mut rest: Mono = Vec::with_capacity(m.len());
            for (v, k) in m {
                let unit = match &v {
                    Var::Z(s) => s.phase(),
                    _ => None,
                };
                match unit {
                    None => rest.push((v, k)),
                    Some(Unit::Pi) => {
                        let (r, exact) = reduce_pi(i64::from(k).rem_euclid(2 * PI_DEN));
                        if let Some(e) = Coef::unit_root(exact) {
                            c = c.mul(&e);
                        }
                        // |r| ≤ TWELFTH/2, so it fits
                        let r = r as i32;
                        if r != 0 && angle {
                            rest.push((v, r));
                        } else if r != 0 {
                            c = c.mul(&float_phase(Unit::Pi, r));
                        }
                    }
                    Some(Unit::Rad) => {
                        if angle && i64::from(k).abs() <= RAD_LIMIT {
                            rest.push((v, k));
                        } else {
                            c = c.mul(&float_phase(Unit::Rad, k));
                        }
                    }
                }
            }
            out.push(rest, c);
        }
        out
    }

    /// An angle of a real form as an expression: a declared angle as its
    /// symbol, a phase variable as its value (π/5, 0.3).
    pub fn angle(s: &Symbol) -> Expr {
        match s.phase() {
            None => Expr::symbol(s.clone()),
            Some(Unit::Pi) => Expr::pi().scale(&Coef::rat(
                Rat::new(1, i128::from(PI_DEN)).unwrap_or(Rat::ZERO),
            )),
            Some(Unit::Rad) => Expr::constant(Coef::rat(
                Rat::new(1, i128::from(RAD_DEN)).unwrap_or(Rat::ZERO),
            )),
        }
    }
}

/// `k` units of a phase as printed: `π/5`, `2π/5`, `π`, `0.3` (LaTeX
/// `\frac{2\pi}{5}`); `k` is positive.
pub fn text(unit: Unit, k: i64, latex: bool) -> String {
    match unit {
        Unit::Pi => {
            let g = gcd(k.abs(), PI_DEN);
            let (p, q) = (k / g, PI_DEN / g);
            let pi = if latex { "\\pi" } else { "π" };
            let top = if p == 1 {
                pi.to_string()
            } else {
                format!("{p}{pi}")
            };
            match (q, latex) {
                (1, _) => top,
                (q, true) => format!("\\frac{{{top}}}{{{q}}}"),
                (q, false) => format!("{top}/{q}"),
            }
        }
        Unit::Rad => {
            let (whole, frac) = (k / RAD_DEN, k % RAD_DEN);
            if frac == 0 {
                return whole.to_string();
            }
            let digits = format!("{frac:06}");
            format!("{whole}.{}", digits.trim_end_matches('0'))
        }
    }
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 { a } else { gcd(b, a % b) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::print::{Style, expr};
    use num_traits::One;

    fn s(n: &str) -> Expr {
        Expr::symbol(Symbol::new(n))
    }
    fn pi(p: i128, q: i128) -> Expr {
        Expr::pi().scale(&Coef::rat(Rat::new(p, q).unwrap()))
    }
    fn show(e: &Expr) -> String {
        expr(e, Style::default())
    }

    #[test]
    fn offsets_fold_as_angles() {
        let (t, t1, t2) = (s("t"), s("t1"), s("t2"));
        assert_eq!(show(&Expr::cos(&t.add(&pi(1, 5)))), "cos(t + π/5)");
        assert_eq!(show(&Expr::sin(&t.sub(&pi(1, 8)))), "sin(t - π/8)");
        let a = t1.add(&Expr::typed(0.3));
        let sum = Expr::cos(&a)
            .mul(&Expr::cos(&t2))
            .sub(&Expr::sin(&a).mul(&Expr::sin(&t2)));
        assert_eq!(sum, Expr::cos(&t1.add(&t2).add(&Expr::typed(0.3))));
        assert_eq!(show(&sum), "cos(t1 + t2 + 0.3)");
        let b = t.add(&pi(2, 7));
        let one = Expr::cos(&b)
            .powi(2)
            .unwrap()
            .add(&Expr::sin(&b).powi(2).unwrap());
        assert_eq!(one, Expr::one());
        // π/5 + 0.3 and 2.5 rad print as typed
        let c = t.add(&pi(1, 5)).add(&Expr::typed(0.3));
        assert_eq!(show(&Expr::sin(&c)), "sin(t + π/5 + 0.3)");
        assert_eq!(show(&Expr::cos(&t.add(&Expr::typed(2.5)))), "cos(t + 2.5)");
    }

    #[test]
    fn a_phase_alone_is_a_number() {
        let t = s("t");
        let a = t.add(&pi(1, 5));
        // cos(t + π/5) cos t + sin(t + π/5) sin t = cos(π/5)
        let e = Expr::cos(&a)
            .mul(&Expr::cos(&t))
            .add(&Expr::sin(&a).mul(&Expr::sin(&t)));
        let x = e.as_f64().expect("a number");
        assert!(
            (x - (std::f64::consts::PI / 5.0).cos()).abs() < 1e-15,
            "{x}"
        );
        assert!(Expr::cos(&pi(1, 5)).as_f64().is_some());
        let mut syms = Vec::new();
        Expr::cos(&a).symbols(&mut syms);
        assert_eq!(syms, vec![Symbol::new("t")]);
    }

    #[test]
    fn phases_evaluate_and_differentiate() {
        let t = s("t");
        let a = t
            .scale(&Coef::int(2))
            .add(&pi(3, 7))
            .add(&Expr::typed(-0.25));
        let e = Expr::sin(&a).mul(&Expr::cos(&t.add(&pi(1, 9))));
        let at = |x: f64| move |_: &Symbol| Some(x);
        for x in [-2.0, 0.1, 1.3] {
            let want = (2.0 * x + 3.0 * std::f64::consts::PI / 7.0 - 0.25).sin()
                * (x + std::f64::consts::PI / 9.0).cos();
            let got = e.eval(&at(x)).unwrap();
            assert!((got - want).abs() < 1e-13, "{got} vs {want}");
        }
        let d = Expr::cos(&t.add(&Expr::typed(0.3))).diff(&crate::sym::Wrt::Time(Symbol::new("t")));
        assert_eq!(d, Expr::sin(&t.add(&Expr::typed(0.3))).neg());
    }

    #[test]
    fn offsets_that_do_not_fit_stay_calls() {
        let t = s("t");
        // π/13 and 1/3 rad have no unit here: kept as the call cos(…)
        for off in [
            pi(1, 13),
            Expr::constant(Coef::rat(Rat::new(1, 3).unwrap())),
        ] {
            let e = Expr::cos(&t.add(&off));
            assert!(!e.has_phase());
            assert!(
                e.terms
                    .keys()
                    .flatten()
                    .any(|(v, _)| matches!(v, Var::Call(_)))
            );
        }
    }
}
