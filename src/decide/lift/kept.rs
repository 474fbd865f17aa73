//! Numbers the lift keeps exactly where the symbolic engine would make a
//! float (issue 35): a square root with no exact form is kept as a call,
//! whose square is its argument (`sin(π/5)` against `√((5 − √5)/8)`), and
//! e^q for a rational q is ε^(qN), N = 27720, ε standing for e^{1/N}:
//! products and sums of such exponentials are then Laurent polynomials in
//! ε (`exp(-1/2) + exp(-3/2) == (1 + exp(1)) exp(-3/2)`). An identity of
//! the forms holds at ε = e^{1/N}: equal forms are equal numbers.

use super::exact;
use crate::sym::Mat;
use crate::sym::coef::{Coef, Rat};
use crate::sym::expr::{Expr, Symbol, Var};
use crate::values::exact::Operation;
use crate::values::value::Value;

/// The symbol ε that stands for e^{1/N} (no typed name holds ⟨).
const EPSILON: &str = "⟨ε⟩";

/// The common denominator of the exponents read exactly: lcm(1, …, 12).
const N: i64 = 27720;

/// The kept form of `op` over lifted operands `forms` (the module's doc),
/// None when it is not one of these.
pub(super) fn kept(op: &Operation, forms: &[Value]) -> Option<Mat> {
    let (Operation::Call(name), [Value::Formula { m, .. }]) = (op, forms) else {
        return None;
    };
    if m.data.len() != 1 || !exact(&m.data[0]) {
        return None;
    }
    let x = &m.data[0];
    match crate::builtins::lookup(name)?.name {
        "sqrt" => Some(Mat::scalar(Expr::sqrt_kept(x))),
        "exp" => {
            let q = x.as_const().and_then(|c| c.as_rat())?;
            let k = q.mul(&Rat::int(N)).as_int()?;
            let k = i32::try_from(k).ok()?;
            let mut e = Expr::default();
            if k == 0 {
                e.push(Vec::new(), Coef::one());
            } else {
                e.push(vec![(Var::Sym(Symbol::new(EPSILON)), k)], Coef::one());
            }
            Some(Mat::scalar(e))
        }
        _ => None,
    }
}
