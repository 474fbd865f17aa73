//! Proofs of identities between numbers made from exact ones (LANGUAGE.md
//! §7, issue 21): `sin(1)^2 + cos(1)^2 == 1`, `cos(2) == cos(1)^2 -
//! sin(1)^2`, `Rotz(1) Rotz(2) == Rotz(3)`. Neither side has an exact form
//! (sin 1 is a float), but each was made by operations over exact numbers
//! (its recipe, [`crate::values::exact::Exact::with_recipe`]). The recipe
//! is made again by the symbolic engine with every angle `x` of a sine,
//! cosine or rotation read as `x·ν`, where ν is a symbol that stands for
//! 1: each side becomes a function of ν that is the side's value at
//! ν = 1. When the two functions have the same canonical form, with no
//! float anywhere in it, they are equal for every ν, so at ν = 1: the
//! sides are equal, proven. Anything else proves nothing
//! ([`super::certify`] then bounds the difference).

use std::collections::HashMap;

use super::value::Value;
use crate::sym::Mat;
use crate::sym::coef::Coef;
use crate::sym::expr::{Expr, Symbol, Var};
use crate::values::exact::Operation;

/// What the canonical forms of both sides' recipes, with their angles
/// scaled by ν (the module's doc), prove of `a == b`: `Ok(())` equal;
/// `Err(d)` different, `d` an entry of `a − b` that is a nonzero exact
/// number (no ν left: the same at ν = 1); None nothing.
pub fn verdict(a: &Value, b: &Value) -> Option<Result<(), Expr>> {
    let mut memo = HashMap::new();
    let (x, y) = (lifted(a, &mut memo, 0)?, lifted(b, &mut memo, 0)?);
    if (x.rows, x.cols) != (y.rows, y.cols)
        || !x.data.iter().all(exact)
        || !y.data.iter().all(exact)
    {
        return None;
    }
    if x.data == y.data {
        return Some(Ok(()));
    }
    x.data
        .iter()
        .zip(&y.data)
        .map(|(p, q)| p.sub(q))
        .find(|d| {
            !d.terms.is_empty()
                && d.terms
                    .keys()
                    .all(|mono| mono.iter().all(|(v, _)| matches!(v, Var::Pi)))
        })
        .map(Err)
}

/// ν, the symbol that stands for 1 in the angles.
fn nu() -> Expr {
    Expr::symbol(Symbol::new("ν"))
}

/// True when no coefficient anywhere in `e` is a float (calls' arguments
/// included): its canonical form is then a proof, not a rounding.
fn exact(e: &Expr) -> bool {
    e.terms.iter().all(|(mono, c)| {
        matches!(c, Coef::Exact { .. })
            && mono.iter().all(|(v, _)| match v {
                Var::Call(call) => call.args.iter().all(exact),
                _ => true,
            })
    })
}

/// The builtins whose scalar arguments are angles: (name, which argument).
fn angle_of(op: &Operation) -> Option<usize> {
    let Operation::Call(name) = op else {
        return None;
    };
    match crate::builtins::lookup(name)?.name {
        "sin" | "cos" | "tan" | "cot" | "sec" | "csc" | "Rotx" | "Roty" | "Rotz" => Some(0),
        "Rot" => Some(1),
        _ => None,
    }
}

/// The canonical form of `v` with its angles scaled by ν: its exact form
/// when it has one, else its recipe made again symbolically.
fn lifted(v: &Value, memo: &mut HashMap<*const (), Option<Mat>>, depth: u32) -> Option<Mat> {
    let Value::Num { exact, .. } = v else {
        return None;
    };
    if let Some(form) = v.exact_form() {
        return Some(form);
    }
    if depth > 64 {
        return None;
    }
    let key = exact.identity()?;
    if let Some(found) = memo.get(&key) {
        return found.clone();
    }
    let out = exact
        .with_recipe(|p| {
            let angle = angle_of(&p.op);
            let forms = p
                .args
                .refs()
                .into_iter()
                .enumerate()
                .map(|(i, a)| {
                    let mut m = lifted(a, memo, depth + 1)?;
                    if Some(i) == angle {
                        if m.data.len() != 1 {
                            return None;
                        }
                        m.data[0] = m.data[0].mul(&nu());
                    }
                    Some(Value::Formula {
                        kind: a.kind(),
                        m,
                        how: None,
                    })
                })
                .collect::<Option<Vec<Value>>>()?;
            super::exactness::formula_of(&p.op, forms, &p.kind)
        })
        .flatten();
    memo.insert(key, out.clone());
    out
}
