//! The printed shape of a sum (issue 35; LANGUAGE.md §7: closed forms print
//! in the book's shape): one display-time pass over the canonical form that
//! chooses, among a few ways of writing the same value, the shortest —
//! trigonometric factors taken out alone ([`super::factor`]), or every
//! shared factor and the integer content collected ([`super::collect`]),
//! each also on the unit sphere's other charts. On the unit sphere the
//! canonical form writes ω̂₃² as 1 − ω̂₁² − ω̂₂² ([`super::axis`]); the
//! printing may write ω̂₁² (or ω̂₂²) as 1 − ω̂₂² − ω̂₃² instead, so that
//! Rodrigues' r₃₃ reads `cos(θ) + w[3]^2 (1 - cos(θ))` as (3.52) does, not
//! `1 - w[1]^2 + (w[1]^2 + w[2]^2) cos(θ) - w[2]^2`. Only the printing
//! changes; each printed form is the value (on the unit sphere, where the
//! axis was assumed to be a unit vector).

use std::collections::BTreeMap;

use super::coef::Coef;
use super::collect::{collect, items, width, worth};
use super::expr::{Mono, Symbol, Var, mono_mul};
use super::print::Style;
use super::trig::{Real, Trig};

/// The most terms a sum may have for its shapes to be compared (past it,
/// an expansion: trigonometric factors taken out alone).
const MAX_TERMS: usize = 300;

/// The signed terms of a real form in its shortest shape: trigonometric
/// factors taken out, or all shared factors collected (on a tie the
/// collected form, the book's), each of the unit sphere's charts tried
/// where a unit axis appears (on a tie the canonical chart).
pub fn shaped(real: &Real, st: Style) -> Vec<(bool, String)> {
    let mut best = super::factor::factored(real, st);
    if real.len() < 2 || real.len() > MAX_TERMS {
        return best;
    }
    let mut best_width = width(&best);
    let charts = std::iter::once(None).chain(unit_charts(real).into_iter().map(Some));
    for (i, chart) in charts.enumerate() {
        let form = chart.as_ref().unwrap_or(real);
        let all = items(form);
        if !worth(&all) && i == 0 {
            continue;
        }
        let mut terms: Vec<(bool, String)> = collect(all, st).into_iter().map(|x| x.1).collect();
        if i > 0 {
            let by_trig = super::factor::factored(form, st);
            if width(&by_trig) < width(&terms) {
                terms = by_trig;
            }
        }
        let w = width(&terms);
        if w < best_width || (i == 0 && w == best_width) {
            best = terms;
            best_width = w;
        }
    }
    best
}

/// The real form rewritten on the unit sphere's other charts: for each
/// unit ω̂ᵢ (i = 1, 2) that appears squared, ω̂ᵢ² = 1 − ω̂ⱼ² − ω̂₃² in every
/// term (the relation the canonical form uses for ω̂₃², solved for ω̂ᵢ).
fn unit_charts(real: &Real) -> Vec<Real> {
    let mut hits: Vec<Symbol> = Vec::new();
    for (poly, _) in real.keys() {
        for (v, e) in poly {
            if let Var::Sym(s) = v
                && s.unit
                && (s.index == 1 || s.index == 2)
                && *e >= 2
                && !hits.contains(s)
            {
                hits.push(s.clone());
            }
        }
    }
    hits.iter().map(|s| rewrite(real, s)).collect()
}

/// `real` with every power ω̂ᵢᵉ (e ≥ 2) of the unit component `s` written
/// as (1 − ω̂ⱼ² − ω̂₃²)^⌊e/2⌋ ω̂ᵢ^(e mod 2).
fn rewrite(real: &Real, s: &Symbol) -> Real {
    let sibling = |index: u8| Symbol { index, ..s.clone() };
    let square = |x: Symbol| -> Mono { vec![(Var::Sym(x), 2)] };
    let others = [square(sibling(3 - s.index)), square(sibling(3))];
    let me = Var::Sym(s.clone());
    let mut out: BTreeMap<(Mono, Vec<Trig>), Coef> = BTreeMap::new();
    for ((poly, trig), c) in real {
        let e = poly.iter().find(|(v, _)| *v == me).map_or(0, |x| x.1);
        let mut parts: Vec<(Mono, Coef)> = vec![(
            poly.iter()
                .filter_map(|(v, k)| match *v == me && *k >= 2 {
                    false => Some((v.clone(), *k)),
                    true => (k % 2 != 0).then(|| (v.clone(), 1)),
                })
                .collect(),
            c.clone(),
        )];
        for _ in 0..(if e >= 2 { e / 2 } else { 0 }) {
            parts = parts
                .into_iter()
                .flat_map(|(m, c)| {
                    let minus = c.neg();
                    [
                        (mono_mul(&m, &others[0]), minus.clone()),
                        (mono_mul(&m, &others[1]), minus),
                        (m, c),
                    ]
                })
                .collect();
        }
        for (m, k) in parts {
            let key = (m, trig.clone());
            let sum = match out.remove(&key) {
                Some(old) => old.add(&k),
                None => k,
            };
            if !sum.is_zero() {
                out.insert(key, sum);
            }
        }
    }
    out
}
