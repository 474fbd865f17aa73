//! How a value made from symbols was made (LANGUAGE.md §7: once every
//! symbol of a value has a number, the value *is* a number, exactly as if
//! the numbers had been typed first). A symbolic scalar, vector or matrix
//! ([`super::value::Value::Formula`]) keeps, beside its canonical form, the
//! operations that made it: each step one operation of the evaluator's
//! seam (`seam::apply::Op`) over the recipes of its operands, down to
//! leaves that are numbers or formulas made by no replayable operation (a
//! `given` symbol, a derivative). Once its symbols have numbers the value
//! is computed by replaying these steps with numbers (`decide::replay`),
//! never from the expanded canonical form, whose large alternating
//! coefficients can cancel in floating point: `(sin a + cos b)^30` at
//! a = 0.3, b = −1.1 is 1.72376e-4 replayed and 1.72299e-4 expanded.
//!
//! A recipe is a DAG (operands made once and used twice are shared, by
//! [`Rc`]) that holds no names: a value keeps what it was made of when it
//! was made, so rebinding a name it read changes nothing.

use std::collections::HashMap;
use std::rc::Rc;

pub use super::operation::Operation;
use super::value::Value;
use crate::check::ty::Kind;

/// The deepest recipe kept: a value made by a longer chain of operations
/// keeps none and is a leaf of the values made from it (its canonical
/// form, evaluated at the numbers), so that replaying a recipe stays
/// within memory (each step replayed grows the stack on the heap, a few
/// hundred bytes; dropping one does not recurse, [`Recipe`]'s `Drop`).
pub const MAX_DEPTH: u32 = 20_000;

/// One step of a recipe: an operation of the evaluator's seam with its
/// data owned ([`Operation`]), a leaf, or one of the steps only a recipe
/// needs (a part of a tuple, a kind given by a name, a comparison).
#[derive(Debug, Clone)]
pub enum Step {
    /// An operand as it was: a number, or a formula no replayable
    /// operation made (a `given` symbol `a`, the rate `q̇`, `diff(x, t)`),
    /// evaluated from its canonical form at the numbers.
    Leaf(Value),
    /// An operation of the seam over the step's operands.
    Op(Operation),
    /// Part `i` of the tuple its one operand gives (`euler_zyx(R)`'s angles).
    Part(usize),
    /// Its one operand, with the kind its name gave it when it was bound
    /// (`V_b = (…)` is a twist).
    Retag,
    /// `start:end` (false) or `start:step:end` (true) over its three
    /// bounds (the step 1 when none was typed): the list, once they have
    /// numbers (`super::waiting`).
    Range(bool),
    /// `a == b`, `a ≈ b`, `a < b`, …: a bool, decided with the numbers as
    /// typed first (over free symbols `==` asks for an identity).
    Compare(crate::syntax::ast::CmpOp),
    /// Its one operand, a call whose value over symbols is a closed form
    /// on a branch ([`OnBranch`]; `MatrixLog6` of a symbolic transform):
    /// replayed as the call (right on every branch), and marking for the
    /// chain rule the closed form whose derivative holds on the branch.
    Closed(Rc<OnBranch>),
    /// Its first operand where the numbers are on the branch of
    /// [`OnBranch`]: the derivative of a closed form holds on the closed
    /// form's branch only. Off it (or too near its bounds to tell), the
    /// second operand where there is one (the rate, [`Step::LogRate`],
    /// right on every branch), else refused.
    Guard(Rc<OnBranch>),
    /// The rate of the exponential coordinates (`MatrixLog6`) of its first
    /// operand, a transform T, moving with its second, Ṫ:
    /// [`crate::lie::dlog::se3_log_rate`], right on every branch of the
    /// logarithm; refused at a half turn, where the logarithm jumps.
    LogRate,
    /// The rate of builtin `name` (part `i` of the tuple it gives, if
    /// `Some(i)`) at its one operand, the first, moving with the second,
    /// that operand's rate: from the numbers (`decide::rate`, over
    /// [`crate::lie::rates`]), where no closed step gives the derivative
    /// (the exponential of an so(3) matrix over symbols, `AxisAng6`, a
    /// norm), for a `diff` of a call kept over symbols. Refused where the
    /// call has no derivative at the numbers (a norm at 0, a log at a
    /// half turn).
    Rate(&'static str, Option<usize>),
}

/// A closed form over symbols that holds on a branch (LANGUAGE.md §7: the
/// note says which; `crate::sym::branch`): `MatrixLog6` of
/// `RpToTrans(Rotz(u), p)` is its form for 1 − cos u > 0 and u in (−π, π).
#[derive(Debug)]
pub struct OnBranch {
    /// The closed form, a formula.
    pub form: Value,
    /// What is positive on the branch.
    pub positive: Vec<crate::sym::Expr>,
    /// The angles in (−π, π] on the branch (or (−π, π): the floats
    /// cannot tell π from either side of it, so the two are decided alike).
    pub angles: Vec<crate::sym::Expr>,
    /// The branch as the note says it.
    pub text: String,
    /// Whether a derivative of the closed form holds on the branch only
    /// ([`Step::Guard`]: the log of a symbolic transform). The closed
    /// forms of the log of a rotation, the Euler angles, `quat`, `cayley`
    /// and `atan2` are marked only so that numbers off their branch say
    /// so (§7); their derivatives are the call's, right on every branch.
    pub guards: bool,
    /// Whether the closed form's own derivative is right off the branch
    /// too (the log of a rotation, ω̂θ about a fixed axis: off the branch
    /// it is ω̂(θ − 2πk), of the same derivative); else, where the chain
    /// rule does not reach the call, that derivative is guarded.
    pub everywhere: bool,
}

impl OnBranch {
    /// The same branch with each formula `leaf` gives a new value for
    /// replaced (the form and each condition: `subs` of a closed form).
    fn rebase(&self, leaf: &dyn Fn(&Value) -> Option<Value>) -> OnBranch {
        let each = |es: &[crate::sym::Expr]| -> Vec<crate::sym::Expr> {
            es.iter()
                .map(|e| {
                    let v = Value::Formula {
                        kind: Kind::Scalar,
                        m: crate::sym::Mat::scalar(e.clone()),
                        how: None,
                    };
                    match leaf(&v) {
                        Some(Value::Formula { m, .. }) if m.data.len() == 1 => m.data[0].clone(),
                        Some(v) => v
                            .as_scalar()
                            .map_or_else(|| e.clone(), crate::sym::Expr::num),
                        None => e.clone(),
                    }
                })
                .collect()
        };
        OnBranch {
            form: leaf(&self.form).unwrap_or_else(|| self.form.clone()),
            positive: each(&self.positive),
            angles: each(&self.angles),
            text: self.text.clone(),
            guards: self.guards,
            everywhere: self.everywhere,
        }
    }

    /// Whether numbers (`at`, each symbol's float) are on the branch:
    /// Some(false) when a condition fails by more than rounding, None when
    /// one is within 1e-12 of its bound or has no number (the floats
    /// cannot tell).
    pub fn holds(&self, at: &dyn Fn(&crate::sym::Symbol) -> Option<f64>) -> Option<bool> {
        const TOL: f64 = 1e-12;
        let pi = std::f64::consts::PI;
        let mut sure = true;
        for p in &self.positive {
            let x = p.eval(at)?;
            if x < -TOL {
                return Some(false);
            }
            sure &= x > TOL;
        }
        for a in &self.angles {
            let x = a.eval(at)?;
            if x.abs() > pi + TOL {
                return Some(false);
            }
            // (a constant angle is what it is: the π of `(π, θ, π)` is
            // on the branch, not near its bound)
            let mut syms = Vec::new();
            a.symbols(&mut syms);
            sure &= x.abs() < pi - TOL || syms.is_empty();
        }
        sure.then_some(true)
    }

    /// The first condition of the branch that numbers `at` break by more
    /// than rounding, as the note says it (`θ = 4 is not in (−π, π)`);
    /// None when they are on the branch or too near its bounds to tell
    /// ([`OnBranch::holds`]).
    pub fn broken(&self, at: &dyn Fn(&crate::sym::Symbol) -> Option<f64>) -> Option<String> {
        if self.holds(at) != Some(false) {
            return None;
        }
        let show = |e: &crate::sym::Expr, x: f64| {
            format!(
                "{} = {}",
                crate::sym::print::expr(e, Default::default()),
                crate::values::number::fmt_num(x, 4)
            )
        };
        let pi = std::f64::consts::PI;
        let angle = self.angles.iter().find_map(|a| {
            let x = a.eval(at)?;
            (x.abs() > pi + 1e-12).then(|| format!("{} is outside [−π, π]", show(a, x)))
        });
        angle.or_else(|| {
            self.positive.iter().find_map(|p| {
                let x = p.eval(at)?;
                (x < -1e-12).then(|| format!("{} is negative", show(p, x)))
            })
        })
    }
}

/// A recipe: a step over the recipes of its operands, with the kind the
/// checker gave its result.
pub struct Recipe {
    /// The operation (or leaf) that made the value.
    pub step: Step,
    /// The recipes of its operands, in the operation's order.
    pub args: Vec<Rc<Recipe>>,
    /// The result's kind as checked (what the numeric operation is given,
    /// as when the numbers are typed first).
    pub kind: Kind,
    /// The longest chain of steps down to a leaf (a leaf is 0).
    pub depth: u32,
    /// The symbols of its leaves, kept the first time [`symbols`] is
    /// asked (a chain `x = x + 0.1` read at every step is then walked
    /// once, not once per step).
    syms: std::cell::OnceCell<Vec<crate::sym::Symbol>>,
}

impl std::fmt::Debug for Recipe {
    /// The step and its depth only: the operands are shared, and printing
    /// them all could take exponential room.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.step {
            Step::Leaf(_) => write!(f, "Recipe(leaf)"),
            step => write!(f, "Recipe({step:?}, depth {})", self.depth),
        }
    }
}

impl Drop for Recipe {
    /// Drops the operands no other recipe shares one by one, without
    /// recursion: a chain of thousands of steps (a statement repeated in a
    /// long script) must not overflow the stack.
    fn drop(&mut self) {
        let mut stack = std::mem::take(&mut self.args);
        while let Some(r) = stack.pop() {
            if let Ok(mut inner) = Rc::try_unwrap(r) {
                stack.append(&mut inner.args);
            }
        }
    }
}

impl Recipe {
    /// A leaf: `v` as it is.
    pub fn leaf(v: Value) -> Rc<Recipe> {
        let kind = v.kind();
        Rc::new(Recipe {
            step: Step::Leaf(v),
            args: Vec::new(),
            kind,
            depth: 0,
            syms: Default::default(),
        })
    }

    /// `step` over `args`; None when the chain would be deeper than
    /// [`MAX_DEPTH`].
    pub fn node(step: Step, args: Vec<Rc<Recipe>>, kind: Kind) -> Option<Rc<Recipe>> {
        let depth = 1 + args.iter().map(|a| a.depth).max().unwrap_or(0);
        (depth <= MAX_DEPTH).then(|| {
            Rc::new(Recipe {
                step,
                args,
                kind,
                depth,
                syms: Default::default(),
            })
        })
    }

    /// The recipe of an operand value: a formula's own (retagged when its
    /// binding gave it another kind), else the value itself as a leaf.
    pub fn of(v: &Value) -> Rc<Recipe> {
        match v {
            Value::Formula {
                how: Some(r), kind, ..
            } if r.kind != *kind && !vague(kind) && !vague(&r.kind) => {
                Recipe::node(Step::Retag, vec![r.clone()], *kind).unwrap_or_else(|| r.clone())
            }
            Value::Formula { how: Some(r), .. } => r.clone(),
            Value::Formula { how: None, kind, m } => Recipe::leaf(Value::Formula {
                kind: *kind,
                m: m.clone(),
                how: None,
            }),
            other => Recipe::leaf(other.clone()),
        }
    }
}

/// What an operation of the seam records of how it made a value.
pub enum Made {
    /// Its step over its operands.
    Step(Step),
    /// The value is its first operand, rewritten (`simplify`, `expand`).
    Same,
    /// The operation reads its operands' symbols, not their values
    /// (`diff(x, t)`, `subs(x, t, 0.5)`): the result is a leaf.
    Opaque,
}

/// `v`, the result of an operation on `args` by the exact path, with how
/// it was made: a formula gets the step over its operands' recipes, each
/// formula in a tuple the part it is of that step. `kind` is the result's
/// kind as checked.
pub fn record(v: Value, made: Made, args: &[&Value], kind: &Kind) -> Value {
    // A number made from formulas (`a/a` is 1) depends on their symbols:
    // it stays a formula, of constant entries, made by its step.
    let v = match v {
        Value::Num { kind, m, exact }
            if !matches!(made, Made::Opaque)
                && args.iter().any(|a| matches!(a, Value::Formula { .. })) =>
        {
            Value::Formula {
                kind,
                m: constant(&m, &exact),
                how: None,
            }
        }
        v => v,
    };
    if !matches!(v, Value::Formula { .. } | Value::Tuple(_)) {
        return v;
    }
    let how = match made {
        Made::Opaque => return v,
        Made::Same => args.first().map(|a| Recipe::of(a)),
        Made::Step(step) => Recipe::node(step, args.iter().map(|a| Recipe::of(a)).collect(), *kind),
    };
    attach(v, how)
}

/// The bool of comparison `op` decided `verdict` over sides `a`, `b` of
/// which one at least is a formula: a formula of kind bool (1 or 0) made
/// by the comparison, decided again with the numbers once its symbols
/// have them (`y = a == 2` is false for every a, and true at a = 2, as
/// typed first). Else the bool itself.
pub fn compared(verdict: bool, op: crate::syntax::ast::CmpOp, a: &Value, b: &Value) -> Value {
    let symbolic = |v: &Value| matches!(v, Value::Formula { .. });
    let numbers = |v: &Value| matches!(v, Value::Formula { .. } | Value::Num { .. });
    if !(symbolic(a) || symbolic(b)) || !numbers(a) || !numbers(b) {
        return Value::Bool(verdict);
    }
    let how = Recipe::node(
        Step::Compare(op),
        vec![Recipe::of(a), Recipe::of(b)],
        Kind::Bool,
    );
    let one = crate::sym::Expr::constant(crate::sym::coef::Coef::rat(crate::sym::coef::Rat::int(
        i64::from(verdict),
    )));
    match how {
        Some(how) => Value::Formula {
            kind: Kind::Bool,
            m: crate::sym::Mat::scalar(one),
            how: Some(how),
        },
        None => Value::Bool(verdict),
    }
}

/// Numbers `m` as a formula of constant entries: their exact form, else
/// their floats.
fn constant(m: &super::num::Num, exact: &super::exact::Exact) -> crate::sym::Mat {
    if let Some(form) = exact.form(m) {
        return form;
    }
    let (r, c) = m.shape();
    let data = (0..r)
        .flat_map(|i| (0..c).map(move |j| (i, j)))
        .map(|(i, j)| crate::sym::Expr::num(m[(i, j)]))
        .collect();
    crate::sym::Mat {
        rows: r,
        cols: c,
        data,
    }
}

/// `v` made by `how`: a formula gets it, each formula in a tuple the part
/// it is of it; anything else is left as it is.
pub fn attach(v: Value, how: Option<Rc<Recipe>>) -> Value {
    let Some(r) = how else { return v };
    match v {
        // a number made from symbols (`diff(euler_zxz(Rotx(u)), u)` is
        // (0, 1, 0) on the closed form's branch) depends on them: it stays
        // a formula of constant entries, replayed once they have numbers
        // (at u = −1 the rate is (0, −1, 0))
        Value::Num { kind, m, exact }
            if {
                let mut syms = Vec::new();
                symbols(&r, &mut syms);
                !syms.is_empty()
            } =>
        {
            Value::Formula {
                kind,
                m: constant(&m, &exact),
                how: Some(r),
            }
        }
        Value::Formula { kind, m, .. } => Value::Formula {
            kind,
            m,
            how: Some(r),
        },
        Value::Tuple(vs) => Value::Tuple(
            vs.into_iter()
                .enumerate()
                .map(|(i, x)| match x {
                    Value::Formula { .. } => {
                        let kind = x.kind();
                        attach(x, Recipe::node(Step::Part(i), vec![r.clone()], kind))
                    }
                    // (a part that came out as numbers is still made by
                    // the call, and replayed with it: `TransToRp`'s R)
                    Value::Num { kind, m, exact } => {
                        let part = Recipe::node(Step::Part(i), vec![r.clone()], kind);
                        match part {
                            Some(p) => Value::Formula {
                                kind,
                                m: constant(&m, &exact),
                                how: Some(p),
                            },
                            None => Value::Num { kind, m, exact },
                        }
                    }
                    x => x,
                })
                .collect(),
        ),
        v => v,
    }
}

/// True when `v` is made from symbols or holds such a value (a list or
/// tuple of them): reading it puts in the numbers bound since.
pub fn holds_symbols(v: &Value) -> bool {
    match v {
        Value::Sym(_) | Value::Formula { .. } => true,
        Value::Tuple(vs) => vs.iter().any(holds_symbols),
        Value::List(vs) => vs.iter().any(holds_symbols),
        _ => false,
    }
}

/// Adds to `out` the symbols of the leaves of `r` (those a value made by
/// `r` depends on, though its canonical form may have lost them: `a/a`
/// is 1 but is no number until `a` has one, and not at a = 0). Shared
/// operands are visited once.
pub fn symbols(r: &Rc<Recipe>, out: &mut Vec<crate::sym::Symbol>) {
    let own = r.syms.get_or_init(|| {
        let mut found = Vec::new();
        let mut seen = std::collections::HashSet::new();
        let mut todo = vec![r];
        while let Some(r) = todo.pop() {
            if !seen.insert(Rc::as_ptr(r)) {
                continue;
            }
            if let Some(known) = r.syms.get() {
                for s in known {
                    if !found.contains(s) {
                        found.push(s.clone());
                    }
                }
                continue;
            }
            match &r.step {
                Step::Leaf(Value::Formula { m, .. }) => {
                    m.data.iter().for_each(|e| e.symbols(&mut found))
                }
                // (a branch's conditions are read with the numbers too:
                // the derivative (0, 0, 1) of MatrixLog3(Rotz(w)) waits
                // for w, to be refused at w = π)
                Step::Closed(on) | Step::Guard(on) => {
                    on.positive
                        .iter()
                        .chain(&on.angles)
                        .for_each(|e| e.symbols(&mut found));
                    todo.extend(r.args.iter())
                }
                _ => todo.extend(r.args.iter()),
            }
        }
        found
    });
    for s in own {
        if !out.contains(s) {
            out.push(s.clone());
        }
    }
}

/// A kind that says only a shape (the numbers then say more).
pub fn vague(kind: &Kind) -> bool {
    matches!(kind, Kind::Unknown | Kind::Matrix(..) | Kind::Vector(None))
}

/// `r` with each leaf `leaf` gives a new value for replaced; unchanged
/// parts are shared.
pub fn rebase(
    r: &Rc<Recipe>,
    leaf: &dyn Fn(&Value) -> Option<Value>,
    memo: &mut HashMap<*const Recipe, Rc<Recipe>>,
) -> Rc<Recipe> {
    let key = Rc::as_ptr(r);
    if let Some(x) = memo.get(&key) {
        return x.clone();
    }
    let out = stacker::maybe_grow(64 * 1024, 1024 * 1024, || match &r.step {
        Step::Leaf(v) => match leaf(v) {
            Some(v) => Recipe::leaf(v),
            None => r.clone(),
        },
        step => {
            let args: Vec<Rc<Recipe>> = r.args.iter().map(|a| rebase(a, leaf, memo)).collect();
            if args.iter().zip(&r.args).all(|(a, b)| Rc::ptr_eq(a, b)) {
                return r.clone();
            }
            let step = match step {
                Step::Closed(on) => Step::Closed(Rc::new(on.rebase(leaf))),
                Step::Guard(on) => Step::Guard(Rc::new(on.rebase(leaf))),
                step => step.clone(),
            };
            Rc::new(Recipe {
                step,
                args,
                kind: r.kind,
                depth: r.depth,
                syms: Default::default(),
            })
        }
    });
    memo.insert(key, out.clone());
    out
}
