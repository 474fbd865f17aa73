//! `solve` for an angle (LANGUAGE.md §8, Exercise 3.7(b)): x inside a
//! sine and cosine of the one argument k x, a cos kx + b sin kx = c with
//! exact numbers a, b, c (π and surds allowed). With R = √(a² + b²) and
//! φ = atan2(b, a) it is R cos(kx − φ) = c, so kx = φ ± acos(c/R) when
//! |c| ≤ R. The roots returned are those in (−π, π], in increasing order,
//! each substituted back into the equation before it is given; the
//! general solution adds 2πn/k, which the caller's note says.

use super::coef::Coef;
use super::expr::{Expr, Func, Symbol, Var};
use super::sign::sign_with_pi;

/// The largest k of sin(k x) solved for: beyond it the roots in (−π, π]
/// are too many to list usefully.
const MAX_MULTIPLE: i32 = 12;

/// The real roots in (−π, π] of `e = 0`, e a cos kx + b sin kx − c in the
/// z = e^{ix} of `x` (see the module), and the multiple k; Err naming why
/// there is no answer to give.
pub fn solve_angle(e: &Expr, x: &Symbol) -> Result<(Vec<Expr>, i32), String> {
    let Some((numerator, d)) = cleared(e, x) else {
        return candidates(e, x).and_then(|(roots, k)| Ok((checked_all(e, x, roots)?, k)));
    };
    // tan x = c is sin x − c cos x = 0 where cos x ≠ 0
    let (roots, k) = candidates(&numerator, x)?;
    let mut kept = Vec::with_capacity(roots.len());
    for r in roots {
        let at = d.subst(&|s| (s == x).then(|| r.clone()));
        if at.terms.is_empty() {
            continue;
        }
        let clear = sign_with_pi(&at).is_some_and(|s| s != 0)
            || at.eval(&|_| None).is_some_and(|v| v.abs() > 1e-9);
        if !clear {
            return Err(format!(
                "cannot decide whether the denominator {} is 0 at a root",
                super::print::expr(&d, Default::default())
            ));
        }
        kept.push(r);
    }
    if kept.is_empty() {
        return Err(format!(
            "no real {} solves it: the roots of its numerator are the zeros of its denominator",
            x.name
        ));
    }
    Ok((checked_all(e, x, kept)?, k))
}

/// Whether x enters `e` through an angle: its z = e^{ix}, or a
/// reciprocal of a sum in it (1/cos x, of tan x).
pub fn is_angular(e: &Expr, x: &Symbol) -> bool {
    let z = |e: &Expr| {
        e.terms
            .keys()
            .any(|m| m.iter().any(|(v, _)| matches!(v, Var::Z(s) if s == x)))
    };
    z(e) || e.terms.keys().any(|m| {
        m.iter()
            .any(|(v, _)| matches!(v, Var::Call(c) if c.f == Func::Recip && z(&c.args[0])))
    })
}

/// The equation `e = 0` with its one reciprocal of a trigonometric
/// polynomial d in x (tan x = sin x · 1/cos x) multiplied out: the
/// numerator e dⁿ and d, whose zeros are no roots. None when `e` has no
/// such reciprocal, or more than one kind of it.
fn cleared(e: &Expr, x: &Symbol) -> Option<(Expr, Expr)> {
    let mut call = None;
    let mut n = 0;
    for m in e.terms.keys() {
        for (v, k) in m {
            if let Var::Call(c) = v
                && c.f == Func::Recip
                && super::solve::mentions(&c.args[0], x)
            {
                if call.as_ref().is_some_and(|d| d != c) || *k < 0 {
                    return None;
                }
                call = Some(c.clone());
                n = n.max(*k);
            }
        }
    }
    let call = call?;
    if n > 4 {
        return None;
    }
    let d = call.args[0].clone();
    let mut out = Expr::default();
    for (m, c) in &e.terms {
        let j = m
            .iter()
            .find(|(v, _)| matches!(v, Var::Call(k) if *k == call))
            .map_or(0, |(_, j)| *j);
        let rest: Vec<_> = m
            .iter()
            .filter(|(v, _)| !matches!(v, Var::Call(k) if *k == call))
            .cloned()
            .collect();
        let mut t = Expr::default();
        t.push(rest, c.clone());
        out = out.add(&t.mul(&d.powi(i64::from(n - j))?));
    }
    Some((out, d))
}

/// Every root substituted back into `e` ([`checked`]), in increasing
/// order; Err when one does not check or two cannot be told apart.
fn checked_all(e: &Expr, x: &Symbol, roots: Vec<Expr>) -> Result<Vec<Expr>, String> {
    let show = |e: &Expr| super::print::expr(e, Default::default());
    let mut keyed = Vec::with_capacity(roots.len());
    for r in roots {
        let v = value(&r).ok_or("a root has no numeric value")?;
        if !checked(e, x, &r) {
            return Err(format!(
                "a root {} = {} did not check when substituted back",
                x.name,
                show(&r)
            ));
        }
        // (a root with no closed form is its number, as asin(1/3) typed is)
        let exact = r
            .terms
            .iter()
            .all(|(m, c)| c.is_exact() && m.iter().all(|(v, _)| matches!(v, Var::Pi)));
        keyed.push((v, if exact { r } else { Expr::float(v) }));
    }
    keyed.sort_by(|p, q| p.0.total_cmp(&q.0));
    if keyed.windows(2).any(|w| w[1].0 - w[0].0 < 1e-9) {
        return Err("cannot order two roots that are too close to tell apart".to_string());
    }
    Ok(keyed.into_iter().map(|(_, r)| r).collect())
}

/// The roots in (−π, π] of a cos kx + b sin kx = c, unchecked, and k.
fn candidates(e: &Expr, x: &Symbol) -> Result<(Vec<Expr>, i32), String> {
    let name = &x.name;
    // the coefficients by the power of z
    let by_power = super::solve::by_power(
        e,
        x,
        |v| matches!(v, Var::Z(s) if s == x),
        |v| match v {
            Var::Sym(s) if s == x => Some(format!(
                "{name} occurs both alone and inside a sine or cosine: solve finds x of a cos x + b sin x = c"
            )),
            Var::Call(call) => Some(format!(
                "{name} is inside {}(…): solve finds x of a cos x + b sin x = c",
                call.f.name()
            )),
            _ => None,
        },
    )?;
    let k = by_power.keys().map(|p| p.abs()).max().unwrap_or(0);
    if k == 0 || by_power.keys().any(|p| *p != 0 && p.abs() != k) {
        return Err(format!(
            "the equation has sines or cosines of more than one multiple of {name} (or their powers): solve finds x of a cos x + b sin x = c"
        ));
    }
    if k > MAX_MULTIPLE {
        return Err(format!(
            "the angle is {k} {name}: solve lists the roots of sin and cos of up to {MAX_MULTIPLE} {name}"
        ));
    }
    let part = |p: i32| by_power.get(&p).cloned().unwrap_or_default();
    let (up, down, c0) = (part(k), part(-k), part(0));
    if [&up, &down, &c0].iter().any(|c| !constant(c)) {
        return Err(format!(
            "the coefficients of the sine and cosine of {name} are not exact numbers: solve finds x of a cos x + b sin x = c with exact a, b, c (give the other symbols numbers first)"
        ));
    }
    // a cos + b sin = z (a − ib)/2 + z⁻¹ (a + ib)/2
    let a = up.add(&down);
    let b = up.sub(&down).scale(&Coef::i());
    let c = c0.neg();
    if a != a.conj() || b != b.conj() || c != c.conj() {
        return Err("the equation is not real".to_string());
    }
    let r2 = a.mul(&a).add(&b.mul(&b));
    let gap = r2.sub(&c.mul(&c));
    let show = |e: &Expr| super::print::expr(e, Default::default());
    let thetas = match sign_with_pi(&gap) {
        Some(s) if s < 0 => {
            return Err(format!(
                "no real {name} solves it: |c| > √(a² + b²) in a cos + b sin = c (c = {}, a² + b² = {})",
                show(&c),
                show(&r2)
            ));
        }
        None => {
            return Err(format!(
                "cannot decide whether c² ≤ a² + b² in a cos + b sin = c (c = {}, a² + b² = {})",
                show(&c),
                show(&r2)
            ));
        }
        Some(s) => angles(&a, &b, &c, &r2, s == 0)?,
    };
    // x = (θ + 2πn)/k in (−π, π]
    let pi = Expr::pi();
    let mut roots = Vec::new();
    for t in &thetas {
        for n in -k..=k {
            let r = t
                .add(&pi.scale(&Coef::int(2 * i64::from(n))))
                .scale(&inv_int(k));
            if within(&r)? {
                roots.push(r);
            }
        }
    }
    Ok((roots, k))
}

/// 1/k as a coefficient.
fn inv_int(k: i32) -> Coef {
    Coef::int(i64::from(k)).inv().unwrap_or(Coef::one())
}

/// θ in (−π, π] with a cos θ + b sin θ = c, given the sign of a² + b² − c²
/// is ≥ 0 (`touching`: = 0, one root).
fn angles(a: &Expr, b: &Expr, c: &Expr, r2: &Expr, touching: bool) -> Result<Vec<Expr>, String> {
    let pi = Expr::pi();
    // the special forms first, for the shortest exact answers
    if a.terms.is_empty() {
        // b sin θ = c: asin(s) and π − asin(s)
        let s = c.div(b).ok_or("cannot divide by b")?;
        // (asin is odd: −asin(1/3), not asin(−1/3))
        let t = match sign_with_pi(&s) {
            Some(-1) => arc(Func::Asin, &s.neg()).neg(),
            _ => arc(Func::Asin, &s),
        };
        if touching {
            return Ok(vec![t]);
        }
        let other = pi.sub(&t);
        return Ok(vec![t, other]);
    }
    if b.terms.is_empty() {
        // a cos θ = c: ±acos(s)
        let s = c.div(a).ok_or("cannot divide by a")?;
        let t = arc(Func::Acos, &s);
        if touching {
            return Ok(vec![t]);
        }
        return Ok(vec![t.neg(), t]);
    }
    if c.terms.is_empty() {
        // a cos θ + b sin θ = 0 is tan θ = −a/b: atan(−a/b), and π after it
        let s = a.neg().div(b).ok_or("cannot divide by b")?;
        let t = match sign_with_pi(&s) {
            Some(-1) => arc(Func::Atan, &s.neg()).neg(),
            _ => arc(Func::Atan, &s),
        };
        let other = t.add(&pi);
        return Ok(vec![t, other]);
    }
    let phi = super::arc::atan2(b, a)
        .unwrap_or_else(|| Expr::call(Func::Atan2, vec![b.clone(), a.clone()]));
    if touching {
        // c = ±R: θ = φ, or φ + π
        let positive = sign_with_pi(c).ok_or("cannot decide the sign of c")? > 0;
        return Ok(vec![if positive { phi } else { phi.add(&pi) }]);
    }
    let r = Expr::sqrt(r2);
    let ratio = c.div(&r).ok_or("cannot divide by √(a² + b²)")?;
    let alpha = arc(Func::Acos, &ratio);
    Ok(vec![phi.sub(&alpha), phi.add(&alpha)])
}

/// asin, acos or atan of an exact number: the book's angle when there is one
/// ([`super::inverse::closed`]), else kept as the call (never a float).
fn arc(f: Func, s: &Expr) -> Expr {
    super::inverse::closed(f, s).unwrap_or_else(|| Expr::call(f, vec![s.clone()]))
}

/// Whether every term is a power of π with an exact real-or-complex
/// coefficient (no symbols, no floats).
fn constant(e: &Expr) -> bool {
    e.terms.iter().all(|(m, c)| {
        matches!(c, Coef::Exact { .. }) && m.iter().all(|(v, _)| matches!(v, Var::Pi))
    })
}

/// The numeric value of a constant root (calls of asin, acos, atan2 of
/// numbers included).
fn value(e: &Expr) -> Option<f64> {
    e.eval(&|_| None)
}

/// Whether the root r lies in (−π, π]: decided exactly for sums of powers
/// of π and surds, else by its value when it is clear of ±π by 1e-9.
fn within(r: &Expr) -> Result<bool, String> {
    let pi = Expr::pi();
    let (above, below) = (r.sub(&pi), r.add(&pi));
    if let (Some(s), Some(t)) = (sign_with_pi(&above), sign_with_pi(&below)) {
        return Ok(s <= 0 && t > 0);
    }
    let v = value(r).ok_or("a root has no numeric value")?;
    let pi = std::f64::consts::PI;
    if (v.abs() - pi).abs() < 1e-9 {
        return Err("cannot decide whether a root is at ±π".to_string());
    }
    Ok(v > -pi && v <= pi)
}

/// Whether `e` vanishes at x = r: exactly when the substitution folds to
/// 0, else to within 1e-12 of the equation's scale at the root's value.
fn checked(e: &Expr, x: &Symbol, r: &Expr) -> bool {
    let back = e.subst(&|s| (s == x).then(|| r.clone()));
    if back.terms.is_empty() {
        return true;
    }
    let Some(v) = value(r) else {
        return false;
    };
    let scale: f64 = e
        .terms
        .values()
        .map(|c| c.to_c64().0.hypot(c.to_c64().1))
        .sum();
    let numeric = e.eval_c(&|s| (s == x).then_some(v));
    numeric.is_some_and(|(re, im)| re.hypot(im) <= 1e-12 * scale.max(1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The roots of e = 0 for x, as printed.
    fn printed(e: &Expr) -> Vec<String> {
        let x = Symbol::new("x");
        let (roots, _) = solve_angle(e, &x).unwrap();
        roots
            .iter()
            .map(|r| super::super::print::expr(r, Default::default()))
            .collect()
    }

    #[test]
    fn the_book_angles_print_exactly() {
        let x = Expr::symbol(Symbol::new("x"));
        let half = Expr::constant(inv_int(2));
        assert_eq!(printed(&Expr::sin(&x).sub(&half)), ["(1/6) π", "(5/6) π"]);
        assert_eq!(printed(&Expr::cos(&x)), ["-(1/2) π", "(1/2) π"]);
        assert_eq!(
            printed(&Expr::sin(&x).sub(&Expr::cos(&x))),
            ["-(3/4) π", "(1/4) π"]
        );
        assert_eq!(printed(&Expr::cos(&x).add(&Expr::int(1))), ["π"]);
        assert_eq!(printed(&Expr::sin(&x)), ["0", "π"]);
    }

    #[test]
    fn no_real_root_is_refused_naming_why() {
        let x = Symbol::new("x");
        let e = Expr::sin(&Expr::symbol(x.clone())).sub(&Expr::int(2));
        let err = solve_angle(&e, &x).unwrap_err();
        assert!(err.contains("|c| > √(a² + b²)"), "{err}");
    }
}
