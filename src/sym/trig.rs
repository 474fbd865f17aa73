//! The real form of a canonical expression: each z-monomial paired with
//! its conjugate back into cosines and sines (e^{ik·θ} = cos k·θ + i sin k·θ).
//! The angles are split into groups — inside a group an angle sum stays one
//! cosine, `cos(t2 + t3)`, across groups products stay products,
//! `sin(t1) cos(t5)` — and the grouping with the fewest terms is chosen
//! (every partition up to five angles, greedy merging beyond).

use std::collections::BTreeMap;

use super::coef::Coef;
use super::expr::{Expr, Mono, Symbol, Var};
use super::phase::{PI_DEN, PI_EDGE, Unit};

/// One trigonometric factor: an integer combination of angles (first
/// coefficient positive), whether it is a sine, and its power (`cos(t)^2`
/// where a single angle prints in powers of cos t and sin t).
pub type Trig = (Vec<(Symbol, i32)>, bool, u32);
/// An integer combination of angles, constant offsets (`π/5`, `0.3`) as
/// phase variables ([`super::phase`]).
pub type Angle = Vec<(Symbol, i32)>;
/// The real terms: (non-angle monomial, trigonometric factors) → coefficient.
pub type Real = BTreeMap<(Mono, Vec<Trig>), Coef>;

/// A grouping of angles, and what printing with it costs (terms, then
/// fewer groups).
type Groups = Vec<Vec<Symbol>>;
type Cost = (usize, usize);

/// How a group of angles prints: cosines and sines of angle sums, or (one
/// angle) powers of cos θ and sin θ with sin² or with cos² eliminated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Power {
    /// Cosines and sines of angle sums, the book's c₁₂ = cos(θ1 + θ2).
    Linear,
    /// Powers of cos θ, sin² θ replaced by 1 − cos² θ (sin θ at most
    /// once in a term).
    Cos,
    /// Powers of sin θ, cos² θ replaced by 1 − sin² θ.
    Sin,
}

/// The real form of `e` for a grouping of its angles, each printed as
/// `powers` says (missing: linear).
pub fn realize(e: &Expr, groups: &[Vec<Symbol>], powers: &[Power]) -> Real {
    let mut out: Real = BTreeMap::new();
    let half_i = Coef::i();
    for (m, c) in &e.terms {
        let mut poly: Mono = Vec::new();
        let mut zs: Vec<(&Symbol, i32)> = Vec::new();
        for (v, k) in m {
            match v {
                Var::Z(s) => zs.push((s, *k)),
                other => poly.push((other.clone(), *k)),
            }
        }
        let mut parts: Vec<(Vec<Trig>, Coef)> = vec![(Vec::new(), c.clone())];
        for (gi, g) in groups.iter().enumerate() {
            if let Some(basis @ (Power::Cos | Power::Sin)) = powers.get(gi).copied()
                && let Some((s, k)) = zs.iter().find(|(s, _)| g.contains(s))
            {
                let expansion = power_form(*k, basis == Power::Sin);
                parts = parts
                    .into_iter()
                    .flat_map(|(t, c)| {
                        expansion.iter().map(move |((a, b), x)| {
                            let mut t = t.clone();
                            if *a > 0 {
                                t.push((vec![((*s).clone(), 1)], false, *a));
                            }
                            if *b > 0 {
                                t.push((vec![((*s).clone(), 1)], true, *b));
                            }
                            (t, c.mul(x))
                        })
                    })
                    .collect();
                continue;
            }
            let mut k: Vec<(Symbol, i32)> = zs
                .iter()
                .filter(|(s, _)| g.contains(s))
                .map(|(s, k)| ((*s).clone(), *k))
                .collect();
            if k.is_empty() {
                continue;
            }
            k.sort();
            let sign = if k[0].1 > 0 { 1 } else { -1 };
            for x in &mut k {
                x.1 *= sign;
            }
            let edge = edge_turn(&mut k, sign);
            let sin_factor = half_i.mul(&Coef::int(i64::from(sign)));
            parts = parts
                .into_iter()
                .flat_map(|(t, c)| {
                    let c = match &edge {
                        Some(turn) => c.mul(turn),
                        None => c,
                    };
                    let mut ct = t.clone();
                    ct.push((k.clone(), false, 1));
                    let mut st = t;
                    st.push((k.clone(), true, 1));
                    let sc = c.mul(&sin_factor);
                    [(ct, c), (st, sc)]
                })
                .collect();
        }
        for (t, k) in parts {
            let key = (poly.clone(), t);
            let sum = match out.get(&key) {
                Some(old) => old.add(&k),
                None => k,
            };
            out.insert(key, sum);
        }
    }
    // e is real, so it is the sum of the real parts: where a monomial's
    // conjugate carries another phase (u^{N/2} and u^{−N/2} are one
    // value), the imaginary parts cancel between keys, not within one
    for c in out.values_mut() {
        *c = real_part(c);
    }
    let scale = largest(out.values());
    out.retain(|_, c| !negligible(c, scale));
    out
}

/// u^{−N/2} = u^{N/2} e^{−iπ/12} for the π-phase u (N units make π/12,
/// [`super::phase`]): an angle whose sign was turned (a conjugate) ends
/// with the offset +π/24 like its partner, not −π/24, so that the two
/// print as one cosine. The factor this takes, e^{−i·sign·π/12}.
fn edge_turn(k: &mut [(Symbol, i32)], sign: i32) -> Option<Coef> {
    let pi = k
        .iter_mut()
        .find(|(s, e)| *e == -PI_EDGE && s.phase() == Some(Unit::Pi))?;
    pi.1 = PI_EDGE;
    Coef::unit_root(super::coef::Rat::new(i128::from(-sign), 12)?)
}

/// Re c, as a coefficient.
fn real_part(c: &Coef) -> Coef {
    match c {
        Coef::Exact { re, .. } => Coef::real(re.clone()),
        Coef::Approx { re, .. } => Coef::Approx { re: *re, im: 0.0 },
    }
}

/// The largest |k| of e^{ikθ} written in powers of cos θ and sin θ.
const MAX_POWER: i32 = 12;

/// e^{ikθ} = (cos θ + i sin θ)^k in powers of c = cos θ and s = sin θ:
/// with s² = 1 − c² (`sin_basis` false) or c² = 1 − s² (true), as
/// (power of cos, power of sin) → coefficient.
fn power_form(k: i32, sin_basis: bool) -> Vec<((u32, u32), Coef)> {
    let n = k.unsigned_abs();
    let unit = Coef::i().mul(&Coef::int(i64::from(k.signum())));
    let mut out: BTreeMap<(u32, u32), Coef> = BTreeMap::new();
    let mut binom = 1i64;
    let mut ij = Coef::one();
    for j in 0..=n {
        // C(n, j) (i sgn)^j c^{n−j} s^j; the reduced one is s (or c)
        let (kept, reduced) = if sin_basis { (j, n - j) } else { (n - j, j) };
        let (m, odd) = (reduced / 2, reduced % 2);
        let mut bm = 1i64;
        for r in 0..=m {
            let sign = if r % 2 == 0 { 1 } else { -1 };
            let x = ij.mul(&Coef::int(binom * bm * sign));
            let main = kept + 2 * r;
            let key = if sin_basis { (odd, main) } else { (main, odd) };
            let sum = match out.get(&key) {
                Some(o) => o.add(&x),
                None => x,
            };
            out.insert(key, sum);
            bm = bm * i64::from(m - r) / i64::from(r + 1);
        }
        ij = ij.mul(&unit);
        binom = binom * i64::from(n - j) / i64::from(j + 1);
    }
    out.into_iter().filter(|(_, c)| !c.is_zero()).collect()
}

/// True for a coefficient that is rounding noise among `all`: exactly 0,
/// or a float below 1e-13 both absolutely and relative to the largest
/// coefficient. (Absolute alone dropped genuine terms of a small
/// expression: `exp(-40) cos(t)` printed 0, and bound later was 0.)
fn negligible(c: &Coef, scale: f64) -> bool {
    match c {
        Coef::Exact { re, .. } => re.is_zero(),
        Coef::Approx { re, .. } => re.abs() < 1e-13 && re.abs() <= 1e-13 * scale,
    }
}

/// The largest real part among the coefficients (the scale of
/// [`negligible`]).
fn largest<'a>(all: impl Iterator<Item = &'a Coef>) -> f64 {
    all.map(|c| c.to_c64().0.abs()).fold(0.0f64, f64::max)
}

/// Real terms being counted: (monomial, canonical exponents) → the
/// coefficient of each cos/sin choice.
type Cells = std::collections::HashMap<(usize, Vec<i32>), Vec<(f64, f64)>>;

/// An expression reduced to what the choice of grouping needs: per term,
/// its non-angle monomial (numbered), its angle exponents, and its
/// coefficient as floats (the search only counts terms; the printed form
/// is exact).
struct Compact {
    terms: Vec<(usize, Vec<i32>, (f64, f64))>,
    /// The index of the π-phase among the angles.
    pi: Option<usize>,
}

impl Compact {
    fn new(e: &Expr, angles: &[Symbol]) -> Compact {
        let mut polys: Vec<Mono> = Vec::new();
        let terms = e
            .terms
            .iter()
            .map(|(m, c)| {
                let mut exps = vec![0; angles.len()];
                let mut poly: Mono = Vec::new();
                for (v, k) in m {
                    match v {
                        Var::Z(s) => {
                            if let Some(i) = angles.iter().position(|a| a == s) {
                                exps[i] = *k;
                            }
                        }
                        other => poly.push((other.clone(), *k)),
                    }
                }
                let id = polys.iter().position(|p| *p == poly).unwrap_or_else(|| {
                    polys.push(poly);
                    polys.len() - 1
                });
                (id, exps, c.to_c64())
            })
            .collect();
        let pi = angles.iter().position(|a| a.phase() == Some(Unit::Pi));
        Compact { terms, pi }
    }

    /// The number of real terms when angle i is in group `of[i]`.
    fn count(&self, of: &[usize], groups: usize) -> usize {
        let mut acc: Cells = std::collections::HashMap::new();
        let mut scale = 0f64;
        for (id, exps, (re, im)) in &self.terms {
            let mut sign = vec![0i32; groups];
            for (i, &k) in exps.iter().enumerate() {
                if k != 0 && sign[of[i]] == 0 {
                    sign[of[i]] = k.signum();
                }
            }
            let mut canon: Vec<i32> = exps
                .iter()
                .enumerate()
                .map(|(i, &k)| k * sign[of[i]])
                .collect();
            // the π-phase at −π/24 turned to +π/24 (see `edge_turn`)
            let (mut re, mut im) = (*re, *im);
            if let Some(i) = self.pi
                && canon[i] == -PI_EDGE
            {
                canon[i] = PI_EDGE;
                let a = -f64::from(sign[of[i]]) * std::f64::consts::PI / 12.0;
                (re, im) = (re * a.cos() - im * a.sin(), re * a.sin() + im * a.cos());
            }
            let active: Vec<i32> = sign.iter().copied().filter(|&s| s != 0).collect();
            let slot = acc
                .entry((*id, canon))
                .or_insert_with(|| vec![(0.0, 0.0); 1 << active.len()]);
            for (mask, cell) in slot.iter_mut().enumerate() {
                // sin choices multiply by i·sign
                let (mut a, mut b) = (re, im);
                for (g, sg) in active.iter().enumerate() {
                    if mask >> g & 1 == 1 {
                        (a, b) = (-b * f64::from(*sg), a * f64::from(*sg));
                    }
                }
                cell.0 += a;
                cell.1 += b;
            }
            scale = scale.max(re.abs()).max(im.abs());
        }
        let tol = 1e-9 * scale.max(1e-300);
        acc.values().flatten().filter(|c| c.0.abs() > tol).count()
    }
}

/// The grouping of `angles` that prints `e` with the fewest terms (ties:
/// more groups): every partition up to five angles, greedy merging beyond.
pub fn best_groups(e: &Expr, angles: &[Symbol]) -> Vec<Vec<Symbol>> {
    let terms = Compact::new(e, angles);
    let cost = |g: &[Vec<Symbol>]| {
        let of: Vec<usize> = angles
            .iter()
            .map(|a| g.iter().position(|grp| grp.contains(a)).unwrap_or(0))
            .collect();
        (terms.count(&of, g.len()), usize::MAX - g.len())
    };
    let n = angles.len();
    if n <= 5 {
        let mut best: Option<(Cost, Groups)> = None;
        let mut code = vec![0usize; n];
        loop {
            let k = code.iter().max().map_or(0, |m| m + 1);
            let mut groups = vec![Vec::new(); k];
            for (i, &c) in code.iter().enumerate() {
                groups[c].push(angles[i].clone());
            }
            let c = cost(&groups);
            if best.as_ref().is_none_or(|(b, _)| c < *b) {
                best = Some((c, groups));
            }
            // next restricted growth string
            let mut i = n;
            loop {
                if i <= 1 {
                    return best.map(|b| b.1).unwrap_or_default();
                }
                i -= 1;
                let max_prev = code[..i].iter().max().copied().unwrap_or(0);
                if code[i] <= max_prev {
                    code[i] += 1;
                    code[i + 1..].iter_mut().for_each(|x| *x = 0);
                    break;
                }
            }
        }
    }
    let mut groups: Vec<Vec<Symbol>> = angles.iter().map(|a| vec![a.clone()]).collect();
    let mut current = cost(&groups);
    loop {
        let mut best: Option<(Cost, Groups)> = None;
        for i in 0..groups.len() {
            for j in i + 1..groups.len() {
                let mut g = groups.clone();
                let moved = g.remove(j);
                g[i].extend(moved);
                let c = cost(&g);
                if c.0 < current.0 && best.as_ref().is_none_or(|(b, _)| c < *b) {
                    best = Some((c, g));
                }
            }
        }
        match best {
            Some((c, g)) => {
                current = c;
                groups = g;
            }
            None => return groups,
        }
    }
}

/// The real terms of `e` with its best grouping of angles.
pub fn real_form(e: &Expr) -> Real {
    let mut angles: Vec<Symbol> = Vec::new();
    for m in e.terms.keys() {
        for (v, _) in m {
            if let Var::Z(s) = v
                && !angles.contains(s)
            {
                angles.push(s.clone());
            }
        }
    }
    angles.sort();
    let groups = best_groups(e, &angles);
    let mut powers = vec![Power::Linear; groups.len()];
    let mut best = realize(e, &groups, &powers);
    // A single angle with multiples (sin t cos t as (1/2) sin(2 t)) may read
    // better in powers of its cosine and sine: kept when shorter (on a tie
    // the multiple angle, so that sin(2 t) prints beside cos(2 t)).
    for (gi, g) in groups.iter().enumerate() {
        let multiples = |k: i32| k.abs() >= 2 && k.abs() <= MAX_POWER;
        let fits = e.terms.keys().flatten().all(|(v, k)| match v {
            Var::Z(s) if g.contains(s) => k.abs() <= MAX_POWER,
            _ => true,
        });
        let has = e
            .terms
            .keys()
            .flatten()
            .any(|(v, k)| matches!(v, Var::Z(s) if g.contains(s)) && multiples(*k));
        if g.len() != 1 || !fits || !has {
            continue;
        }
        for basis in [Power::Cos, Power::Sin] {
            let old = powers[gi];
            powers[gi] = basis;
            let tried = realize(e, &groups, &powers);
            if tried.len() < best.len() {
                best = tried;
            } else {
                powers[gi] = old;
            }
        }
    }
    fold_offsets(best)
}

/// a cos K + b sin K = r cos(K − φ) (or r sin(K + ψ)) where the offset is
/// a multiple of π/12 and r is exact: `cos(t1 + t2 + π/4)` prints as one
/// term, not (1/√2) cos(t1 + t2) − (1/√2) sin(t1 + t2). The offset is
/// added to the angle's π-phase ([`super::phase`]).
fn fold_offsets(real: Real) -> Real {
    let mut out: Real = BTreeMap::new();
    let mut used: std::collections::BTreeSet<(Mono, Vec<Trig>)> = Default::default();
    for (key, a) in &real {
        if used.contains(key) {
            continue;
        }
        let (poly, trig) = key;
        let mut folded = None;
        for i in 0..trig.len() {
            if trig[i].1 || trig[i].2 != 1 {
                continue;
            }
            let mut partner = trig.clone();
            partner[i].1 = true;
            let pkey = (poly.clone(), partner);
            let Some(b) = real.get(&pkey).filter(|_| !used.contains(&pkey)) else {
                continue;
            };
            if let Some((r, angle, sin)) = offset(a, b, &trig[i].0) {
                let mut t = trig.clone();
                t[i] = (angle, sin, 1);
                folded = Some((pkey, (poly.clone(), t), r));
                break;
            }
        }
        match folded {
            Some((pkey, k, r)) => {
                used.insert(pkey);
                let sum = match out.get(&k) {
                    Some(o) => o.add(&r),
                    None => r,
                };
                out.insert(k, sum);
            }
            None => {
                let sum = out.get(key).map_or_else(|| a.clone(), |o| o.add(a));
                out.insert(key.clone(), sum);
            }
        }
    }
    let scale = largest(out.values());
    out.retain(|_, c| !negligible(c, scale));
    out
}

/// (r, K ± offset, whether a sine) with a cos K + b sin K = r·f(K ± offset).
fn offset(a: &Coef, b: &Coef, k: &[(Symbol, i32)]) -> Option<(Coef, Angle, bool)> {
    let (Coef::Exact { .. }, Coef::Exact { .. }) = (a, b) else {
        return None;
    };
    let (x, y) = (a.to_c64().0, b.to_c64().0);
    // a cos K + b sin K = r cos(K − φ), φ = atan2(b, a) in twelfths of π,
    // taken within ±π/2 (r may be negative)
    let mut phi = (y.atan2(x) / (std::f64::consts::PI / 12.0)).round() as i64;
    if phi > 6 {
        phi -= 12;
    } else if phi < -6 {
        phi += 12;
    }
    if phi == 0 || phi.abs() == 6 {
        return None;
    }
    // r = a / cos φ exactly, checked against b = r sin φ
    let (cos_phi, sin_phi) = match Coef::unit_root(super::coef::Rat::new(i128::from(phi), 12)?)? {
        Coef::Exact { re, im } => (Coef::real(re), Coef::real(im)),
        Coef::Approx { .. } => return None,
    };
    let r = a.mul(&cos_phi.inv()?);
    if r.mul(&sin_phi) != *b {
        return None;
    }
    // or r sin(K + ψ), ψ = π/2 − φ (−r sin(K + ψ − π) past π/2): the
    // smaller offset, the positive one on a tie
    let (psi, flip) = if 6 - phi > 6 {
        (6 - phi - 12, true)
    } else {
        (6 - phi, false)
    };
    let as_sin = (true, psi, if flip { r.neg() } else { r.clone() });
    let as_cos = (false, -phi, r);
    if k.iter().any(|(s, _)| s.phase() == Some(Unit::Pi)) {
        // with a π-phase, the simplest total offset (denominator, then
        // numerator), then a positive factor: −cos(t − 2π/5), not
        // −sin(t + π/10), for cos(t + 3π/5)
        let turned = |(sin, off, r): &(bool, i64, Coef)| (*sin, off + 12, r.neg());
        let options = [turned(&as_sin), turned(&as_cos), as_sin, as_cos];
        let key = |(_, off, r): &(bool, i64, Coef)| {
            let (q, p, neg) = plainness(&with_offset(k, *off));
            (q, p, r.to_c64().0 < 0.0, neg)
        };
        let (sin, off, r) = options.into_iter().min_by_key(key)?;
        return Some((r, with_offset(k, off), sin));
    }
    let (sin, off, r) = if psi.abs() < phi.abs() || (psi.abs() == phi.abs() && psi > 0) {
        as_sin
    } else {
        as_cos
    };
    Some((r, with_offset(k, off), sin))
}

/// How plain an angle's π-offset p/q·π reads: (q, |p|, negative).
fn plainness(k: &[(Symbol, i32)]) -> (i64, i64, bool) {
    let e = k
        .iter()
        .find(|(s, _)| s.phase() == Some(Unit::Pi))
        .map_or(0, |(_, e)| i64::from(*e));
    let g = gcd(e.abs(), PI_DEN).max(1);
    (PI_DEN / g, e.abs() / g, e < 0)
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 { a } else { gcd(b, a % b) }
}

/// The angle K + off·π/12, the offset added to K's π-phase (`t + π/5`, not
/// `t + π/30 + π/6`), or one of its own.
fn with_offset(k: &[(Symbol, i32)], off: i64) -> Angle {
    let pi = Unit::Pi.symbol();
    let units = off * (PI_DEN / 12);
    let mut angle: Angle = k.iter().filter(|(s, _)| *s != pi).cloned().collect();
    let old = k
        .iter()
        .find(|(s, _)| *s == pi)
        .map_or(0, |(_, e)| i64::from(*e));
    // within (−π, π]
    let mut sum = (old + units).rem_euclid(2 * PI_DEN);
    if sum > PI_DEN {
        sum -= 2 * PI_DEN;
    }
    if sum != 0 {
        // |sum| ≤ PI_DEN fits; the π-phase sorts before the radian one
        let at = angle
            .iter()
            .position(|(s, _)| s.phase() == Some(Unit::Rad))
            .unwrap_or(angle.len());
        angle.insert(at, (pi, sum as i32));
    }
    angle
}
