//! The canonical form of a scalar expression (LANGUAGE.md §7): a sum of
//! monomials with exact coefficients ([`super::coef`]), where a monomial is a
//! product of integer powers of variables. An angle θ enters through
//! z = e^{iθ} (cos θ = (z + z⁻¹)/2, sin θ = (z − z⁻¹)/2i), so that a
//! trigonometric polynomial is a Laurent polynomial in the z's: its
//! monomials are unique, angle sums fold by themselves (cos(θ1 + θ2) is the
//! real part of z1 z2), sin² + cos² = 1 needs no rule, and d/dt z = i θ̇ z.
//! Two expressions are equal exactly when their term maps are equal.
//! Functions with no such form (sqrt, atan2, 1/(a + b), sin of a non-linear
//! argument) are kept as calls whose arguments are canonical in turn.

use std::collections::BTreeMap;
use std::sync::Arc;

use super::coef::{Coef, Rat};
use num_traits::{One, Zero};

mod symbol;
pub use symbol::Symbol;

/// A function kept as a call.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Func {
    /// sin of an argument not linear in angles (else it is a sum of z's).
    Sin,
    /// cos of an argument not linear in angles.
    Cos,
    /// tan x.
    Tan,
    /// asin x, in [−π/2, π/2].
    Asin,
    /// acos x, in [0, π], as in θ = acos((tr R − 1)/2) (§3.2.3.3).
    Acos,
    /// atan x.
    Atan,
    /// atan2(y, x), the angle of (x, y): two arguments, y first.
    Atan2,
    /// The non-negative square root.
    Sqrt,
    /// |x|.
    Abs,
    /// eˣ of a real x.
    Exp,
    /// 1/x of a sum.
    Recip,
}

impl Func {
    /// The name as printed.
    pub fn name(self) -> &'static str {
        match self {
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Asin => "asin",
            Func::Acos => "acos",
            Func::Atan => "atan",
            Func::Atan2 => "atan2",
            Func::Sqrt => "sqrt",
            Func::Abs => "abs",
            Func::Exp => "exp",
            Func::Recip => "1/",
        }
    }
}

/// A call with canonical arguments. Calls are shared ([`super::intern`]):
/// equal calls made on one thread are one allocation, so comparing them
/// (as monomials are compared in every sum and product) is one pointer
/// comparison, not a walk of their arguments.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Call {
    /// The function applied.
    pub f: Func,
    /// Its arguments in canonical form (two for atan2, else one).
    pub args: Vec<Expr>,
}

/// A variable of a monomial, in the order of its variants (a shared call
/// compares equal to itself at once: [`super::intern`]).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Var {
    /// π, transcendental, so an independent variable.
    Pi,
    /// A real symbol as itself (lengths; θ where G(θ) brings it in).
    Sym(Symbol),
    /// e^{iθ} of a symbol θ.
    Z(Symbol),
    /// A function kept as a call, shared.
    Call(Arc<Call>),
}

/// Variables with their nonzero exponents, sorted by variable.
pub type Mono = Vec<(Var, i32)>;

/// A canonical expression: monomials to nonzero coefficients.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Default, Hash)]
pub struct Expr {
    /// Each monomial with its coefficient; the empty map is 0.
    pub terms: BTreeMap<Mono, Coef>,
}

/// The deepest nesting of calls kept (see [`Expr::depth`]).
pub const MAX_DEPTH: usize = 100;

/// What to differentiate by (LANGUAGE.md §7): a plain symbol t, by the
/// chain rule (t ↦ 1, θ(t) ↦ θ̇ for every function of t: the total
/// derivative), or a function of time or one of its rates, q or q̇ (the
/// partial derivative holding the other coordinates and rates fixed, as in
/// a Lagrangian).
#[derive(Debug, Clone, PartialEq)]
pub enum Wrt {
    /// By a plain symbol t: the total derivative d/dt (the chain rule).
    Time(Symbol),
    /// By a function of time or a rate, q or q̇: the partial derivative.
    Sym(Symbol),
}

pub(super) fn mono_mul(a: &Mono, b: &Mono) -> Mono {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match a[i].0.cmp(&b[j].0) {
            std::cmp::Ordering::Less => {
                out.push(a[i].clone());
                i += 1;
            }
            std::cmp::Ordering::Greater => {
                out.push(b[j].clone());
                j += 1;
            }
            std::cmp::Ordering::Equal => {
                let e = a[i].1.saturating_add(b[j].1);
                if e != 0 {
                    out.push((a[i].0.clone(), e));
                }
                i += 1;
                j += 1;
            }
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
    out
}

impl Expr {
    /// A constant.
    pub fn constant(c: Coef) -> Expr {
        let mut e = Expr::zero();
        if !c.is_zero() {
            e.terms.insert(Vec::new(), c);
        }
        e
    }
    /// An integer.
    pub fn int(n: i64) -> Expr {
        Expr::constant(Coef::int(n))
    }
    /// A float as a constant ([`Coef::from_f64`]): exact only when the
    /// float is itself a simple fraction (an integer, 0.5), else a float.
    /// No closed form (1/√2, π/9) is guessed: exact numbers come in with
    /// their exact forms (LANGUAGE.md §7).
    pub fn num(x: f64) -> Expr {
        Expr::constant(Coef::from_f64(x))
    }
    /// A float computed by a function with no exact value there (sin 1,
    /// √(10¹⁸ + 1)): a float coefficient even when it happens to be an
    /// integer or a simple fraction (cos(1e-9) is 1 in floats, not 1;
    /// `cos(1e-9) == 1` was true).
    pub fn float(x: f64) -> Expr {
        if x == 0.0 {
            return Expr::default();
        }
        Expr::constant(Coef::Approx { re: x, im: 0.0 })
    }
    /// A number as typed, exactly: the shortest decimal that reads back as
    /// `x` (`0.3` is 3/10; LANGUAGE.md §7), a float only for inf or NaN.
    pub fn typed(x: f64) -> Expr {
        match Rat::typed(x) {
            Some(r) => Expr::constant(Coef::rat(r)),
            None => Expr::num(x),
        }
    }
    /// One variable.
    pub fn var(v: Var) -> Expr {
        Expr::var_pow(v, 1)
    }
    fn var_pow(v: Var, e: i32) -> Expr {
        let mut x = Expr::zero();
        x.terms.insert(vec![(v, e)], Coef::one());
        x
    }
    /// A symbol as itself (not as an angle).
    pub fn symbol(s: Symbol) -> Expr {
        Expr::var(Var::Sym(s))
    }
    /// π.
    pub fn pi() -> Expr {
        Expr::var(Var::Pi)
    }
    pub(super) fn call(f: Func, args: Vec<Expr>) -> Expr {
        Expr::var(Var::Call(super::intern::call(Call { f, args })))
    }
    /// The constant, when there are no variables.
    pub fn as_const(&self) -> Option<Coef> {
        match self.terms.len() {
            0 => Some(Coef::ZERO),
            1 => self.terms.get(&Vec::new()).cloned(),
            _ => None,
        }
    }
    /// Terms plus nested call arguments, a coefficient beyond two machine
    /// words counting one more per word: the size that the expression
    /// limit bounds (so the work of exact big coefficients is bounded too).
    pub fn size(&self) -> usize {
        self.size_with(&mut std::collections::HashMap::new())
    }
    /// [`Expr::size`], each shared call's arguments measured once (a call
    /// may sit in hundreds of terms).
    fn size_with(&self, seen: &mut std::collections::HashMap<*const Call, usize>) -> usize {
        let mut n = 0;
        for (m, c) in &self.terms {
            n += 1 + c.words();
            for (v, _) in m {
                if let Var::Call(call) = v {
                    let key = Arc::as_ptr(call);
                    let k = match seen.get(&key) {
                        Some(k) => *k,
                        None => {
                            let k = call.args.iter().map(|a| a.size_with(seen)).sum();
                            seen.insert(key, k);
                            k
                        }
                    };
                    n += k;
                }
            }
        }
        n
    }

    /// How deeply calls nest (`sin(sin(t))` is 2): printing and evaluation
    /// recurse this deep, so the interpreter bounds it by [`MAX_DEPTH`].
    pub fn depth(&self) -> usize {
        self.terms
            .keys()
            .flatten()
            .map(|(v, _)| match v {
                Var::Call(c) => 1 + c.args.iter().map(Expr::depth).max().unwrap_or(0),
                _ => 0,
            })
            .max()
            .unwrap_or(0)
    }

    /// Adds the term c·m in place: [`Expr::add`] without copying the sum.
    pub fn push(&mut self, m: Mono, c: Coef) {
        if c.is_zero() {
            return;
        }
        match self.terms.entry(m) {
            std::collections::btree_map::Entry::Vacant(v) => {
                v.insert(c);
            }
            std::collections::btree_map::Entry::Occupied(mut o) => {
                let s = o.get().add(&c);
                if s.is_zero() {
                    o.remove();
                } else {
                    *o.get_mut() = s;
                }
            }
        }
    }
    /// a + b.
    pub fn add(&self, o: &Expr) -> Expr {
        let mut out = self.clone();
        for (m, c) in &o.terms {
            out.push(m.clone(), c.clone());
        }
        out
    }
    /// −a.
    pub fn neg(&self) -> Expr {
        self.scale(&Coef::int(-1))
    }
    /// a − b.
    pub fn sub(&self, o: &Expr) -> Expr {
        self.add(&o.neg())
    }
    /// c·a for a constant c.
    pub fn scale(&self, c: &Coef) -> Expr {
        let mut out = Expr::zero();
        for (m, k) in &self.terms {
            out.push(m.clone(), k.mul(c));
        }
        out
    }
    /// a·b, monomial by monomial.
    pub fn mul(&self, o: &Expr) -> Expr {
        // large products over small fractions: packed ([`super::dense`])
        let work = self.terms.len().saturating_mul(o.terms.len());
        let packed = (work >= super::dense::MIN_WORK)
            .then(|| super::dense::product(self, o))
            .flatten();
        let out = packed.unwrap_or_else(|| super::dense::term_by_term(self, o));
        out.folded(self.has_phase() || o.has_phase())
    }

    /// A raw product made canonical: roots, exponentials ([`super::exps`]), unit
    /// axes, half angles ([`super::half`]) and (when a factor had one) phases folded. Each fold maps term by term, so a sum of
    /// raw products folds to the sum of the folded products.
    pub(super) fn folded(self, phases: bool) -> Expr {
        let out = self
            .fold_exps()
            .fold_roots()
            .fold_root_quotients()
            .fold_units()
            .fold_halves();
        if phases {
            return out.fold_phases();
        }
        out
    }

    /// The complex conjugate (symbols and calls are real; z̄ = z⁻¹).
    pub fn conj(&self) -> Expr {
        let mut out = Expr::zero();
        for (m, c) in &self.terms {
            let m: Mono = m
                .iter()
                .map(|(v, e)| match v {
                    Var::Z(_) => (v.clone(), e.saturating_neg()),
                    _ => (v.clone(), *e),
                })
                .collect();
            let mut m2 = Vec::new();
            for f in m {
                m2 = mono_mul(&m2, &vec![f]);
            }
            out.push(m2, c.conj());
        }
        out.fold_phases()
    }
    /// 1/x: exact for a single term, else a [`Func::Recip`] call of a *real*
    /// sum (calls are real), scaled so its first term prints as 1; a complex
    /// x is made real first, 1/x = x̄ / (x x̄). None for 0.
    pub fn recip(&self) -> Option<Expr> {
        if self.terms.len() == 1 {
            let (m, c) = self.terms.iter().next()?;
            return super::together::turned_term(m, c);
        }
        // 1/(n/d) = d/n (`1/cot(t)` is `tan(t)`, one canonical form)
        if self.has_recip()
            && let Some(r) = super::together::turned_over(self)
        {
            return Some(r);
        }
        let bar = self.conj();
        if bar != *self {
            // x x̄ is real; its real part drops any rounding of float coefficients.
            let n = self.mul(&bar);
            let n = n.add(&n.conj()).scale(&Coef::rat(Rat::new(1, 2)?));
            return Some(bar.mul(&n.recip()?));
        }
        let (m, lead) = self.terms.iter().next()?;
        // A term with an angle prints as twice its real (or imaginary) part.
        let paired = m.iter().any(|(v, _)| matches!(v, Var::Z(_)));
        let k = lead.real_scale(if paired { Rat::new(1, 2)? } else { Rat::ONE })?;
        Some(Expr::call(Func::Recip, vec![self.scale(&k)]).scale(&k))
    }
    /// a / b; None when b is 0.
    pub fn div(&self, b: &Expr) -> Option<Expr> {
        if self == b && !b.is_zero() {
            return Some(Expr::one());
        }
        Some(self.mul(&b.recip()?))
    }
    /// An integer power; None for a negative power of 0.
    pub fn powi(&self, n: i64) -> Option<Expr> {
        if n < 0 {
            return self.recip()?.powi(-n);
        }
        let mut result = Expr::one();
        let mut base = self.clone();
        let mut n = n;
        while n > 0 {
            if n & 1 == 1 {
                result = result.mul(&base);
            }
            n >>= 1;
            if n > 0 {
                base = base.mul(&base);
            }
        }
        Some(result)
    }

    /// e^{i·arg} as a monomial in the z's, when `arg` is an integer
    /// combination of symbols plus a multiple of π/12, or plus another
    /// rational multiple of π or a decimal offset (a phase variable,
    /// [`super::phase`]; only beside a symbol: `cos(π/5)` is a number).
    pub fn expi(arg: &Expr) -> Option<Expr> {
        let mut mono: Mono = Vec::new();
        let (mut pi, mut rad) = (Rat::ZERO, Rat::ZERO);
        for (m, c) in &arg.terms {
            let k = c.as_rat()?;
            match m.as_slice() {
                [(Var::Sym(s), 1)] => {
                    let k = i32::try_from(k.as_int()?).ok()?;
                    mono = mono_mul(&mono, &vec![(Var::Z(s.clone()), k)]);
                }
                [(Var::Pi, 1)] => pi = k.rem_euclid(2), // (period 2: cos(2^60 π) is 1)
                [] => rad = k,
                _ => return None,
            }
        }
        let coef = match Coef::unit_root(pi.clone()) {
            Some(c) if rad.is_zero() => c,
            _ if mono.is_empty() => return None,
            _ => {
                let (m, c) = super::phase::offset(&pi, &rad)?;
                mono = mono_mul(&mono, &m);
                c
            }
        };
        let mut e = Expr::zero();
        e.push(mono, coef);
        Some(e)
    }
    /// cos x: folded into the z's when x is linear, else a call.
    pub fn cos(x: &Expr) -> Expr {
        if let Some(e) = Expr::expi(x) {
            return e
                .add(&e.conj())
                .scale(&Coef::rat(Rat::new(1, 2).unwrap_or(Rat::ONE)));
        }
        Expr::apply(Func::Cos, x, f64::cos)
    }
    /// sin x: folded into the z's when x is linear, else a call.
    pub fn sin(x: &Expr) -> Expr {
        if let Some(e) = Expr::expi(x) {
            // (e − ē)/(2i) = −i/2 (e − ē)
            let k = Coef::i().mul(&Coef::rat(Rat::new(-1, 2).unwrap_or(Rat::ONE)));
            return e.sub(&e.conj()).scale(&k);
        }
        Expr::apply(Func::Sin, x, f64::sin)
    }
    /// A one-argument function: evaluated when the argument is a number,
    /// else kept as a call.
    pub fn apply(f: Func, x: &Expr, num: fn(f64) -> f64) -> Expr {
        // (asin, acos, atan at the book's angles, sin and cos of them)
        if let Some(e) = super::inverse::closed(f, x) {
            return e;
        }
        match x.as_f64() {
            Some(v) if num(v).is_finite() => Expr::float(num(v)),
            _ => Expr::call(f, vec![x.clone()]),
        }
    }
    /// |x|: x or −x for an exact number whose sign the exact bounds tell
    /// (−7/3, −√2, −π/3: [`super::sign::sign_with_pi`]), so that
    /// `abs(-7/3) == 7/3` is decided; else the float of a number, or the
    /// call kept over symbols, of the sign of x whose leading coefficient
    /// is positive (|−x| = |x|: `abs(-a)` is `abs(a)`, one canonical form).
    pub fn abs(x: &Expr) -> Expr {
        match super::sign::sign_with_pi(x) {
            Some(sign) if sign < 0 => x.neg(),
            Some(_) => x.clone(),
            None if x.as_f64().is_none() && x.leads_negative() => {
                Expr::call(Func::Abs, vec![x.neg()])
            }
            None => Expr::apply(Func::Abs, x, f64::abs),
        }
    }
    /// Whether the leading term's coefficient is a negative real.
    fn leads_negative(&self) -> bool {
        self.terms
            .iter()
            .next()
            .is_some_and(|(_, c)| match c.as_real() {
                Some(r) => r.signum() < 0.0,
                None => matches!(c.to_c64(), (re, im) if im == 0.0 && re < 0.0),
            })
    }
    /// √x: exact for p/q with a square-free part among 1, 2, 3, 6; |p| for
    /// the square of an expression p.
    pub fn sqrt(x: &Expr) -> Expr {
        if let Some(r) = x.as_const().and_then(|c| c.as_rat())
            && !r.is_negative()
        {
            return match super::coef::Surd::sqrt_of(&r) {
                Some(s) => Expr::constant(Coef::real(s)),
                None => Expr::float(r.to_f64().sqrt()),
            };
        }
        // (a root of a surd that denests, √(2 + √3) = (√6 + √2)/2)
        if let Some(s) = x.as_const().and_then(|c| c.as_real())
            && let Some(r) = s.sqrt()
        {
            return Expr::constant(Coef::real(r));
        }
        if x.as_const().is_none()
            && let Some(r) = x.sqrt_of_square()
        {
            return r;
        }
        Expr::apply(Func::Sqrt, x, f64::sqrt)
    }
    /// atan2(y, x), a number when both are.
    pub fn atan2(y: &Expr, x: &Expr) -> Expr {
        if let Some(e) = super::arc::atan2(y, x) {
            return e;
        }
        match (y.as_f64(), x.as_f64()) {
            // (a float zero's sign is no angle: atan2(0, 0) is 0, as typed first)
            (Some(a), Some(b)) => Expr::float((a + 0.0).atan2(b + 0.0)),
            _ => Expr::call(Func::Atan2, vec![y.clone(), x.clone()]),
        }
    }

    /// The symbols the expression depends on.
    pub fn symbols(&self, out: &mut Vec<Symbol>) {
        for m in self.terms.keys() {
            for (v, _) in m {
                match v {
                    Var::Sym(s) | Var::Z(s) => {
                        if !out.contains(s) && !s.is_phase() {
                            out.push(s.clone());
                        }
                    }
                    Var::Call(c) => c.args.iter().for_each(|a| a.symbols(out)),
                    Var::Pi => {}
                }
            }
        }
    }
}

/// The symbol, when the expression is exactly one symbol.
pub fn as_symbol(e: &Expr) -> Option<Symbol> {
    let (m, c) = e.terms.iter().next()?;
    match (e.terms.len(), m.as_slice()) {
        (1, [(Var::Sym(s), 1)]) if c.is_one() => Some(s.clone()),
        _ => None,
    }
}

mod ring;
#[cfg(test)]
mod tests;
