//! Trees over `given` symbols with the numbers bound since put in
//! (LANGUAGE.md §7: "binding numbers later makes them numeric"):
//! `T_ab * T_bc` over `given` transforms is the product's value once both
//! have numbers. Every operation whose operands have all become numbers is
//! computed as when the numbers are typed first ([`replay::as_typed`]: its
//! kind by its rule on the operands' kinds, its exact form, a builtin's
//! warnings); one that fails with its numbers (`Rot(w, θ)` with w = 0)
//! is the value's refusal, as typed first.

use super::Bindings;
pub use super::formula_now::{bound, formula_now};
use crate::check::ty::Kind;
use crate::decide::replay::{self, Failed};
use crate::diagnostics::Diagnostic;
use crate::seam::apply::to_sym;
use crate::seam::apply::{self, Op};
use crate::syntax::ast::BinOp;
use crate::syntax::name::Name;
use crate::values::formula;
use crate::values::ops::Sel;
use crate::values::value::{Sym, Value};

/// Where a tree is resolved: the session's bindings, the warnings of the
/// operations computed, and the first that failed with its numbers.
pub(super) struct Resolving<'a, 'w> {
    pub(super) env: &'a dyn Bindings,
    pub(super) warnings: &'w mut Vec<Diagnostic>,
    pub(super) failed: Option<String>,
    /// The symbol and what is put for it in every formula read (the
    /// operand of a `subs` kept as a call: [`Resolving::substituted`]).
    pub(super) put: Option<[Value; 2]>,
}

/// `s` with every `given` name that is now bound to numbers replaced by
/// them, and every operation whose operands are all numbers computed as
/// typed first. Err with the message of the first operation that fails
/// with its numbers (the value is refused, as typed first); an operation
/// whose operands are not yet all numbers stays symbolic.
pub fn resolve(s: &Sym, env: &dyn Bindings, warnings: &mut Vec<Diagnostic>) -> Result<Sym, Failed> {
    let mut r = Resolving {
        env,
        warnings,
        failed: None,
        put: None,
    };
    let out = r.go(s);
    match r.failed {
        Some(why) => Err(Failed(why)),
        None => Ok(out),
    }
}

impl Resolving<'_, '_> {
    /// `op` on numbers, as typed first; None (and the failure kept) when
    /// it fails with them.
    fn compute(&mut self, op: Op, args: &[&Value]) -> Option<Value> {
        match replay::as_typed(op, args, self.warnings) {
            Ok(v) => Some(v),
            Err(e) => {
                if replay::refusal(&e) && self.failed.is_none() {
                    self.failed = Some(e.to_string());
                }
                None
            }
        }
    }

    pub(super) fn go(&mut self, s: &Sym) -> Sym {
        match s {
            // (a name substituted stands in a formula, never as a tree's
            // leaf: refused rather than read with its own number)
            Sym::Name(_) if self.put.is_some() && self.puts_name(s) => {
                self.kept_call("subs");
                s.clone()
            }
            Sym::Name(n) => match self.env.binding(Name::new(n)).and_then(|b| b.val) {
                Some(v @ Value::Num { .. }) => to_sym(v),
                _ if n == "deg" => to_sym(&Value::scalar(std::f64::consts::PI / 180.0)),
                _ => s.clone(),
            },
            Sym::Const(v, _) => match &**v {
                v @ Value::Formula { .. } if self.put.is_some() => match self.put_in(v) {
                    Some(v) => match formula_now(&v, self.env, self.warnings) {
                        Ok(x) => to_sym(&x),
                        Err(Failed(why)) => {
                            self.failed.get_or_insert(why);
                            s.clone()
                        }
                    },
                    None => s.clone(),
                },
                v @ Value::Formula { .. } => match formula_now(v, self.env, self.warnings) {
                    Ok(x) => to_sym(&x),
                    Err(Failed(why)) => {
                        self.failed.get_or_insert(why);
                        s.clone()
                    }
                },
                _ => s.clone(),
            },
            Sym::Identity(_) => s.clone(),
            Sym::Product(fs) => {
                let mut out: Vec<Sym> = Vec::new();
                for f in fs.iter() {
                    let f = self.go(f);
                    let merged = match (out.last().and_then(num), num(&f)) {
                        (Some(a), Some(b)) => {
                            let (a, b) = (a.clone(), b.clone());
                            self.compute(Op::Arith(BinOp::Mul), &[&a, &b])
                        }
                        _ => None,
                    };
                    match merged {
                        Some(v) => {
                            out.pop();
                            out.push(constant(v));
                        }
                        None => {
                            // (numbers beside a name: their kinds multiply
                            // as typed first, `eye(k) T` at k = 3 is refused)
                            if let Some(why) = out
                                .last()
                                .and_then(|a| super::kinds::unmultiplied(self.env, a, &f))
                            {
                                self.failed.get_or_insert(why);
                            }
                            out.push(f)
                        }
                    }
                }
                Sym::product(out)
            }
            Sym::Inv(x) => self.unary(Op::Inverse, x),
            Sym::Transpose(x) => self.unary(Op::Transpose, x),
            Sym::Neg(x) => self.unary(Op::Neg, x),
            Sym::Member(x, part) => self.unary(Op::Member(*part), x),
            Sym::Index(x, sels) => {
                let sel: Vec<Sel> = sels.iter().map(|s| s.map_or(Sel::All, Sel::At)).collect();
                self.unary(Op::Index(&sel), x)
            }
            Sym::Compare(op, a, b) => self.compared(*op, a, b),
            Sym::Add(a, b) => self.binary(BinOp::Add, a, b),
            Sym::Sub(a, b) => self.binary(BinOp::Sub, a, b),
            Sym::Div(a, b) => self.binary(BinOp::Div, a, b),
            Sym::Pow(a, b) => self.binary(BinOp::Pow, a, b),
            Sym::Bracket(x) => {
                let x = self.go(x);
                match num(&x).map(|v| apply::block_numeric(&[vec![v.clone()]])) {
                    Some(Ok(v)) => constant(v),
                    Some(Err(e)) => {
                        self.fail(&e);
                        Sym::Bracket(Box::new(x))
                    }
                    None => Sym::Bracket(Box::new(x)),
                }
            }
            Sym::Block(rows_written) => {
                let rows: Vec<Vec<Sym>> = rows_written
                    .iter()
                    .map(|r| r.iter().map(|x| self.go(x)).collect())
                    .collect();
                let mut vals: Option<Vec<Vec<Value>>> = rows
                    .iter()
                    .map(|r| r.iter().map(|x| num(x).cloned()).collect())
                    .collect();
                // `[R, p; 0, 1]`: its lone 0 is a zero block, as typed first
                let written = &rows_written;
                if let Some(v) = vals.as_mut() {
                    crate::seam::shapes::zero_blocks_where(
                        |i, j| matches!(&written[i][j], Sym::Const(c, _) if c.as_scalar() == Some(0.0)),
                        v,
                    );
                }
                match vals.map(|v| apply::block_numeric(&v)) {
                    Some(Ok(v)) => constant(v),
                    Some(Err(e)) => {
                        self.fail(&e);
                        Sym::Block(rows)
                    }
                    None => Sym::Block(rows),
                }
            }
            Sym::Vector(parts) => {
                let parts: Vec<Sym> = parts.iter().map(|x| self.go(x)).collect();
                let vals: Option<Vec<Value>> = parts
                    .iter()
                    .map(|x| num(x).filter(|v| v.as_scalar().is_some()).cloned())
                    .collect();
                match vals {
                    Some(vals) => {
                        let refs: Vec<&Value> = vals.iter().collect();
                        match self.compute(Op::Vector, &refs) {
                            Some(v) => constant(v),
                            None => Sym::Vector(parts),
                        }
                    }
                    None => Sym::Vector(parts),
                }
            }
            Sym::Call(fun, args) if matches!(fun.name, "diff" | "subs") && self.put.is_some() => {
                // (subs(diff(x, a), a, 0.37): the derivative at the number, kept.rs)
                if fun.name == "diff"
                    && let Some(d) = self.put_diff(s, args)
                {
                    return d;
                }
                self.kept_call(fun.name);
                s.clone()
            }
            Sym::Call(fun, args)
                if fun.name == "subs"
                    && num(&args[0]).is_none()
                    && let [x, name, by] = args.as_slice()
                    && plain_symbol(name) =>
            {
                self.substituted(s, [x, name, by])
            }
            Sym::Call(fun, args)
                if matches!(fun.name, "diff" | "subs") && num(&args[0]).is_none() =>
            {
                // diff and subs of an expression kept as a call act on its
                // symbols: once numbers replace some of them, diff would
                // see constants (0) and subs nothing to replace — refused,
                // never computed from what is left.
                let x = self.go(&args[0]);
                if x != args[0] {
                    // (diff with the numbers bound, or some of them: kept.rs)
                    if fun.name == "diff"
                        && let Some(d) = self.bound_diff(s, *fun, args)
                    {
                        return d;
                    }
                    self.kept_call(fun.name);
                    return s.clone();
                }
                // (the symbol diff and subs act by stays one: diff(x, a)
                // of an x free of a, read at a = 0.5, is no diff(x, 0.5))
                let mut rest: Vec<Sym> = args[2..].iter().map(|a| self.go(a)).collect();
                rest.splice(0..0, [x, args[1].clone()]);
                Sym::Call(*fun, rest)
            }
            Sym::Call(fun, args) => {
                let args: Vec<Sym> = args.iter().map(|a| self.go(a)).collect();
                let vals: Option<Vec<Value>> = args.iter().map(|a| num(a).cloned()).collect();
                match vals.zip(crate::builtins::lookup(fun.name)) {
                    Some((vals, b)) => {
                        let refs: Vec<&Value> = vals.iter().collect();
                        match self.compute(Op::Call(b, fun.name), &refs) {
                            Some(v) => constant(v),
                            None => Sym::Call(*fun, args),
                        }
                    }
                    None => Sym::Call(*fun, args),
                }
            }
        }
    }

    /// `subs(x, name, by)` kept as a call (x a tree over `given` names,
    /// `subs(R, θ, 1)` of `R = exp([u] θ)` with u a given vector): `by`
    /// put for the symbol in each formula of x *before* the numbers bound
    /// since are put in (the symbol's own number, if it has one, is not
    /// what is substituted; one that `by` holds is), then x read as any
    /// tree is — the substitution commutes with the tree's operations, so
    /// this is the value typed first with `by` in place of the symbol.
    /// Refused as before where `by` is no formula or number, or x holds
    /// another `diff` or `subs` (whose order the leaves would not keep).
    fn substituted(&mut self, s: &Sym, [x, name, by]: [&Sym; 3]) -> Sym {
        // (no number bound since reaches x: the call is kept as it was)
        let mut dry = Resolving {
            env: self.env,
            warnings: &mut Vec::new(),
            failed: None,
            put: None,
        };
        // (a refusal in the dry run is not kept: the number it read may be
        // the substituted symbol's own, which the substitution replaces)
        if dry.go(x) == *x && dry.failed.is_none() {
            // (a derivative over the substituted symbol only: kept.rs)
            if let Some(d) = self.put_diff_now(s, [x, name, by]) {
                return d;
            }
            // (the name substituted stays a symbol, whatever its number)
            let rest: Vec<Sym> = [x, name, by]
                .iter()
                .enumerate()
                .map(|(i, a)| if i < 2 { (*a).clone() } else { self.go(a) })
                .collect();
            return match s {
                Sym::Call(fun, _) => Sym::Call(*fun, rest),
                _ => s.clone(),
            };
        }
        let by = self.go(by);
        let (Sym::Const(n, _), Sym::Const(b, _)) = (name, &by) else {
            self.kept_call("subs");
            return s.clone();
        };
        let mut inner = Resolving {
            env: self.env,
            warnings: &mut *self.warnings,
            failed: None,
            put: Some([(**n).clone(), (**b).clone()]),
        };
        let out = inner.go(x);
        if let Some(why) = inner.failed {
            self.failed.get_or_insert(why);
            return s.clone();
        }
        out
    }

    /// A formula with `by` put for the symbol `subs` substitutes
    /// ([`Resolving::substituted`]); None (and refused) where it cannot
    /// be.
    fn put_in(&mut self, v: &Value) -> Option<Value> {
        let [name, by] = self.put.as_ref()?;
        let refs = [v, name, by];
        let made = crate::decide::replay::subs_numbers(&refs, self.warnings)
            .map(|r| r.map_err(crate::values::error::OpError::Message))
            .or_else(|| {
                crate::builtins::lookup("subs")
                    .and_then(|b| Op::Call(b, "subs").exact_or_symbolic(&refs, &v.kind()))
            });
        match made {
            Some(Ok(v)) => Some(v),
            // (refused as the substitution typed so is: subs(3/θ, θ, 0))
            Some(Err(e)) => {
                self.failed.get_or_insert(e.to_string());
                None
            }
            None => {
                self.kept_call("subs");
                None
            }
        }
    }

    /// Whether tree leaf `s` is the name of the symbol being substituted.
    fn puts_name(&self, s: &Sym) -> bool {
        let (Sym::Name(n), Some([Value::Formula { m, .. }, _])) = (s, &self.put) else {
            return false;
        };
        matches!(m.data.as_slice(), [e] if crate::sym::expr::as_symbol(e)
            .is_some_and(|sym| formula::binding_name(&sym) == *n))
    }

    /// The refusal of `diff` or `subs` of a kept call whose operand the
    /// numbers changed.
    fn kept_call(&mut self, fun: &str) {
        if self.failed.is_none() {
            self.failed = Some(format!(
                "{fun}(…) of an expression with no closed form cannot be computed with \
                 numbers (the {} of a kept call is not known); write it in a form the \
                 engine has (sqrt(u) for u^(1/2), whole powers, the book's maps)",
                if fun == "diff" {
                    "derivative"
                } else {
                    "substitution"
                }
            ));
        }
    }

    fn fail(&mut self, e: &crate::values::error::OpError) {
        if replay::refusal(e) && self.failed.is_none() {
            self.failed = Some(e.to_string());
        }
    }

    /// A unary operation on a resolved operand: its value when that is a
    /// number, else its symbolic form.
    fn unary(&mut self, op: Op, x: &Sym) -> Sym {
        let x = self.go(x);
        match num(&x).cloned().and_then(|v| self.compute(op, &[&v])) {
            Some(v) => constant(v),
            None => op.symbolic(vec![x]),
        }
    }

    /// A comparison that waited for numbers: decided as typed first once
    /// both sides are numbers (LANGUAGE.md §7), else still waiting.
    fn compared(&mut self, op: crate::syntax::ast::CmpOp, a: &Sym, b: &Sym) -> Sym {
        let (a, b) = (self.go(a), self.go(b));
        if let (Some(l), Some(r)) = (num(&a), num(&b)) {
            match crate::decide::equality::equal(l, r, op) {
                Ok(Some(v)) => return constant(Value::Bool(v)),
                Ok(None) => {}
                Err(m) => {
                    self.failed.get_or_insert(m);
                }
            }
        }
        Sym::Compare(op, Box::new(a), Box::new(b))
    }

    /// An arithmetic operation on resolved operands, computed when both
    /// are numbers.
    fn binary(&mut self, op: BinOp, a: &Sym, b: &Sym) -> Sym {
        let (a, b) = (self.go(a), self.go(b));
        if let (Some(l), Some(r)) = (num(&a).cloned(), num(&b).cloned())
            && let Some(v) = self.compute(Op::Arith(op), &[&l, &r])
        {
            return constant(v);
        }
        // (a division by a number 0 is refused whatever is divided, as
        // typed first: `a/u[1]` at u = (0, 0, 1) printed `a/0`)
        if op == BinOp::Div && num(&b).and_then(Value::as_scalar) == Some(0.0) {
            self.failed.get_or_insert_with(|| "division by zero".into());
        }
        let (a, b) = (Box::new(a), Box::new(b));
        match op {
            BinOp::Add => Sym::Add(a, b),
            BinOp::Sub => Sym::Sub(a, b),
            BinOp::Div => Sym::Div(a, b),
            BinOp::Pow => Sym::Pow(a, b),
            BinOp::Mul => Sym::times(*a, *b),
        }
    }
}

/// The numbers of a constant operand (a tuple of numbers too: a
/// builtin's result, whose parts are read by index; a bool, what
/// `TestIfSO3` gives).
fn num(s: &Sym) -> Option<&Value> {
    let numbers = |v: &Value| match v {
        Value::Num { .. } | Value::Bool(_) => true,
        Value::Tuple(vs) => vs.iter().all(|x| matches!(x, Value::Num { .. })),
        _ => false,
    };
    match s {
        Sym::Const(v, _) if numbers(v) => Some(v),
        _ => None,
    }
}

/// A computed value as a constant, its kind recognized by its entries when
/// the operation could not tell it.
pub(super) fn constant(v: Value) -> Sym {
    let v = match v {
        Value::Num {
            kind: Kind::Unknown,
            m,
            exact,
        } => Value::Num {
            kind: replay::classify(&m),
            m,
            exact,
        },
        other => other,
    };
    to_sym(&v)
}

/// Whether the name a `subs` kept as a call substitutes is a plain scalar
/// symbol (not a component `w[3]` of a given vector, which stands in the
/// tree as the vector's name, nor a rate or a function of time, whose
/// numbers are bound under other names).
pub(super) fn plain_symbol(s: &Sym) -> bool {
    let Sym::Const(v, _) = s else {
        return false;
    };
    let Value::Formula { m, .. } = &**v else {
        return false;
    };
    let [e] = m.data.as_slice() else {
        return false;
    };
    crate::sym::expr::as_symbol(e)
        .is_some_and(|sym| sym.index == 0 && sym.dots == 0 && sym.time.is_none())
}
