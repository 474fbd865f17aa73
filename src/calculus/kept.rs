//! `diff` of a call kept over `given` symbols, read once its numbers are
//! bound (LANGUAGE.md §7: "binding numbers later makes them numeric"):
//! `given a; R = Rot((1, a, 2), a); D = diff(R, a); a = 0.3; D` is the
//! derivative at a = 0.3, as with the numbers typed first, where it was
//! refused ("the derivative of a kept call is not known"). The kept tree
//! is made into a recipe over its formulas (each step the operation the
//! tree's node is, its kind what the operation gives the numbers), the
//! chain rule runs on that recipe, through the kept calls by their rates
//! at the numbers (`seam::of_kept`), and the derivative is replayed with
//! the numbers (`decide::replay`). Where a symbol has no number yet, or a
//! step is one the chain rule does not know, the refusal stands; where a
//! call has no derivative at the numbers (a norm at 0, a log at a half
//! turn) that is the refusal.

use std::rc::Rc;

use super::resolve::{Resolving, bound, formula_now};
use super::{Bindings, Bound};
use crate::check::ty::Kind;
use crate::decide::replay::{self, Failed};
use crate::seam::apply::Op;
use crate::syntax::ast::BinOp;
use crate::syntax::name::Name;
use crate::values::ops::Sel;
use crate::values::recipe::{Operation, Recipe, Step};
use crate::values::symbolic::{Fun, Role};
use crate::values::value::{Sym, Value};

/// A recipe and the numbers it gives now.
type Made = (Rc<Recipe>, Value);

/// The session's bindings with one symbol given a number: what a `subs`
/// kept as a call puts for it (`subs(diff(x, a), a, 0.37)`), read after
/// the derivative is taken (the substitution is of the derivative).
/// With no number (None), the symbol is read as a symbol: the one a
/// `diff` read while other symbols are free differentiates by.
struct Put<'a> {
    env: &'a dyn Bindings,
    name: Name,
    val: Option<Value>,
}

impl Bindings for Put<'_> {
    fn binding(&self, name: Name) -> Option<Bound<'_>> {
        if name == self.name {
            return self.val.as_ref().map(|v| Bound {
                val: Some(v),
                kind: Kind::Scalar,
                symbolic: false,
                derived: false,
            });
        }
        self.env.binding(name)
    }
    fn is_given(&self, name: Name) -> bool {
        self.env.is_given(name)
    }
    fn declared(&self, name: Name) -> Option<&Value> {
        self.env.declared(name)
    }
}

/// `subs(diff(x, by), name, v)` with `v` a number, once every other
/// symbol has one: the derivative at those numbers with v for the
/// symbol (None where that is not known, as [`Resolving::kept_derivative`]).
pub(super) fn put_derivative(
    env: &dyn Bindings,
    warnings: &mut Vec<crate::diagnostics::Diagnostic>,
    [name, v]: [&Value; 2],
    [x, by]: [&Sym; 2],
) -> Option<Result<Value, String>> {
    let Value::Formula { m, .. } = name else {
        return None;
    };
    let sym = match m.data.as_slice() {
        [e] => crate::sym::expr::as_symbol(e)?,
        _ => return None,
    };
    if !matches!(v, Value::Num { .. }) || sym.index > 0 {
        return None;
    }
    let put = Put {
        env,
        name: Name::new(&crate::values::formula::binding_name(&sym)),
        val: Some(v.clone()),
    };
    let mut r = Resolving {
        env: &put,
        warnings,
        failed: None,
        put: None,
    };
    r.kept_derivative(x, by)
}

/// `diff(x, by)` read while some symbols of x other than `by` are still
/// free: x with the numbers bound since put in for every symbol but
/// `by` (the derivative by `by` is taken before by's own number is put
/// in, so that is put by a `subs` of the derivative, read when the rest
/// have numbers: [`put_derivative`]). Ok(None) where no symbol but `by`
/// is free (the derivative was known then, or not at all) or x holds a
/// function of time or a rate (whose numbers the chain rule reads).
pub(super) fn partly(
    env: &dyn Bindings,
    warnings: &mut Vec<crate::diagnostics::Diagnostic>,
    fun: Fun,
    [x, by]: [&Sym; 2],
) -> Result<Option<Sym>, String> {
    let Some(sym) = symbol(by).filter(|s| s.index == 0 && s.dots == 0 && s.time.is_none()) else {
        return Ok(None);
    };
    let mut timed = false;
    for_symbols(x, &mut |s| timed |= s.time.is_some() || s.dots > 0);
    if timed {
        return Ok(None);
    }
    let name = Name::new(&crate::values::formula::binding_name(&sym));
    let hidden = Put {
        env,
        name,
        val: None,
    };
    let mut r = Resolving {
        env: &hidden,
        warnings,
        failed: None,
        put: None,
    };
    let x = r.go(x);
    if let Some(why) = r.failed {
        return Err(why);
    }
    let mut free = false;
    for_symbols(&x, &mut |s| free |= *s != sym);
    free |= x.any(&mut |t| matches!(t, Sym::Name(_)));
    if !free {
        return Ok(None);
    }
    let d = Sym::Call(fun, vec![x, by.clone()]);
    Ok(Some(match env.binding(name).and_then(|b| b.val) {
        Some(v @ Value::Num { .. }) => Sym::Call(
            Fun {
                name: "subs",
                role: Role::Plain,
            },
            vec![d, by.clone(), crate::seam::apply::to_sym(v)],
        ),
        _ => d,
    }))
}

/// The symbol a tree leaf is (`by` of a `diff`).
fn symbol(s: &Sym) -> Option<crate::sym::Symbol> {
    let Sym::Const(v, _) = s else { return None };
    let Value::Formula { m, .. } = &**v else {
        return None;
    };
    match m.data.as_slice() {
        [e] => crate::sym::expr::as_symbol(e),
        _ => None,
    }
}

/// `f` of each symbol of the formulas in tree `x` (and of how they were made).
fn for_symbols(x: &Sym, f: &mut impl FnMut(&crate::sym::Symbol)) {
    x.any(&mut |t| {
        if let Sym::Const(v, _) = t
            && let Value::Formula { m, how, .. } = &**v
        {
            let mut syms = Vec::new();
            m.data.iter().for_each(|e| e.symbols(&mut syms));
            if let Some(r) = how {
                crate::values::recipe::symbols(r, &mut syms);
            }
            syms.iter().for_each(&mut *f);
        }
        false
    });
}

impl Resolving<'_, '_> {
    /// `diff(x, by)` of the tree `x` with every symbol now a number: the
    /// derivative's numbers (Ok), or why there are none at these numbers
    /// (Err); None where it is not known (a symbol without a number, a
    /// step the chain rule does not reach).
    pub(super) fn kept_derivative(&mut self, x: &Sym, by: &Sym) -> Option<Result<Value, String>> {
        let Sym::Const(by, _) = by else {
            return None;
        };
        let (r, _) = self.made(x)?;
        let d = crate::seam::of_kept(&r, by)?;
        let env = self.env;
        let lookup = |s: &crate::sym::Symbol| bound(env, s);
        match replay::numbers(&d, &lookup, self.warnings) {
            Ok(v) => v.map(Ok),
            Err(Failed(why)) => Some(Err(why)),
        }
    }

    /// The recipe of tree `s` over its formulas, with its numbers; None
    /// where a symbol has no number or a node makes no step.
    fn made(&mut self, s: &Sym) -> Option<Made> {
        let numbers = |v: &Value| matches!(v, Value::Num { .. } | Value::Tuple(_));
        match s {
            Sym::Const(v, _) => match &**v {
                v @ Value::Formula { .. } => {
                    let x = formula_now(v, self.env, &mut Vec::new()).ok()?;
                    numbers(&x).then(|| (Recipe::of(v), x))
                }
                v if numbers(v) => Some((Recipe::leaf(v.clone()), v.clone())),
                _ => None,
            },
            Sym::Name(n) => {
                let v = self.env.binding(Name::new(n))?.val?;
                numbers(v).then(|| (Recipe::leaf(v.clone()), v.clone()))
            }
            Sym::Product(fs) => {
                let mut fs = fs.iter();
                let first = self.made(fs.next()?)?;
                fs.try_fold(first, |acc, f| {
                    let f = self.made(f)?;
                    self.step(Op::Arith(BinOp::Mul), None, vec![acc, f])
                })
            }
            // (the inverse by its call, whose derivative the chain rule knows)
            Sym::Inv(x) => {
                let x = self.made(x)?;
                self.step(Op::Inverse, Some(Operation::Call("inv")), vec![x])
            }
            Sym::Transpose(x) => self.unary_made(Op::Transpose, x),
            Sym::Neg(x) => self.unary_made(Op::Neg, x),
            Sym::Member(x, part) => self.unary_made(Op::Member(*part), x),
            Sym::Index(x, sels) => {
                let x = self.made(x)?;
                // (a part of a tuple a call gives: AxisAng3(ω)[1])
                if let (Value::Tuple(vs), [Some(i)]) = (&x.1, sels.as_slice()) {
                    let part = (*i as usize).checked_sub(1)?;
                    let v = vs.get(part)?.clone();
                    let kind = v.kind();
                    return Some((Recipe::node(Step::Part(part), vec![x.0], kind)?, v));
                }
                let sel: Vec<Sel> = sels.iter().map(|s| s.map_or(Sel::All, Sel::At)).collect();
                self.step(Op::Index(&sel), None, vec![x])
            }
            Sym::Add(a, b) => self.binary_made(BinOp::Add, a, b),
            Sym::Sub(a, b) => self.binary_made(BinOp::Sub, a, b),
            Sym::Div(a, b) => self.binary_made(BinOp::Div, a, b),
            Sym::Pow(a, b) => self.binary_made(BinOp::Pow, a, b),
            Sym::Bracket(x) => self.unary_made(Op::Block(&[1]), x),
            Sym::Block(rows) => self.block_made(rows),
            Sym::Vector(parts) => {
                let parts = parts.iter().map(|p| self.made(p)).collect::<Option<_>>()?;
                self.step(Op::Vector, None, parts)
            }
            Sym::Call(fun, args) if !matches!(fun.name, "diff" | "subs") => {
                let b = crate::builtins::lookup(fun.name)?;
                let args = args.iter().map(|a| self.made(a)).collect::<Option<_>>()?;
                self.step(Op::Call(b, fun.name), None, args)
            }
            Sym::Call(..) | Sym::Identity | Sym::Compare(..) => None,
        }
    }

    fn unary_made(&mut self, op: Op, x: &Sym) -> Option<Made> {
        let x = self.made(x)?;
        self.step(op, None, vec![x])
    }

    fn binary_made(&mut self, op: BinOp, a: &Sym, b: &Sym) -> Option<Made> {
        let (a, b) = (self.made(a)?, self.made(b)?);
        self.step(Op::Arith(op), None, vec![a, b])
    }

    /// `[R, p; 0, 1]`: its lone 0 is a zero block, as typed first.
    fn block_made(&mut self, rows: &[Vec<Sym>]) -> Option<Made> {
        let mut made: Vec<Vec<Made>> = rows
            .iter()
            .map(|r| r.iter().map(|x| self.made(x)).collect::<Option<_>>())
            .collect::<Option<_>>()?;
        let mut vals: Vec<Vec<Value>> = made
            .iter()
            .map(|r| r.iter().map(|(_, v)| v.clone()).collect())
            .collect();
        let lone = |i: usize, j: usize| matches!(&rows[i][j], Sym::Const(c, _) if c.as_scalar() == Some(0.0));
        crate::seam::shapes::zero_blocks_where(lone, &mut vals);
        for (row, vs) in made.iter_mut().zip(&vals) {
            for (m, v) in row.iter_mut().zip(vs) {
                if m.1.kind() != v.kind() || lone_changed(&m.1, v) {
                    *m = (Recipe::leaf(v.clone()), v.clone());
                }
            }
        }
        let widths: Vec<usize> = rows.iter().map(Vec::len).collect();
        self.step(
            Op::Block(&widths),
            None,
            made.into_iter().flatten().collect(),
        )
    }

    /// `op` over made operands: its numbers as typed first, its step
    /// (`step`, where the recipe records another operation than `op`).
    fn step(&mut self, op: Op, step: Option<Operation>, args: Vec<Made>) -> Option<Made> {
        let refs: Vec<&Value> = args.iter().map(|(_, v)| v).collect();
        let v = replay::as_typed(op, &refs, &mut Vec::new()).ok()?;
        let step = Step::Op(step.unwrap_or_else(|| op.owned()));
        let r = Recipe::node(step, args.into_iter().map(|(r, _)| r).collect(), v.kind())?;
        Some((r, v))
    }
}

/// Whether a lone 0 was made a zero block (its numbers changed shape).
fn lone_changed(was: &Value, now: &Value) -> bool {
    match (was, now) {
        (Value::Num { m: a, .. }, Value::Num { m: b, .. }) => a.shape() != b.shape(),
        _ => false,
    }
}
