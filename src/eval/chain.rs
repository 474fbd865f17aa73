//! The chain rule on how a value was made (LANGUAGE.md §7; the book's
//! derivatives by the chain rule, §3.2.2). `diff(x, t)` of a symbolic
//! scalar gives its derivative in canonical form; for the numbers bound
//! later it also records how that derivative is computed from the steps
//! that made `x` ([`crate::values::recipe`]): d(u v) = du v + u dv,
//! d sin u = cos u du, …, down to the leaves, whose derivatives the
//! canonical engine gives (a symbol's is 0 or 1, q's by t is q̇). So the
//! derivative of `(sin a + cos b)^30` bound later is 30 (sin a + cos b)^29
//! cos a replayed with numbers, not its expanded form, whose coefficients
//! cancel. Scalars only: where a step is not a scalar function this
//! module knows, the derivative is a leaf, as before.

use std::collections::HashMap;
use std::rc::Rc;

use super::value::Value;
use crate::check::ty::Kind;
use crate::syntax::ast::BinOp;
use crate::values::recipe::{Recipe, Step};

/// A derivative: None for 0 (so that products with it vanish).
type D = Option<Rc<Recipe>>;

/// How `diff(x, by)` is computed from how `x` was made, or None where
/// the chain rule here does not reach (then the result is a leaf).
pub(super) fn derivative(x: &Value, by: &Value) -> Option<Rc<Recipe>> {
    let r = match x {
        Value::Formula { how: Some(r), .. } if r.kind == Kind::Scalar => r,
        _ => return None,
    };
    let mut memo = HashMap::new();
    let d = Chain {
        by,
        memo: &mut memo,
    }
    .of(r)?;
    Some(d.unwrap_or_else(|| number(0.0)))
}

struct Chain<'a> {
    by: &'a Value,
    memo: &'a mut HashMap<*const Recipe, Option<D>>,
}

fn number(x: f64) -> Rc<Recipe> {
    Recipe::leaf(Value::scalar(x))
}

fn node(step: Step, args: Vec<Rc<Recipe>>) -> Option<Rc<Recipe>> {
    Recipe::node(step, args, Kind::Scalar)
}

fn arith(op: BinOp, a: Rc<Recipe>, b: Rc<Recipe>) -> Option<Rc<Recipe>> {
    node(Step::Arith(op), vec![a, b])
}

fn call(name: &'static str, args: Vec<Rc<Recipe>>) -> Option<Rc<Recipe>> {
    node(Step::Call(name), args)
}

/// `a + b` of derivatives (0 + b = b).
fn plus(a: D, b: D) -> Option<D> {
    Some(match (a, b) {
        (Some(a), Some(b)) => Some(arith(BinOp::Add, a, b)?),
        (a, b) => a.or(b),
    })
}

/// `f du` (0 when du is).
fn times(f: Option<Rc<Recipe>>, du: D) -> Option<D> {
    match du {
        None => Some(None),
        Some(du) => Some(Some(arith(BinOp::Mul, f?, du)?)),
    }
}

/// `-x`.
fn neg(x: D) -> Option<D> {
    match x {
        None => Some(None),
        Some(x) => Some(Some(node(Step::Neg, vec![x])?)),
    }
}

/// `x^n`.
fn pow(x: &Rc<Recipe>, n: f64) -> Option<Rc<Recipe>> {
    arith(BinOp::Pow, x.clone(), number(n))
}

impl Chain<'_> {
    /// The derivative of `r`; None where the rule does not reach.
    fn of(&mut self, r: &Rc<Recipe>) -> Option<D> {
        let key = Rc::as_ptr(r);
        if let Some(d) = self.memo.get(&key) {
            return d.clone();
        }
        // (recipes are at most recipe::MAX_DEPTH deep)
        let d = stacker::maybe_grow(64 * 1024, 1024 * 1024, || self.step(r));
        self.memo.insert(key, d.clone());
        d
    }

    fn step(&mut self, r: &Rc<Recipe>) -> Option<D> {
        if r.kind != Kind::Scalar {
            return None;
        }
        let x = |i: usize| r.args.get(i).cloned();
        match &r.step {
            Step::Leaf(v) => self.leaf(v),
            Step::Neg => neg(self.of(&x(0)?)?),
            // x deg = x π/180
            Step::Degrees => match self.of(&x(0)?)? {
                None => Some(None),
                Some(dx) => Some(Some(node(Step::Degrees, vec![dx])?)),
            },
            Step::Arith(op) => {
                let (u, v) = (x(0)?, x(1)?);
                let (du, dv) = (self.of(&u)?, self.of(&v)?);
                match op {
                    BinOp::Add => plus(du, dv),
                    BinOp::Sub => plus(du, neg(dv)?),
                    // d(u v) = du v + u dv
                    BinOp::Mul => plus(times(Some(v), du)?, times(Some(u), dv)?),
                    // d(u / v) = du / v − u dv / v²
                    BinOp::Div => {
                        let a = match du {
                            None => None,
                            Some(du) => Some(arith(BinOp::Div, du, v.clone())?),
                        };
                        let b = match dv {
                            None => None,
                            Some(dv) => {
                                let udv = arith(BinOp::Mul, u, dv)?;
                                Some(arith(BinOp::Div, udv, pow(&v, 2.0)?)?)
                            }
                        };
                        plus(a, neg(b)?)
                    }
                    // d(u^n) = n u^(n−1) du, for a number n
                    BinOp::Pow => {
                        if dv.is_some() {
                            return None;
                        }
                        let n = match &v.step {
                            Step::Leaf(n) => n.as_scalar()?,
                            _ => return None,
                        };
                        if n == 0.0 {
                            return Some(None);
                        }
                        let f = arith(BinOp::Mul, number(n), pow(&u, n - 1.0)?);
                        times(f, du)
                    }
                }
            }
            Step::Call(name) => self.call(name, &r.args),
            _ => None,
        }
    }

    /// A leaf's derivative by the canonical engine (a number's is 0).
    fn leaf(&mut self, v: &Value) -> Option<D> {
        match v {
            Value::Num { .. } => Some(None),
            Value::Formula { .. } => {
                let kind = Kind::Scalar;
                match crate::builtins::eval_symbolic("diff", &[v.clone(), self.by.clone()], &kind)?
                    .ok()?
                {
                    d @ Value::Num { .. } if d.as_scalar() == Some(0.0) => Some(None),
                    d => Some(Some(Recipe::leaf(d))),
                }
            }
            _ => None,
        }
    }

    /// The derivative of a builtin scalar function of its arguments.
    fn call(&mut self, name: &str, args: &[Rc<Recipe>]) -> Option<D> {
        let u = args.first()?.clone();
        let du = self.of(&u)?;
        let one = || number(1.0);
        // 1 − u², 1 + u²
        let one_minus_sq = || arith(BinOp::Sub, one(), pow(&u, 2.0)?);
        let one_plus_sq = |x: &Rc<Recipe>| arith(BinOp::Add, one(), pow(x, 2.0)?);
        let f = match name {
            "atan2" => {
                // d atan2(u, w) = (w du − u dw) / (u² + w²)
                let w = args.get(1)?.clone();
                let dw = self.of(&w)?;
                let top = plus(
                    times(Some(w.clone()), du)?,
                    neg(times(Some(u.clone()), dw)?)?,
                )?;
                let Some(top) = top else {
                    return Some(None);
                };
                let den = arith(BinOp::Add, pow(&u, 2.0)?, pow(&w, 2.0)?)?;
                return Some(Some(arith(BinOp::Div, top, den)?));
            }
            _ if args.len() != 1 => return None,
            "sin" => call("cos", vec![u.clone()]),
            "cos" => return neg(times(call("sin", vec![u.clone()]), du)?),
            "tan" => one_plus_sq(&call("tan", vec![u.clone()])?),
            "cot" => return neg(times(one_plus_sq(&call("cot", vec![u.clone()])?), du)?),
            "sec" => {
                let sec = call("sec", vec![u.clone()])?;
                arith(BinOp::Mul, sec, call("tan", vec![u.clone()])?)
            }
            "csc" => {
                let csc = call("csc", vec![u.clone()])?;
                let f = arith(BinOp::Mul, csc, call("cot", vec![u.clone()])?);
                return neg(times(f, du)?);
            }
            "exp" => call("exp", vec![u.clone()]),
            "sqrt" => arith(BinOp::Div, number(0.5), call("sqrt", vec![u.clone()])?),
            "asin" => arith(BinOp::Div, one(), call("sqrt", vec![one_minus_sq()?])?),
            "acos" => {
                let f = arith(BinOp::Div, one(), call("sqrt", vec![one_minus_sq()?])?);
                return neg(times(f, du)?);
            }
            "atan" => arith(BinOp::Div, one(), one_plus_sq(&u)?),
            _ => return None,
        };
        times(f, du)
    }
}
