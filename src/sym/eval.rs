//! Expressions at numbers (LANGUAGE.md §7, "binding numbers later makes
//! them numeric"): evaluation with numbers for the symbols, and
//! substitution of numbers or expressions, re-canonicalized.

use super::coef::Coef;
use super::expr::{Call, Expr, Func, Symbol, Var};
use num_traits::Zero;

impl Expr {
    /// The number, when the expression is constant (π included) and real.
    pub fn as_f64(&self) -> Option<f64> {
        let (re, im) = match self.as_const() {
            Some(c) => c.to_c64(),
            // π is a number: 2 + π, once its symbols are bound, is 5.1416;
            // and so is the reciprocal of a number, 0.0415/(1 + π²), a
            // float divided by a sum with π (`subs` of a derivative, §7:
            // with no symbol left the value is a number)
            None => self.terms.iter().try_fold((0.0, 0.0), |(re, im), (m, c)| {
                let p = m.iter().try_fold(1.0, |p, (v, e)| match v {
                    Var::Pi => Some(p * std::f64::consts::PI.powi(*e)),
                    Var::Call(call) if call.f == Func::Recip => match call.args.as_slice() {
                        [x] => x
                            .as_f64()
                            .filter(|x| *x != 0.0)
                            .map(|x| p * x.recip().powi(*e)),
                        _ => None,
                    },
                    _ => None,
                })?;
                let (a, b) = c.to_c64();
                Some((re + a * p, im + b * p))
            })?,
        };
        (im.abs() <= 1e-12 * re.abs().max(1.0)).then_some(re)
    }

    /// The value with numbers for the symbols (the real part); None when a
    /// symbol has no number.
    pub fn eval(&self, at: &dyn Fn(&Symbol) -> Option<f64>) -> Option<f64> {
        self.eval_c(at).map(|(re, _)| re)
    }

    /// The complex value with numbers for the symbols ((re, im): a
    /// monomial in z = e^{iθ} alone is complex); None when a symbol has no
    /// number.
    pub fn eval_c(&self, at: &dyn Fn(&Symbol) -> Option<f64>) -> Option<(f64, f64)> {
        let (mut sre, mut sim) = (0.0, 0.0);
        for (m, c) in &self.terms {
            let (mut re, mut im) = c.to_c64();
            for (v, e) in m {
                let (a, b) = match v {
                    Var::Pi => (std::f64::consts::PI.powi(*e), 0.0),
                    Var::Sym(s) => (at(s)?.powi(*e), 0.0),
                    Var::Z(s) => {
                        let x = match s.phase() {
                            Some(unit) => unit.radians(),
                            None => at(s)?,
                        };
                        let t = x * f64::from(*e);
                        (t.cos(), t.sin())
                    }
                    Var::Call(c) => (eval_call(c, at)?.powi(*e), 0.0),
                };
                (re, im) = (re * a - im * b, re * b + im * a);
            }
            sre += re;
            sim += im;
        }
        Some((sre, sim))
    }

    /// The expression with some symbols replaced (by numbers or other
    /// expressions), re-canonicalized.
    pub fn subst(&self, by: &dyn Fn(&Symbol) -> Option<Expr>) -> Expr {
        let mut out = Expr::zero();
        for (m, c) in &self.terms {
            let mut t = Expr::constant(c.clone());
            for (v, e) in m {
                let f = match v {
                    Var::Sym(s) => by(s).unwrap_or_else(|| Expr::var(v.clone())),
                    Var::Z(s) => match by(s) {
                        Some(x) => Expr::cos(&x).add(&Expr::sin(&x).scale(&Coef::i())),
                        None => Expr::var(v.clone()),
                    },
                    Var::Pi => Expr::pi(),
                    Var::Call(c) => {
                        let args: Vec<Expr> = c.args.iter().map(|a| a.subst(by)).collect();
                        rebuild(c.f, &args)
                    }
                };
                t = t.mul(&power(&f, *e));
            }
            out = out.add(&t);
        }
        out
    }
}

impl Expr {
    /// The expression with numbers for some of its symbols (LANGUAGE.md
    /// §7, numbers bound later): a symbol becomes its number, exact where
    /// [`Expr::num`] finds a closed form; an angle's z = e^{iθ} becomes
    /// e^{iθ} exactly for a multiple of π/12 ([`Expr::expi`]), else the
    /// complex number cos θ + i sin θ (never sin and cos kept as calls of
    /// a number, whose reciprocals would not fold).
    pub fn at_numbers(&self, by: &dyn Fn(&Symbol) -> Option<f64>) -> Expr {
        let mut out = Expr::zero();
        for (m, c) in &self.terms {
            let mut t = Expr::constant(c.clone());
            for (v, e) in m {
                let f = match v {
                    Var::Sym(s) => by(s).map_or_else(|| Expr::var(v.clone()), Expr::num),
                    Var::Z(s) => match by(s) {
                        Some(x) => Expr::expi(&Expr::num(x)).unwrap_or_else(|| {
                            Expr::constant(Coef::Approx {
                                re: x.cos(),
                                im: x.sin(),
                            })
                        }),
                        None => Expr::var(v.clone()),
                    },
                    Var::Pi => Expr::pi(),
                    Var::Call(c) => {
                        let args: Vec<Expr> = c.args.iter().map(|a| a.at_numbers(by)).collect();
                        rebuild(c.f, &args)
                    }
                };
                t = t.mul(&power(&f, *e));
            }
            out = out.add(&t);
        }
        out
    }
}

impl Expr {
    /// Why the expression has no real value, if it has none whatever its
    /// free symbols are: a coefficient that is NaN (a power of 0 or 1/0
    /// substituted, `subst`, `at_numbers`), or a call of
    /// numbers outside its domain (1/0, √−1, asin 2). Numbers bound while
    /// other symbols are free (LANGUAGE.md §7) make these where the
    /// numbers typed first are refused; the value must be refused too.
    pub fn undefined(&self) -> Option<String> {
        for (m, c) in &self.terms {
            let (re, im) = c.to_c64();
            if re.is_nan() || im.is_nan() {
                return Some("division by zero".into());
            }
            for (v, _) in m {
                let Var::Call(call) = v else { continue };
                if let Some(why) = call.args.iter().find_map(Expr::undefined) {
                    return Some(why);
                }
                // (a call of numbers alone: its value, if it has one)
                if eval_call(call, &|_| None).is_some_and(|x| !x.is_finite()) {
                    return Some(match call.f {
                        Func::Recip => "division by zero".into(),
                        f => {
                            let args: Vec<String> = call
                                .args
                                .iter()
                                .map(|a| super::print::expr(a, Default::default()))
                                .collect();
                            format!("{}({}) is not a real number", f.name(), args.join(", "))
                        }
                    });
                }
            }
        }
        None
    }
}

/// f^e of a factor substituted: a negative power of 0 is NaN (`1/b` at
/// b = 0 has no value: [`Expr::undefined`] says so), never 0.
fn power(f: &Expr, e: i32) -> Expr {
    f.powi(i64::from(e)).unwrap_or_else(nan)
}

/// The NaN of a substitution with no value.
fn nan() -> Expr {
    Expr::constant(Coef::Approx {
        re: f64::NAN,
        im: 0.0,
    })
}

/// A call rebuilt through its constructor (so numbers fold).
pub fn rebuild(f: Func, args: &[Expr]) -> Expr {
    let x = &args[0];
    match f {
        Func::Sin => Expr::sin(x),
        Func::Cos => Expr::cos(x),
        Func::Tan => Expr::apply(f, x, f64::tan),
        Func::Asin => Expr::apply(f, x, f64::asin),
        Func::Acos => Expr::apply(f, x, f64::acos),
        Func::Atan => Expr::apply(f, x, f64::atan),
        Func::Abs => Expr::abs(x),
        Func::Exp => Expr::apply(f, x, f64::exp),
        Func::Sqrt => Expr::sqrt(x),
        // 1/0 has no value (NaN, [`Expr::undefined`]); a reciprocal whose
        // exact form does not fit stays a call
        Func::Recip if x.is_zero() => nan(),
        Func::Recip => x
            .recip()
            .unwrap_or_else(|| Expr::call(Func::Recip, vec![x.clone()])),
        Func::Atan2 => Expr::atan2(x, &args[1]),
    }
}

fn eval_call(c: &Call, at: &dyn Fn(&Symbol) -> Option<f64>) -> Option<f64> {
    let x = c.args[0].eval(at)?;
    Some(match c.f {
        Func::Sin => x.sin(),
        Func::Cos => x.cos(),
        Func::Tan => x.tan(),
        Func::Asin => x.asin(),
        Func::Acos => x.acos(),
        Func::Atan => x.atan(),
        Func::Sqrt => x.sqrt(),
        Func::Abs => x.abs(),
        Func::Exp => x.exp(),
        Func::Recip => 1.0 / x,
        Func::Atan2 => x.atan2(c.args.get(1)?.eval(at)?),
    })
}
