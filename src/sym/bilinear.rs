//! A sum as symbols times angles (issue 35; LANGUAGE.md §7): each term is
//! a monomial in the symbols (lengths, axis components) times a monomial
//! in the angles (their sines, cosines and powers), so that the sum is a
//! matrix of coefficients between the two. Symbol monomials whose rows are
//! proportional share their angle sum, and print as one product:
//! Rodrigues' r₁₂ = ω̂₁ω̂₂(1 − cθ) − ω̂₃sθ (3.52), and the book's G(θ)v
//! of Proposition 3.16, `S[4] sin(t) + (S[2] S[6] - S[3] S[5]) (1 -
//! cos(t)) + S[1] (S[1] S[4] + S[2] S[5] + S[3] S[6]) (t - sin(t))`, where
//! the expansion has 17 terms. The symbol side is collected in turn
//! ([`super::collect`]), the angle side has its trigonometric factors taken
//! out ([`super::factor`]).

use super::coef::Coef;
use super::collect::{Item, Node, collect};
use super::expr::{Mono, Symbol, Var};
use super::trig::{Real, Trig};

/// Angle terms with their coefficients: one row of the matrix.
type Angles = Vec<((Mono, Vec<Trig>), Coef)>;
/// One row: a symbol monomial's place, the monomial, its angle terms.
type Row = (usize, Mono, Angles);

/// The sum as products of a symbol sum and an angle sum, one product per
/// class of proportional rows, in the place of its first term; None when
/// no two rows are proportional (nothing to share). `partial` as in
/// [`collect`].
pub(super) fn bilinear(items: &[Item], partial: bool) -> Option<Vec<Node>> {
    // the angles: symbols inside a sine or cosine (θ itself, as in G(θ),
    // is on the angle side)
    let mut angles: Vec<&Symbol> = Vec::new();
    for (_, _, trig, _) in items {
        for (k, _, _) in trig {
            for (s, _) in k {
                if !angles.contains(&s) {
                    angles.push(s);
                }
            }
        }
    }
    let is_angle = |v: &Var| matches!(v, Var::Sym(s) if angles.contains(&s));
    let mut rows: Vec<Row> = Vec::new();
    for (i, poly, trig, c) in items {
        let (b, a): (Mono, Mono) = poly.iter().cloned().partition(|(v, _)| is_angle(v));
        let key = (b, trig.clone());
        match rows.iter_mut().find(|r| r.1 == a) {
            Some(r) => r.2.push((key, c.clone())),
            None => rows.push((*i, a, vec![(key, c.clone())])),
        }
    }
    // each row over its first coefficient: rows alike share the angle sum
    let mut classes: Vec<(usize, Vec<Item>, Angles)> = Vec::new();
    for (i, a, mut row) in rows {
        row.sort_by(|x, y| x.0.cmp(&y.0));
        // (over floats, rows alike only when equal: no new rounded ratios)
        let lead = match row.iter().all(|(_, c)| c.is_exact()) {
            true => row[0].1.clone(),
            false => Coef::one(),
        };
        let inv = lead.inv()?;
        let unit: Angles = row.into_iter().map(|(k, c)| (k, c.mul(&inv))).collect();
        match classes.iter_mut().find(|c| c.2 == unit) {
            Some(class) => class.1.push((i, a, Vec::new(), lead)),
            None => classes.push((i, vec![(i, a, Vec::new(), lead)], unit)),
        }
    }
    let alone = |c: &(usize, Vec<Item>, _)| c.1.len() == 1 && c.1[0].1.is_empty();
    if classes.len() == items.len() || (classes.len() == 1 && alone(&classes[0])) {
        return None;
    }
    let one = |r: &[((Mono, Vec<Trig>), Coef)]| matches!(r, [((b, t), c)] if b.is_empty() && t.is_empty() && c.is_one());
    let mut out = Vec::new();
    for (first, mut left, mut right) in classes {
        // one angle term: its coefficient (a float, unnormalized) joins the
        // symbols, `(0.5 a + 0.5 b) cos(t)`, not `(a + b) 0.5 cos(t)`
        if let [(_, c)] = right.as_mut_slice()
            && !c.is_one()
        {
            left.iter_mut().for_each(|x| x.3 = x.3.mul(c));
            *c = Coef::one();
        }
        if one(&right) {
            // no angle: the symbol sum itself, collected
            out.extend(collect(left, partial));
            continue;
        }
        let right: Real = right.into_iter().collect();
        out.push(match (left.len(), right.len()) {
            // one term: as it is
            (1, 1) => {
                let (i, a, _, k) = &left[0];
                let ((b, trig), c) = right
                    .iter()
                    .next()
                    .map(|(x, c)| (x.clone(), c.clone()))
                    .unwrap_or_else(|| ((Vec::new(), Vec::new()), Coef::one()));
                Node::Term((*i, super::expr::mono_mul(a, &b), trig, k.mul(&c)))
            }
            _ => Node::Product {
                first,
                left: collect(left, partial),
                // (the angle side collected too: `(1 - cos(t1 + t2)) sin(t3)`)
                right: collect(super::collect::items(&right), partial),
            },
        });
    }
    out.sort_by_key(Node::first);
    Some(out)
}
