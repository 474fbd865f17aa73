//! Closed forms of the inverse maps of a symbolic rotation or transform
//! (LANGUAGE.md §7, §8): atan2(k sin θ, k cos θ) = θ, the logarithm of
//! Rot(ω̂, θ) (3.51 read backwards, §3.2.3.3), the logarithm of a transform
//! (§3.3.3.2, with G⁻¹(θ) of 3.94) and the Euler angles of Appendix B. Each
//! holds on one branch only — k > 0, θ ∈ (−π, π) — and returns the
//! assumption with the value, so that the caller can say which branch was
//! taken. Where no such form is found, the caller keeps its general form.

use super::coef::Coef;
use super::expr::{Expr, Symbol, Var};
use super::matrix::{Mat, skew, unskew};
use num_traits::{One, Zero};

/// A closed form on a branch: the value, and the expressions assumed
/// positive (`cos(b)` for the ZYX angles) and the angles assumed in
/// (−π, π).
#[derive(Debug, Clone, Default)]
pub struct Branch {
    /// Expressions assumed > 0 on this branch (`cos(b)` for ZYX angles).
    pub positive: Vec<Expr>,
    /// Angles assumed in (−π, π), the range where the closed form (a
    /// matrix log's θ, §3.2.3.3; a ZYX angle) gives back the angle itself.
    pub angles: Vec<Expr>,
}

impl Branch {
    fn assume_positive(&mut self, k: &Expr) {
        if k.as_const().is_none() && !self.positive.contains(k) {
            self.positive.push(k.clone());
        }
    }
    fn assume_angle(&mut self, a: &Expr) {
        if a.as_const().is_none() && !self.angles.contains(a) {
            self.angles.push(a.clone());
        }
    }
}

/// The integer combinations of angles worth trying as θ in k e^{iθ}: each
/// angle, and each combination that a monomial of `e` carries.
fn candidates(e: &Expr) -> Vec<Vec<(Symbol, i32)>> {
    let mut out: Vec<Vec<(Symbol, i32)>> = Vec::new();
    let mut push = |k: Vec<(Symbol, i32)>| {
        if !k.is_empty() && !out.contains(&k) {
            out.push(k);
        }
    };
    for m in e.terms.keys() {
        let zs: Vec<(Symbol, i32)> = m
            .iter()
            .filter_map(|(v, k)| match v {
                Var::Z(s) => Some((s.clone(), *k)),
                _ => None,
            })
            .collect();
        for z in &zs {
            push(vec![(z.0.clone(), 1)]);
        }
        push(zs);
    }
    out
}

fn angle_of(k: &[(Symbol, i32)]) -> Expr {
    k.iter().fold(Expr::zero(), |acc, (s, c)| {
        acc.add(&Expr::angle(s).scale(&Coef::int(i64::from(*c))))
    })
}

/// θ and k with y = k sin θ and x = k cos θ, so that atan2(y, x) = θ
/// where k > 0 and θ ∈ (−π, π]: x + i y = k e^{iθ}, θ a combination of
/// the angles plus a multiple of π/2, k real (the simplest found).
pub fn atan2_angle(y: &Expr, x: &Expr) -> Option<(Expr, Expr)> {
    let w = x.add(&y.scale(&Coef::i()));
    if let (Some(a), Some(b)) = (y.as_f64(), x.as_f64()) {
        if a == 0.0 && b == 0.0 {
            return None;
        }
        return Some((Expr::num(a.atan2(b)), Expr::num(a.hypot(b))));
    }
    let mut best: Option<(Expr, Expr)> = None;
    // θ = 0 first: atan2(0, cos b) = 0 and atan2(cos b, 0) = π/2 for cos b > 0
    let mut tries = vec![Vec::new()];
    tries.extend(candidates(&w));
    for k in tries {
        let theta = angle_of(&k);
        let Some(turn) = Expr::expi(&theta.neg()) else {
            continue;
        };
        let r = w.mul(&turn);
        // r = k e^{iφ} with k real: φ a multiple of π/2
        for n in 0..4i64 {
            let phase = Coef::unit_root(super::coef::Rat::new(i128::from(n), 2)?)?;
            let k = r.scale(&phase.conj());
            // k as printed leads with a positive term (cos b, sin b, L1)
            let lead_positive = super::trig::real_form(&k)
                .values()
                .next()
                .is_some_and(|c| c.to_c64().0 > 0.0);
            if k.is_zero() || k.conj() != k || !lead_positive || has_angle(&k, &theta) {
                continue;
            }
            let phi = Expr::pi().scale(&Coef::rat(super::coef::Rat::new(i128::from(n), 2)?));
            let phi = if n == 3 {
                phi.sub(&Expr::pi().scale(&Coef::int(2)))
            } else {
                phi
            };
            let theta = theta.add(&phi);
            if best
                .as_ref()
                .is_none_or(|(_, b)| k.terms.len() < b.terms.len())
            {
                best = Some((theta, k));
            }
        }
    }
    best
}

/// True when k still depends on an angle of θ (then θ is not its angle).
fn has_angle(k: &Expr, theta: &Expr) -> bool {
    let mut ts = Vec::new();
    theta.symbols(&mut ts);
    k.terms
        .keys()
        .flatten()
        .any(|(v, _)| matches!(v, Var::Z(s) if ts.contains(s)))
}

/// The unit axis ω̂ and angle θ of R = Rot(ω̂, θ) = e^{[ω̂]θ} (3.51) with a
/// numeric ω̂: cos θ = (tr R − 1)/2 and ω̂ sin θ the vector of (R − Rᵀ)/2.
/// Its log is [ω̂]θ for θ ∈ (−π, π) (the book's θ ∈ [0, π] with −ω̂ for
/// negative θ gives the same matrix).
pub fn axis_angle(r: &Mat) -> Option<(Vec<Expr>, Expr)> {
    if (r.rows, r.cols) != (3, 3) {
        return None;
    }
    let half = Coef::rat(super::coef::Rat::new(1, 2)?);
    let c = r.trace().sub(&Expr::one()).scale(&half);
    let u: Vec<Expr> = unskew(&r.add(&r.transpose(), true)?)
        .iter()
        .map(|e| e.scale(&half))
        .collect();
    for k in candidates(&c) {
        let theta = angle_of(&k);
        let Some(e) = Expr::expi(&theta) else {
            continue;
        };
        // c = (e^{iθ'} + e^{−iθ'})/2 with θ' = θ + φ: the coefficient of e
        let Some(coef) = e.terms.keys().next().and_then(|m| c.terms.get(m)) else {
            continue;
        };
        let coef = coef.mul(&Coef::int(2));
        let (re, im) = coef.to_c64();
        let theta = match Expr::num(im.atan2(re)) {
            phi if phi.is_zero() => theta,
            phi => theta.add(&phi),
        };
        if Expr::cos(&theta) != c {
            continue;
        }
        let s = Expr::sin(&theta);
        // a numeric axis, or the unit components of a `given` one
        let axis: Option<Vec<Expr>> = u
            .iter()
            .map(|x| {
                x.div_exact(&s)
                    .filter(|q| q.as_const().is_some() || unit_part(q, &theta))
            })
            .collect();
        let Some(axis) = axis else { continue };
        let n2 = axis.iter().fold(Expr::zero(), |acc, a| acc.add(&a.mul(a)));
        if n2 == Expr::one() && Expr::cos(&theta).sub(&c).is_zero() {
            return Some((axis, theta));
        }
    }
    None
}

/// True for an expression in the unit components of `given` axes only,
/// free of θ (no angle, no other symbol).
fn unit_part(q: &Expr, theta: &Expr) -> bool {
    let mut syms = Vec::new();
    q.symbols(&mut syms);
    !syms.is_empty()
        && syms.iter().all(|s| s.unit)
        && !has_angle(q, theta)
        && q.terms
            .keys()
            .flatten()
            .all(|(v, _)| matches!(v, Var::Sym(_)))
}

/// log R = [ω̂]θ for R = Rot(ω̂, θ), θ assumed in (−π, π).
pub fn log3(r: &Mat) -> Option<(Mat, Branch)> {
    let (axis, theta) = axis_angle(r)?;
    let mut b = Branch::default();
    b.assume_angle(&theta);
    let w: Vec<Expr> = axis.iter().map(|a| a.mul(&theta)).collect();
    Some((skew(&w), b))
}

/// log T = \[S\]θ for T = \[R, p; 0, 1\] (§3.3.3.2): for R = I, \[0, p; 0, 0\]
/// (case (i), no branch); for R = Rot(ω̂, θ) with a numeric ω̂ (case
/// (iii)), \[ω̂\]θ and vθ = θ G⁻¹(θ) p = p − (θ/2)\[ω̂\]p + (1 − (θ/2)
/// cot(θ/2))\[ω̂\]²p (3.94), cot(θ/2) = sin θ/(1 − cos θ), checked
/// exactly by G(θ)(vθ) = θ p (3.93). θ is assumed in (−π, π), and
/// 1 − cos θ > 0 where a quotient by it is left.
pub fn log6(t: &Mat) -> Option<(Mat, Branch)> {
    let mut last = Mat::zeros(1, 4);
    last.set(0, 3, Expr::one());
    if (t.rows, t.cols) != (4, 4) || t.block(3..4, 0..4) != last {
        return None;
    }
    let (r, p) = (t.block(0..3, 0..3), t.block(0..3, 3..4));
    let mut out = Mat::zeros(4, 4);
    if r == Mat::identity(3) {
        out.put(0, 3, &p);
        return Some((out, Branch::default()));
    }
    let (axis, theta) = axis_angle(&r)?;
    let w = skew(&axis);
    let (wp, w2p) = (w.mul(&p)?, w.mul(&w.mul(&p)?)?);
    let half = Coef::rat(super::coef::Rat::new(1, 2)?);
    let h = theta.scale(&half);
    let (s, c) = (Expr::sin(&theta), Expr::cos(&theta));
    let one_c = Expr::one().sub(&c);
    let cot_half = s.mul(&one_c.recip()?);
    let k = Expr::one().sub(&h.mul(&cot_half));
    let vt: Vec<Expr> = (0..3)
        .map(|i| {
            p.data[i]
                .sub(&h.mul(&wp.data[i]))
                .add(&k.mul(&w2p.data[i]))
                .cancel()
        })
        .collect();
    // G(θ)(vθ) = θ p, exactly
    let w2 = w.mul(&w)?;
    let mut g = Mat::identity(3).scale(&theta);
    for i in 0..9 {
        g.data[i] = g.data[i]
            .add(&w.data[i].mul(&one_c))
            .add(&w2.data[i].mul(&theta.sub(&s)));
    }
    let back = g.mul(&Mat::column(vt.clone()))?;
    if back
        .data
        .iter()
        .zip(&p.data)
        .any(|(b, x)| b.cancel() != x.mul(&theta))
    {
        return None;
    }
    let mut b = Branch::default();
    if vt.iter().any(Expr::has_recip) {
        b.assume_positive(&one_c);
    }
    b.assume_angle(&theta);
    out.put(
        0,
        0,
        &skew(&axis.iter().map(|a| a.mul(&theta)).collect::<Vec<_>>()),
    );
    out.put(0, 3, &Mat::column(vt));
    Some((out, b))
}

/// The unit quaternion (cos θ/2, ω̂ sin θ/2) of R = Rot(ω̂, θ) (Appendix
/// B), θ assumed in (−π, π) so that w ≥ 0.
pub fn quat(r: &Mat) -> Option<(Vec<Expr>, Branch)> {
    let (axis, theta) = axis_angle(r)?;
    let half = theta.scale(&Coef::rat(super::coef::Rat::new(1, 2)?));
    let s = Expr::sin(&half);
    let mut out = vec![Expr::cos(&half)];
    out.extend(axis.iter().map(|a| a.mul(&s)));
    let mut b = Branch::default();
    b.assume_angle(&theta);
    Some((out, b))
}

/// The Cayley parameters ω̂ tan(θ/2) of R = Rot(ω̂, θ), θ assumed in
/// (−π, π).
pub fn cayley(r: &Mat) -> Option<(Vec<Expr>, Branch)> {
    let (axis, theta) = axis_angle(r)?;
    let half = theta.scale(&Coef::rat(super::coef::Rat::new(1, 2)?));
    let t = Expr::apply(super::expr::Func::Tan, &half, f64::tan);
    let mut b = Branch::default();
    b.assume_angle(&theta);
    Some((axis.iter().map(|a| a.mul(&t)).collect(), b))
}

/// `e` with a lone `abs(f)` (times a constant) read as f where f is
/// assumed positive on the branch — or, when nothing is assumed yet, with
/// f > 0 assumed now (√(cos² b) = |cos b| = cos b for cos b > 0).
fn drop_abs(e: &Expr, br: &mut Branch) -> Expr {
    let Some((m, c)) = e.terms.iter().next() else {
        return e.clone();
    };
    let f = match (e.terms.len(), m.as_slice()) {
        (1, [(Var::Call(call), 1)]) if call.f == super::expr::Func::Abs => match &call.args[..] {
            [f] => f,
            _ => return e.clone(),
        },
        _ => return e.clone(),
    };
    if br.positive.is_empty() {
        br.assume_positive(f);
    }
    if br.positive.contains(f) {
        f.scale(c)
    } else {
        e.clone()
    }
}

/// atan2(y, x) on the branch `br`: θ when y = k sin θ and x = k cos θ with
/// k a positive constant or a factor assumed positive on the branch (or,
/// when nothing is assumed yet, assumed now), θ then assumed in (−π, π];
/// else the call itself (right on every branch).
fn reduce(y: &Expr, x: &Expr, br: &mut Branch) -> (Expr, bool) {
    let mut tried = br.clone();
    let (y2, x2) = (drop_abs(y, &mut tried), drop_abs(x, &mut tried));
    if let Some((theta, k)) = atan2_angle(&y2, &x2) {
        let known = k.as_const().is_some() || tried.positive.contains(&k);
        if known || tried.positive.is_empty() {
            tried.assume_positive(&k);
            tried.assume_angle(&theta);
            *br = tried;
            return (theta, true);
        }
    }
    (Expr::atan2(y, x), false)
}

/// atan2(y, x) of symbolic arguments where a closed form holds with no
/// assumption but the angle's range: y = k sin θ, x = k cos θ with k a
/// positive constant gives θ, assumed in (−π, π].
pub fn atan2(y: &Expr, x: &Expr) -> Option<(Expr, Branch)> {
    if y.as_f64().is_some() && x.as_f64().is_some() {
        return None;
    }
    let (theta, k) = atan2_angle(y, x)?;
    k.as_const()?;
    let mut b = Branch::default();
    b.assume_angle(&theta);
    Some((theta, b))
}

/// Euler angles (a, b, c) of R = Rot(i, a) Rot(j, b) Rot(i or k, c): for
/// ZYX (`zyx` true) a = atan2(r21, r11) and c = atan2(r32, r33) with the
/// common factor k = cos b, and b = atan2(−r31, k) where k = √(r32² +
/// r33²); for ZXZ a = atan2(r13, −r23) and c = atan2(r31, r32) with k =
/// sin b, and b = atan2(k, r33). Each atan2 whose arguments are k sin θ and
/// k cos θ is θ on the branch k > 0, θ ∈ (−π, π] (one factor assumed
/// positive, the others positive constants or the same); the others are
/// kept as atan2 calls, right on every branch. None at gimbal lock (k ≡ 0),
/// where numbers choose c = 0.
pub fn euler(r: &Mat, zyx: bool) -> Option<(Vec<Expr>, Branch)> {
    let g = |i: usize, j: usize| r.get(i, j).clone();
    let sq = |e: &Expr| e.mul(e);
    let mut br = Branch::default();
    let ((ya, xa), (yc, xc)) = if zyx {
        ((g(1, 0), g(0, 0)), (g(2, 1), g(2, 2)))
    } else {
        ((g(0, 2), g(1, 2).neg()), (g(2, 0), g(2, 1)))
    };
    if ya.is_zero() && xa.is_zero() {
        return None;
    }
    let (a, a_done) = reduce(&ya, &xa, &mut br);
    let (c, c_done) = reduce(&yc, &xc, &mut br);
    // k: the factor a or c was found with, else √(the sum of squares)
    let k = match (a_done || c_done, br.positive.first()) {
        (true, Some(k)) => k.clone(),
        (true, None) => {
            let (y, x) = if a_done { (&ya, &xa) } else { (&yc, &xc) };
            atan2_angle(y, x).map_or_else(|| Expr::sqrt(&sq(&ya).add(&sq(&xa))), |(_, k)| k)
        }
        _ => Expr::sqrt(&sq(&yc).add(&sq(&xc))),
    };
    let (b, _) = if zyx {
        reduce(&g(2, 0).neg(), &k, &mut br)
    } else {
        reduce(&k, &g(2, 2), &mut br)
    };
    // the angles assumed, in the order a, b, c
    let mut out = Branch {
        positive: br.positive.clone(),
        angles: Vec::new(),
    };
    for x in [&a, &b, &c] {
        if br.angles.contains(x) {
            out.assume_angle(x);
        }
    }
    Some((vec![a, b, c], out))
}

#[cfg(test)]
mod tests;
