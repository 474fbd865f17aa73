//! Values made from symbols, computed with numbers by replaying how they
//! were made (LANGUAGE.md §7: once every symbol of a value has a number,
//! the value *is* a number, to machine precision, exactly as if the
//! numbers had been typed first). Every operation of the seam that makes a
//! formula from formulas records its step (`Op::made`, a
//! [`crate::values::recipe::Recipe`]); once the symbols have numbers,
//! [`numbers`] runs the same steps through [`Op::numeric`] — the function
//! the evaluator applies to numbers typed first — instead of evaluating
//! the expanded canonical form, whose coefficients can cancel.
//! [`at_numbers`] puts the numbers bound so far into a recipe's leaves,
//! for a value read while some of its symbols are still free.

use std::collections::HashMap;
use std::rc::Rc;

use crate::check::ty::Kind;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::seam::apply::{self, Op};
use crate::sym::{Expr, Mat, Symbol};
use crate::syntax::ast::Span;
use crate::values::exact::Exact;
use crate::values::recipe::{OnBranch, Recipe, Step, vague};
use crate::values::value::Value;

/// A symbol's number, if it has one now: the value bound to it, with its
/// exact form (`a = 60 deg` is π/3, §3), as typed first.
pub(crate) type Lookup<'a> = &'a dyn Fn(&Symbol) -> Option<Value>;

/// A symbol's number as a float.
fn float(at: Lookup, s: &Symbol) -> Option<f64> {
    at(s).and_then(|v| v.as_scalar())
}

/// A symbol's exact number, as an expression.
fn exact(at: Lookup, s: &Symbol) -> Option<Expr> {
    at(s)?.exact_form()?.data.into_iter().next()
}

/// The numbers of a formula with numbers for its symbols, from its
/// canonical form (a leaf; `kind` says what it is where the formula's
/// kind says only a shape), with its exact form when every symbol's
/// number has one (`cos(a)` at a = π/3 is 1/2). A formula that is one
/// symbol is the value bound to it. None when a symbol has no number.
pub(crate) fn canonical(kind: &Kind, m: &Mat, at: Lookup) -> Option<Value> {
    if *kind == Kind::Bool {
        return crate::values::formula::constant_shown(&Value::Formula {
            kind: *kind,
            m: m.clone(),
            how: None,
        });
    }
    if let [e] = m.data.as_slice()
        && let Some(s) = crate::sym::expr::as_symbol(e)
    {
        return at(&s).filter(|v| v.as_scalar().is_some());
    }
    let f = |s: &Symbol| float(at, s);
    let xs: Vec<f64> = m.data.iter().map(|e| e.eval(&f)).collect::<Option<_>>()?;
    let nums: crate::values::num::Num =
        nalgebra::DMatrix::from_row_slice(m.rows, m.cols, &xs).into();
    let kind = if vague(kind) { classify(&nums) } else { *kind };
    let mut syms = Vec::new();
    m.data.iter().for_each(|e| e.symbols(&mut syms));
    let forms: Option<Vec<(Symbol, Expr)>> = syms
        .into_iter()
        .map(|s| exact(at, &s).map(|e| (s, e)))
        .collect();
    let exact = match forms {
        Some(forms) => {
            let m = m.clone();
            Exact::later(move || {
                let by = |s: &Symbol| forms.iter().find(|(t, _)| t == s).map(|(_, e)| e.clone());
                Some(m.map(|e| e.subst(&by)))
            })
        }
        None => Exact::Float,
    };
    Some(Value::Num {
        kind,
        m: nums,
        exact,
    })
}

/// `e` with the numbers bound so far put in: exact where the number has
/// an exact form (`cos(b) x` at b = π/6 is `(√3/2) x`), else as a float.
pub(crate) fn put_numbers(e: &Expr, at: Lookup) -> Expr {
    let by = |s: &Symbol| exact(at, s);
    e.subst(&by).at_numbers(&|s: &Symbol| float(at, s))
}

/// Operation `op` on numbers `args`, exactly as the evaluator applies it
/// to numbers typed first: its numeric function with its exact form
/// ([`Op::with_exact`]); a builtin by its table row with its warnings
/// (the gimbal lock of `euler_zyx`) put in `warnings`, and a group
/// element with an inf or NaN entry refused.
pub(crate) fn typed_first(
    op: Op,
    args: &[&Value],
    kind: &Kind,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Value, crate::values::error::OpError> {
    use crate::values::error::OpError;
    match op {
        Op::Call(b, _) => {
            // (`sum`, `min`, `max` of a range that waited: as typed first)
            if let [xs] = args
                && let Some(v) = super::folds::of_call(b.name, xs)
            {
                return v.map_err(OpError::Message);
            }
            let exact = op.exact_of(args, kind);
            let site = apply::Site {
                spans: apply::Spans::repeat(Default::default(), args.len()),
                call_span: Default::default(),
                typed: Vec::new(),
                warnings,
                certified_turn: Some(super::turn::half_turn),
                certified_entries: Some(super::turn::entries),
            };
            let vals = args.iter().map(|v| (*v).clone()).collect();
            let mut v =
                apply::call(b, vals, site).map_err(|d| OpError::Message(d.into_message()))?;
            v.set_call_exact(exact);
            super::domain::not_finite_group(&v, b.name, Default::default())
                .map_err(|d| OpError::Message(d.into_message()))?;
            Ok(v)
        }
        Op::Block(_) => op.numeric(args, Some(kind)),
        _ => {
            let v = op.numeric(args, Some(kind))?;
            Ok(op.with_exact(v, args, kind))
        }
    }
}

/// The kind of numbers by shape and, for a square matrix, by the group
/// it is in ([`crate::values::convert::classify`]).
pub(crate) fn classify(m: &crate::values::num::Num) -> Kind {
    if m.shape() == (1, 1) {
        Kind::Scalar
    } else if m.ncols() == 1 {
        Kind::Vector(Some(m.nrows()))
    } else {
        crate::values::convert::classify(m)
    }
}

/// The value of recipe `r` with the numbers `at` gives: each step applied
/// to its operands' numbers by [`Op::numeric`], as when they are typed
/// first; shared operands computed once. None when a leaf's symbol has no
/// number or a step's operands are not what it takes (the caller then
/// evaluates the canonical form, as before there were recipes). A step
/// whose numbers are outside its domain (`(a² − b²)/(a − b)` at a = b,
/// `cot u` at u = 0) is that step's error, as when the numbers are typed
/// first: the canonical form, whose factors may have cancelled, must not
/// answer in its place.
pub(crate) fn numbers(
    r: &Rc<Recipe>,
    at: Lookup,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Option<Value>, Failed> {
    let mut memo = Memo::default();
    let v = replay(r, at, &mut memo);
    for w in memo.warnings {
        if !warnings.iter().any(|x| x.message == w.message) {
            warnings.push(w);
        }
    }
    match memo.failed {
        Some(msg) => Err(Failed(msg)),
        None => Ok(v),
    }
}

/// Why a replayed step failed with numbers: the message of the numeric
/// operation, as a user sees it when the numbers are typed first.
#[derive(Debug, Clone)]
pub struct Failed(pub String);

/// The values of the steps replayed so far (shared operands are computed
/// once), and the first step that failed with numbers outside its domain.
#[derive(Default)]
struct Memo {
    seen: HashMap<*const Recipe, Option<Value>>,
    failed: Option<String>,
    /// The warnings of the steps (a builtin's, as typed first).
    warnings: Vec<Diagnostic>,
    /// Every operand replayed, also after one with no number yet
    /// ([`failure`]: the steps that are numbers while others wait).
    every: bool,
}

/// The first step of recipe `r` that fails with the numbers bound so far
/// while some symbols are still free (LANGUAGE.md §7: as typed first, a
/// step whose operands are numbers is computed, and refused outside its
/// domain: `cot(b)` at b = 0, `(b² − b)/b` at b = 0, whose canonical form
/// cancelled the factor; a division by a number 0 is refused whatever the
/// numerator). None when no step fails.
pub(crate) fn failure(r: &Rc<Recipe>, at: Lookup) -> Option<Failed> {
    let mut memo = Memo {
        every: true,
        ..Memo::default()
    };
    replay(r, at, &mut memo);
    memo.failed.map(Failed)
}

/// Whether the divisor recipe `r`, still over free symbols, is 0 with the
/// numbers bound so far: made again by its operations over formulas with
/// those numbers in its leaves (`super::partly::made_with`: `a b` at
/// b = 0 is 0, so `(a b)/(a b) + c` is a division by zero, as typed
/// first, though its canonical form cancelled the quotient to 1 + c).
/// False where it cannot tell. Any depth a recipe may have
/// (`recipe::MAX_DEPTH`): the remaking is linear in the recipe's steps
/// (each made once), grows its stack on the heap, and a formula grown
/// past the symbolic budget is None here; a limit of 64 steps let a
/// divisor made in 3,000 (`x = x + b a` again and again) through as
/// nonzero.
fn vanishes(r: &Rc<Recipe>, at: Lookup) -> bool {
    match super::partly::made_with(r, at) {
        Some(Value::Formula { m, .. }) => m.data.iter().all(|e| e.as_f64() == Some(0.0)),
        Some(v) => v.as_scalar() == Some(0.0),
        None => false,
    }
}

fn replay(r: &Rc<Recipe>, at: Lookup, memo: &mut Memo) -> Option<Value> {
    let key = Rc::as_ptr(r);
    if let Some(v) = memo.seen.get(&key) {
        return v.clone();
    }
    // (recipes are at most recipe::MAX_DEPTH deep; the stack grows on the
    // heap when it runs low, as the evaluator's does)
    let v = stacker::maybe_grow(64 * 1024, 1024 * 1024, || step(r, at, memo));
    memo.seen.insert(key, v.clone());
    v
}

fn step(r: &Recipe, at: Lookup, memo: &mut Memo) -> Option<Value> {
    if let Step::Leaf(v) = &r.step {
        return match v {
            Value::Formula { kind, m, .. } => canonical(kind, m, at),
            Value::Sym(_) => None,
            v => Some(v.clone()),
        };
    }
    let args: Vec<Value> = if memo.every {
        let args: Vec<Option<Value>> = r.args.iter().map(|a| replay(a, at, memo)).collect();
        if let (Step::Op(o), [_, d]) = (&r.step, args.as_slice())
            && matches!(Op::of(o), Some(Op::Arith(crate::syntax::ast::BinOp::Div)))
            && match d {
                Some(d) => d.as_scalar() == Some(0.0),
                None => vanishes(&r.args[1], at),
            }
        {
            memo.failed.get_or_insert_with(|| "division by zero".into());
        }
        args.into_iter().collect::<Option<_>>()?
    } else {
        r.args
            .iter()
            .map(|a| replay(a, at, memo))
            .collect::<Option<_>>()?
    };
    let refs: Vec<&Value> = args.iter().collect();
    let op = match &r.step {
        Step::Part(i) => {
            return match refs.as_slice() {
                [Value::Tuple(vs)] => vs.get(*i).cloned(),
                // (numbers give the angles as a vector, symbols a tuple)
                [Value::Num { m, .. }] if m.ncols() == 1 => {
                    (*i < m.nrows()).then(|| Value::scalar(m[*i]))
                }
                _ => None,
            };
        }
        Step::Retag => {
            return match refs.as_slice() {
                [Value::Num { m, exact, .. }] => Some(Value::Num {
                    kind: r.kind,
                    m: m.clone(),
                    exact: exact.clone(),
                }),
                _ => None,
            };
        }
        Step::Leaf(_) => return None,
        // a range that waited for its numbers: the list typed first gives
        Step::Range(_) => {
            let [a, h, b] = refs.as_slice() else {
                return None;
            };
            return match crate::seam::range::range_items(a, h, b) {
                Ok(v) => Some(v),
                Err(e) => {
                    memo.failed.get_or_insert(e.to_string());
                    None
                }
            };
        }
        Step::Compare(op) => {
            let [a, b] = refs.as_slice() else {
                return None;
            };
            return match super::equality::equal(a, b, *op) {
                Ok(Some(v)) => {
                    if !v
                        && *op == crate::syntax::ast::CmpOp::Eq
                        && let Some(note) = super::equality::false_note(a, b, Default::default())
                    {
                        memo.warnings.push(note);
                    }
                    Some(Value::Bool(v))
                }
                Ok(None) => None,
                Err(m) => {
                    memo.failed.get_or_insert(m);
                    None
                }
            };
        }
        // the call the closed form was made by, right on every branch;
        // numbers off the branch the closed form assumed say so (§7)
        Step::Closed(on) => {
            if let Some(why) = on.broken(&|s: &Symbol| float(at, s)) {
                memo.warnings.push(off_branch(on, &why));
            }
            return args.into_iter().next();
        }
        // a derivative of a closed form, on its branch only; off it, the
        // rate where there is one
        Step::Guard(on) => {
            let f = |s: &Symbol| float(at, s);
            let held = on.holds(&f);
            let mut args = args.into_iter();
            let (closed, rate) = (args.next(), args.next());
            return match (held, rate) {
                (Some(true), _) => closed,
                (_, Some(rate)) => Some(rate),
                (held, None) => {
                    memo.failed.get_or_insert(format!(
                        "{}, and the numbers {}: the derivative of the closed form holds on \
                         the branch only",
                        on.text,
                        if held.is_some() {
                            "are off it"
                        } else {
                            "are too near its bounds to tell"
                        },
                    ));
                    None
                }
            };
        }
        // the rate of a transform's exponential coordinates
        Step::LogRate => {
            let (Some(t), Some(dt)) = (
                refs.first().and_then(|v| mat4(v)),
                refs.get(1).and_then(|v| mat4(v)),
            ) else {
                return None;
            };
            return match crate::lie::dlog::se3_log_rate(&t, &dt) {
                Some(v) => Some(Value::vector(r.kind, v.as_slice())),
                None => {
                    memo.failed.get_or_insert(
                        "the rate of log(T) at a half turn (θ = π): the logarithm jumps there, \
                         so it has no derivative"
                            .to_string(),
                    );
                    None
                }
            };
        }
        // the rate of a call at numbers (rate.rs)
        Step::Rate(name, part) => {
            let [x, dx] = refs.as_slice() else {
                return None;
            };
            return super::rate::of(name, *part, x, dx, r.kind).unwrap_or_else(|why| {
                memo.failed.get_or_insert(why);
                None
            });
        }
        Step::Op(o) => Op::of(o)?,
    };
    // (the kind as the checker gives it for these numbers typed first)
    let kind = rule_kind(op, &refs).unwrap_or(r.kind);
    match typed_first(op, &refs, &kind, &mut memo.warnings) {
        Ok(v) => Some(v),
        Err(e) => {
            if refusal(&e) && memo.failed.is_none() {
                memo.failed = Some(e.to_string());
            }
            None
        }
    }
}

/// The warning of a value whose closed form held on a branch that the
/// numbers bound since leave (LANGUAGE.md §7: the value that relied on an
/// assumption says so when numbers break it): the value is the call
/// itself, computed from the numbers as if they had been typed first.
fn off_branch(on: &OnBranch, why: &str) -> Diagnostic {
    Diagnostic::warning(
        ErrorKind::Domain,
        Span::default(),
        format!(
            "{}, which the numbers bound since leave ({why}): this value is computed from the \
             numbers, as if they had been typed first",
            on.text
        ),
    )
    .with_help(
        "the closed form printed before holds on its branch only; off it the value is the \
         book's principal one for these numbers, not the closed form's",
    )
}

/// The 4×4 of numbers `v` is, if it is one.
fn mat4(v: &Value) -> Option<crate::lie::Mat4> {
    match v {
        Value::Num { m, .. } if m.shape() == (4, 4) => {
            Some(crate::lie::Mat4::from_column_slice(m.as_slice()))
        }
        _ => None,
    }
}

/// Operation `op` on numbers `args` as typed first ([`typed_first`]),
/// its result's kind given by its rule on the operands' kinds, as the
/// checker gives it when the numbers are typed first (`[1, 0; 0, 1]^-1`
/// is SO(2)); an operation the rule refuses gets no kind from it.
pub(crate) fn as_typed(
    op: Op,
    args: &[&Value],
    warnings: &mut Vec<Diagnostic>,
) -> Result<Value, crate::values::error::OpError> {
    let kind = rule_kind(op, args).unwrap_or(Kind::Unknown);
    typed_first(op, args, &kind, warnings)
}

/// The kind `op`'s rule gives its result from the kinds of numbers
/// `args`, as the checker does when they are typed first; None when the
/// rule refuses them.
fn rule_kind(op: Op, args: &[&Value]) -> Option<Kind> {
    let tys: Vec<crate::check::ty::Ty> = args
        .iter()
        .map(|v| crate::check::ty::Ty::plain(v.kind()))
        .collect();
    let exponent = match (op, args) {
        (Op::Arith(crate::syntax::ast::BinOp::Pow), [_, e]) => e.as_scalar(),
        _ => None,
    };
    let hints = crate::seam::apply::Hints {
        exponent,
        ..Default::default()
    };
    op.rule(&tys, hints).ok().map(|t| t.kind)
}

/// Whether a step's error says its numbers are outside its domain (the
/// answer is a refusal) rather than that its operands are not what the
/// numeric operation takes (then the canonical form answers).
pub(crate) fn refusal(e: &crate::values::error::OpError) -> bool {
    use crate::values::error::OpError as E;
    !matches!(e, E::NotNumbers(_) | E::Operands)
}

/// Recipe `r` with the numbers bound so far put into its leaves (a value
/// read while some of its symbols are free keeps the numbers of the time
/// it was read, as its canonical form does); unchanged parts are shared.
pub(crate) fn at_numbers(r: &Rc<Recipe>, at: Lookup) -> Rc<Recipe> {
    let mut memo = HashMap::new();
    let leaf = |v: &Value| with_numbers(v, at);
    crate::values::recipe::rebase(r, &leaf, &mut memo)
}

/// A formula leaf with the numbers bound so far put in (numbers once it
/// has no free symbol left); None when it is no formula or none of its
/// symbols has a number.
pub(crate) fn with_numbers(v: &Value, at: Lookup) -> Option<Value> {
    let Value::Formula { kind, m, .. } = v else {
        return None;
    };
    let mut syms = Vec::new();
    m.data.iter().for_each(|e| e.symbols(&mut syms));
    if !syms.iter().any(|s| at(s).is_some()) {
        return None;
    }
    Some(
        canonical(kind, m, at)
            .unwrap_or_else(|| crate::values::formula::make(kind, m.map(|e| put_numbers(e, at)))),
    )
}

/// `subs(x, name, value)` with a number for the last symbol of `x`: the
/// value `x` was made to have there, replayed as if the number had been
/// typed first (§7) — refused where a step is outside its domain, as the
/// substituted canonical form, whose factors may have cancelled
/// (`(a² − 1)/(a − 1)` is `1 + a`), would not be. When `x` keeps other
/// symbols, only that refusal ([`failure`]). None when there is none or
/// `x` was made by no recorded steps (the canonical form is substituted).
pub(crate) fn subs_numbers(
    args: &[&Value],
    warnings: &mut Vec<Diagnostic>,
) -> Option<Result<Value, String>> {
    let [
        Value::Formula {
            m, how: Some(r), ..
        },
        Value::Formula { m: name, .. },
        by,
    ] = args
    else {
        return None;
    };
    let sym = match name.data.as_slice() {
        [e] => crate::sym::expr::as_symbol(e)?,
        _ => return None,
    };
    by.as_scalar()?;
    let mut syms = Vec::new();
    m.data.iter().for_each(|e| e.symbols(&mut syms));
    syms.retain(|s| !crate::values::waiting::stand_in(s));
    crate::values::recipe::symbols(r, &mut syms);
    let at = |s: &Symbol| (*s == sym).then(|| (*by).clone());
    if syms.iter().any(|s| *s != sym) {
        // (a closed form's branch left at the number: its form there is
        // not the call's, and the call waits for the other numbers)
        if let Some(x) = by.as_scalar()
            && let Some(branch) = super::branch_at::left_at(r, &|s| (*s == sym).then_some(x))
        {
            return Some(Err(format!(
                "cannot decide: {} = {} is not inside the branch of the closed form ({branch}), \
                 where it is not the call's value; bind the other symbols first",
                crate::sym::print::symbol(&sym, Default::default()),
                crate::values::number::fmt_num(x, 4)
            )));
        }
        // (others stay symbols: refused only where a step of numbers is)
        if let Some(Failed(msg)) = failure(r, &at) {
            return Some(Err(msg));
        }
        // (a canonical form singular at the number where the expression as
        // typed is not, `exp([S] a)^-1` of a non-unit axis at a = 0: made
        // again from its recipe with the number, as typed first)
        let singular = m
            .data
            .iter()
            .any(|e| put_numbers(e, &at).undefined().is_some());
        return singular
            .then(|| super::partly::made_defined(r, &at))
            .flatten()
            .map(Ok);
    }
    match numbers(r, &at, warnings) {
        Err(Failed(msg)) => Some(Err(msg)),
        Ok(Some(v @ Value::Num { .. })) if same_shape(&v, m) => Some(Ok(v)),
        Ok(_) => None,
    }
}

/// True when numbers `v` have the shape of formula `m` (a bool is what a
/// comparison gives, a list what a range gives).
pub(crate) fn same_shape(v: &Value, m: &Mat) -> bool {
    matches!(v, Value::Num { m: xs, .. } if xs.shape() == (m.rows, m.cols))
        || matches!(v, Value::Bool(_) | Value::List(_))
}
