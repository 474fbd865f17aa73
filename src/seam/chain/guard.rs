//! The derivative of a closed form on a branch (`recipe::Step::Closed`:
//! `MatrixLog6` of a symbolic transform is its form for 1 − cos u > 0 and
//! u in (−π, π)). Where the chain rule reaches the call itself (the rates
//! of the Euler angles, rates.rs) its derivative is right on every
//! branch; elsewhere it is the closed form's derivative, which holds on
//! the branch only, so it is guarded (`Step::Guard`): replayed where the
//! numbers are on the branch and refused off it. `diff(MatrixLog6(T), u)`
//! at u = 4 printed the branch's formula there (entry 4: −1.4383; the log
//! at u = 4 is the angle 4 − 2π, and its derivative 0.4615).

use std::rc::Rc;

use super::build::{node_k, zero};
use super::{Chain, D};
use crate::check::ty::Kind;
use crate::values::recipe::{OnBranch, Operation, Recipe, Step};
use crate::values::value::Value;

/// `v`, the value of builtin `name` over `args` made with its recipe,
/// marked as a closed form on a branch where it is one (LANGUAGE.md §7:
/// the note says which, and numbers bound later that leave it say so,
/// `decide::replay`). The log of a symbolic transform guards its
/// derivative ([`OnBranch::guards`]); the other marks (the log of a
/// rotation, whose closed forms are ω̂θ about a fixed axis: off the
/// branch the log is ω̂(θ − 2πk), of the same derivative ω̂ dθ) leave
/// the chain rule as it was.
pub(in crate::seam) fn closed_form(name: &str, v: Value, args: &[&Value]) -> Value {
    let Value::Formula {
        kind,
        m,
        how: Some(r),
    } = &v
    else {
        return v;
    };
    let transform = |a: &Value| matches!(a.kind().shape(), Some((Some(4), Some(4))));
    let guards = matches!(name, "log" | "MatrixLog6") && args.first().is_some_and(|a| transform(a));
    let marked = matches!(
        name,
        "log" | "MatrixLog3" | "quat" | "cayley" | "atan2" | "euler_zyx" | "euler_zxz" | "rpy"
    );
    if !guards && !marked {
        return v;
    }
    let vals: Vec<Value> = args.iter().map(|a| (*a).clone()).collect();
    let Some((b, text)) = crate::builtins::branch_of(name, &vals) else {
        return v;
    };
    let on = OnBranch {
        form: Value::Formula {
            kind: *kind,
            m: m.clone(),
            how: None,
        },
        positive: b.positive,
        angles: b.angles,
        text,
        guards,
        everywhere: matches!(name, "log" | "MatrixLog3") && !guards,
    };
    match Recipe::node(Step::Closed(Rc::new(on)), vec![r.clone()], r.kind) {
        Some(how) => Value::Formula {
            kind: *kind,
            m: m.clone(),
            how: Some(how),
        },
        None => v,
    }
}

impl Chain<'_> {
    /// The derivative of `call`, marked as the closed form `on` (a step of
    /// shape `k`): the call's own where the chain rule reaches it (right
    /// on every branch), else the closed form's, guarded. Unguarded,
    /// `diff(euler_zxz(rot_quat((cos(u), -sin(u), 0, 0))), u)` at u = −0.688
    /// (off the branch sin 2u > 0, where the angle is −2u) was the closed
    /// form's (0, 2, 0), not (0, −2, 0), and said nothing.
    pub(super) fn closed(&mut self, on: &Rc<OnBranch>, call: &Rc<Recipe>, k: Kind) -> Option<D> {
        if let Some(d) = self.of(call) {
            return Some(d);
        }
        let d = self.leaf(&on.form, &k)?.unwrap_or_else(|| zero(&k));
        if on.everywhere {
            return Some(Some(d));
        }
        let rate = if on.guards {
            self.log_rate(call, k)
        } else {
            None
        };
        guarded(on, d, rate, k)
    }

    /// The derivative of a guarded derivative: guarded alike (with no rate
    /// off the branch: the rate's own derivative is not written).
    pub(super) fn guard(&mut self, on: &Rc<OnBranch>, x: &Rc<Recipe>, k: Kind) -> Option<D> {
        let d = self.of(x)?.unwrap_or_else(|| zero(&k));
        guarded(on, d, None, k)
    }

    /// The rate of `call`, the log of a transform T (`MatrixLog6(T)`, a
    /// 6-vector, or `log(T)`, its se(3) matrix), from T's derivative
    /// ([`Step::LogRate`]); None where T's derivative is not reached.
    fn log_rate(&mut self, call: &Rc<Recipe>, k: Kind) -> Option<Rc<Recipe>> {
        let t = call.args.first()?.clone();
        let dt = self
            .of(&t)?
            .unwrap_or_else(|| zero(&Kind::Matrix(Some(4), Some(4))));
        let rate = node_k(Step::LogRate, vec![t, dt], Kind::Vector(Some(6)))?;
        match k.shape() {
            Some((Some(6), Some(1))) => Some(rate),
            _ => node_k(Step::Op(Operation::Call("VecTose3")), vec![rate], k),
        }
    }
}

/// `d` where the numbers are on `on`'s branch (a zero too: off it the
/// derivative need not be 0), else `rate` where there is one.
fn guarded(on: &Rc<OnBranch>, d: Rc<Recipe>, rate: Option<Rc<Recipe>>, k: Kind) -> Option<D> {
    let args = match rate {
        Some(rate) => vec![d, rate],
        None => vec![d],
    };
    Some(Some(node_k(Step::Guard(on.clone()), args, k)?))
}
