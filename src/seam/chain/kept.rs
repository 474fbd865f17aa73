//! The chain rule through calls kept over symbols (LANGUAGE.md §7:
//! `given a; R = Rot((1, a, 2), a); D = diff(R, a); a = 0.3; D` is a
//! number, as typed first). A call with no closed form over symbols (the
//! rotation about an axis that is no unit vector, the exponential of a
//! general so(3) or se(3) matrix, `AxisAng3`, `AxisAng6`, a log, a norm)
//! has, at numbers, a derivative all the same: its rate at the numbers
//! ([`Step::Rate`], computed by `decide::rate` from the book's maps in
//! `lie`). Where the closed steps of the chain rule (mod.rs) do not reach
//! a step, these rates do, for the derivative of a kept call only
//! ([`of_kept`]): a formula's derivative stays the closed one.

use std::collections::HashMap;
use std::rc::Rc;

use super::build::{arith, node_k, shape, zero};
use super::{Chain, D};
use crate::check::ty::Kind;
use crate::syntax::ast::BinOp;
use crate::values::recipe::{Operation, Recipe, Step};
use crate::values::value::Value;

/// The derivative by `by` of the value recipe `r` makes (a kept call's
/// tree, made into a recipe over its formulas), with the rates at numbers
/// where no closed step reaches; None where neither does.
pub(crate) fn of_kept(r: &Rc<Recipe>, by: &Value) -> Option<Rc<Recipe>> {
    let kind = shape(r)?;
    let mut memo = HashMap::new();
    let d = Chain {
        by,
        memo: &mut memo,
        top: (Rc::as_ptr(r), kind),
        rates: true,
    }
    .of(r)?;
    Some(d.unwrap_or_else(|| zero(&kind)))
}

impl Chain<'_> {
    /// The derivative of a step no closed rule reaches, by the rate of
    /// its call at the numbers.
    pub(super) fn rated(&mut self, r: &Rc<Recipe>) -> Option<D> {
        // `[x]` of a vector over symbols, recorded with no shape: [ω] is
        // 3×3, [V] 4×4, and linear (d[x] = [dx])
        if let (Step::Op(Operation::Block(w)), [x], None) = (&r.step, r.args.as_slice(), shape(r))
            && **w == [1]
        {
            let k = match shape(x)? {
                Kind::Vector(Some(3)) => Kind::Matrix(Some(3), Some(3)),
                Kind::Vector(Some(6)) => Kind::Matrix(Some(4), Some(4)),
                _ => return None,
            };
            let Some(dx) = self.of(x)? else {
                return Some(None);
            };
            return Some(Some(node_k(r.step.clone(), vec![dx], k)?));
        }
        let k = shape(r)?;
        match &r.step {
            Step::Op(Operation::Call(name)) => {
                let b = crate::builtins::lookup(name)?;
                match (b.name, r.args.as_slice()) {
                    // Rot(ω, θ) = exp([ω/‖ω‖] θ) (3.51), ω ≠ 0
                    ("Rot", [w, t]) => {
                        let unit = node_k(
                            Step::Op(Operation::Call("Normalize")),
                            vec![w.clone()],
                            Kind::Vector(Some(3)),
                        )?;
                        let hat =
                            node_k(Step::Op(Operation::Call("VecToso3")), vec![unit], Kind::So3)?;
                        let a = arith(BinOp::Mul, hat, t.clone())?;
                        self.rate("exp", None, &a, k)
                    }
                    (
                        name @ ("exp" | "MatrixExp3" | "MatrixExp6" | "log" | "MatrixLog3"
                        | "MatrixLog6" | "norm" | "Normalize" | "abs"),
                        [u],
                    ) => self.rate(name, None, u, k),
                    // d Trans(p) = [0, dp; 0, 0]
                    ("Trans", [p]) => {
                        let Some(dp) = self.of(p)? else {
                            return Some(None);
                        };
                        let m = Kind::Matrix(Some(3), Some(3));
                        let row = zero(&Kind::Matrix(Some(1), Some(3)));
                        let parts = vec![zero(&m), dp, row, super::build::number(0.0)];
                        let block = Step::Op(Operation::Block(Box::new([2, 2])));
                        Some(Some(node_k(block, parts, k)?))
                    }
                    _ => None,
                }
            }
            // M^0 = I, M^-1 = inv(M): d(M⁻¹) = −M⁻¹ dM M⁻¹
            Step::Op(Operation::Arith(BinOp::Pow)) => {
                let [m, n] = r.args.as_slice() else {
                    return None;
                };
                let Step::Leaf(n) = &n.step else { return None };
                match n.as_scalar()? {
                    0.0 => Some(None),
                    -1.0 => {
                        let Some(dm) = self.of(m)? else {
                            return Some(None);
                        };
                        let left = arith(BinOp::Mul, r.clone(), dm)?;
                        super::build::neg(Some(arith(BinOp::Mul, left, r.clone())?))
                    }
                    _ => None,
                }
            }
            // a part of a tuple a call gives: AxisAng3(x)[1], TransToRp(T)[2]
            Step::Part(i) => {
                let call = r.args.first()?;
                let Step::Op(Operation::Call(name)) = &call.step else {
                    return None;
                };
                let b = crate::builtins::lookup(name)?;
                match (b.name, call.args.as_slice()) {
                    (name @ ("AxisAng3" | "AxisAng6" | "TransToRp"), [u]) => {
                        self.rate(name, Some(*i), u, k)
                    }
                    _ => None,
                }
            }
            _ => None,
        }
    }

    /// The rate of builtin `name` (its part `part`) at `u` moving with
    /// u's derivative, of shape `k` (0 where u does not move).
    fn rate(
        &mut self,
        name: &'static str,
        part: Option<usize>,
        u: &Rc<Recipe>,
        k: Kind,
    ) -> Option<D> {
        let Some(du) = self.of(u)? else {
            return Some(None);
        };
        Some(Some(node_k(
            Step::Rate(name, part),
            vec![u.clone(), du],
            k,
        )?))
    }
}
