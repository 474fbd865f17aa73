//! Printing canonical expressions as the book writes them (LANGUAGE.md §7),
//! from their real form ([`super::trig`]; for the UR5 the angle groups
//! {θ1}, {θ2, θ3, θ4}, {θ5}, {θ6}). Output is plain text
//! `L1 cos(t1) + L2 cos(t1 + t2)`, the book's shorthand `L1 c₁ + L2 c₁₂`,
//! or LaTeX `L_1 \cos t_1 + …`.

use super::coef::{Coef, Rat};
use super::expr::{Expr, Func, Symbol, Var};
use num_traits::One;

/// The output form.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mode {
    /// Plain text: `cos(theta1)`, `sqrt(2)`, `π`.
    #[default]
    Text,
    /// The book's shorthand: c₁ = cos θ1, s₁₂ = sin(θ1 + θ2).
    Short,
    /// LaTeX source: `\sqrt{2}`, `\pi`.
    Latex,
}

/// How to print: the form and the decimals of inexact coefficients.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Style {
    /// Text, the book's shorthand or LaTeX.
    pub mode: Mode,
    /// Decimal places of a coefficient with no exact form (trailing zeros
    /// dropped).
    pub digits: usize,
}

impl Default for Style {
    fn default() -> Style {
        Style {
            mode: Mode::Text,
            digits: 4,
        }
    }
}

/// The terms of `e`, each with its sign: `("+", "L1 cos(t1)")`. Angles
/// that are not integer combinations of the symbols (`sin(√6 x)`) are
/// first folded through fresh symbols ([`super::generalize::refolded`]),
/// where that leaves fewer terms: `sin(√6 x)^2 + cos(√6 x)^2` prints `1`.
pub fn terms(e: &Expr, st: Style) -> Vec<(bool, String)> {
    if let Some(f) = super::generalize::refolded(e, &|g| g.clone())
        && f.terms.len() < e.terms.len()
    {
        return super::fraction::terms(&f, st);
    }
    super::fraction::terms(e, st)
}

pub use super::layout::join;

/// An expression on one line.
pub fn expr(e: &Expr, st: Style) -> String {
    join(&terms(e, st), usize::MAX, 0)
}

pub(super) fn power(base: &str, e: i32, latex: bool) -> String {
    match (e, latex) {
        (1, _) => base.to_string(),
        (_, true) => format!("{base}^{{{e}}}"),
        (_, false) => format!("{base}^{e}"),
    }
}

pub(super) fn var(v: &Var, st: Style) -> String {
    let latex = st.mode == Mode::Latex;
    match v {
        Var::Pi if latex => "\\pi".into(),
        Var::Pi => "π".into(),
        Var::Sym(s) | Var::Z(s) => symbol(s, st),
        Var::Call(c) => {
            let args: Vec<String> = c.args.iter().map(|a| call_arg(a, st)).collect();
            match (c.f, latex) {
                (Func::Recip, true) => format!("\\left({}\\right)", args[0]),
                (Func::Recip, false) => format!("({})", args[0]),
                (Func::Sqrt, true) => format!("\\sqrt{{{}}}", args[0]),
                // the book's exponential, as LaTeX names it
                (Func::Exp, true) => format!("\\exp\\left({}\\right)", args[0]),
                (f, true) => format!(
                    "\\operatorname{{{}}}\\left({}\\right)",
                    f.name(),
                    args.join(", ")
                ),
                (f, false) => format!("{}({})", f.name(), args.join(", ")),
            }
        }
    }
}

/// A call's argument: `t/2` for (1/2) t, as the book writes half angles.
fn call_arg(e: &Expr, st: Style) -> String {
    if st.mode != Mode::Latex
        && e.terms.len() == 1
        && let Some(r) = e.terms.values().next().and_then(Coef::as_rat)
        && let Some((n, d)) = r.small()
        && n.abs() == 1
        && d > 1
    {
        let top = expr(&e.scale(&Coef::rat(Rat::int(d))), st);
        if !top.contains(' ') {
            return format!("{top}/{d}");
        }
    }
    expr(e, st)
}

const GREEK: [(&str, char, &str); 30] = [
    ("alpha", 'α', "\\alpha"),
    ("beta", 'β', "\\beta"),
    ("gamma", 'γ', "\\gamma"),
    ("delta", 'δ', "\\delta"),
    ("epsilon", 'ε', "\\epsilon"),
    ("zeta", 'ζ', "\\zeta"),
    ("eta", 'η', "\\eta"),
    ("theta", 'θ', "\\theta"),
    ("iota", 'ι', "\\iota"),
    ("kappa", 'κ', "\\kappa"),
    ("lambda", 'λ', "\\lambda"),
    ("mu", 'μ', "\\mu"),
    ("nu", 'ν', "\\nu"),
    ("xi", 'ξ', "\\xi"),
    ("rho", 'ρ', "\\rho"),
    ("sigma", 'σ', "\\sigma"),
    ("tau", 'τ', "\\tau"),
    ("phi", 'φ', "\\phi"),
    ("chi", 'χ', "\\chi"),
    ("psi", 'ψ', "\\psi"),
    ("omega", 'ω', "\\omega"),
    ("Gamma", 'Γ', "\\Gamma"),
    ("Delta", 'Δ', "\\Delta"),
    ("Theta", 'Θ', "\\Theta"),
    ("Lambda", 'Λ', "\\Lambda"),
    ("Xi", 'Ξ', "\\Xi"),
    ("Sigma", 'Σ', "\\Sigma"),
    ("Phi", 'Φ', "\\Phi"),
    ("Psi", 'Ψ', "\\Psi"),
    ("Omega", 'Ω', "\\Omega"),
];

/// A name split into its letters and its subscript: `theta1` → (`theta`,
/// `1`), `L_2` → (`L`, `2`), `t_{ab}` → (`t`, `ab`).
fn split_name(name: &str) -> (&str, &str) {
    if let Some((b, s)) = name.split_once('_') {
        return (b, s.trim_start_matches('{').trim_end_matches('}'));
    }
    let cut = name
        .char_indices()
        .rev()
        .take_while(|(_, c)| c.is_ascii_digit())
        .last()
        .map_or(name.len(), |(i, _)| i);
    (&name[..cut], &name[cut..])
}

/// A symbol's name: as typed; a time derivative θ̇ with the Greek letter
/// and a dot (two dots for θ̈, primes beyond).
pub fn symbol(s: &Symbol, st: Style) -> String {
    if s.index > 0 {
        return component(s, st);
    }
    // a constant offset: one unit of a phase variable (see `trig_factor`)
    if let Some(unit) = s.phase() {
        return super::phase::text(unit, 1, st.mode == Mode::Latex);
    }
    let (base, sub) = split_name(&s.name);
    if st.mode == Mode::Latex {
        let b = GREEK
            .iter()
            .find(|(w, c, _)| *w == base || base.chars().eq(std::iter::once(*c)))
            .map_or_else(|| base.to_string(), |g| g.2.to_string());
        let wrap = |cmd: &str| {
            if b.starts_with('\\') {
                format!("{cmd}{b}")
            } else {
                format!("{cmd}{{{b}}}")
            }
        };
        let b = match s.dots {
            0 => b.clone(),
            1 => wrap("\\dot"),
            2 => wrap("\\ddot"),
            n => format!("{b}^{{({n})}}"),
        };
        return match sub.chars().count() {
            0 => b,
            1 => format!("{b}_{sub}"),
            _ => format!("{b}_{{{sub}}}"),
        };
    }
    if s.dots == 0 {
        return s.name.to_string();
    }
    let greek = GREEK.iter().find(|(w, _, _)| *w == base).map(|g| g.1);
    // beyond two dots, or over a name of several letters (`th`: a dot over
    // the first would read ṫh), the rate as it is typed: th', q'''
    if s.dots > 2 || (greek.is_none() && base.chars().count() > 1) {
        return format!("{}{}", s.name, "'".repeat(s.dots as usize));
    }
    let mut chars = base.chars();
    let first = greek.or_else(|| chars.next()).unwrap_or('?');
    let rest: String = if greek.is_some() {
        String::new()
    } else {
        chars.collect()
    };
    let mark = if s.dots == 1 { '\u{307}' } else { '\u{308}' };
    let tail = &s.name[base.len()..];
    format!("{first}{mark}{rest}{tail}")
}

/// A component of a `given` vector as it is indexed, `w[2]` (LaTeX
/// `w_{2}`, `\omega_{b,2}` for `omega_b`).
fn component(s: &Symbol, st: Style) -> String {
    let (letters, sub) = split_name(&s.name);
    let name = if st.mode == Mode::Latex {
        letters
    } else {
        &*s.name
    };
    let base = symbol(
        &Symbol {
            index: 0,
            unit: false,
            ..Symbol::new(name)
        },
        st,
    );
    match st.mode {
        Mode::Latex if sub.is_empty() => format!("{base}_{{{}}}", s.index),
        Mode::Latex => format!("{base}_{{{sub},{}}}", s.index),
        _ => format!("{base}[{}]", s.index),
    }
}

/// `f(k·θ)^p` for f one of sin, cos, tan, cot (the book's shorthand
/// `s₁₂`, `c₁` for sin and cos).
pub(super) fn trig_factor(k: &[(Symbol, i32)], f: &str, p: u32, st: Style) -> String {
    if st.mode == Mode::Short
        && (f == "sin" || f == "cos")
        && let Some(short) = short_trig(k, f == "sin")
    {
        const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
        let sup: String = if p > 1 {
            p.to_string()
                .chars()
                .map(|d| SUP[d.to_digit(10).unwrap_or(0) as usize])
                .collect()
        } else {
            String::new()
        };
        return format!("{short}{sup}");
    }
    let mut arg = String::new();
    for (i, (s, c)) in k.iter().enumerate() {
        let mag = c.abs();
        let piece = match s.phase() {
            // an offset, `π/5`, `0.3`, as its value
            Some(unit) => super::phase::text(unit, i64::from(mag), st.mode == Mode::Latex),
            None if mag == 1 => symbol(s, st),
            None => format!("{mag} {}", symbol(s, st)),
        };
        match (i, *c < 0) {
            (0, _) => arg.push_str(&piece),
            (_, false) => arg.push_str(&format!(" + {piece}")),
            (_, true) => arg.push_str(&format!(" - {piece}")),
        }
    }
    let sup = if p > 1 {
        format!("^{{{p}}}")
    } else {
        String::new()
    };
    if st.mode == Mode::Latex {
        if k.len() == 1 && k[0].1 == 1 {
            let space = if arg.starts_with('\\') { "" } else { " " };
            format!("\\{f}{sup}{space}{arg}")
        } else {
            format!("\\{f}{sup}({arg})")
        }
    } else {
        power(&format!("{f}({arg})"), p as i32, false)
    }
}

/// `c₁₂` for cos(θ1 + θ2), `sθ` for sin θ: the book's shorthand, when it
/// applies (all coefficients 1, indexed names or a single angle).
fn short_trig(k: &[(Symbol, i32)], sin: bool) -> Option<String> {
    const SUB: [char; 10] = ['₀', '₁', '₂', '₃', '₄', '₅', '₆', '₇', '₈', '₉'];
    if k.iter().any(|(s, c)| *c != 1 || s.dots > 0 || s.is_phase()) {
        return None;
    }
    let f = if sin { 's' } else { 'c' };
    let mut out = String::from(f);
    for (s, _) in k {
        let (base, sub) = split_name(&s.name);
        if sub.is_empty() || !sub.chars().all(|c| c.is_ascii_digit()) {
            if k.len() == 1 {
                let g = GREEK
                    .iter()
                    .find(|(w, _, _)| *w == base)
                    .map(|g| g.1.to_string());
                return Some(format!("{f}{}", g.unwrap_or_else(|| s.name.to_string())));
            }
            return None;
        }
        out.extend(
            sub.chars()
                .map(|c| SUB[c.to_digit(10).unwrap_or(0) as usize]),
        );
    }
    Some(out)
}

/// A coefficient's sign and magnitude as text ("1" for one).
pub(super) fn coefficient(c: &Coef, st: Style) -> (bool, String) {
    let latex = st.mode == Mode::Latex;
    match c {
        Coef::Approx { re, .. } => (*re < 0.0, fmt_float(re.abs(), st.digits)),
        Coef::Exact { re, .. } => {
            // the sign in front when every part is negative; a sum of
            // mixed signs keeps its own (`(1/2 - √5/2) t`, not
            // `-(-1/2 + √5/2) t`)
            let neg = re.terms().all(|(_, r)| r.is_negative()) && !re.is_zero();
            let s = if neg { re.neg() } else { re.clone() };
            let parts: Vec<(u128, &Rat)> = s.terms().collect();
            match parts.as_slice() {
                [] => (false, "0".into()),
                [(k, r)] => (neg, surd_term(r, *k, latex)),
                _ => {
                    let inner: Vec<String> =
                        parts.iter().map(|(k, r)| surd_term(r, *k, latex)).collect();
                    let sum = inner.join(" + ").replace("+ -", "- ");
                    let wrapped = if latex {
                        format!("\\left({sum}\\right)")
                    } else {
                        format!("({sum})")
                    };
                    (neg, wrapped)
                }
            }
        }
    }
}

/// (p/q)√k as text or LaTeX: `3`, `17/40` (or `0.425`), `√2`, `1/√2`, `√3/2`.
fn surd_term(r: &Rat, k: u128, latex: bool) -> String {
    let (p, q) = r.parts();
    let sign = if r.is_negative() { "-" } else { "" };
    let p = p.magnitude();
    // an integer however large has denominator 1 (a big one is not `small`)
    let q_small = match r.small() {
        Some((_, q)) => Some(i128::from(q)),
        None => q.is_one().then_some(1),
    };
    let p_one = *p == num_bigint::BigUint::from(1u8);
    if k == 1 {
        if let Some(e) = super::rat::scientific(&p.to_string(), &q.magnitude().to_string()) {
            return format!("{sign}{e}");
        }
        if q_small == Some(1) {
            return format!("{sign}{p}");
        }
        // a decimal as typed (0.1, 0.425), in full up to 12 places; halves,
        // quarters and fifths stay fractions (0.392 = 49/125 is a decimal),
        // and so does a fraction computed from integers (1/8, 1/16)
        if let Some(q) = q_small
            && r.is_typed()
            && q > 5
            && (1..=12).any(|k| 10i128.pow(k) % q == 0)
            && let Some(digits) = (if r.is_negative() { r.neg() } else { r.clone() }).decimal_text()
        {
            return format!("{sign}{digits}");
        }
        return if latex {
            format!("{sign}\\frac{{{p}}}{{{q}}}")
        } else {
            format!("{sign}{p}/{q}")
        };
    }
    let root = if latex {
        format!("\\sqrt{{{k}}}")
    } else {
        format!("√{k}")
    };
    let top = if p_one {
        root.clone()
    } else {
        format!("{p}{root}")
    };
    match (q_small, latex) {
        (Some(1), _) => format!("{sign}{top}"),
        _ if p_one && i128::try_from(k).ok() == q_small => {
            if latex {
                format!("{sign}\\frac{{1}}{{{root}}}")
            } else {
                format!("{sign}1/{root}")
            }
        }
        (_, true) => format!("{sign}\\frac{{{top}}}{{{q}}}"),
        (_, false) => format!("{sign}{top}/{q}"),
    }
}

fn fmt_float(x: f64, digits: usize) -> String {
    // (inf and NaN as numbers print them, not `infe0`)
    if x.is_nan() {
        return "NaN".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf" } else { "-inf" }.into();
    }
    if x != 0.0 && !(1e-6..1e12).contains(&x.abs()) {
        let s = format!("{x:.digits$e}");
        let (m, e) = s.split_once('e').unwrap_or((&s, "0"));
        let m = if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.')
        } else {
            m
        };
        return format!("{m}e{e}");
    }
    let s = format!("{x:.digits$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" { "0".into() } else { s }
}

/// Columns a text takes on screen (combining marks, as in θ̇, take none).
pub fn text_width(s: &str) -> usize {
    s.chars()
        .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
        .count()
}

/// Cells of a symbolic matrix: text with aligned columns (`[a, b;` …), one
/// entry per line with long entries wrapped when a row is wider than
/// `width`, or a LaTeX `bmatrix`. `indent` is the column of the `[`.
pub fn matrix(cells: &[Vec<Expr>], st: Style, indent: usize, width: usize) -> String {
    if st.mode == Mode::Latex {
        let rows: Vec<String> = cells
            .iter()
            .map(|r| {
                r.iter()
                    .map(|e| expr(e, st))
                    .collect::<Vec<_>>()
                    .join(" & ")
            })
            .collect();
        return format!(
            "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
            rows.join(" \\\\ ")
        );
    }
    let text: Vec<Vec<Vec<(bool, String)>>> = cells
        .iter()
        .map(|r| r.iter().map(|e| terms(e, st)).collect())
        .collect();
    let flat: Vec<Vec<String>> = text
        .iter()
        .map(|r| r.iter().map(|t| join(t, usize::MAX, 0)).collect())
        .collect();
    let ncols = flat.first().map_or(0, Vec::len);
    let widths: Vec<usize> = (0..ncols)
        .map(|j| flat.iter().map(|r| text_width(&r[j])).max().unwrap_or(0))
        .collect();
    let pad = " ".repeat(indent + 1);
    let total: usize = widths.iter().sum::<usize>() + 2 * ncols + indent;
    if total <= width {
        let rows: Vec<String> = flat
            .iter()
            .map(|r| {
                r.iter()
                    .enumerate()
                    .map(|(j, c)| {
                        if j + 1 < ncols {
                            format!("{c},{}", " ".repeat(widths[j] - text_width(c) + 1))
                        } else {
                            c.clone()
                        }
                    })
                    .collect::<String>()
            })
            .collect();
        return format!("[{}]", rows.join(&format!("\n{pad}")));
    }
    // Too wide to align: a row per line where it fits, else an entry per
    // line, long entries wrapped under themselves.
    let rows: Vec<String> = text
        .iter()
        .zip(&flat)
        .map(|(r, one)| {
            let line = one.join(", ");
            if indent + 1 + text_width(&line) < width {
                return line;
            }
            r.iter()
                .map(|t| {
                    let w = width.saturating_sub(indent + 1).max(40);
                    super::layout::join_from(t, w, indent + 3, indent + 1)
                })
                .collect::<Vec<_>>()
                .join(&format!(",\n{pad}"))
        })
        .collect();
    format!("[{}]", rows.join(&format!(";\n{pad}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(n: &str) -> Expr {
        Expr::symbol(Symbol::new(n))
    }

    #[test]
    fn planar_arm_prints_as_the_book() {
        let (t1, t2) = (s("t1"), s("t2"));
        let x = s("L1")
            .mul(&Expr::cos(&t1))
            .add(&s("L2").mul(&Expr::cos(&t1.add(&t2))));
        assert_eq!(expr(&x, Style::default()), "L1 cos(t1) + L2 cos(t1 + t2)");
        let short = Style {
            mode: Mode::Short,
            digits: 4,
        };
        assert_eq!(expr(&x, short), "L1 c₁ + L2 c₁₂");
        let latex = Style {
            mode: Mode::Latex,
            digits: 4,
        };
        assert_eq!(expr(&x, latex), "L_1 \\cos t_1 + L_2 \\cos(t_1 + t_2)");
    }

    #[test]
    fn products_of_separate_angles_stay_products() {
        let (a, b) = (s("t1"), s("t5"));
        let x = Expr::sin(&a)
            .mul(&Expr::cos(&b))
            .scale(&Coef::from_f64(-0.082));
        assert_eq!(expr(&x, Style::default()), "-0.082 sin(t1) cos(t5)");
    }

    #[test]
    fn one_angle_prints_in_powers_when_shorter() {
        let t = s("t");
        let (c, sn) = (Expr::cos(&t), Expr::sin(&t));
        // double angles print alike: sin(2 t) beside cos(2 t) (issue 21)
        assert_eq!(expr(&sn.mul(&c), Style::default()), "(1/2) sin(2 t)");
        let two = Expr::cos(&t.scale(&Coef::int(2)));
        assert_eq!(expr(&two, Style::default()), "cos(2 t)");
        let two = Expr::sin(&t.scale(&Coef::int(2)));
        assert_eq!(expr(&two, Style::default()), "sin(2 t)");
        assert_eq!(expr(&c.mul(&c), Style::default()), "cos(t)^2");
        assert_eq!(expr(&c.powi(3).unwrap(), Style::default()), "cos(t)^3");
    }

    #[test]
    fn dots_and_exact_constants() {
        let th = Symbol::timed("theta");
        let half = crate::sym::coef::Rat::new(1, 2).unwrap();
        let r2 = crate::sym::coef::Surd::of_basis([Rat::ZERO, half, Rat::ZERO, Rat::ZERO]);
        let x = Expr::symbol(th.dot()).scale(&Coef::real(r2));
        assert_eq!(expr(&x, Style::default()), "(1/√2) θ̇");
        let latex = Style {
            mode: Mode::Latex,
            digits: 4,
        };
        assert_eq!(expr(&Expr::symbol(th.dot()), latex), "\\dot\\theta");
        // a name of several letters: the rate as typed, the LaTeX dot over
        // the whole name
        let th = Symbol::timed("th1");
        assert_eq!(expr(&Expr::symbol(th.dot()), Style::default()), "th1'");
        assert_eq!(
            expr(&Expr::symbol(th.dot().dot()), Style::default()),
            "th1''"
        );
        assert_eq!(expr(&Expr::symbol(th.dot()), latex), "\\dot{th}_1");
    }
}
