//! Derivatives of canonical expressions by the chain rule (LANGUAGE.md §7):
//! by a symbol (a partial derivative) or by time, where a function of time
//! θ(t) gives θ̇ and e^{iθ} gives i θ̇ e^{iθ} — so d/dt R(θ(t)) of §3.2.2
//! needs no trigonometric rule.

use std::sync::Arc;

use super::coef::Coef;
use super::expr::{Call, Expr, Func, Mono, Symbol, Var, Wrt};
use num_traits::{One, Zero};

impl Wrt {
    /// The derivative a symbol asks for: the total one by a plain symbol
    /// (which is the partial one when nothing is a function of it), the
    /// partial one by a function of time or its rate.
    pub fn by(s: Symbol) -> Wrt {
        if s.is_timed() {
            Wrt::Sym(s)
        } else {
            Wrt::Time(s)
        }
    }
}

/// The derivatives of variables worked out so far (a call may sit in
/// thousands of terms, and in every entry of a matrix; a shared call is
/// known by its pointer), and the work a derivative may spend on the
/// products its calls' chain rule forms ([`Known::limited`]).
#[derive(Default)]
pub struct Known {
    vars: Vec<(Var, Expr)>,
    /// The most work ([`super::size::work`]) the calls' products may take;
    /// None for no limit.
    budget: Option<usize>,
    /// The work spent so far.
    spent: usize,
    /// Set when a product would pass the budget: the derivative is then
    /// incomplete and must be refused ([`Known::over`]).
    over: bool,
}

impl Known {
    /// Derivatives whose calls' products may take at most `work` term
    /// products (issue 21: refuse in time, never after seconds of work —
    /// the derivative of atan2 of two large entries formed x·dy − y·dx and
    /// x² + y² before the result was refused by its size).
    pub fn limited(work: usize) -> Known {
        Known {
            budget: Some(work),
            ..Known::default()
        }
    }

    /// The work spent when a product passed the budget (the derivatives
    /// are then incomplete: refuse them); None while within it.
    pub fn over(&self) -> Option<usize> {
        self.over.then_some(self.spent)
    }

    /// The index of dv, worked out on first sight.
    fn of(&mut self, v: &Var, wrt: &Wrt) -> usize {
        let same = |(k, _): &(Var, Expr)| match (k, v) {
            (Var::Call(a), Var::Call(b)) => Arc::ptr_eq(a, b),
            _ => k == v,
        };
        match self.vars.iter().position(same) {
            Some(k) => k,
            None => {
                let d = var_diff(v, wrt, self);
                self.vars.push((v.clone(), d));
                self.vars.len() - 1
            }
        }
    }

    /// Charges `work` to the budget: false (and [`Known::over`] set) past
    /// it, or once it has been passed.
    fn charge(&mut self, work: usize) -> bool {
        if self.over {
            return false;
        }
        if let Some(budget) = self.budget {
            self.spent = self.spent.saturating_add(work);
            if self.spent > budget {
                self.over = true;
                return false;
            }
        }
        true
    }

    /// a·b, its work charged to the budget; 0 (and [`Known::over`] set)
    /// past it.
    fn mul(&mut self, a: &Expr, b: &Expr) -> Expr {
        if self.budget.is_some() && !self.charge(super::size::work(&[(a, b)])) {
            return Expr::zero();
        }
        a.mul(b)
    }
}

impl Expr {
    /// The derivative (chain rule through every variable): Σ_v R_v·dv over
    /// [`Expr::diff_parts`], the products packed where that pays.
    pub fn diff(&self, wrt: &Wrt) -> Expr {
        self.diff_with(wrt, &mut Known::default())
    }

    /// The derivative, the variables' derivatives shared with (and their
    /// products charged to) `known`.
    fn diff_with(&self, wrt: &Wrt, known: &mut Known) -> Expr {
        let parts = self.diff_parts(wrt, known);
        let pairs: Vec<(&Expr, &Expr)> = parts.iter().map(|(r, d)| (r, d)).collect();
        if !known.charge(super::size::flat_work(&pairs)) {
            return Expr::zero();
        }
        super::dense::sum_of_products(&pairs)
    }

    /// The derivative as parts (R_v, dv), one for each variable v whose
    /// derivative dv is not 0: R_v = ∂self/∂v, the terms that hold v with
    /// its power brought down, so that the derivative is Σ_v R_v·dv — a
    /// sum of products whose size and work can be told before any of it
    /// is formed ([`super::size::sum_of_products`], [`super::size::work`]).
    /// `known` carries the variables' derivatives from entry to entry.
    pub fn diff_parts(&self, wrt: &Wrt, known: &mut Known) -> Vec<(Expr, Expr)> {
        // (the index of dv in `known`, R_v)
        let mut parts: Vec<(usize, Expr)> = Vec::new();
        for (m, c) in &self.terms {
            for (i, (v, e)) in m.iter().enumerate() {
                let k = known.of(v, wrt);
                if known.vars[k].1.is_zero() {
                    continue;
                }
                let mut rest: Mono = m.clone();
                if *e == 1 {
                    rest.remove(i);
                } else {
                    rest[i].1 = e.saturating_sub(1);
                }
                let c = c.mul(&Coef::int(i64::from(*e)));
                // (R_v summed in place)
                match parts.iter_mut().find(|(j, _)| *j == k) {
                    Some((_, r)) => r.push(rest, c),
                    None => {
                        let mut r = Expr::zero();
                        r.push(rest, c);
                        parts.push((k, r));
                    }
                }
            }
        }
        parts
            .into_iter()
            .filter(|(_, r)| !r.is_zero())
            .map(|(k, r)| (r, known.vars[k].1.clone()))
            .collect()
    }
}

/// ∂s/∂x or ds/dt of one symbol: 1 for the symbol itself; by a plain
/// symbol t, θ̇ for a function of t (the chain rule); 0 otherwise — a
/// partial derivative by q or q̇ holds every other coordinate and rate
/// fixed, and q and q̇ are independent (LANGUAGE.md §7).
/// (The symbol decides which: [`Wrt::by`].)
fn symbol_diff(s: &Symbol, wrt: &Wrt) -> Expr {
    let (Wrt::Time(x) | Wrt::Sym(x)) = wrt;
    if x == s {
        Expr::one()
    } else if !x.is_timed() && s.time.as_deref() == Some(&*x.name) {
        Expr::symbol(s.dot())
    } else {
        Expr::zero()
    }
}

fn var_diff(v: &Var, wrt: &Wrt, known: &mut Known) -> Expr {
    match v {
        Var::Pi => Expr::zero(),
        Var::Sym(s) => symbol_diff(s, wrt),
        // d/dt e^{iθ} = i θ̇ e^{iθ}
        Var::Z(s) => symbol_diff(s, wrt)
            .mul(&Expr::var(v.clone()))
            .scale(&Coef::i()),
        Var::Call(c) => call_diff(c, wrt, known),
    }
}

/// The derivative of a call by the chain rule, its products charged to
/// `known`'s budget (its argument's derivative shares `known`).
fn call_diff(c: &Arc<Call>, wrt: &Wrt, known: &mut Known) -> Expr {
    let x = &c.args[0];
    let me = Expr::var(Var::Call(c.clone()));
    // 1/e, as a plain call where the exact reciprocal does not fit (never
    // 0: a derivative that cannot be formed exactly is still right).
    let recip = |e: &Expr| {
        e.recip()
            .unwrap_or_else(|| Expr::call(Func::Recip, vec![e.clone()]))
    };
    let one = Expr::one();
    let outer = match c.f {
        Func::Sin => Expr::cos(x),
        Func::Cos => Expr::sin(x).neg(),
        Func::Tan => one.add(&known.mul(&me, &me)),
        Func::Exp => me.clone(),
        Func::Sqrt => recip(&me.scale(&Coef::int(2))),
        Func::Asin => recip(&Expr::sqrt(&one.sub(&known.mul(x, x)))),
        Func::Acos => recip(&Expr::sqrt(&one.sub(&known.mul(x, x)))).neg(),
        Func::Atan => recip(&one.add(&known.mul(x, x))),
        Func::Abs => known.mul(x, &recip(&me)),
        Func::Recip => known.mul(&me, &me).neg(),
        Func::Atan2 => {
            // d atan2(y, x) = (x dy − y dx)/(x² + y²)
            let (y, xx) = (&c.args[0], &c.args[1]);
            let (dy, dxx) = (y.diff_with(wrt, known), xx.diff_with(wrt, known));
            let num = known.mul(xx, &dy).sub(&known.mul(y, &dxx));
            let den = known.mul(xx, xx).add(&known.mul(y, y));
            return known.mul(&num, &recip(&den));
        }
    };
    let dx = x.diff_with(wrt, known);
    known.mul(&outer, &dx)
}
