//! How terms and quotients print (LANGUAGE.md §7): a term's coefficient,
//! variables and trigonometric factors; a kept reciprocal 1/(d) whose d is
//! one real term is opened (`1/(2 cos t)` is (1/2)/cos(t)), so that a sine
//! over a cosine of the same angle prints as the tangent, `tan(t)`, and a
//! cosine over a sine as `cot(t)`; terms over the same sum print as one
//! quotient, `(a + b)/(c + d sin(t))`.

use super::coef::Coef;
use super::expr::{Expr, Func, Mono, Symbol, Var, mono_mul};
use super::perfect::var_power;
use super::print::{Mode, Style, coefficient, join, trig_factor};
use super::trig::{Trig, real_form};
use num_traits::Zero;

/// A trigonometric factor as printed: the function, the angle, the power.
pub(super) struct Factor {
    pub(super) f: &'static str,
    pub(super) k: Vec<(Symbol, i32)>,
    pub(super) p: u32,
}

fn is_recip(v: &Var) -> bool {
    matches!(v, Var::Call(c) if c.f == Func::Recip)
}

/// The signed terms of `e`; terms that share a kept reciprocal print as
/// one quotient.
pub fn terms(e: &Expr, st: Style) -> Vec<(bool, String)> {
    if !e.has_recip() {
        return plain(e, st);
    }
    let mut groups: Vec<(Mono, Expr)> = Vec::new();
    for (m, c) in &e.terms {
        let (den, rest): (Mono, Mono) = m.iter().cloned().partition(|(v, k)| is_recip(v) && *k > 0);
        match groups.iter_mut().find(|(d, _)| *d == den) {
            Some((_, num)) => num.push(rest, c.clone()),
            None => {
                let mut num = Expr::zero();
                num.push(rest, c.clone());
                groups.push((den, num));
            }
        }
    }
    let mut out = Vec::new();
    for (den, num) in groups {
        if den.is_empty() {
            out.extend(plain(&num, st));
            continue;
        }
        if let Some(t) = super::tangents::tangent_product(&num, &den, st) {
            out.push(t);
            continue;
        }
        let real = real_form(&num);
        let below = denominator(&den, st);
        let Some((scale, den_text)) = below.filter(|_| real.len() > 1) else {
            for ((poly, trig), c) in &real {
                out.push(term(c, &mono_mul(poly, &den), trig, st));
            }
            continue;
        };
        // (numerator)/(denominator): the denominator's own constant moves up
        // (one term above, its sign in front: `-8 (r[2]^2 + r[3]^2)/(…)^2`)
        let top = plain(&num.scale(&scale), st);
        let (neg, body) = match top.as_slice() {
            [(neg, one)] => (*neg, one.clone()),
            _ => (false, join(&top, usize::MAX, 0)),
        };
        let text = match (st.mode == Mode::Latex, top.len()) {
            (true, _) => format!("\\frac{{{body}}}{{{den_text}}}"),
            (false, 1) => format!("{body}/{den_text}"),
            (false, _) => format!("({body})/{den_text}"),
        };
        out.push((neg, text));
    }
    out
}

fn plain(e: &Expr, st: Style) -> Vec<(bool, String)> {
    // powers of half-angle tangents, which the canonical form folds
    if let Some(t) = super::tangents::half_tangents(e) {
        return super::shape::shaped(&real_form(&t), st);
    }
    super::shape::shaped(&real_form(e), st)
}

/// A kept reciprocal 1/(d)^e whose d is one real term k·(variables)·(trig
/// factors): (1/k^e, the variables, the factors), each to the power e.
pub(super) fn opened(v: &Var, e: i32) -> Option<(Coef, Mono, Vec<Factor>)> {
    let Var::Call(call) = v else { return None };
    if call.f != Func::Recip || e <= 0 {
        return None;
    }
    let real = real_form(&call.args[0]);
    let (((poly, trig), k),) = {
        let mut it = real.iter();
        let first = it.next()?;
        if it.next().is_some() {
            return None;
        }
        (first,)
    };
    let (_, im) = k.to_c64();
    if im != 0.0 {
        return None;
    }
    let mut scale = k.inv()?;
    for _ in 1..e {
        scale = scale.mul(&k.inv()?);
    }
    let vars = poly
        .iter()
        .map(|(v, p)| (v.clone(), p.saturating_mul(e)))
        .collect();
    let factors = trig
        .iter()
        .map(|(k, sin, p)| Factor {
            f: if *sin { "sin" } else { "cos" },
            k: k.clone(),
            p: p * e.unsigned_abs(),
        })
        .collect();
    Some((scale, vars, factors))
}

/// The denominator of a quotient as text, and the constant its opened
/// reciprocals move to the numerator.
fn denominator(den: &Mono, st: Style) -> Option<(Coef, String)> {
    let mut scale = Coef::one();
    let mut parts: Vec<String> = Vec::new();
    for (v, e) in den {
        match opened(v, *e) {
            // (a kept reciprocal inside belongs above the bar: the caller
            // prints the terms one by one)
            Some((_, vars, _)) if vars.iter().any(|(w, _)| is_recip(w)) => return None,
            Some((k, vars, factors)) => {
                scale = scale.mul(&k);
                for (v, p) in &vars {
                    parts.push(var_power(v, *p, st).1);
                }
                for f in &factors {
                    parts.push(trig_factor(&f.k, f.f, f.p, st));
                }
            }
            None => {
                // d^e = f·(text): 1/f moves up
                let (f, text) = var_power(v, *e, st);
                scale = scale.mul(&f.inv()?);
                parts.push(text);
            }
        }
    }
    let text = parts.join(" ");
    let text = if parts.len() > 1 && st.mode != Mode::Latex {
        format!("({text})")
    } else {
        text
    };
    Some((scale, text))
}

/// The two sides of a term's fraction bar as they are filled in: the
/// coefficient, the factors above and below, the trigonometric factors
/// above and below.
struct Sides<'a> {
    c: &'a mut Coef,
    num: &'a mut Vec<String>,
    den: &'a mut Vec<String>,
    num_t: &'a mut Vec<Factor>,
    den_t: &'a mut Vec<Factor>,
    st: Style,
}

impl Sides<'_> {
    /// The factor v^e on its side of the bar: above for e > 0, below for
    /// e < 0. A kept reciprocal 1/(x) is x on the other side, opened when
    /// x is one real term (its constant joins the coefficient, its
    /// variables — kept reciprocals among them, issue 35: `1/tan(t)`
    /// printed 1/((cos(t)) sin(t)) — and trigonometric factors go where
    /// they belong), else `(x)`.
    fn place(&mut self, v: &Var, e: i32, depth: u32) {
        if e == 0 {
            return;
        }
        if is_recip(v) {
            // v^e = x^(−e): above when e < 0
            if depth < 8
                && let Some((k, vars, factors)) = opened(v, e.saturating_abs())
            {
                // opened gives 1/x^|e| = k / (vars · factors)
                match e > 0 {
                    true => {
                        *self.c = self.c.mul(&k);
                        for (w, q) in &vars {
                            self.place(w, q.saturating_neg(), depth + 1);
                        }
                        self.den_t.extend(factors);
                    }
                    false => {
                        *self.c = self.c.mul(&k.inv().unwrap_or_else(Coef::one));
                        for (w, q) in &vars {
                            self.place(w, *q, depth + 1);
                        }
                        self.num_t.extend(factors);
                    }
                }
                return;
            }
            let into = if e > 0 {
                &mut *self.den
            } else {
                &mut *self.num
            };
            // d^|e| = f·(text): f joins the coefficient, or 1/f below
            let (f, text) = var_power(v, e.saturating_abs(), self.st);
            let f = if e > 0 {
                f.inv().unwrap_or_else(Coef::one)
            } else {
                f
            };
            *self.c = self.c.mul(&f);
            into.push(text);
            return;
        }
        let into = if e > 0 {
            &mut *self.num
        } else {
            &mut *self.den
        };
        into.push(var_power(v, e.saturating_abs(), self.st).1);
    }
}

/// sin(θ)/cos(θ) is tan(θ), cos(θ)/sin(θ) is cot(θ), power by power.
fn tangents(num: &mut Vec<Factor>, den: &mut Vec<Factor>) {
    for (top, bottom, name) in [("sin", "cos", "tan"), ("cos", "sin", "cot")] {
        for i in 0..num.len() {
            if num[i].f != top {
                continue;
            }
            let Some(j) = den.iter().position(|d| d.f == bottom && d.k == num[i].k) else {
                continue;
            };
            let m = num[i].p.min(den[j].p);
            num[i].p -= m;
            den[j].p -= m;
            num.push(Factor {
                f: name,
                k: num[i].k.clone(),
                p: m,
            });
        }
        num.retain(|f| f.p > 0);
        den.retain(|f| f.p > 0);
    }
}

/// One term: its sign and its text, `(1/2) L1 cos(t1)`, `tan(t)`,
/// `3/(a + b sin(t))`.
pub(super) fn term(c: &Coef, poly: &Mono, trig: &[Trig], st: Style) -> (bool, String) {
    let latex = st.mode == Mode::Latex;
    let mut c = c.clone();
    let mut num: Vec<String> = Vec::new();
    let mut den: Vec<String> = Vec::new();
    let mut num_t: Vec<Factor> = trig
        .iter()
        .map(|(k, sin, p)| Factor {
            f: if *sin { "sin" } else { "cos" },
            k: k.clone(),
            p: *p,
        })
        .collect();
    let mut den_t: Vec<Factor> = Vec::new();
    let mut sides = Sides {
        c: &mut c,
        num: &mut num,
        den: &mut den,
        num_t: &mut num_t,
        den_t: &mut den_t,
        st,
    };
    let (poly, kept_tangents) = super::tangents::call_tangents(poly, st);
    for (v, e) in &poly {
        sides.place(v, *e, 0);
    }
    num.extend(kept_tangents);
    tangents(&mut num_t, &mut den_t);
    num.extend(num_t.iter().map(|f| trig_factor(&f.k, f.f, f.p, st)));
    den.extend(den_t.iter().map(|f| trig_factor(&f.k, f.f, f.p, st)));
    let (neg, coef) = coefficient(&c, st);
    let has_factors = !num.is_empty() || !den.is_empty();
    let sep = " ";
    let mut body = num.join(sep);
    if num.is_empty() && !den.is_empty() && coef != "1" && !latex {
        // (1/2)/(1 + cos(t)), 3/L2
        let d = den.join(sep);
        let d = if den.len() > 1 { format!("({d})") } else { d };
        let c = if needs_parens(&coef) {
            format!("({coef})")
        } else {
            coef
        };
        return (neg, format!("{c}/{d}"));
    }
    if !den.is_empty() {
        let d = den.join(sep);
        if latex {
            body = format!(
                "\\frac{{{}}}{{{d}}}",
                if body.is_empty() { "1" } else { &body }
            );
        } else {
            let d = if den.len() > 1 { format!("({d})") } else { d };
            body = format!("{}/{d}", if body.is_empty() { "1" } else { &body });
        }
    }
    let text = match (coef.as_str(), has_factors) {
        ("1", true) => body,
        (_, true) => {
            let wrap = !latex && needs_parens(&coef);
            if wrap {
                format!("({coef}) {body}")
            } else {
                format!("{coef} {body}")
            }
        }
        _ => coef,
    };
    (neg, text)
}

/// True when a coefficient's text needs parentheses before a factor
/// (`(1/2) t`): a fraction or a sum not already in them (`(1 + √2) t`).
pub(super) fn needs_parens(coef: &str) -> bool {
    coef.contains(['/', ' ']) && !(coef.starts_with('(') && coef.ends_with(')'))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::print::expr;
    use num_traits::One;

    fn s(n: &str) -> Expr {
        Expr::symbol(Symbol::new(n))
    }

    #[test]
    fn sine_over_cosine_is_the_tangent() {
        let t = s("t");
        let tan = Expr::sin(&t)
            .scale(&Coef::int(2))
            .mul(&Expr::cos(&t).scale(&Coef::int(2)).recip().unwrap());
        assert_eq!(expr(&tan, Style::default()), "tan(t)");
        let cot = Expr::cos(&t).mul(&Expr::sin(&t).recip().unwrap());
        assert_eq!(expr(&cot, Style::default()), "cot(t)");
        let csc = Expr::sin(&t).recip().unwrap();
        assert_eq!(expr(&csc, Style::default()), "1/sin(t)");
        let sec = Expr::cos(&t).scale(&Coef::int(3)).recip().unwrap();
        assert_eq!(expr(&sec, Style::default()), "(1/3)/cos(t)");
    }

    #[test]
    fn terms_over_one_sum_print_as_one_quotient() {
        let (a, b, t) = (s("a"), s("b"), s("t"));
        let d = a.add(&b.mul(&Expr::sin(&t)));
        let x = a.add(&Expr::one()).mul(&d.recip().unwrap());
        assert_eq!(expr(&x, Style::default()), "(1 + a)/(a + b sin(t))");
    }
}
