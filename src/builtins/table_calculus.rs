//! The builtins of symbols themselves (LANGUAGE.md §7): `diff(x, t)` by
//! the chain rule (§3.2.2's Ṙ Rᵀ = [ω_s]; partial derivatives by q and q̇),
//! `simplify(x)`, `expand(x)` and `subs(x, name, value)`. Their symbolic
//! values are computed here; [`super::table_sym::eval_symbolic`] calls them.

use super::{Area, ArgError, Args, Builtin, Typing};
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::Diagnostic;
use crate::sym::Expr;
use crate::sym::expr::{Wrt, as_symbol};
use crate::sym::matrix::Mat;
use crate::values::formula::{self, make};
use crate::values::value::Value;

/// `subs(x, name, value)`: x with the symbol `name` replaced by `value` (a
/// number or an expression), re-canonicalized; an error where that leaves
/// no real value (a division by zero, √ of a negative number).
pub(super) fn subs(v: &Value, x: &Mat, name: &Mat, by: &Mat) -> Result<Value, String> {
    let sym = match name.data.as_slice() {
        [e] => as_symbol(e),
        _ => None,
    }
    .ok_or("subs(x, name, value) replaces a symbol: subs(x, t, 0.5), subs(x, t1, t2 - t3)")?;
    let value = match by.data.as_slice() {
        [e] => e.clone(),
        _ => return Err("subs(x, name, value) puts a scalar in place of the symbol".into()),
    };
    // (θ(t) at t = 2 is θ(2), no symbol here: `subs(th t, t, 2)` printed
    // `2 th`, whose derivative is 2 θ̇)
    let mut syms = Vec::new();
    x.data.iter().for_each(|e| e.symbols(&mut syms));
    if sym.time.is_none()
        && let Some(f) = syms.iter().find(|s| s.time.as_deref() == Some(&*sym.name))
    {
        return Err(format!(
            "subs(x, {0}, value) of an expression with {1}({0}) in it: {1} at another {0} has \
             no name here; substitute {1} (and its rates) instead",
            sym.name, f.name
        ));
    }
    // θ(t) put equal to a function of t (`subs(x, θ, t^2)`): its rates
    // are that function's (θ̇ = 2t), as SymPy substitutes inside
    // derivatives; they stayed θ̇, a rate of no function. So by another
    // function of t (`subs(x, θ, 2 φ)`: θ̇ = 2φ̇). (A value free of t is a
    // state, `subs(x, θ, 0.3)`, its rates other coordinates.)
    let mut rates: Vec<(crate::sym::Symbol, Expr)> = Vec::new();
    let mut in_value = Vec::new();
    value.symbols(&mut in_value);
    if let Some(t) = &sym.time
        && sym.dots == 0
        && in_value
            .iter()
            .any(|s| (s.time.is_none() && s.name == *t) || s.time.as_ref() == Some(t))
    {
        let wrt = crate::sym::expr::Wrt::by(crate::sym::Symbol::new(t));
        let (mut rate, mut d) = (sym.clone(), value.clone());
        while syms
            .iter()
            .any(|s| s.name == sym.name && s.dots > rate.dots)
        {
            rate = rate.dot();
            d = d.diff(&wrt).cancel();
            rates.push((rate.clone(), d.clone()));
        }
    }
    let by = |s: &crate::sym::Symbol| {
        (*s == sym)
            .then(|| value.clone())
            .or_else(|| rates.iter().find_map(|(r, d)| (r == s).then(|| d.clone())))
    };
    let out = x.map(|e| e.subst(&by).cancel());
    // (`subs(a/b, b, 0)` is a division by zero, as typed first: never a
    // term with an inf coefficient dropped)
    if let Some(why) = out.data.iter().find_map(Expr::undefined) {
        return Err(why);
    }
    Ok(make(&v.kind(), out))
}

/// `diff(x, t)` of an expression over given matrices (no scalar symbol in
/// it, so no function of time: only a scalar can be one, §7): 0, of the
/// result's shape `kind`. None for any other call.
pub fn constant_derivative(name: &str, args: &[&Value], kind: &Kind) -> Option<Value> {
    let [Value::Sym(t), _] = args else {
        return None;
    };
    let symbols = |n: &crate::values::symbolic::Tree<Value>| matches!(n, crate::values::symbolic::Tree::Const(v, _) if crate::values::recipe::holds_symbols(v));
    if name != "diff" || t.any(&mut { symbols }) {
        return None;
    }
    let (Some(r), Some(c)) = kind.shape()? else {
        return None;
    };
    Some(Value::Num {
        kind: *kind,
        m: crate::values::num::Num::zeros(r, c),
        exact: crate::values::exact::Exact::Typed,
    })
}

/// `diff(x, t)`: entrywise by the chain rule. By a plain symbol (the time
/// variable, or a name not bound) the total derivative, every θ(t) giving
/// θ̇; by a function of time q or its rate q̇, the partial derivative
/// ([`Wrt::by`]).
pub(super) fn diff(v: &Value, x: &Mat, by: &Mat, kind: &Kind) -> Result<Value, String> {
    let sym = match by.data.as_slice() {
        [e] => as_symbol(e),
        _ => None,
    }
    .ok_or("diff(x, t) differentiates by a symbol: diff(R, t), diff(x, theta)")?;
    let wrt = Wrt::by(sym);
    let kind = match kind {
        Kind::Unknown => v.kind(),
        k => *k,
    };
    // Σ_v R_v·dv in each entry, refused before it is formed when too large
    let mut known = crate::sym::diff::Known::limited(crate::values::limits::MAX_WORK);
    let parts: Vec<Vec<(Expr, Expr)>> = x
        .data
        .iter()
        .map(|e| e.diff_parts(&wrt, &mut known))
        .collect();
    if let Some(work) = known.over() {
        return Err(format!(
            "symbolic expression too large: the derivative's chain rule would take at least {work} \
             term products (more than {})",
            crate::values::limits::MAX_WORK
        ));
    }
    let pairs: Vec<Vec<(&Expr, &Expr)>> = parts
        .iter()
        .map(|p| p.iter().map(|(r, d)| (r, d)).collect())
        .collect();
    formula::fits_sums(&pairs, "derivative")?;
    // canonical as a quotient is (common factors cancelled): d tan t is
    // 1 + tan² t, not tan² t + cos t/cos t
    let data = pairs
        .iter()
        .map(|p| crate::sym::dense::sum_of_products(p).cancel())
        .collect();
    Ok(make(
        &kind,
        Mat {
            rows: x.rows,
            cols: x.cols,
            data,
        },
    ))
}

/// `diff`: the kind of a derivative (a rotation's is a plain matrix).
fn diff_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    if args[1].kind != Kind::Scalar && args[1].kind != Kind::Unknown {
        return Err(ArgError::type_of(
            1,
            "diff(x, t) differentiates by a scalar symbol",
        ));
    }
    let t = &args[0];
    Ok(match &t.kind {
        Kind::Scalar => Ty::scalar(),
        k if k.is_vector() => Ty::new(*k, t.frames),
        k => match k.shape() {
            Some((r, c)) => Ty::new(Kind::Matrix(r, c), t.frames),
            None => {
                return Err(ArgError::type_of(
                    0,
                    format!("cannot differentiate {}", k.a()),
                ));
            }
        },
    })
}

fn same_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    Ok(args[0])
}

/// `subs`: a scalar symbol replaced by a scalar; the result has x's type.
fn subs_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    for (i, what) in [(1, "the name of a scalar symbol"), (2, "a scalar value")] {
        if args[i].kind != Kind::Scalar && args[i].kind != Kind::Unknown {
            return Err(ArgError::type_of(
                i,
                format!("subs(x, name, value) takes {what} here"),
            ));
        }
    }
    Ok(args[0])
}

/// The numeric meaning of `diff`: a number is constant, its derivative 0.
fn eval_diff(a: &mut Args) -> Result<Value, Diagnostic> {
    let m = a.mat(0)?;
    Ok(Value::Num {
        kind: a.value(0).kind(),
        m: crate::values::num::Num::zeros(m.nrows(), m.ncols()),
        exact: Default::default(),
    })
}

pub(super) fn builtins() -> Vec<Builtin> {
    vec![
        Builtin {
            name: "diff",
            aliases: &[],
            signature: "diff(x: scalar | vector | matrix, t: symbol) -> the same shape",
            section: "§3.2.2",
            doc: "the derivative by the chain rule, entrywise; diff(R, t) * R^T is [ω_s]",
            example: "given theta(t) : scalar; diff(Rotz(theta), t) Rotz(theta)^T",
            area: Area::Scalars,
            typing: Typing::Custom {
                arity: (2, 2),
                rule: diff_rule,
            },
            eval: eval_diff,
        },
        Builtin {
            name: "simplify",
            aliases: &[],
            signature: "simplify(x) -> x in canonical form",
            section: "§7 (docs/language.md)",
            doc: "the canonical form: like terms collected, sin² + cos² = 1, angle sums folded",
            example: "given a, b : scalar; simplify(cos(a) cos(b) - sin(a) sin(b))",
            area: Area::Scalars,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: same_rule,
            },
            eval: |a| Ok(a.value(0).clone()),
        },
        Builtin {
            name: "expand",
            aliases: &[],
            signature: "expand(x) -> x multiplied out",
            section: "§7 (docs/language.md)",
            doc: "products and powers multiplied out (the canonical form always is; angle sums stay folded)",
            example: "given a, b : scalar; expand((a + b)^2)",
            area: Area::Scalars,
            typing: Typing::Custom {
                arity: (1, 1),
                rule: same_rule,
            },
            eval: |a| Ok(a.value(0).clone()),
        },
        Builtin {
            name: "subs",
            aliases: &[],
            signature: "subs(x, name: symbol, value: scalar) -> x with value for name",
            section: "§7 (docs/language.md)",
            doc: "substitution: the symbol replaced by a number or an expression, simplified",
            example: "given t1, t2 : scalar; subs(cos(t1 + t2), t2, -t1)",
            area: Area::Scalars,
            typing: Typing::Custom {
                arity: (3, 3),
                rule: subs_rule,
            },
            eval: |a| Ok(a.value(0).clone()),
        },
        Builtin {
            name: "solve",
            aliases: &[],
            signature: "solve(lhs == rhs, x: symbol) -> x (or the tuple of the real roots, increasing)",
            section: "Exercises 2.7 and 3.7(b); §8 (docs/language.md)",
            doc: "one unknown of a linear equation, the real roots of a quadratic with exact numbers, or the angles x in (−π, π] of a cos kx + b sin kx = c (tan x = c too) with exact a, b, c; vectors and matrices entry by entry",
            example: "given x : scalar; solve(x^2 - 5*x + 6 == 0, x)",
            area: Area::Scalars,
            typing: Typing::Custom {
                arity: (2, 2),
                rule: solve_rule,
            },
            eval: |a| {
                Err(a.domain(
                    "solve(lhs == rhs, x) solves for a symbol: declare it first, given x : scalar",
                ))
            },
        },
    ]
}

/// `solve`: an equation (or an expression, = 0) and a scalar symbol; the
/// result is a scalar, or a tuple of them (known only from the roots).
fn solve_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    if !matches!(args[1].kind, Kind::Scalar | Kind::Unknown) {
        return Err(ArgError::type_of(
            1,
            "solve(lhs == rhs, x) solves for a scalar symbol x",
        ));
    }
    Ok(Ty::plain(Kind::Unknown))
}
