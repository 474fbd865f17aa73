//! Tangents and cotangents as printed (LANGUAGE.md §7: "tan and cot kept
//! as tan and cot"), beside [`super::fraction`]'s sin/cos pairs of one
//! term: a quotient whose numerator is the co-functions of its
//! denominator's angles (`cot(x) cot(x + y)`, a sum once multiplied out),
//! and a kept half-angle sine over its cosine (`tan(x/2)`).

use super::coef::Coef;
use super::expr::{Expr, Func, Mono, Var};
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
