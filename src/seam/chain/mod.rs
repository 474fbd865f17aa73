//! The chain rule on how a value was made (LANGUAGE.md §7; the book's
//! derivatives by the chain rule, §3.2.2). `diff(x, t)` of a symbolic
//! scalar gives its derivative in canonical form; for the numbers bound
//! later it also records how that derivative is computed from the steps
//! that made `x` ([`crate::values::recipe`]): d(u v) = du v + u dv,
//! d sin u = cos u du, …, down to the leaves, whose derivatives the
//! canonical engine gives (a symbol's is 0 or 1, q's by t is q̇). So the
//! derivative of `(sin a + cos b)^30` bound later is 30 (sin a + cos b)^29
//! cos a replayed with numbers, not its expanded form, whose coefficients
//! cancel. Vectors and matrices too (`diff(Rotz(a) Roty(b), a)`,
//! `diff((sin a + cos b)^30 (1, 2, 3), a)`): products keep their order,
//! d(M⁻¹) = −M⁻¹ dM M⁻¹, dRotz(u) = Rotz(u) [ẑ] du (3.51),
//! d exp(A u) = A exp(A u) du for a constant A (`exp([S] θ)`, 3.86),
//! d Ad_T = Ad_T [ad_V] with [V] = T⁻¹ dT (3.83, 8.3); where a step is
//! not one this module knows, the derivative is a leaf, as before.

mod build;
mod guard;
mod kept;
mod rates;
mod subs;

use build::*;

use guard::closed_form;
pub(crate) use kept::of_kept;
use subs::substituted;

use std::collections::HashMap;
use std::rc::Rc;

use crate::check::ty::Kind;
use crate::syntax::ast::BinOp;
use crate::values::exact::Exact;
use crate::values::recipe::{Operation, Recipe, Step};
use crate::values::value::Value;

/// A derivative: None for 0 (so that products with it vanish).
type D = Option<Rc<Recipe>>;

/// How `diff(x, by)` is computed from how `x` was made, or None where
/// the chain rule here does not reach (then the result is a leaf).
pub(super) fn derivative(x: &Value, by: &Value) -> Option<Rc<Recipe>> {
    let r = match x {
        Value::Formula { how: Some(r), .. } => r,
        _ => return None,
    };
    // A matrix literal over formulas (`[1, E]`) is recorded with the kind
    // the check gave it, which can leave its shape open; the value itself
    // knows it (matrix differential seed 329: without it the derivative
    // was read from the expanded form, whose coefficients cancel).
    let kind = shape(r).or_else(|| shape_of(&x.kind()))?;
    let mut memo = HashMap::new();
    let d = Chain {
        by,
        memo: &mut memo,
        top: (Rc::as_ptr(r), kind),
        rates: false,
    }
    .of(r)?;
    Some(d.unwrap_or_else(|| zero(&kind)))
}

/// `v`, the value of builtin `call` ("" for an operator) over `args`,
/// with how it was made: `diff`'s by the chain rule, `subs`'s by
/// substitution in its operand's recipe, a closed form on a branch
/// marked so ([`closed_form`]), anything else by `record`.
pub(super) fn made(
    call: &str,
    v: Value,
    args: &[&Value],
    record: impl FnOnce(Value) -> Value,
) -> Value {
    match (call, args) {
        ("diff", [x, by]) => crate::values::recipe::attach(v, derivative(x, by)),
        ("subs", [x, name, by]) => crate::values::recipe::attach(v, substituted(x, name, by)),
        _ => closed_form(call, record(v), args),
    }
}

struct Chain<'a> {
    by: &'a Value,
    memo: &'a mut HashMap<*const Recipe, Option<D>>,
    /// The recipe differentiated, with its shape (from the value where
    /// the recipe's kind leaves it open).
    top: (*const Recipe, Kind),
    /// Whether the rates at numbers may stand where no closed step
    /// reaches (kept.rs: the derivative of a call kept over symbols).
    rates: bool,
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
        match self.rule(r) {
            None if self.rates => self.rated(r),
            d => d,
        }
    }

    /// The derivative of `r` by the closed steps of the chain rule.
    fn rule(&mut self, r: &Rc<Recipe>) -> Option<D> {
        let k = match shape(r) {
            Some(k) => k,
            None if Rc::as_ptr(r) == self.top.0 => self.top.1,
            None => return None,
        };
        let x = |i: usize| r.args.get(i).cloned();
        // (the steps alike for every shape)
        match &r.step {
            Step::Leaf(v) => return self.leaf(v, &k),
            // (a mark only: the derivative of the call, §7; where the
            // chain rule does not reach the call, `closed` guards the
            // closed form's own derivative)
            Step::Closed(on) => return self.closed(on, &x(0)?, k),
            Step::Guard(on) => return self.guard(on, &x(0)?, k),
            Step::Op(Operation::Neg) => return neg(self.of(&x(0)?)?),
            _ => {}
        }
        if k != Kind::Scalar {
            return self.matrix_step(r, k);
        }
        match &r.step {
            // x deg = x π/180
            Step::Op(Operation::Degrees) => match self.of(&x(0)?)? {
                None => Some(None),
                Some(dx) => Some(Some(node(Step::Op(Operation::Degrees), vec![dx])?)),
            },
            Step::Op(Operation::Arith(op)) => {
                let (u, v) = (x(0)?, x(1)?);
                let (du, dv) = (self.of(&u)?, self.of(&v)?);
                match op {
                    BinOp::Add => plus(du, dv),
                    BinOp::Sub => plus(du, neg(dv)?),
                    // d(u v) = du v + u dv (a row times a column too)
                    BinOp::Mul => plus(times_after(du, v)?, times(Some(u), dv)?),
                    // d(u / v) = du / v − u dv / v²
                    BinOp::Div => {
                        if v.kind != Kind::Scalar {
                            return None;
                        }
                        quotient(u, &v, du, dv)
                    }
                    // d(u^n) = n u^(n−1) du, for a number n
                    BinOp::Pow => {
                        if dv.is_some() || u.kind != Kind::Scalar {
                            return None;
                        }
                        let (n, typed) = match &v.step {
                            Step::Leaf(x @ Value::Num { exact, .. }) => {
                                (x.as_scalar()?, matches!(exact, Exact::Typed))
                            }
                            _ => return None,
                        };
                        if n == 0.0 {
                            return Some(None);
                        }
                        // (n as it came, exact or not; n − 1 exact only
                        // when n is a whole number or half as typed)
                        let n_minus_1 = Recipe::leaf(Value::Num {
                            kind: Kind::Scalar,
                            m: crate::values::num::Num::Scalar(n - 1.0),
                            exact: if typed {
                                exact_constant(&[n])
                            } else {
                                Exact::Float
                            },
                        });
                        let power = arith(BinOp::Pow, u.clone(), n_minus_1)?;
                        let f = arith(BinOp::Mul, v.clone(), power);
                        times(f, du)
                    }
                }
            }
            // a scalar part of a vector or matrix: the same part of its
            // derivative
            Step::Op(Operation::Index(_) | Operation::Member(_)) | Step::Retag => {
                linear(&r.step, self.of(&x(0)?)?, k)
            }
            Step::Op(Operation::Call(name)) => self.call(name, &r.args),
            // `[x]` of a scalar is the scalar, 1 × 1
            Step::Op(Operation::Block(_)) if r.args.len() == 1 && x(0)?.kind == Kind::Scalar => {
                self.of(&x(0)?)
            }
            _ => None,
        }
    }

    /// The derivative of a vector or matrix step (of shape `k`).
    fn matrix_step(&mut self, r: &Rc<Recipe>, k: Kind) -> Option<D> {
        let x = |i: usize| r.args.get(i).cloned();
        match &r.step {
            Step::Op(Operation::Transpose | Operation::Index(_) | Operation::Member(_))
            | Step::Retag => linear(&r.step, self.of(&x(0)?)?, k),
            Step::Op(Operation::Arith(op)) => {
                let (u, v) = (x(0)?, x(1)?);
                let (du, dv) = (self.of(&u)?, self.of(&v)?);
                match op {
                    BinOp::Add => plus(du, dv),
                    BinOp::Sub => plus(du, neg(dv)?),
                    BinOp::Mul => plus(times_after(du, v.clone())?, times_point(u, &v, dv)?),
                    // M / s = M (1/s)
                    BinOp::Div if v.kind == Kind::Scalar => quotient(u, &v, du, dv),
                    // d(M^n) = Σ M^j dM M^(n−1−j), for a whole n ≥ 1
                    BinOp::Pow if dv.is_none() => {
                        let n = match &v.step {
                            Step::Leaf(n) => n.as_scalar()?,
                            _ => return None,
                        };
                        if n.fract() != 0.0 || !(1.0..=16.0).contains(&n) {
                            return None;
                        }
                        let n = n as i32;
                        let power = |j: i32| pow(&u, f64::from(j));
                        let mut sum: D = None;
                        for j in 0..n {
                            let mut term = du.clone();
                            if j > 0 {
                                term = times(Some(power(j)?), term)?;
                            }
                            if n - 1 - j > 0 {
                                term = times_after(term, power(n - 1 - j)?)?;
                            }
                            sum = plus(sum, term)?;
                        }
                        Some(sum)
                    }
                    _ => None,
                }
            }
            Step::Op(Operation::Vector | Operation::Block(_)) => {
                let mut ds = Vec::with_capacity(r.args.len());
                let mut any = false;
                for a in &r.args {
                    let d = self.of(a)?;
                    any |= d.is_some();
                    ds.push(d.unwrap_or_else(|| zero(&shape(a).unwrap_or(Kind::Scalar))));
                }
                if !any {
                    return Some(None);
                }
                Some(Some(node_k(r.step.clone(), ds, k)?))
            }
            Step::Op(Operation::Call(name)) => self.matrix_call(name, r, k),
            _ => None,
        }
    }

    /// The derivative of a builtin whose value is a vector or matrix.
    fn matrix_call(&mut self, name: &str, r: &Rc<Recipe>, k: Kind) -> Option<D> {
        let b = crate::builtins::lookup(name)?;
        let args = &r.args;
        let u = args.first()?.clone();
        let du = self.of(&u)?;
        match b.name {
            // linear in their one operand
            "transpose" | "VecToso3" | "VecTose3" | "so3ToVec" | "se3ToVec" | "untag" | "vee"
                if args.len() == 1 =>
            {
                linear(&r.step, du, k)
            }
            // bilinear: d(u × v) = du × v + u × dv
            "cross" if args.len() == 2 => {
                let v = args[1].clone();
                let dv = self.of(&v)?;
                let a = match du {
                    None => None,
                    Some(du) => Some(node_k(r.step.clone(), vec![du, v], k)?),
                };
                let b = match dv {
                    None => None,
                    Some(dv) => Some(node_k(r.step.clone(), vec![u, dv], k)?),
                };
                plus(a, b)
            }
            // dRotz(u) = Rotz(u) [ẑ] du (and x, y alike)
            "Rotx" | "Roty" | "Rotz" if args.len() == 1 && u.kind == Kind::Scalar => {
                let g: [f64; 9] = match b.name {
                    "Rotx" => [0., 0., 0., 0., 0., -1., 0., 1., 0.],
                    "Roty" => [0., 0., 1., 0., 0., 0., -1., 0., 0.],
                    _ => [0., -1., 0., 1., 0., 0., 0., 0., 0.],
                };
                let rg = arith(BinOp::Mul, r.clone(), matrix(3, 3, &g, Kind::So3))?;
                times_after(du, rg)
            }
            // d Rot(ω̂, θ) = [ω̂] Rot(ω̂, θ) dθ for a constant axis (3.51)
            "Rot" if args.len() == 2 => {
                let (w, t) = (u, args[1].clone());
                if du.is_some() {
                    return None;
                }
                let dt = self.of(&t)?;
                let unit = node_k(
                    Step::Op(Operation::Call("Normalize")),
                    vec![w],
                    Kind::Vector(Some(3)),
                )?;
                let hat = node_k(Step::Op(Operation::Call("VecToso3")), vec![unit], Kind::So3)?;
                let f = arith(BinOp::Mul, hat, r.clone());
                times_after(dt, f?)
            }
            // d exp(A u) = A exp(A u) du for a constant A ([S] θ, [ω̂] θ)
            "exp" | "MatrixExp3" | "MatrixExp6" if args.len() == 1 => {
                let Step::Op(Operation::Arith(BinOp::Mul)) = u.step else {
                    return None;
                };
                let (p, q) = (u.args.first()?.clone(), u.args.get(1)?.clone());
                let (a, s) = match (p.kind, q.kind) {
                    (Kind::Scalar, Kind::Scalar) => return None,
                    (Kind::Scalar, _) => (q, p),
                    (_, Kind::Scalar) => (p, q),
                    _ => return None,
                };
                if self.of(&a)?.is_some() {
                    return None;
                }
                let ds = self.of(&s)?;
                let f = arith(BinOp::Mul, a, r.clone())?;
                times_after(ds, f)
            }
            // the inverse maps of a rotation, by their rates on the
            // numbers' branch (rates.rs)
            "euler_zyx" | "euler_zxz" | "rpy" | "quat" | "cayley"
                if args.len() == 1
                    && shape(&u).and_then(|k| k.shape()) == Some((Some(3), Some(3))) =>
            {
                let Some(du) = du else {
                    return Some(None);
                };
                Some(Some(rates::of(b.name, r, &u, du)?))
            }
            // d [R, p; 0, 1] = [dR, dp; 0, 0]
            "RpToTrans" if args.len() == 2 => {
                let p = args[1].clone();
                let dp = self.of(&p)?;
                if du.is_none() && dp.is_none() {
                    return Some(None);
                }
                let dr = du.unwrap_or_else(|| zero(&Kind::Matrix(Some(3), Some(3))));
                let dp = dp.unwrap_or_else(|| zero(&Kind::Vector(Some(3))));
                let row = matrix(1, 3, &[0.0; 3], Kind::Matrix(Some(1), Some(3)));
                let parts = vec![dr, dp, row, number(0.0)];
                Some(Some(node_k(
                    Step::Op(Operation::Block(Box::new([2, 2]))),
                    parts,
                    k,
                )?))
            }
            // d(R⁻¹) = dRᵀ for a rotation (R⁻¹ = Rᵀ): no products that
            // cancel, so an entry exactly 0 stays 0 (matrix differential
            // seed 831222 gave −5.3e-19 by the general rule below)
            "inv" | "RotInv" if args.len() == 1 && u.kind == Kind::SO3 => linear(
                &Step::Op(Operation::Transpose),
                du,
                Kind::Matrix(Some(3), Some(3)),
            ),
            // d(M⁻¹) = −M⁻¹ dM M⁻¹
            "inv" | "RotInv" | "TransInv" if args.len() == 1 => {
                let Some(du) = du else {
                    return Some(None);
                };
                let left = arith(BinOp::Mul, r.clone(), du)?;
                neg(Some(arith(BinOp::Mul, left, r.clone())?))
            }
            // d Ad_T = Ad_T [ad_V], [V] = T⁻¹ dT (for T in SE(3))
            "Adjoint" if args.len() == 1 && u.kind == Kind::SE3 => {
                let Some(du) = du else {
                    return Some(None);
                };
                let tinv = node_k(Step::Op(Operation::Call("TransInv")), vec![u], Kind::SE3)?;
                let body = arith(BinOp::Mul, tinv, du)?;
                let v = node_k(
                    Step::Op(Operation::Call("se3ToVec")),
                    vec![body],
                    Kind::Vector(Some(6)),
                )?;
                let ad = node_k(
                    Step::Op(Operation::Call("ad")),
                    vec![v],
                    Kind::Matrix(Some(6), Some(6)),
                )?;
                Some(Some(arith(BinOp::Mul, r.clone(), ad)?))
            }
            _ => None,
        }
    }

    /// A leaf's derivative by the canonical engine (a number's is 0).
    fn leaf(&mut self, v: &Value, kind: &Kind) -> Option<D> {
        match v {
            Value::Num { .. } => Some(None),
            Value::Formula { .. } => {
                match crate::builtins::eval_symbolic("diff", &[v.clone(), self.by.clone()], kind)?
                    .ok()?
                {
                    d @ Value::Num { .. } if d.as_scalar() == Some(0.0) => Some(None),
                    Value::Num { m, .. } if m.iter().all(|x| *x == 0.0) => Some(None),
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
            // d(u · v) = du · v + u · dv
            "dot" => {
                let v = args.get(1)?.clone();
                let dv = self.of(&v)?;
                let a = match du {
                    None => None,
                    Some(du) => Some(call("dot", vec![du, v])?),
                };
                let b = match dv {
                    None => None,
                    Some(dv) => Some(call("dot", vec![u, dv])?),
                };
                return plus(a, b);
            }
            "trace" => return linear(&Step::Op(Operation::Call("trace")), du, Kind::Scalar),
            // Jacobi's formula, column by column (rates.rs)
            "det" if args.len() == 1 => {
                let Some(du) = du else { return Some(None) };
                let n = match shape(&u)?.shape()? {
                    (Some(r), Some(c)) if r == c => r,
                    _ => return None,
                };
                return Some(Some(rates::det(&u, &du, n)?));
            }
            _ if u.kind != Kind::Scalar => return None,
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
