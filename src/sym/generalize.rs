//! Angles that are not integer combinations of the symbols: products of
//! symbols (`cos(x y)`, SymPy's `cos(x y) − cos y = −2 sin((x y − y)/2)
//! sin((x y + y)/2)`) and irrational multiples (`sin(√6 x)`, `cos(π x)`,
//! the angles of `exp(A t)` for a 2×2 A with complex eigenvalues 1 ± √6 i,
//! §3.2.3.1). Each such term of a sine's or cosine's argument is written
//! as an integer multiple of a fresh symbol w — one w for all terms on
//! one monomial whose coefficients have rational ratios (√6 x and 2√6 x
//! are w and 2w with w = √6 x), the same on both sides of an equation —
//! so that the angles are linear and the canonical form (with
//! [`super::together::unhalved`]) decides them: sin²(√6 x) + cos²(√6 x)
//! is 1. An identity in independent w, x, y holds in particular at
//! w = √6 x, so a `true` so found is a proof; a difference is not (w = √6
//! x is a special case), and the caller answers only `true` from it.

use super::coef::{Coef, Rat};
use super::expr::{Expr, Func, Mono, Symbol, Var};
use num_traits::{One, Zero};

/// One fresh angle: the monomial it stands on, the coefficient w has
/// there, and its symbol.
type Fresh = (Mono, Coef, Symbol);

/// One fresh angle for a sum: the part of a sine's or cosine's argument
/// that is itself a trigonometric polynomial (the `sin(a)` of
/// `sin(sin(a))`, whose e^{±ia} terms are not real alone, so no term of it
/// is renamed), w standing for it — one w for every such part that is a
/// rational multiple of it (`sin(2 sin a)` is sin(2w)) — and its symbol.
type FreshSum = (Expr, Symbol);

/// The terms of argument `a` that hold an angle's e^{iθ} (its
/// trigonometric part; real as a whole, as the argument is).
fn trig_part(a: &Expr) -> Expr {
    let mut out = Expr::zero();
    for (m, c) in &a.terms {
        if m.iter().any(|(v, _)| matches!(v, Var::Z(_))) {
            out.push(m.clone(), c.clone());
        }
    }
    out
}

/// r with p = r q, rational; None when p is no rational multiple of q.
fn multiple(p: &Expr, q: &Expr) -> Option<Rat> {
    let (m, c) = q.terms.iter().next()?;
    let r = ratio(p.terms.get(m)?, c)?;
    (q.scale(&Coef::rat(r.clone())) == *p).then_some(r)
}

/// The trigonometric parts of the arguments of the sines and cosines of
/// `e` (not nested in another call's argument: those are renamed with
/// the call, or not at all).
fn sums(e: &Expr, out: &mut Vec<Expr>) {
    for (v, _) in e.terms.keys().flatten() {
        let Var::Call(c) = v else { continue };
        if !matches!(c.f, Func::Sin | Func::Cos) {
            continue;
        }
        for a in &c.args {
            let p = trig_part(a);
            if p.is_zero() || !p.terms.values().all(Coef::is_exact) {
                continue;
            }
            if !out.contains(&p) {
                out.push(p);
            }
        }
    }
}

/// The least common denominator of ratios `rs` (the w of a class of
/// rational multiples is its first member over it); None past i128.
fn common_denominator(rs: &[Rat]) -> Option<i128> {
    let mut den = num_bigint::BigInt::from(1);
    for r in rs {
        let (_, d) = r.parts();
        den = num_integer::Integer::lcm(&den, &d);
    }
    i128::try_from(den).ok()
}

/// The fresh angles of the trigonometric parts: one per class of rational
/// multiples, w the first part over the least common denominator of the
/// ratios (so every part is an integer multiple of w).
fn fresh_sums(found: &[Expr]) -> Vec<FreshSum> {
    let mut classes: Vec<(Expr, Vec<Rat>)> = Vec::new();
    for p in found {
        match classes
            .iter_mut()
            .find_map(|(base, rs)| multiple(p, base).map(|r| (rs, r)))
        {
            Some((rs, r)) => rs.push(r),
            None => classes.push((p.clone(), vec![Rat::ONE])),
        }
    }
    classes
        .into_iter()
        .enumerate()
        .filter_map(|(i, (base, rs))| {
            let den = common_denominator(&rs)?;
            let w = base.scale(&Coef::rat(Rat::new(1, den)?));
            Some((w, Symbol::new(&format!("\u{1}sum angle {i}"))))
        })
        .collect()
}

/// True for a term of an argument that is not a plain angle: a product
/// or quotient of symbols (or of π and symbols, `x y`, `v t/r`), a real
/// call such as `√x` or `1/(a + b)` in it, or a symbol with an
/// irrational coefficient. A symbol with a rational coefficient, π alone
/// and a constant are the canonical form's own; a term with an angle's
/// e^{iθ} is not real alone, so it is never renamed.
fn odd(m: &Mono, c: &Coef) -> bool {
    let real = m.iter().all(|(v, _)| !matches!(v, Var::Z(_)));
    let symbols = m
        .iter()
        .any(|(v, _)| matches!(v, Var::Sym(_) | Var::Call(_)));
    let angle = matches!(m.as_slice(), [(Var::Sym(_), 1)]) && c.as_rat().is_some();
    real && symbols && !angle
}

/// The odd terms (monomial and coefficient) in the arguments of the sines
/// and cosines of `e`.
fn terms(e: &Expr, out: &mut Vec<(Mono, Coef)>) {
    for (v, _) in e.terms.keys().flatten() {
        let Var::Call(c) = v else { continue };
        for a in &c.args {
            if matches!(c.f, Func::Sin | Func::Cos) {
                // a float coefficient (sin(cot(1) b)) has no rational
                // ratio to any fresh angle, not even its own: renamed it
                // would stay odd, and `refolded` would recurse forever
                for (m, k) in &a.terms {
                    if odd(m, k) && k.is_exact() && !out.iter().any(|(n, j)| n == m && j == k) {
                        out.push((m.clone(), k.clone()));
                    }
                }
            }
            terms(a, out);
        }
    }
}

/// c/base when it is rational.
fn ratio(c: &Coef, base: &Coef) -> Option<Rat> {
    c.mul(&base.inv()?).as_rat()
}

/// The fresh angles of the odd terms: on each monomial, one per class of
/// coefficients with rational ratios, its coefficient the first one's
/// divided by the least common denominator of the ratios (so every term
/// is an integer multiple of it).
fn fresh(found: &[(Mono, Coef)]) -> Vec<Fresh> {
    let mut classes: Vec<(Mono, Coef, Vec<Rat>)> = Vec::new();
    for (m, c) in found {
        let class = classes
            .iter_mut()
            .find_map(|(n, base, rs)| (n == m).then_some(()).and(ratio(c, base).map(|r| (rs, r))));
        match class {
            Some((rs, r)) => rs.push(r),
            None => classes.push((m.clone(), c.clone(), vec![Rat::ONE])),
        }
    }
    classes
        .into_iter()
        .enumerate()
        .filter_map(|(i, (m, base, rs))| {
            let den = common_denominator(&rs)?;
            let w = base.mul(&Coef::rat(Rat::new(1, den)?));
            Some((m, w, Symbol::new(&format!("\u{1}angle {i}"))))
        })
        .collect()
}

/// `e` with each odd term in a sine's or cosine's argument written as an
/// integer multiple of its fresh symbol.
fn rewrite(e: &Expr, names: &[Fresh], parts: &[FreshSum]) -> Expr {
    let mut out = Expr::zero();
    for (m, c) in &e.terms {
        let mut t = Expr::constant(c.clone());
        for (v, k) in m {
            let f = match v {
                Var::Call(call) => {
                    let args: Vec<Expr> = call
                        .args
                        .iter()
                        .map(|a| {
                            let a = rewrite(a, names, parts);
                            if matches!(call.f, Func::Sin | Func::Cos) {
                                renamed(&a, names, parts)
                            } else {
                                a
                            }
                        })
                        .collect();
                    super::eval::rebuild(call.f, &args)
                }
                other => Expr::var(other.clone()),
            };
            t = t.mul(&f.powi(i64::from(*k)).unwrap_or_default());
        }
        out = out.add(&t);
    }
    out
}

/// An argument with its odd terms renamed.
fn renamed(a: &Expr, names: &[Fresh], parts: &[FreshSum]) -> Expr {
    let mut out = Expr::zero();
    let trig = trig_part(a);
    let part = parts
        .iter()
        .find_map(|(p, s)| multiple(&trig, p).map(|r| (r, s)));
    if let Some((r, s)) = &part {
        out = Expr::symbol((*s).clone()).scale(&Coef::rat(r.clone()));
    }
    for (m, c) in &a.terms {
        if part.is_some() && trig.terms.contains_key(m) {
            continue;
        }
        let multiple = names
            .iter()
            .find_map(|(n, w, s)| (n == m).then(|| ratio(c, w).map(|r| (r, s))).flatten());
        match multiple {
            Some((r, s)) => out = out.add(&Expr::symbol(s.clone()).scale(&Coef::rat(r))),
            None => {
                let mut t = Expr::zero();
                t.push(m.clone(), c.clone());
                out = out.add(&t);
            }
        }
    }
    out
}

/// p and q with every odd term inside their sines and cosines renamed to
/// a multiple of a fresh symbol (module doc); None when there is none.
pub fn linearized(p: &Expr, q: &Expr) -> Option<(Expr, Expr)> {
    let mut found = Vec::new();
    terms(p, &mut found);
    terms(q, &mut found);
    let mut found_sums = Vec::new();
    sums(p, &mut found_sums);
    sums(q, &mut found_sums);
    let (names, parts) = angles(&found, &found_sums)?;
    Some((rewrite(p, &names, &parts), rewrite(q, &names, &parts)))
}

/// The fresh angles of the odd terms and of the trigonometric parts
/// found; None when there is none, or too many to try.
fn angles(found: &[(Mono, Coef)], found_sums: &[Expr]) -> Option<(Vec<Fresh>, Vec<FreshSum>)> {
    if found.len() > 8 || found_sums.len() > 4 {
        return None;
    }
    let names = fresh(found);
    let parts = fresh_sums(found_sums);
    if (names.is_empty() && parts.is_empty()) || names.len() + parts.len() > 4 {
        return None;
    }
    Some((names, parts))
}

/// `e` made again through fresh angles: its odd terms renamed (module
/// doc), `make` applied there (where the canonical form folds
/// sin²(w) + cos²(w) into 1, or `simplify`), and the angles put back —
/// e^{ikw} as cos(k a) + i sin(k a) of the angle a that w stands for, w
/// itself as a. The same value by construction (an identity in an
/// independent w holds at w = a), so `sin(√6 x)^2 + cos(√6 x)^2` prints
/// `1`, as `==` proves it. None when `e` has no odd angle, or one nested
/// in a call that is not a sine or cosine of it, or a float coefficient.
pub fn refolded(e: &Expr, make: &dyn Fn(&Expr) -> Expr) -> Option<Expr> {
    // (a float coefficient, such as a constant offset's e^{0.3i} in
    // cos(y + 0.3), would be multiplied into the calls put back, where
    // it prints in floats: not folded)
    if !e.terms.values().all(Coef::is_exact) {
        return None;
    }
    let mut found = Vec::new();
    terms(e, &mut found);
    let mut found_sums = Vec::new();
    sums(e, &mut found_sums);
    let (names, parts) = angles(&found, &found_sums)?;
    let general = make(&rewrite(e, &names, &parts));
    let angle = |s: &Symbol| {
        let part = parts.iter().find(|(_, n)| n == s).map(|(p, _)| p.clone());
        part.or_else(|| {
            names.iter().find(|(_, _, n)| n == s).map(|(m, w, _)| {
                let mut a = Expr::zero();
                a.push(m.clone(), w.clone());
                a
            })
        })
    };
    let mut out = Expr::zero();
    for (m, c) in &general.terms {
        let mut rest: Mono = Vec::new();
        let mut turn = Expr::zero();
        let mut factor = Expr::one();
        // a plain angle beside a fresh one joins it (e^{iw} e^{iy} is
        // e^{i(√2 x + y)}: `sin(√2 x + y)`, one call)
        let fresh_here = m
            .iter()
            .any(|(v, _)| matches!(v, Var::Z(s) if angle(s).is_some()));
        for (v, k) in m {
            match v {
                Var::Z(s) if let Some(a) = angle(s) => {
                    turn = turn.add(&a.scale(&Coef::int(i64::from(*k))));
                }
                Var::Z(s) if fresh_here && s.phase().is_none() => {
                    turn = turn.add(&Expr::symbol(s.clone()).scale(&Coef::int(i64::from(*k))));
                }
                // a constant offset (y + 0.3) beside a fresh angle would
                // print in floats: not folded
                Var::Z(_) if fresh_here => return None,
                Var::Sym(s) if let Some(a) = angle(s) => {
                    factor = factor.mul(&a.powi(i64::from(*k))?);
                }
                Var::Call(_) => {
                    let mut syms = Vec::new();
                    Expr::var(v.clone()).symbols(&mut syms);
                    if syms.iter().any(|s| angle(s).is_some()) {
                        return None;
                    }
                    rest.push((v.clone(), *k));
                }
                _ => rest.push((v.clone(), *k)),
            }
        }
        let mut t = Expr::zero();
        t.push(rest, c.clone());
        if !turn.is_zero() {
            // e^{iθ} = cos θ + i sin θ, over the angle whose first
            // coefficient is positive (sin(−θ) is another call than
            // sin θ: written −sin θ, the terms of ±θ meet)
            let neg = turn
                .terms
                .values()
                .next()
                .is_some_and(|c| c.to_c64().0 < 0.0);
            let (turn, i) = match neg {
                true => (turn.neg(), Coef::i().neg()),
                false => (turn, Coef::i()),
            };
            factor = factor.mul(&Expr::cos(&turn).add(&Expr::sin(&turn).scale(&i)));
        }
        out = out.add(&t.mul(&factor));
    }
    // never floats where the value had none
    out.terms.values().all(Coef::is_exact).then_some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::print::{Style, expr};

    #[test]
    fn irrational_angles_fold_through_fresh_symbols() {
        let x = Expr::symbol(Symbol::new("x"));
        let a = x.scale(&Coef::real(
            crate::sym::coef::Surd::sqrt_of(&Rat::int(6)).unwrap(),
        ));
        let (s, c) = (Expr::sin(&a), Expr::cos(&a));
        let one = s.mul(&s).add(&c.mul(&c));
        assert_eq!(expr(&one, Style::default()), "1");
        let f = refolded(&one, &|g| g.clone()).expect("an odd angle");
        assert_eq!(f, Expr::one());
        let two = s.mul(&c).scale(&Coef::int(2));
        let back = refolded(&two, &|g| g.clone()).expect("an odd angle");
        assert_eq!(expr(&back, Style::default()), "sin(2√6 x)");
        assert_eq!(
            expr(&crate::sym::together::simplest(&two), Style::default()),
            "sin(2√6 x)"
        );
    }
}
