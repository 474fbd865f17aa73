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
use super::collect::{Node, PLAIN, collect, items, measure, render_all, worth};
use super::expr::{Mono, Symbol, Var, mono_mul};
use super::print::Style;
use super::trig::{Real, Trig};

/// The most terms a sum may have for its shapes to be compared (past it,
/// an expansion: trigonometric factors taken out alone).
const MAX_TERMS: usize = 300;

/// A shape's terms as plain text, what it costs ([`measure`]), and how to
/// print it in another style.
type Scored<'a> = (Vec<(bool, String)>, (usize, usize), Chosen<'a>);

/// A shape chosen: trigonometric factors taken out alone from a form, or
/// a collected shape.
enum Chosen<'a> {
    ByTrig(&'a Real),
    Nodes(Vec<Node>),
}

/// The signed terms of a real form in the shape with the fewest factors
/// (`collect::measure`): trigonometric factors taken out alone, or all shared
/// factors collected (on a tie the collected form, the book's: `cos(θ) +
/// w[1]^2 (1 - cos(θ))`), each of the unit sphere's charts tried where a
/// unit axis appears (kept when it costs less). The shape is decided on
/// the plain text, so that every style prints the same one.
pub fn shaped(real: &Real, st: Style) -> Vec<(bool, String)> {
    if real.len() < 2 || real.len() > MAX_TERMS {
        return super::factor::factored(real, st);
    }
    let charts = unit_charts(real);
    let partial = real.len() <= super::collect::LONG;
    let mut best_terms = super::factor::factored(real, PLAIN);
    let mut best_cost = measure(&best_terms);
    let mut chosen = Chosen::ByTrig(real);
    for (i, form) in std::iter::once(real).chain(&charts).enumerate() {
        let all = items(form);
        // this form's shapes, the book's last: on a tie in factors, the
        // later one
        let mut shapes: Vec<Vec<Node>> = Vec::new();
        if i > 0 || worth(&all) {
            shapes.push(collect(all.clone(), partial));
        }
        shapes.extend(super::bilinear::bilinear(&all, partial));
        let mut here: Option<Scored> = None;
        if i > 0 {
            let by_trig = super::factor::factored(form, PLAIN);
            let cost = measure(&by_trig);
            here = Some((by_trig, cost, Chosen::ByTrig(form)));
        }
        for mut nodes in shapes {
            let mut plain = render_all(&nodes, PLAIN);
            // a sum starts with a positive term where it has one (3.52:
            // `w[2] w[3] (1 - cos(θ)) - w[1] sin(θ)`)
            if plain.first().is_some_and(|t| t.0)
                && let Some(j) = plain.iter().position(|t| !t.0)
            {
                let n = nodes.remove(j);
                nodes.insert(0, n);
                let t = plain.remove(j);
                plain.insert(0, t);
            }
            let cost = measure(&plain);
            if here.as_ref().is_none_or(|h| cost.0 <= h.1.0) {
                here = Some((plain, cost, Chosen::Nodes(nodes)));
            }
        }
        let Some((terms, cost, how)) = here else {
            continue;
        };
        let wins = match i {
            0 => cost.0 <= best_cost.0,
            _ => cost < best_cost,
        };
        if wins {
            (best_terms, best_cost, chosen) = (terms, cost, how);
        }
    }
    if st == PLAIN {
        return best_terms;
    }
    match chosen {
        Chosen::ByTrig(form) => super::factor::factored(form, st),
        Chosen::Nodes(nodes) => render_all(&nodes, st),
    }
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
