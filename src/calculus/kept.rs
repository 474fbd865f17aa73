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

use std::collections::HashMap;
use std::rc::Rc;

use super::resolve::{Resolving, bound, constant, formula_now};
use super::{Bindings, Bound};
use crate::check::ty::Kind;
use crate::decide::replay::{self, Failed};
use crate::seam::apply::Op;
use crate::syntax::ast::BinOp;
use crate::syntax::name::Name;
use crate::values::ops::Sel;
use crate::values::recipe::{self, Operation, Recipe, Step};
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
fn put_derivative(
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
fn partly(
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
    /// `diff(x, by)` kept as a call (`s`, of operands `args`) whose
    /// operand the numbers bound since changed: its numbers, where every
    /// symbol has one; the tree that waits for the rest, where some are
    /// free ([`partly`]); the refusal, where the call has no derivative at
    /// the numbers. None where it is not known (refused as before).
    pub(super) fn bound_diff(&mut self, s: &Sym, fun: Fun, args: &[Sym]) -> Option<Sym> {
        let [x, by] = args else { return None };
        if self.failed.is_some() {
            return None;
        }
        if let Some(d) = self.kept_derivative(x, by) {
            return Some(self.settle(s, d));
        }
        match partly(self.env, &mut *self.warnings, fun, [x, by]) {
            Ok(d) => d,
            Err(why) => {
                self.failed = Some(why);
                Some(s.clone())
            }
        }
    }

    /// `diff(x, by)` (`s`, of operands `args`) inside a `subs` kept as a
    /// call that puts a number for a symbol ([`put_derivative`]).
    pub(super) fn put_diff(&mut self, s: &Sym, args: &[Sym]) -> Option<Sym> {
        let ([x, by], Some([name, v])) = (args, self.put.clone()) else {
            return None;
        };
        if self.failed.is_some() {
            return None;
        }
        let d = put_derivative(self.env, &mut *self.warnings, [&name, &v], [x, by])?;
        Some(self.settle(s, d))
    }

    /// `subs(diff(x, by), name, v)` (`s`) that no number bound since
    /// changes, with v a number: the derivative at v where x waits for no
    /// other symbol (`subs(diff(Rot((2 a, a, -1), a), a), a, 0.5)` stayed
    /// that call for good); None where it waits.
    pub(super) fn put_diff_now(&mut self, s: &Sym, [x, name, by]: [&Sym; 3]) -> Option<Sym> {
        let (Sym::Call(f, args), Sym::Const(name, _)) = (x, name) else {
            return None;
        };
        if f.name != "diff" || self.failed.is_some() {
            return None;
        }
        let Sym::Const(v, _) = self.go(by) else {
            return None;
        };
        let [x, by] = args.as_slice() else {
            return None;
        };
        let d = put_derivative(self.env, &mut *self.warnings, [name, &v], [x, by])?;
        Some(self.settle(s, d))
    }

    /// The derivative's numbers as a constant, or `s` with the refusal kept.
    fn settle(&mut self, s: &Sym, d: Result<Value, String>) -> Sym {
        match d {
            Ok(v) => constant(v),
            Err(why) => {
                self.failed = Some(why);
                s.clone()
            }
        }
    }

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
                    numbers(&x).then(|| (shaped(&Recipe::of(v), &mut HashMap::new()), x))
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
            Sym::Call(..) | Sym::Identity(_) | Sym::Compare(..) => None,
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

/// Recipe `r` with each `[x]` of a vector, recorded with no kind (the
/// check left it open), given the kind its vector gives it: [ω] is in
/// so(3), [V] in se(3). The chain rule takes a product's shape from its
/// operands' (`[ω] a`); unchanged parts are shared.
fn shaped(r: &Rc<Recipe>, memo: &mut HashMap<*const Recipe, Rc<Recipe>>) -> Rc<Recipe> {
    if let Some(x) = memo.get(&Rc::as_ptr(r)) {
        return x.clone();
    }
    let out = stacker::maybe_grow(64 * 1024, 1024 * 1024, || {
        let args: Vec<Rc<Recipe>> = r.args.iter().map(|a| shaped(a, memo)).collect();
        let kind = match (&r.step, args.as_slice()) {
            (Step::Op(Operation::Block(w)), [x]) if **w == [1] && recipe::vague(&r.kind) => {
                match (x.kind.is_vector(), x.kind.vec_len()) {
                    (true, Some(3)) => Kind::So3,
                    (true, Some(6)) => Kind::Se3,
                    _ => r.kind,
                }
            }
            (Step::Op(Operation::Block(w)), _) if r.kind == Kind::Unknown => {
                block_kind(w, &args).unwrap_or(r.kind)
            }
            _ => r.kind,
        };
        if kind == r.kind && args.iter().zip(&r.args).all(|(a, b)| Rc::ptr_eq(a, b)) {
            return r.clone();
        }
        Recipe::node(r.step.clone(), args, kind).unwrap_or_else(|| r.clone())
    });
    memo.insert(Rc::as_ptr(r), out.clone());
    out
}

/// The shape of a block matrix `[R, p; 0, 1]` of operands `args` (row by
/// row, `widths` in each row) recorded with no kind: each row as high as
/// its first block, the first row as wide as its blocks together. None
/// where a block's shape is open, or a lone 0 (a zero block of the shape
/// that fits) stands in the first row or column.
fn block_kind(widths: &[usize], args: &[Rc<Recipe>]) -> Option<Kind> {
    let size = |r: &Rc<Recipe>| match (&r.step, r.kind.shape()?) {
        (Step::Leaf(v), _) if v.as_scalar() == Some(0.0) => None,
        (_, (Some(h), Some(w))) => Some((h, w)),
        _ => None,
    };
    let (mut rows, mut cols, mut at) = (0, 0, 0);
    for (i, &n) in widths.iter().enumerate() {
        let row = args.get(at..at + n)?;
        at += n;
        rows += size(row.first()?)?.0;
        if i == 0 {
            cols = row
                .iter()
                .map(|b| size(b).map(|s| s.1))
                .sum::<Option<usize>>()?;
        }
    }
    Some(match (rows, cols) {
        (1, 1) => Kind::Scalar,
        (n, 1) => Kind::Vector(Some(n)),
        (r, c) => Kind::Matrix(Some(r), Some(c)),
    })
}

/// Whether a lone 0 was made a zero block (its numbers changed shape).
fn lone_changed(was: &Value, now: &Value) -> bool {
    match (was, now) {
        (Value::Num { m: a, .. }, Value::Num { m: b, .. }) => a.shape() != b.shape(),
        _ => false,
    }
}
