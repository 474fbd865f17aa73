//! A formula over `given` symbols read with the numbers bound since
//! (LANGUAGE.md §7: "once every symbol of a value has a number, the value
//! *is* a number … exactly as if the numbers had been typed first"): the
//! value bound to a symbol now, and a formula with those numbers put in,
//! replayed from how it was made where they are all bound.

use super::Bindings;
use crate::check::ty::Kind;
use crate::decide::replay;
use crate::diagnostics::Diagnostic;
use crate::sym::{Mat, Symbol};
use crate::syntax::name::Name;
use crate::values::formula;
use crate::values::recipe;
use crate::values::value::Value;
use std::rc::Rc;

/// The symbols a formula depends on: those of its canonical form and of
/// how it was made (`a/a` is 1, yet depends on `a`).
fn symbols_of(m: &Mat, how: Option<&Rc<recipe::Recipe>>) -> Vec<Symbol> {
    let mut syms = Vec::new();
    m.data.iter().for_each(|e| e.symbols(&mut syms));
    // (a value computed from a range that waits stands as a symbol no
    // binding gives a number: it depends on the range's symbols)
    syms.retain(|s| !crate::values::waiting::stand_in(s));
    if let Some(r) = how {
        recipe::symbols(r, &mut syms);
    }
    syms
}

/// The value bound to a symbol now, if it is a number.
pub fn bound(env: &dyn Bindings, s: &Symbol) -> Option<Value> {
    // (a component u[i] of a given vector: entry i of the numbers bound
    // to u, so that a bool over u[1] is decided again, issue 35)
    if s.index > 0 && s.dots == 0 && s.time.is_none() {
        return match env.binding(Name::new(&s.name)).and_then(|b| b.val) {
            Some(v @ Value::Num { m, .. })
                if m.ncols() == 1 && usize::from(s.index) <= m.nrows() =>
            {
                let i = usize::from(s.index) - 1;
                // (exact where the vector is: u = (0.6, 0, 0.8) as typed)
                Some(match v.exact_form() {
                    Some(f) if f.data.len() == m.nrows() => formula::make(
                        &crate::check::ty::Kind::Scalar,
                        crate::sym::Mat::scalar(f.data[i].clone()),
                    ),
                    _ => Value::scalar(m[(i, 0)]),
                })
            }
            _ => None,
        };
    }
    match env
        .binding(Name::new(&formula::binding_name(s)))
        .and_then(|b| b.val)
    {
        Some(v @ Value::Num { .. }) => Some(v.clone()),
        _ => None,
    }
}

/// A formula with the numbers bound since substituted. Once every symbol
/// it depends on has a number (those of its canonical form and of how it
/// was made: `a/a` at a = 0 is a division by zero, as typed first) the
/// value *is* a number (§7), computed by replaying how it was made with
/// those numbers ([`replay::numbers`]: the operations as typed, with the
/// numbers' exact forms, as if the numbers had been typed first), never
/// from its expanded canonical form, whose coefficients can cancel; only
/// a formula made by no replayable operation (a symbol, a derivative) is
/// evaluated from its canonical form. It is typed by what it is: what the
/// operations give the numbers, as typed first. Partly bound, the numbers
/// are put in, exactly where they are exact ([`replay::put_numbers`], and
/// into how it was made).
pub fn formula_now(
    v: &Value,
    env: &dyn Bindings,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Value, replay::Failed> {
    let Value::Formula { kind, m, how } = v else {
        return Ok(v.clone());
    };
    let lookup = |s: &Symbol| bound(env, s);
    let syms = symbols_of(m, how.as_ref());
    if !syms.iter().any(|s| lookup(s).is_some()) {
        return Ok(v.clone());
    }
    if syms.iter().all(|s| lookup(s).is_some()) {
        // (with the kind its binding gave it: `V_b = (…)` is a twist)
        if how.is_some()
            && let Some(x) = replay::numbers(&recipe::Recipe::of(v), &lookup, warnings)?
            && replay::same_shape(&x, m)
        {
            return Ok(x);
        }
        if let Some(v) = replay::canonical(kind, m, &lookup) {
            return Ok(v);
        }
    }
    // partly bound: refused where the numbers typed first are (a step of
    // numbers outside its domain, a division by 0), never a canonical form
    // with an inf or NaN coefficient or a call with no value in it
    if let Some(failed) = how.as_ref().and_then(|r| replay::failure(r, &lookup)) {
        return Err(failed);
    }
    // (numbers off a closed form's branch, other symbols free)
    let at = |s: &Symbol| lookup(s).and_then(|v| v.as_scalar());
    if let Some(why) = how
        .as_ref()
        .and_then(|r| crate::decide::branch_at::refusal(r, &at))
    {
        return Err(replay::Failed(why));
    }
    // (a comparison is decided again over the symbols still free: `a*b == 0`
    // at b = 0 is true, as typed first, though false over free a and b)
    // (one that waits for its numbers, `values::waiting`, waits as before)
    if *kind == Kind::Bool
        && crate::values::waiting::sides(v).is_none()
        && let Some(v) = how
            .as_ref()
            .and_then(|r| crate::decide::partly::compared(r, &lookup))
    {
        return v.map_err(replay::Failed);
    }
    let put = m.map(|e| replay::put_numbers(e, &lookup));
    if let Some(why) = put.data.iter().find_map(crate::sym::Expr::undefined) {
        // (a closed form singular where the expression as typed is not:
        // the inverse of exp([S] a) with a non-unit axis divides by a, and
        // at a = 0 it is the identity, as typed first — made again from
        // its recipe with the numbers in its leaves)
        return match how
            .as_ref()
            .and_then(|r| crate::decide::partly::made_defined(r, &lookup))
        {
            Some(v) => Ok(v),
            None => Err(replay::Failed(why)),
        };
    }
    Ok(match formula::make(kind, put.clone()) {
        Value::Formula { kind, m, .. } => Value::Formula {
            kind,
            m,
            how: how.as_ref().map(|r| replay::at_numbers(r, &lookup)),
        },
        // (numbers with symbols left in how it was made stay a formula)
        Value::Num { kind, m: xs, exact } => match how {
            Some(r) => Value::Formula {
                kind,
                m: put,
                how: Some(replay::at_numbers(r, &lookup)),
            },
            None => Value::Num { kind, m: xs, exact },
        },
        v => v,
    })
}
