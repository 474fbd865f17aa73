//! Tangents and cotangents as printed (LANGUAGE.md §7: "tan and cot kept
//! as tan and cot"), beside [`super::fraction`]'s sin/cos pairs of one
//! term: a quotient whose numerator is the co-functions of its
//! denominator's angles (`cot(x) cot(x + y)`, a sum once multiplied out),
//! and a kept half-angle sine over its cosine (`tan(x/2)`).

use super::coef::Coef;
use super::expr::{Expr, Func, Mono, Var, mono_mul};
use super::fraction::{Factor, needs_parens, opened};
use super::print::{Mode, Style, coefficient, power, trig_factor, var};
use num_traits::Zero;

/// A quotient whose denominator is a product of sines and cosines of
/// angles A and whose numerator is a constant times the co-functions of
/// the same angles, as a product of cotangents and tangents:
/// cos(x) cos(x + y)/(sin(x) sin(x + y)) is `cot(x) cot(x + y)` (the
/// numerator, a sum once multiplied out, is found by exact division by
/// each co-function). None for any other quotient.
pub(super) fn tangent_product(num: &Expr, den: &Mono, st: Style) -> Option<(bool, String)> {
    if num.terms.len() < 2 {
        return None;
    }
    let mut num = num.clone();
    let mut scale = Coef::one();
    let mut out: Vec<Factor> = Vec::new();
    for (v, e) in den {
        let (k, vars, factors) = opened(v, *e)?;
        if !vars.is_empty() {
            return None;
        }
        scale = scale.mul(&k);
        for f in factors {
            let mut angle = Expr::zero();
            for (s, n) in &f.k {
                if s.phase().is_some() {
                    return None;
                }
                angle = angle.add(&Expr::symbol(s.clone()).scale(&Coef::int(i64::from(*n))));
            }
            let (co, name) = if f.f == "sin" {
                (Expr::cos(&angle), "cot")
            } else {
                (Expr::sin(&angle), "tan")
            };
            for _ in 0..f.p {
                num = num.div_exact(&co)?;
            }
            out.push(Factor {
                f: name,
                k: f.k,
                p: f.p,
            });
        }
    }
    let c = num.as_const()?.mul(&scale);
    let (neg, coef) = coefficient(&c, st);
    let body: Vec<String> = out
        .iter()
        .map(|f| trig_factor(&f.k, f.f, f.p, st))
        .collect();
    let body = body.join(" ");
    let text = match coef.as_str() {
        "1" => body,
        _ if st.mode != Mode::Latex && needs_parens(&coef) => format!("({coef}) {body}"),
        _ => format!("{coef} {body}"),
    };
    Some((neg, text))
}

/// sin(x)/cos(x) and cos(x)/sin(x) of one kept call's argument (a half
/// angle, `tan(x/2)`) as the tangent and cotangent, power by power: the
/// monomial left, and the tangents' texts.
pub(super) fn call_tangents(poly: &Mono, st: Style) -> (Mono, Vec<String>) {
    let latex = st.mode == Mode::Latex;
    let call = |v: &Var, f: Func| match v {
        Var::Call(c) if c.f == f => Some(c.args[0].clone()),
        _ => None,
    };
    let mut left: Mono = poly.clone();
    let mut texts = Vec::new();
    for (top, bottom, from, to) in [
        (Func::Sin, Func::Cos, "sin", "tan"),
        (Func::Cos, Func::Sin, "cos", "cot"),
    ] {
        for i in 0..left.len() {
            let Some(x) = call(&left[i].0, top).filter(|_| left[i].1 > 0) else {
                continue;
            };
            let Some(j) = left
                .iter()
                .position(|(w, k)| *k < 0 && call(w, bottom).as_ref() == Some(&x))
            else {
                continue;
            };
            let text = var(&left[i].0, st);
            let renamed = if latex {
                let a = format!("operatorname{{{from}}}");
                text.contains(&a)
                    .then(|| text.replacen(&a, &format!("operatorname{{{to}}}"), 1))
            } else {
                text.strip_prefix(from).map(|r| format!("{to}{r}"))
            };
            let Some(renamed) = renamed else { continue };
            let m = left[i].1.min(-left[j].1);
            left[i].1 -= m;
            left[j].1 += m;
            texts.push(power(&renamed, m, latex));
        }
        left.retain(|(_, k)| *k != 0);
    }
    (left, texts)
}

/// The most terms a sum may have for its half-angle tangents to be looked
/// for (each is an exact division).
const MAX_HALF_TERMS: usize = 64;

/// `e` with its quotients over a power of a kept half-angle cosine written
/// as powers of the tangent, a kept call, and those over a power of the
/// sine with the cosine to the same power above, which [`call_tangents`]
/// prints as the cotangent: the canonical form folds sin(x/2)² into
/// (1 − cos x)/2, and `tan(x/2)^2` printed
/// `(1/2) (1/cos(x/2)^2 - cos(x)/cos(x/2)^2)`. The terms over
/// cos(u)^p, N/cos(u)^p, are Q·tan(u)^p where N = Q·sin(u)^p exactly
/// (checked by multiplying back), with Q no longer than N: the same value,
/// with a variable the canonical form does not use for it. None when
/// nothing changes.
pub(super) fn half_tangents(e: &Expr) -> Option<Expr> {
    if e.terms.len() > MAX_HALF_TERMS {
        return None;
    }
    let below = |v: &Var| matches!(v, Var::Call(c) if matches!(c.f, Func::Sin | Func::Cos));
    let mut keys: Vec<(Var, i32)> = Vec::new();
    for m in e.terms.keys() {
        for (v, k) in m {
            if *k < 0 && below(v) && !keys.iter().any(|(w, j)| w == v && j == k) {
                keys.push((v.clone(), *k));
            }
        }
    }
    if keys.is_empty() {
        return None;
    }
    let mut out = e.clone();
    let mut changed = false;
    for (v, k) in keys {
        let Var::Call(c) = &v else { continue };
        let u = &c.args[0];
        let co = if c.f == Func::Cos {
            Expr::sin(u)
        } else {
            Expr::cos(u)
        };
        // the co-function must be a kept call of the same angle
        let Some(co_var) = co
            .terms
            .iter()
            .next()
            .filter(|(m, c)| co.terms.len() == 1 && m.len() == 1 && m[0].1 == 1 && c.is_one())
            .map(|(m, _)| m[0].0.clone())
        else {
            continue;
        };
        let over: Mono = vec![(v.clone(), -k)];
        let (mut num, mut rest) = (Expr::zero(), Expr::zero());
        for (m, c) in &out.terms {
            if m.iter().any(|(w, j)| *w == v && *j == k) {
                num.terms.insert(mono_mul(m, &over), c.clone());
            } else {
                rest.terms.insert(m.clone(), c.clone());
            }
        }
        let Some(power) = co.powi(i64::from(-k)) else {
            continue;
        };
        let Some(q) = num.div_exact(&power) else {
            continue;
        };
        if q.terms.len() > num.terms.len() || q.mul(&power) != num {
            continue;
        }
        // tan(u)^p as a kept call (a variable of its own, so that a sum
        // above collects: `(a + b) tan(x/2)^2`); cot(u)^p as cos(u)^p over
        // sin(u)^p, which [`call_tangents`] prints, for one term above
        let tan = Expr::apply(Func::Tan, u, f64::tan);
        let tan_var = (tan.terms.len() == 1)
            .then(|| tan.terms.iter().next())
            .flatten()
            .filter(|(m, c)| m.len() == 1 && m[0].1 == 1 && c.is_one())
            .map(|(m, _)| m[0].0.clone());
        let pair: Mono = match (c.f, tan_var) {
            (Func::Cos, Some(t)) => vec![(t, -k)],
            (Func::Sin, _) if q.terms.len() == 1 => {
                mono_mul(&vec![(v.clone(), k)], &vec![(co_var.clone(), -k)])
            }
            _ => continue,
        };
        for (m, c) in &q.terms {
            rest.terms.insert(mono_mul(m, &pair), c.clone());
        }
        if rest.terms.len() != out.terms.len() - num.terms.len() + q.terms.len() {
            // (two monomials met: leave the form as it was)
            continue;
        }
        out = rest;
        changed = true;
    }
    changed.then_some(out)
}
