//! The rest of the matrix and Lie builtins for the matrix differential
//! test ([`super`]): every builtin of `src/builtins/table_*.rs` that takes
//! or makes a matrix over symbols — logs (`log`, `MatrixLog3/6`, planar
//! `log`, with θ ∈ [0, π]), Euler/RPY angles, quaternions and Cayley
//! parameters (with their branch rules), `AxisAng3/6`, `TransToRp`, `ad`,
//! power invariance of twists and wrenches, `inv` of SO(3), SE(3) and
//! general matrices, exp of twists with any ω and of screw axes with
//! pitch, `so3ToVec/se3ToVec/vee`, `AngVel*`, `Twist*`, `screw_params`,
//! `quat_mul`, `rot_*`, `displacement`, projections and distances, `det`,
//! `norm`, `Normalize`, `diag`, `rad2deg`, `SE2`, exp of a general matrix.
//! Each has a reference computed here in forward mode ([`S`]); where the
//! reference is not trustworthy (a gimbal lock, θ near π, a branch cut of
//! an angle) the case is skipped (`None`).

use super::{AXES, M, Mx, S, T, b, frac, hat, padded, rodrigues, vec_src};
use crate::{At, By};
use proptest::prelude::*;
use std::f64::consts::PI;

impl S {
    /// f(x, y) from its value, gradient and a bound on its second
    /// derivatives.
    fn of2(x: S, y: S, v: f64, g: (f64, f64), h: f64) -> S {
        let d = g.0 * x.d + g.1 * y.d;
        S {
            v,
            e: v.abs() + g.0.abs() * x.e + g.1.abs() * y.e,
            d,
            ed: g.0.abs() * x.ed
                + g.1.abs() * y.ed
                + h * (x.e + y.e) * (x.d.abs() + y.d.abs())
                + 2.0 * d.abs(),
        }
    }
    pub(super) fn div(self, o: S) -> S {
        let v = self.v / o.v;
        let h = 2.0 * (1.0 + v.abs()) / (o.v * o.v);
        S::of2(self, o, v, (1.0 / o.v, -v / o.v), h)
    }
    fn sqrt(self) -> S {
        let r = self.v.sqrt();
        self.map((r, 0.5 / r, -0.25 / (r * self.v)))
    }
    fn atan2(y: S, x: S) -> S {
        let r2 = x.v * x.v + y.v * y.v;
        S::of2(
            y,
            x,
            y.v.atan2(x.v),
            (x.v / r2, -y.v / r2),
            2.0 / r2.powf(1.5),
        )
    }
}

impl Mx {
    fn sub(&self, o: &Mx) -> Mx {
        self.add(&o.scale(S::num(-1.0)))
    }
    /// ω of a 3×3 [ω] (its skew part's entries as they are).
    fn vee(&self) -> Mx {
        col(vec![self.at(2, 1), self.at(0, 2), self.at(1, 0)])
    }
    fn dot(&self, o: &Mx) -> S {
        self.t().mul(o).x[0]
    }
    fn norm(&self) -> S {
        let mut s = S::num(0.0);
        for x in &self.x {
            s = s.add(x.mul(*x));
        }
        s.sqrt()
    }
    fn trace(&self) -> S {
        let mut s = self.at(0, 0);
        for i in 1..self.r {
            s = s.add(self.at(i, i));
        }
        s
    }
    fn det(&self) -> S {
        let g = |i, j| self.at(i, j);
        match self.r {
            2 => g(0, 0).mul(g(1, 1)).sub(g(0, 1).mul(g(1, 0))),
            _ => {
                let c = |i: usize, j: usize| self.cofactor(i, j);
                g(0, 0)
                    .mul(c(0, 0))
                    .add(g(0, 1).mul(c(0, 1)))
                    .add(g(0, 2).mul(c(0, 2)))
            }
        }
    }
    /// The (i, j) cofactor of a 3×3.
    fn cofactor(&self, i: usize, j: usize) -> S {
        let (r, c) = (
            [(i + 1) % 3, (i + 2) % 3].map(|k| k.min(2)),
            [(j + 1) % 3, (j + 2) % 3],
        );
        self.at(r[0], c[0])
            .mul(self.at(r[1], c[1]))
            .sub(self.at(r[0], c[1]).mul(self.at(r[1], c[0])))
    }
    /// The inverse of a 2×2 or 3×3 by its adjugate.
    fn inverse(&self) -> Mx {
        let d = self.det();
        let n = self.r;
        let mut x = Vec::new();
        for i in 0..n {
            for j in 0..n {
                let c = if n == 2 {
                    let s = if (i + j) % 2 == 0 { 1.0 } else { -1.0 };
                    self.at(1 - j, 1 - i).mul(S::num(s))
                } else {
                    self.cofactor(j, i)
                };
                x.push(c.div(d));
            }
        }
        Mx { r: n, c: n, x }
    }
    fn rows(r: usize, c: usize, x: Vec<S>) -> Mx {
        Mx { r, c, x }
    }
    fn stack(parts: &[&Mx]) -> Mx {
        col(parts.iter().flat_map(|m| m.x.clone()).collect())
    }
}

fn col(x: Vec<S>) -> Mx {
    Mx {
        r: x.len(),
        c: 1,
        x,
    }
}

fn n(x: f64) -> S {
    S::num(x)
}

/// [V] of a 6-vector: [[ω], v; 0, 0].
fn hat6(v: &Mx) -> Mx {
    let w = hat(&col(v.x[..3].to_vec()));
    let mut x = Vec::new();
    for i in 0..3 {
        x.extend_from_slice(&w.x[i * 3..i * 3 + 3]);
        x.push(v.x[3 + i]);
    }
    x.extend([n(0.0); 4]);
    Mx::rows(4, 4, x)
}

/// exp of the exponential coordinates (ω θ, v θ) (Prop. 3.16, any ω).
fn exp6(w: &Mx, v: &Mx) -> Mx {
    let th = w.norm();
    if th.v < 1e-300 {
        return Mx::rp(&Mx::eye(3), v);
    }
    let (wh, vh) = (w.scale(n(1.0).div(th)), v.scale(n(1.0).div(th)));
    let h = hat(&wh);
    let g = Mx::eye(3)
        .scale(th)
        .add(&h.scale(n(1.0).sub(th.cos())))
        .add(&h.mul(&h).scale(th.sub(th.sin())));
    Mx::rp(&rodrigues(&wh, th), &g.mul(&vh))
}

/// exp of a 3-vector of exponential coordinates.
fn exp3(w: &Mx) -> Mx {
    let th = w.norm();
    if th.v < 1e-300 {
        return Mx::eye(3);
    }
    rodrigues(&w.scale(n(1.0).div(th)), th)
}

/// exp of a general square matrix: scaling and squaring of its Taylor
/// series.
fn expm(a: &Mx) -> Mx {
    let big = a.x.iter().fold(0.0f64, |m, s| m.max(s.v.abs())) * a.r as f64;
    let k = if big > 0.25 {
        (big / 0.25).log2().ceil() as i32
    } else {
        0
    };
    let a = a.scale(n(0.5f64.powi(k)));
    let (mut sum, mut term) = (Mx::eye(a.r), Mx::eye(a.r));
    for j in 1..20 {
        term = term.mul(&a).scale(n(1.0 / j as f64));
        sum = sum.add(&term);
    }
    for _ in 0..k {
        sum = sum.mul(&sum);
    }
    sum
}

/// log of a rotation: (ω̂θ, θ), θ ∈ [0, π]; None near π (the reference
/// is ill-conditioned there).
fn log3(r: &Mx) -> Option<(Mx, S)> {
    let w2 = r.sub(&r.t()).vee();
    let s = w2.norm().mul(n(0.5));
    let c = r.trace().sub(n(1.0)).mul(n(0.5));
    let th = S::atan2(s, c);
    if th.v > PI - 1e-2 {
        return None;
    }
    if s.v < 1e-150 {
        return Some((col(vec![n(0.0); 3]), n(0.0)));
    }
    Some((w2.scale(th.div(s).mul(n(0.5))), th))
}

/// log of a transform as its 6 exponential coordinates.
fn log6(t: &Mx) -> Option<Mx> {
    let (w, th) = log3(&t.block(0, 0, 3, 3))?;
    let p = t.block(0, 3, 3, 1);
    // vθ = p − [W]p/2 + k(θ)[W]²p, k = (1 − (θ/2) cot(θ/2))/θ²
    let k = if th.v < 1e-3 {
        n(1.0 / 12.0).add(th.mul(th).mul(n(1.0 / 720.0)))
    } else {
        let h = th.mul(n(0.5));
        let cot = h.cos().div(h.sin());
        n(1.0).sub(h.mul(cot)).div(th.mul(th))
    };
    let wh = hat(&w);
    let v = p
        .sub(&wh.mul(&p).scale(n(0.5)))
        .add(&wh.mul(&wh).mul(&p).scale(k));
    Some(Mx::stack(&[&w, &v]))
}

/// An angle in (−π, π] that is no branch-cut case.
fn angle(a: S) -> Option<S> {
    (a.v.abs() < PI - 1e-6).then_some(a)
}

/// The ZYX angles (a, b, c) with b ∈ [−π/2, π/2]; None near gimbal lock.
fn zyx(r: &Mx) -> Option<[S; 3]> {
    let g = |i, j| r.at(i, j);
    let cb = g(0, 0).mul(g(0, 0)).add(g(1, 0).mul(g(1, 0))).sqrt();
    if cb.v < 1e-3 {
        return None;
    }
    Some([
        angle(S::atan2(g(1, 0), g(0, 0)))?,
        S::atan2(g(2, 0).neg(), cb),
        angle(S::atan2(g(2, 1), g(2, 2)))?,
    ])
}

/// The ZXZ angles with b ∈ [0, π]; None near gimbal lock.
fn zxz(r: &Mx) -> Option<[S; 3]> {
    let g = |i, j| r.at(i, j);
    let sb = g(0, 2).mul(g(0, 2)).add(g(1, 2).mul(g(1, 2))).sqrt();
    if sb.v < 1e-3 {
        return None;
    }
    Some([
        angle(S::atan2(g(0, 2), g(1, 2).neg()))?,
        S::atan2(sb, g(2, 2)),
        angle(S::atan2(g(2, 0), g(2, 1)))?,
    ])
}

/// The unit quaternion with w ≥ 0; None near θ = π.
fn quat(r: &Mx) -> Option<Mx> {
    let t = n(1.0).add(r.trace());
    if t.v < 0.05 {
        return None;
    }
    let w = t.sqrt().mul(n(0.5));
    let k = n(1.0).div(w.mul(n(4.0)));
    let d = |i, j| r.at(i, j).sub(r.at(j, i)).mul(k);
    Some(col(vec![w, d(2, 1), d(0, 2), d(1, 0)]))
}

fn quat_mul(q: &Mx, p: &Mx) -> Mx {
    let (qv, pv) = (col(q.x[1..].to_vec()), col(p.x[1..].to_vec()));
    let w = q.x[0].mul(p.x[0]).sub(qv.dot(&pv));
    let v = pv
        .scale(q.x[0])
        .add(&qv.scale(p.x[0]))
        .add(&hat(&qv).mul(&pv));
    Mx::stack(&[&col(vec![w]), &v])
}

/// Ad(T), 6×6.
pub(super) fn adjoint(m: &Mx) -> Mx {
    let rot = m.block(0, 0, 3, 3);
    let pr = hat(&m.block(0, 3, 3, 1)).mul(&rot);
    let z = n(0.0);
    let mut out = Vec::new();
    for i in 0..6 {
        for j in 0..6 {
            out.push(match (i < 3, j < 3) {
                (true, true) => rot.at(i, j),
                (true, false) => z,
                (false, true) => pr.at(i - 3, j),
                (false, false) => rot.at(i - 3, j - 3),
            });
        }
    }
    Mx::rows(6, 6, out)
}

/// ad(V), 6×6: [[ω], 0; [v], [ω]].
fn ad(v: &Mx) -> Mx {
    let (w, l) = (hat(&col(v.x[..3].to_vec())), hat(&col(v.x[3..].to_vec())));
    let mut out = Vec::new();
    for i in 0..6 {
        for j in 0..6 {
            out.push(match (i < 3, j < 3) {
                (true, true) => w.at(i, j),
                (true, false) => n(0.0),
                (false, true) => l.at(i - 3, j),
                (false, false) => w.at(i - 3, j - 3),
            });
        }
    }
    Mx::rows(6, 6, out)
}

fn ints(v: &[i8]) -> Mx {
    Mx::of(
        v.len(),
        1,
        &v.iter().map(|x| f64::from(*x)).collect::<Vec<_>>(),
    )
}

fn six(w: [i8; 3], v: [i8; 3]) -> String {
    format!(
        "({}, {}, {}, {}, {}, {})",
        w[0], w[1], w[2], v[0], v[1], v[2]
    )
}

fn dec_s(d: (i64, u32)) -> (f64, String) {
    (super::super::dec(d.0, d.1), super::super::dec_src(d.0, d.1))
}

/// More matrices: leaves and operations beyond [`M`]'s.
#[derive(Debug, Clone)]
pub enum G {
    /// `exp([(ω, v)] * s)` (0), `MatrixExp6((ω, v) * s)` (1),
    /// `MatrixExp6(VecTose3((ω, v)) * s)` (2): any integer ω, 0 too.
    ExpV([i8; 3], [i8; 3], T, u8),
    /// `exp([ω] * s)`, `MatrixExp3(ω * s)`, `MatrixExp3(VecToso3(ω) * s)`.
    ExpW3([i8; 3], T, u8),
    /// `exp([ScrewToAxis(q, ŝ, h)] * θ)` (or `screw(…)`): pitch h.
    Screw([i8; 3], usize, (i64, u32), T, bool),
    /// `rot_zyx`, `rot_zxz`, `rot_rpy` of three scalars.
    RotE(u8, T, T, T),
    /// `rot_quat((s, k1, k2, k3))` (normalized by rot_quat).
    RotQ(T, [i8; 3]),
    /// `rot_cayley(s * (k1, k2, k3))`.
    RotC(T, [i8; 3]),
    /// `displacement(T_sb, T_sc)` = T_sc T_sb⁻¹.
    Disp(Box<M>, Box<M>),
    /// `RotInv(R)` / `TransInv(T)`.
    InvB(Box<M>),
    /// `SO3(R)` / `SE3`-less retag: the same matrix.
    Tag(Box<M>),
    /// A general n×n matrix literal of scalars.
    Gen(usize, Vec<T>),
    /// `inv` of a general matrix.
    Inverse(Box<M>),
    /// `exp(A * s)` for an integer n×n A.
    ExpA(usize, Vec<i8>, T),
    /// `SE2(s, x, y)`.
    Se2(T, [i8; 2]),
    /// `ProjectToSO3(c * R)` / `ProjectToSE3` of a scaled rotation block.
    Proj(Box<M>, (i64, u32)),
    /// `rad2deg(X)`.
    Deg(Box<M>),
}

impl G {
    pub(super) fn size(&self) -> usize {
        match self {
            G::ExpV(..) | G::Screw(..) | G::Disp(..) => 4,
            G::ExpW3(..) | G::RotE(..) | G::RotQ(..) | G::RotC(..) | G::Se2(..) => 3,
            G::InvB(x) | G::Tag(x) | G::Inverse(x) | G::Proj(x, _) | G::Deg(x) => x.size(),
            G::Gen(k, _) | G::ExpA(k, ..) => *k,
        }
    }

    pub(super) fn source(&self) -> String {
        match self {
            G::ExpV(w, v, s, f) => match f {
                0 => format!("exp([{}] * {})", six(*w, *v), s.source()),
                1 => format!("MatrixExp6({} * {})", six(*w, *v), s.source()),
                _ => format!("MatrixExp6(VecTose3({}) * {})", six(*w, *v), s.source()),
            },
            G::ExpW3(w, s, f) => match f {
                0 => format!("exp([{}] * {})", vec_src(*w), s.source()),
                1 => format!("MatrixExp3({} * {})", vec_src(*w), s.source()),
                _ => format!("MatrixExp3(VecToso3({}) * {})", vec_src(*w), s.source()),
            },
            G::Screw(q, k, h, s, named) => {
                let w = AXES[*k].0;
                format!(
                    "exp([{}({}, ({}, {}, {}), {})] * {})",
                    if *named { "ScrewToAxis" } else { "screw" },
                    vec_src(*q),
                    frac(w[0]),
                    frac(w[1]),
                    frac(w[2]),
                    dec_s(*h).1,
                    s.source()
                )
            }
            G::RotE(k, x, y, z) => format!(
                "{}({}, {}, {})",
                ["rot_zyx", "rot_zxz", "rot_rpy"][*k as usize],
                x.source(),
                y.source(),
                z.source()
            ),
            G::RotQ(s, k) => format!("rot_quat(({}, {}, {}, {}))", s.source(), k[0], k[1], k[2]),
            G::RotC(s, k) => format!("rot_cayley({} * {})", s.source(), vec_src(*k)),
            G::Disp(x, y) => format!("displacement({}, {})", x.source(), y.source()),
            G::InvB(x) => format!(
                "{}({})",
                if x.size() == 3 { "RotInv" } else { "TransInv" },
                x.source()
            ),
            G::Tag(x) => format!("SO3({})", x.source()),
            G::Gen(k, es) => {
                let rows: Vec<String> = es
                    .chunks(*k)
                    .map(|r| r.iter().map(T::source).collect::<Vec<_>>().join(", "))
                    .collect();
                format!("[{}]", rows.join("; "))
            }
            G::Inverse(x) => format!("inv({})", x.source()),
            G::ExpA(k, a, s) => {
                let rows: Vec<String> = a
                    .chunks(*k)
                    .map(|r| {
                        r.iter()
                            .map(|x| x.to_string())
                            .collect::<Vec<_>>()
                            .join(", ")
                    })
                    .collect();
                format!("exp([{}] * {})", rows.join("; "), s.source())
            }
            G::Se2(s, p) => format!("SE2({}, {}, {})", s.source(), p[0], p[1]),
            G::Proj(x, c) => format!(
                "{}({} * {})",
                if x.size() == 3 {
                    "ProjectToSO3"
                } else {
                    "ProjectToSE3"
                },
                dec_s(*c).1,
                x.source()
            ),
            G::Deg(x) => format!("rad2deg({})", x.source()),
        }
    }

    pub(super) fn eval(&self, at: &At, by: By) -> Mx {
        let s = |t: &T| {
            let (v, e, d, ed) = t.dual(at, by);
            S { v, e, d, ed }
        };
        match self {
            G::ExpV(w, v, t, _) => {
                let th = s(t);
                exp6(&ints(w).scale(th), &ints(v).scale(th))
            }
            G::ExpW3(w, t, _) => exp3(&ints(w).scale(s(t))),
            G::Screw(q, k, h, t, _) => {
                let sh = Mx::of(3, 1, &AXES[*k].0);
                let v = hat(&ints(q)).mul(&sh).add(&sh.scale(n(dec_s(*h).0)));
                let th = s(t);
                exp6(&sh.scale(th), &v.scale(th))
            }
            G::RotE(k, x, y, z) => {
                let r = |axis: u8, t: S| {
                    let (c, sn, o, z) = (t.cos(), t.sin(), n(1.0), n(0.0));
                    let x = match axis {
                        0 => vec![o, z, z, z, c, sn.neg(), z, sn, c],
                        1 => vec![c, z, sn, z, o, z, sn.neg(), z, c],
                        _ => vec![c, sn.neg(), z, sn, c, z, z, z, o],
                    };
                    Mx::rows(3, 3, x)
                };
                let (a, bb, c) = (s(x), s(y), s(z));
                match k {
                    0 => r(2, a).mul(&r(1, bb)).mul(&r(0, c)),
                    1 => r(2, a).mul(&r(0, bb)).mul(&r(2, c)),
                    _ => r(2, c).mul(&r(1, bb)).mul(&r(0, a)),
                }
            }
            G::RotQ(t, k) => {
                let q = Mx::stack(&[&col(vec![s(t)]), &ints(k)]);
                let q = q.scale(n(1.0).div(q.norm()));
                let vm = hat(&col(q.x[1..].to_vec()));
                Mx::eye(3)
                    .add(&vm.scale(q.x[0].mul(n(2.0))))
                    .add(&vm.mul(&vm).scale(n(2.0)))
            }
            G::RotC(t, k) => {
                let r = ints(k).scale(s(t));
                let rm = hat(&r);
                let c = n(2.0).div(n(1.0).add(r.dot(&r)));
                Mx::eye(3).add(&rm.add(&rm.mul(&rm)).scale(c))
            }
            G::Disp(x, y) => y.eval(at, by).mul(&inv_group(&x.eval(at, by))),
            G::InvB(x) => inv_group(&x.eval(at, by)),
            G::Tag(x) => x.eval(at, by),
            G::Proj(x, c) => {
                // (ProjectToSE3 keeps the position as it is: c p)
                let m = x.eval(at, by);
                if m.r == 4 {
                    Mx::rp(
                        &m.block(0, 0, 3, 3),
                        &m.block(0, 3, 3, 1).scale(n(dec_s(*c).0)),
                    )
                } else {
                    m
                }
            }
            G::Gen(k, es) => Mx::rows(*k, *k, es.iter().map(s).collect()),
            G::Inverse(x) => x.eval(at, by).inverse(),
            G::ExpA(k, a, t) => expm(
                &Mx::of(*k, *k, &a.iter().map(|x| f64::from(*x)).collect::<Vec<_>>()).scale(s(t)),
            ),
            G::Se2(t, p) => {
                let th = s(t);
                let (c, sn, z, o) = (th.cos(), th.sin(), n(0.0), n(1.0));
                let (x, y) = (n(f64::from(p[0])), n(f64::from(p[1])));
                Mx::rows(3, 3, vec![c, sn.neg(), x, sn, c, y, z, z, o])
            }
            G::Deg(x) => x.eval(at, by).scale(n(180.0 / PI)),
        }
    }

    pub(super) fn scalars(&self) -> Vec<&T> {
        match self {
            G::ExpV(_, _, t, _)
            | G::ExpW3(_, t, _)
            | G::Screw(_, _, _, t, _)
            | G::RotQ(t, _)
            | G::RotC(t, _)
            | G::ExpA(_, _, t)
            | G::Se2(t, _) => vec![t],
            G::RotE(_, x, y, z) => vec![x, y, z],
            G::Disp(x, y) => [x.scalars(), y.scalars()].concat(),
            G::InvB(x) | G::Tag(x) | G::Inverse(x) | G::Proj(x, _) | G::Deg(x) => x.scalars(),
            G::Gen(_, es) => es.iter().collect(),
        }
    }
}

/// The inverse of a rotation (Rᵀ) or transform (3.64).
pub(super) fn inv_group(m: &Mx) -> Mx {
    if m.r == 3 {
        m.t()
    } else {
        let rt = m.block(0, 0, 3, 3).t();
        let p = rt.mul(&m.block(0, 3, 3, 1)).scale(n(-1.0));
        Mx::rp(&rt, &p)
    }
}

/// Outputs beyond [`super::Out`]'s: maps out of the groups, and values
/// that are no matrices of the group (tuples, scalars, bools).
#[derive(Debug, Clone)]
pub enum L {
    /// `log(R)` (0), `MatrixLog3(R)` (1), `so3ToVec(log(R))` (2).
    Log3(M, u8),
    /// `log(T)`, `MatrixLog6(T)`, `se3ToVec(log(T))`.
    Log6(M, u8),
    /// `log` of an SE(2).
    Log2(M),
    /// `euler_zyx` (0), `euler_zxz`, `rpy`, `quat`, `cayley` (4).
    Angles(M, u8),
    /// `AxisAng3(s * (R * v))`.
    AxisAng3(M, [i8; 3], T),
    /// `AxisAng6(s * (Ad(T) * S))`, S a unit-ω screw axis.
    AxisAng6(M, usize, [i8; 3], T),
    TransToRp(M),
    /// `ad(Ad(T) * V)`.
    AdOf(M, [i8; 3]),
    /// `dot(transpose(Ad(inv(T))) * wrench(m, f), Ad(T) * twist(w, v))`,
    /// or (true) the same `~= dot(F, V)`.
    Power(M, [i8; 3], [i8; 3], bool),
    /// `quat_mul(quat(R1), quat(R2))`.
    QuatMul(M, M),
    /// `screw_params(Ad(T) * S)`.
    ScrewParams(M, usize, [i8; 3]),
    /// `AngVelSpace(R, diff(R, t))` (true) / `AngVelBody`.
    AngVel(M, bool),
    /// `TwistSpace(T, diff(T, t))` (true) / `TwistBody`.
    TwistOf(M, bool),
    /// `so3ToVec(diff(R, t) * transpose(R))`, `se3ToVec(diff(T, t) * inv(T))`.
    VeeDiff(M),
    Det(M),
    /// `norm(X)` (Frobenius).
    Norm(M),
    /// `norm(R * v)` (false), `Normalize(R * v)` (true).
    NormV(M, [i8; 3], bool),
    Diag(M),
    /// `DistanceToSO3(c * R)` / `DistanceToSE3`.
    Distance(M, (i64, u32)),
    /// `TestIfSO3(R)` / `TestIfSE3(T)`: true.
    TestIf(M),
    /// `vee([R * v])`.
    VeeHat(M, [i8; 3]),
}

/// A 6-vector of AXES[k] and v: (ω̂, v).
fn screw6(k: usize, v: [i8; 3]) -> (Mx, String) {
    let w = AXES[k].0;
    (
        Mx::stack(&[&Mx::of(3, 1, &w), &ints(&v)]),
        format!(
            "({}, {}, {}, {}, {}, {})",
            frac(w[0]),
            frac(w[1]),
            frac(w[2]),
            v[0],
            v[1],
            v[2]
        ),
    )
}

fn scalar_mx(s: S) -> Mx {
    col(vec![s])
}

impl L {
    pub(super) fn source(&self) -> String {
        match self {
            L::Log3(m, f) => match f {
                0 => format!("log({})", m.source()),
                1 => format!("MatrixLog3({})", m.source()),
                _ => format!("so3ToVec(log({}))", m.source()),
            },
            L::Log6(m, f) => match f {
                0 => format!("log({})", m.source()),
                1 => format!("MatrixLog6({})", m.source()),
                _ => format!("se3ToVec(log({}))", m.source()),
            },
            L::Log2(m) => format!("log({})", m.source()),
            L::Angles(m, k) => format!(
                "{}({})",
                ["euler_zyx", "euler_zxz", "rpy", "quat", "cayley"][*k as usize],
                m.source()
            ),
            L::AxisAng3(m, v, s) => {
                format!(
                    "AxisAng3({} * ({} * {}))",
                    s.source(),
                    m.source(),
                    vec_src(*v)
                )
            }
            L::AxisAng6(m, k, v, s) => format!(
                "AxisAng6({} * (Ad({}) * {}))",
                s.source(),
                m.source(),
                screw6(*k, *v).1
            ),
            L::TransToRp(m) => format!("TransToRp({})", m.source()),
            L::AdOf(m, v) => format!("ad(Ad({}) * {})", m.source(), padded(6, *v).1),
            L::Power(m, f, v, eq) => {
                let (ff, vv) = (
                    format!("wrench({}, {})", vec_src(*f), vec_src(*v)),
                    format!("twist({}, {})", vec_src(*v), vec_src(*f)),
                );
                let lhs = format!(
                    "dot(transpose(Ad(inv({m}))) * {ff}, Ad({m}) * {vv})",
                    m = m.source()
                );
                if *eq {
                    format!("({lhs} ~= dot({ff}, {vv}))")
                } else {
                    lhs
                }
            }
            L::QuatMul(x, y) => format!("quat_mul(quat({}), quat({}))", x.source(), y.source()),
            L::ScrewParams(m, k, v) => {
                format!("screw_params(Ad({}) * {})", m.source(), screw6(*k, *v).1)
            }
            L::AngVel(m, sp) => format!(
                "{}({m}, diff({m}, t))",
                if *sp { "AngVelSpace" } else { "AngVelBody" },
                m = m.source()
            ),
            L::TwistOf(m, sp) => format!(
                "{}({m}, diff({m}, t))",
                if *sp { "TwistSpace" } else { "TwistBody" },
                m = m.source()
            ),
            L::VeeDiff(m) => {
                if m.size() == 3 {
                    format!("so3ToVec(diff({m}, t) * transpose({m}))", m = m.source())
                } else {
                    format!("se3ToVec(diff({m}, t) * inv({m}))", m = m.source())
                }
            }
            L::Det(m) => format!("det({})", m.source()),
            L::Norm(m) => format!("norm({})", m.source()),
            L::NormV(m, v, unit) => format!(
                "{}({} * {})",
                if *unit { "Normalize" } else { "norm" },
                m.source(),
                vec_src(*v)
            ),
            L::Diag(m) => format!("diag({})", m.source()),
            L::Distance(m, c) => format!(
                "{}({} * {})",
                if m.size() == 3 {
                    "DistanceToSO3"
                } else {
                    "DistanceToSE3"
                },
                dec_s(*c).1,
                m.source()
            ),
            L::TestIf(m) => format!(
                "{}({})",
                if m.size() == 3 {
                    "TestIfSO3"
                } else {
                    "TestIfSE3"
                },
                m.source()
            ),
            L::VeeHat(m, v) => format!("vee([{} * {}])", m.source(), vec_src(*v)),
        }
    }

    /// The reference, flattened (a tuple's parts one after the other);
    /// None where it is not trustworthy.
    pub(super) fn eval(&self, at: &At, by: By) -> Option<Mx> {
        let s = |t: &T| {
            let (v, e, d, ed) = t.dual(at, by);
            S { v, e, d, ed }
        };
        Some(match self {
            L::Log3(m, f) => {
                let (w, _) = log3(&m.eval(at, by))?;
                if *f == 0 { hat(&w) } else { w }
            }
            L::Log6(m, f) => {
                let v = log6(&m.eval(at, by))?;
                if *f == 0 { hat6(&v) } else { v }
            }
            L::Log2(m) => {
                let x = m.eval(at, by);
                let th = angle(S::atan2(x.at(1, 0), x.at(0, 0)))?;
                let p = col(vec![x.at(0, 2), x.at(1, 2)]);
                // v = G⁻¹ p, G = [sθ/θ, −(1−cθ)/θ; (1−cθ)/θ, sθ/θ]
                let v = if th.v.abs() < 1e-150 {
                    p
                } else {
                    let (a, c) = (th.sin().div(th), n(1.0).sub(th.cos()).div(th));
                    Mx::rows(2, 2, vec![a, c.neg(), c, a]).inverse().mul(&p)
                };
                let z = n(0.0);
                Mx::rows(3, 3, vec![z, th.neg(), v.x[0], th, z, v.x[1], z, z, z])
            }
            L::Angles(m, k) => {
                let r = m.eval(at, by);
                match k {
                    0 => col(zyx(&r)?.to_vec()),
                    1 => col(zxz(&r)?.to_vec()),
                    2 => {
                        let [a, bb, c] = zyx(&r)?;
                        col(vec![c, bb, a])
                    }
                    3 => quat(&r)?,
                    _ => {
                        let q = quat(&r)?;
                        col(q.x[1..].to_vec()).scale(n(1.0).div(q.x[0]))
                    }
                }
            }
            L::AxisAng3(m, v, t) => {
                let e = m.eval(at, by).mul(&ints(v)).scale(s(t));
                let th = e.norm();
                if th.v < 1e-3 {
                    return None;
                }
                Mx::stack(&[&e.scale(n(1.0).div(th)), &scalar_mx(th)])
            }
            L::AxisAng6(m, k, v, t) => {
                let e = adjoint(&m.eval(at, by)).mul(&screw6(*k, *v).0).scale(s(t));
                let th = col(e.x[..3].to_vec()).norm();
                if th.v < 1e-3 {
                    return None;
                }
                Mx::stack(&[&e.scale(n(1.0).div(th)), &scalar_mx(th)])
            }
            L::TransToRp(m) => {
                let x = m.eval(at, by);
                Mx::stack(&[&x.block(0, 0, 3, 3), &x.block(0, 3, 3, 1)])
            }
            L::AdOf(m, v) => ad(&adjoint(&m.eval(at, by)).mul(&padded(6, *v).0)),
            L::Power(m, f, v, eq) => {
                let ff = Mx::stack(&[&ints(f), &ints(v)]);
                let vv = Mx::stack(&[&ints(v), &ints(f)]);
                if *eq {
                    return Some(scalar_mx(n(1.0)));
                }
                let x = m.eval(at, by);
                let fa = adjoint(&inv_group(&x)).t().mul(&ff);
                scalar_mx(fa.dot(&adjoint(&x).mul(&vv)))
            }
            L::QuatMul(x, y) => quat_mul(&quat(&x.eval(at, by))?, &quat(&y.eval(at, by))?),
            L::ScrewParams(m, k, v) => {
                let e = adjoint(&m.eval(at, by)).mul(&screw6(*k, *v).0);
                let (w, l) = (col(e.x[..3].to_vec()), col(e.x[3..].to_vec()));
                let w2 = w.dot(&w);
                let q = hat(&w).mul(&l).scale(n(1.0).div(w2));
                let h = w.dot(&l).div(w2);
                Mx::stack(&[&q, &w.scale(n(1.0).div(w2.sqrt())), &scalar_mx(h)])
            }
            L::AngVel(m, space) | L::TwistOf(m, space) => {
                let (x, xd) = rates(m, at);
                let k = if x.r == 3 {
                    if *space {
                        xd.mul(&x.t())
                    } else {
                        x.t().mul(&xd)
                    }
                } else if *space {
                    xd.mul(&inv_group(&x))
                } else {
                    inv_group(&x).mul(&xd)
                };
                vee_any(&k)
            }
            L::VeeDiff(m) => {
                let (x, xd) = rates(m, at);
                if x.r == 3 {
                    vee_any(&xd.mul(&x.t()))
                } else {
                    vee_any(&xd.mul(&inv_group(&x)))
                }
            }
            L::Det(m) => scalar_mx(m.eval(at, by).det()),
            L::Norm(m) => scalar_mx(m.eval(at, by).norm()),
            L::NormV(m, v, unit) => {
                let x = m.eval(at, by).mul(&ints(v));
                let k = x.norm();
                if *unit {
                    x.scale(n(1.0).div(k))
                } else {
                    scalar_mx(k)
                }
            }
            L::Diag(m) => {
                let x = m.eval(at, by);
                col((0..x.r).map(|i| x.at(i, i)).collect())
            }
            L::Distance(m, c) => {
                // ‖RᵀR − I‖ of the block R of c X, and for a transform the
                // last row's difference from (0, 0, 0, 1) too
                let k = n(dec_s(*c).0);
                let x = m.eval(at, by).block(0, 0, 3, 3).scale(k);
                let mut d = x.t().mul(&x).sub(&Mx::eye(3));
                if m.size() == 4 {
                    d.x.push(k.sub(n(1.0)));
                }
                scalar_mx(d.norm())
            }
            L::TestIf(_) => scalar_mx(n(1.0)),
            L::VeeHat(m, v) => m.eval(at, by).mul(&ints(v)),
        })
    }

    pub(super) fn matrices(&self) -> Vec<&M> {
        match self {
            L::QuatMul(x, y) => vec![x, y],
            L::Log3(m, _)
            | L::Log6(m, _)
            | L::Log2(m)
            | L::Angles(m, _)
            | L::AxisAng3(m, ..)
            | L::AxisAng6(m, ..)
            | L::TransToRp(m)
            | L::AdOf(m, _)
            | L::Power(m, ..)
            | L::ScrewParams(m, ..)
            | L::AngVel(m, _)
            | L::TwistOf(m, _)
            | L::VeeDiff(m)
            | L::Det(m)
            | L::Norm(m)
            | L::NormV(m, ..)
            | L::Diag(m)
            | L::Distance(m, _)
            | L::TestIf(m)
            | L::VeeHat(m, _) => vec![m],
        }
    }

    /// A derivative by t inside (the reference has none of a derivative).
    pub(super) fn inner_diff(&self) -> bool {
        matches!(self, L::AngVel(..) | L::TwistOf(..) | L::VeeDiff(..))
    }

    /// A bool, compared as 1 (true) or 0.
    pub(super) fn is_bool(&self) -> bool {
        matches!(self, L::TestIf(_) | L::Power(.., true))
    }
}

/// X and Ẋ (by t) as matrices of the reference, Ẋ's entries with their
/// rounding bounds as values.
fn rates(m: &M, at: &At) -> (Mx, Mx) {
    let x = m.eval(at, By::Time);
    let val = Mx::rows(
        x.r,
        x.c,
        x.x.iter()
            .map(|s| S {
                d: 0.0,
                ed: 0.0,
                ..*s
            })
            .collect(),
    );
    let dot = Mx::rows(
        x.r,
        x.c,
        x.x.iter()
            .map(|s| S {
                v: s.d,
                e: s.ed,
                d: 0.0,
                ed: 0.0,
            })
            .collect(),
    );
    (val, dot)
}

/// ω of [ω] (3×3), (ω, v) of [V] (4×4).
fn vee_any(k: &Mx) -> Mx {
    if k.r == 3 {
        k.vee()
    } else {
        Mx::stack(&[&k.block(0, 0, 3, 3).vee(), &k.block(0, 3, 3, 1)])
    }
}

/// The leaves and operations of [`G`] as strategies: rotations,
/// transforms, general matrices and planar transforms.
pub fn more_rotations(scalar: BoxedStrategy<T>) -> BoxedStrategy<M> {
    let k3 = prop::array::uniform3(-2..3i8);
    prop_oneof![
        2 => (0..3u8, scalar.clone(), scalar.clone(), scalar.clone())
            .prop_map(|(k, x, y, z)| M::G(b(G::RotE(k, x, y, z)))),
        1 => (scalar.clone(), k3.clone()).prop_map(|(s, k)| M::G(b(G::RotQ(s, k)))),
        1 => (scalar.clone(), k3.clone()).prop_map(|(s, k)| M::G(b(G::RotC(s, k)))),
        2 => (k3, scalar, 0..3u8).prop_map(|(w, s, f)| M::G(b(G::ExpW3(w, s, f)))),
    ]
    .boxed()
}

pub fn more_transforms(scalar: BoxedStrategy<T>) -> BoxedStrategy<M> {
    let k3 = prop::array::uniform3(-2..3i8);
    let pitch = (-30..31i64, 0..2u32);
    prop_oneof![
        2 => (k3.clone(), k3.clone(), scalar.clone(), 0..3u8)
            .prop_map(|(w, v, s, f)| M::G(b(G::ExpV(w, v, s, f)))),
        2 => (k3, 0..6usize, pitch, scalar, any::<bool>())
            .prop_map(|(q, k, h, s, nm)| M::G(b(G::Screw(q, k, h, s, nm)))),
    ]
    .boxed()
}

/// General (not group) square matrices, 2×2 or 3×3.
pub fn general(scalar: BoxedStrategy<T>) -> BoxedStrategy<M> {
    let entry = prop_oneof![
        2 => (-3..4i64).prop_map(T::Int),
        1 => scalar.clone(),
    ];
    let gm = (2..4usize)
        .prop_flat_map(move |k| {
            prop::collection::vec(entry.clone(), k * k).prop_map(move |es| (k, es))
        })
        .prop_map(|(k, es)| M::G(b(G::Gen(k, es))));
    let expa = (2..4usize).prop_flat_map(move |k| {
        (prop::collection::vec(-2..3i8, k * k), scalar.clone())
            .prop_map(move |(a, s)| M::G(b(G::ExpA(k, a, s))))
    });
    prop_oneof![
        3 => gm.clone(),
        2 => gm.clone().prop_map(|g| M::G(b(G::Inverse(b(g))))),
        1 => expa,
        1 => (gm.clone(), gm).prop_filter("one size", |(x, y)| x.size() == y.size())
            .prop_map(|(x, y)| M::Mul(b(x), b(y))),
    ]
    .boxed()
}

/// Planar transforms: SE2 leaves, products and inverses.
pub fn planar(scalar: BoxedStrategy<T>) -> BoxedStrategy<M> {
    let leaf = (scalar, prop::array::uniform2(-2..3i8)).prop_map(|(s, p)| M::G(b(G::Se2(s, p))));
    leaf.prop_recursive(1, 3, 2, |inner| {
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(x, y)| M::Mul(b(x), b(y))),
            inner.prop_map(|x| M::G(b(G::Inverse(b(x))))),
        ]
    })
    .boxed()
}

/// The outputs of [`L`] over the given strategies.
pub fn outputs(
    scalar: BoxedStrategy<T>,
    rot: BoxedStrategy<M>,
    tf: BoxedStrategy<M>,
    gm: BoxedStrategy<M>,
    plane: BoxedStrategy<M>,
) -> BoxedStrategy<L> {
    let k3 = prop::array::uniform3(-2..3i8);
    let c = (101..400i64, 2..3u32);
    prop_oneof![
        3 => (rot.clone(), 0..3u8).prop_map(|(m, f)| L::Log3(m, f)),
        3 => (tf.clone(), 0..3u8).prop_map(|(m, f)| L::Log6(m, f)),
        1 => plane.clone().prop_map(L::Log2),
        4 => (rot.clone(), 0..5u8).prop_map(|(m, k)| L::Angles(m, k)),
        1 => (rot.clone(), k3.clone(), scalar.clone()).prop_map(|(m, v, s)| L::AxisAng3(m, v, s)),
        1 => (tf.clone(), 0..6usize, k3.clone(), scalar)
            .prop_map(|(m, k, v, s)| L::AxisAng6(m, k, v, s)),
        1 => tf.clone().prop_map(L::TransToRp),
        1 => (tf.clone(), k3.clone()).prop_map(|(m, v)| L::AdOf(m, v)),
        2 => (tf.clone(), k3.clone(), k3.clone(), any::<bool>())
            .prop_map(|(m, f, v, eq)| L::Power(m, f, v, eq)),
        1 => (rot.clone(), rot.clone()).prop_map(|(x, y)| L::QuatMul(x, y)),
        1 => (tf.clone(), 0..6usize, k3.clone()).prop_map(|(m, k, v)| L::ScrewParams(m, k, v)),
        1 => (rot.clone(), any::<bool>()).prop_map(|(m, s)| L::AngVel(m, s)),
        1 => (tf.clone(), any::<bool>()).prop_map(|(m, s)| L::TwistOf(m, s)),
        1 => prop_oneof![rot.clone(), tf.clone()].prop_map(L::VeeDiff),
        2 => prop_oneof![gm.clone(), rot.clone(), plane.clone()].prop_map(L::Det),
        1 => prop_oneof![gm.clone(), rot.clone()].prop_map(L::Norm),
        1 => (rot.clone(), k3.clone(), any::<bool>()).prop_map(|(m, v, u)| L::NormV(m, v, u)),
        1 => prop_oneof![gm, tf.clone()].prop_map(L::Diag),
        1 => (prop_oneof![rot.clone(), tf.clone()], c).prop_map(|(m, c)| L::Distance(m, c)),
        1 => prop_oneof![rot.clone(), tf].prop_map(L::TestIf),
        1 => (rot, k3).prop_map(|(m, v)| L::VeeHat(m, v)),
    ]
    .boxed()
}
