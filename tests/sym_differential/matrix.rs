//! The differential test over vectors and matrices (issue 21): random
//! rotations (`Rotx/Roty/Rotz`, `Rot(w, θ)`, `exp([ω̂] θ)`), transforms
//! (`exp([S] θ)`, `RpToTrans`), their products, transposes, inverses,
//! scalar multiples and `Ad`, points moved by them, `cross`, `dot`,
//! entries and traces — of symbolic scalars from the scalar generator —
//! then `diff` by t, a symbol, q or q̇, `subs`, `simplify` or `expand`.
//! Each is computed by the language with the numbers bound later (and,
//! without `diff`/`subs`, typed first) and by an independent forward-mode
//! evaluation of the tree as written here ([`S`]: value, derivative and
//! their rounding bounds, as [`super::T::dual`] gives for scalars).

use super::{At, By, Point, QS, SYMS, T, b, bindings, dec, dec_src, session};
#[path = "lie.rs"]
mod lie;
use chasles::eval::value::Value;
use lie::{G, L};
use proptest::prelude::*;

/// A scalar of the reference: value, derivative, and rounding bounds of
/// both in units of the machine epsilon.
#[derive(Debug, Clone, Copy)]
struct S {
    v: f64,
    e: f64,
    d: f64,
    ed: f64,
}

impl S {
    fn num(x: f64) -> S {
        S {
            v: x,
            e: x.abs(),
            d: 0.0,
            ed: 0.0,
        }
    }
    fn add(self, o: S) -> S {
        let (v, d) = (self.v + o.v, self.d + o.d);
        S {
            v,
            e: self.e + o.e + v.abs(),
            d,
            ed: self.ed + o.ed + d.abs(),
        }
    }
    fn neg(self) -> S {
        S {
            v: -self.v,
            d: -self.d,
            ..self
        }
    }
    fn sub(self, o: S) -> S {
        self.add(o.neg())
    }
    fn mul(self, o: S) -> S {
        let (a, b) = (self, o);
        let (v, d) = (a.v * b.v, a.d * b.v + a.v * b.d);
        S {
            v,
            e: a.e * b.v.abs() + b.e * a.v.abs() + v.abs(),
            d,
            ed: a.ed * b.v.abs()
                + a.d.abs() * b.e
                + a.e * b.d.abs()
                + a.v.abs() * b.ed
                + (a.d * b.v).abs()
                + (a.v * b.d).abs()
                + d.abs(),
        }
    }
    /// f(self) given f, f′, f″ at the value.
    fn map(self, f: (f64, f64, f64)) -> S {
        let (v, d1, d2) = f;
        let d = d1 * self.d;
        S {
            v,
            e: v.abs() + d1.abs() * self.e,
            d,
            ed: d1.abs() * self.ed + d2.abs() * self.e * self.d.abs() + 2.0 * d.abs(),
        }
    }
    fn sin(self) -> S {
        let u = self.v;
        self.map((u.sin(), u.cos(), -u.sin()))
    }
    fn cos(self) -> S {
        let u = self.v;
        self.map((u.cos(), -u.sin(), -u.cos()))
    }
}

/// A matrix of the reference, row by row.
#[derive(Debug, Clone)]
struct Mx {
    r: usize,
    c: usize,
    x: Vec<S>,
}

impl Mx {
    fn of(r: usize, c: usize, xs: &[f64]) -> Mx {
        Mx {
            r,
            c,
            x: xs.iter().map(|v| S::num(*v)).collect(),
        }
    }
    fn at(&self, i: usize, j: usize) -> S {
        self.x[i * self.c + j]
    }
    fn eye(n: usize) -> Mx {
        let mut m = Mx::of(n, n, &vec![0.0; n * n]);
        for i in 0..n {
            m.x[i * n + i] = S::num(1.0);
        }
        m
    }
    fn mul(&self, o: &Mx) -> Mx {
        let mut x = Vec::with_capacity(self.r * o.c);
        for i in 0..self.r {
            for j in 0..o.c {
                let mut s = self.at(i, 0).mul(o.at(0, j));
                for k in 1..self.c {
                    s = s.add(self.at(i, k).mul(o.at(k, j)));
                }
                x.push(s);
            }
        }
        Mx {
            r: self.r,
            c: o.c,
            x,
        }
    }
    fn add(&self, o: &Mx) -> Mx {
        Mx {
            r: self.r,
            c: self.c,
            x: self.x.iter().zip(&o.x).map(|(a, b)| a.add(*b)).collect(),
        }
    }
    fn scale(&self, s: S) -> Mx {
        Mx {
            r: self.r,
            c: self.c,
            x: self.x.iter().map(|a| s.mul(*a)).collect(),
        }
    }
    fn t(&self) -> Mx {
        let mut x = Vec::with_capacity(self.x.len());
        for j in 0..self.c {
            for i in 0..self.r {
                x.push(self.at(i, j));
            }
        }
        Mx {
            r: self.c,
            c: self.r,
            x,
        }
    }
    /// The r×c block at (i, j).
    fn block(&self, i: usize, j: usize, r: usize, c: usize) -> Mx {
        let mut x = Vec::new();
        for a in i..i + r {
            for b in j..j + c {
                x.push(self.at(a, b));
            }
        }
        Mx { r, c, x }
    }
    /// [R, p; 0, 1].
    fn rp(rot: &Mx, p: &Mx) -> Mx {
        let mut x = Vec::new();
        for i in 0..3 {
            x.extend_from_slice(&rot.x[i * 3..i * 3 + 3]);
            x.push(p.x[i]);
        }
        x.extend([0.0, 0.0, 0.0, 1.0].map(S::num));
        Mx { r: 4, c: 4, x }
    }
}

/// [ω] of a vector of the reference.
fn hat(w: &Mx) -> Mx {
    let z = S::num(0.0);
    let (a, b, c) = (w.x[0], w.x[1], w.x[2]);
    Mx {
        r: 3,
        c: 3,
        x: vec![z, c.neg(), b, c, z, a.neg(), b.neg(), a, z],
    }
}

/// Unit axes with exact forms (ω̂ of `Rot`, `exp([ω̂] θ)`, `exp([S] θ)`).
const AXES: [([f64; 3], &str); 6] = [
    ([1.0, 0.0, 0.0], "(1, 0, 0)"),
    ([0.0, 1.0, 0.0], "(0, 1, 0)"),
    ([0.0, 0.0, 1.0], "(0, 0, 1)"),
    ([1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0], "(1, 2, 2)/3"),
    ([2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0], "(2, 3, 6)/7"),
    ([2.0 / 7.0, -6.0 / 7.0, 3.0 / 7.0], "(2, -6, 3)/7"),
];

/// A random 3×3 rotation (`R`) or 4×4 transform (`F`) tree.
#[derive(Debug, Clone)]
pub enum M {
    /// Rotx, Roty, Rotz.
    Rot(u8, T),
    /// `Rot(w, θ)` with an integer axis (normalized by Rot).
    RotW([i8; 3], T),
    /// `exp([ω̂] θ)`.
    ExpW(usize, T),
    /// `exp([S] θ)`, S = (ω̂, v).
    ExpS(usize, [i8; 3], T),
    /// `RpToTrans(R, p)`.
    Rp(Box<M>, [i8; 3]),
    Mul(Box<M>, Box<M>),
    /// `x.T` (true) or `transpose(x)` of a rotation.
    Tr(Box<M>, bool),
    Inv(Box<M>),
    /// A scalar times it (no longer a group element: only at the top).
    Scale(T, Box<M>),
    /// `Ad(T)`: 6×6.
    Ad(Box<M>),
    /// The other builtins' matrices ([`lie`]).
    G(Box<G>),
}

/// What the test computes: a matrix, a vector, or a scalar of them.
#[derive(Debug, Clone)]
pub enum Out {
    M(M),
    /// M times an integer vector (a 4×4 takes a point (p, 1), a 6×6 a twist).
    Apply(M, [i8; 3]),
    Cross(M, M, [i8; 3]),
    Dot(M, M, [i8; 3]),
    /// The (i, j) entry (1-based, within 3×3).
    Entry(M, u8, u8),
    Trace(M),
    /// Maps out of the groups, tuples, scalars and bools ([`lie`]).
    Lie(L),
}

/// What is done to it.
#[derive(Debug, Clone)]
pub enum Wrap {
    None,
    Diff(By),
    /// `subs(x, a|b|c, decimal)`.
    Subs(usize, i64),
    Simplify,
    Expand,
}

fn vec_src(v: [i8; 3]) -> String {
    format!("({}, {}, {})", v[0], v[1], v[2])
}

fn vec_mx(v: [i8; 3]) -> Mx {
    Mx::of(3, 1, &v.map(f64::from))
}

impl M {
    fn size(&self) -> usize {
        match self {
            M::Rot(..) | M::RotW(..) | M::ExpW(..) => 3,
            M::ExpS(..) | M::Rp(..) => 4,
            M::Mul(x, _) | M::Tr(x, _) | M::Inv(x) | M::Scale(_, x) => x.size(),
            M::Ad(_) => 6,
            M::G(g) => g.size(),
        }
    }

    fn source(&self) -> String {
        match self {
            // (every spelling of an axis rotation, issue 35: `Rotx(θ)`, the
            // axis keyword `Rot(x, θ)`, `exp([(1, 0, 0)] θ)`)
            M::Rot(k, s) => {
                let axis = ["x", "y", "z"][*k as usize];
                let unit = ["(1, 0, 0)", "(0, 1, 0)", "(0, 0, 1)"][*k as usize];
                let src = s.source();
                match src.len() % 3 {
                    0 => format!("Rot{axis}({src})"),
                    1 => format!("Rot({axis}, {src})"),
                    _ => format!("exp([{unit}] * {src})"),
                }
            }
            M::RotW(w, s) => format!("Rot({}, {})", vec_src(*w), s.source()),
            M::ExpW(k, s) => format!("exp([{}] * {})", AXES[*k].1, s.source()),
            M::ExpS(k, v, s) => {
                let w = AXES[*k].0;
                format!(
                    "exp([({}, {}, {}, {}, {}, {})] * {})",
                    frac(w[0]),
                    frac(w[1]),
                    frac(w[2]),
                    v[0],
                    v[1],
                    v[2],
                    s.source()
                )
            }
            M::Rp(r, p) => format!("RpToTrans({}, {})", r.source(), vec_src(*p)),
            M::Mul(x, y) => format!("({} * {})", x.source(), y.source()),
            M::Tr(x, true) => format!("({}).T", x.source()),
            M::Tr(x, false) => format!("transpose({})", x.source()),
            M::Inv(x) => format!("inv({})", x.source()),
            M::Scale(s, x) => format!("({} * {})", s.source(), x.source()),
            M::Ad(x) => format!("Ad({})", x.source()),
            M::G(g) => g.source(),
        }
    }

    fn eval(&self, at: &At, by: By) -> Mx {
        let s = |t: &T| {
            let (v, e, d, ed) = t.dual(at, by);
            S { v, e, d, ed }
        };
        match self {
            M::Rot(k, t) => {
                let a = s(t);
                let (c, sn, o, z) = (a.cos(), a.sin(), S::num(1.0), S::num(0.0));
                let x = match k {
                    0 => vec![o, z, z, z, c, sn.neg(), z, sn, c],
                    1 => vec![c, z, sn, z, o, z, sn.neg(), z, c],
                    _ => vec![c, sn.neg(), z, sn, c, z, z, z, o],
                };
                Mx { r: 3, c: 3, x }
            }
            M::RotW(w, t) => {
                let w = w.map(f64::from);
                let n = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
                rodrigues(&Mx::of(3, 1, &w.map(|x| x / n)), s(t))
            }
            M::ExpW(k, t) => rodrigues(&Mx::of(3, 1, &AXES[*k].0), s(t)),
            M::ExpS(k, v, t) => {
                let (w, th) = (Mx::of(3, 1, &AXES[*k].0), s(t));
                let rot = rodrigues(&w, th);
                // G(θ) = Iθ + (1 − cos θ)[ω] + (θ − sin θ)[ω]² (3.87)
                let h = hat(&w);
                let g = Mx::eye(3)
                    .scale(th)
                    .add(&h.scale(S::num(1.0).sub(th.cos())))
                    .add(&h.mul(&h).scale(th.sub(th.sin())));
                Mx::rp(&rot, &g.mul(&vec_mx(*v)))
            }
            M::Rp(r, p) => Mx::rp(&r.eval(at, by), &vec_mx(*p)),
            M::Mul(x, y) => x.eval(at, by).mul(&y.eval(at, by)),
            M::Tr(x, _) => x.eval(at, by).t(),
            M::Inv(x) => lie::inv_group(&x.eval(at, by)),
            M::G(g) => g.eval(at, by),
            M::Scale(t, x) => x.eval(at, by).scale(s(t)),
            M::Ad(x) => lie::adjoint(&x.eval(at, by)),
        }
    }

    fn scalars(&self) -> Vec<&T> {
        match self {
            M::Rot(_, t) | M::RotW(_, t) | M::ExpW(_, t) | M::ExpS(_, _, t) => vec![t],
            M::Rp(x, _) | M::Tr(x, _) | M::Inv(x) | M::Ad(x) => x.scalars(),
            M::Mul(x, y) => [x.scalars(), y.scalars()].concat(),
            M::Scale(t, x) => [vec![t], x.scalars()].concat(),
            M::G(g) => g.scalars(),
        }
    }
}

/// An exact fraction of a unit axis entry as typed (k/3 or k/7).
fn frac(x: f64) -> String {
    for d in [1.0, 3.0, 7.0] {
        let n = x * d;
        if (n - n.round()).abs() < 1e-12 {
            return if d == 1.0 {
                format!("{}", n.round())
            } else {
                format!("{}/{d}", n.round())
            };
        }
    }
    format!("{x:?}")
}

/// exp([ω̂] θ) by Rodrigues (3.51).
fn rodrigues(w: &Mx, th: S) -> Mx {
    let h = hat(w);
    Mx::eye(3)
        .add(&h.scale(th.sin()))
        .add(&h.mul(&h).scale(S::num(1.0).sub(th.cos())))
}

/// A vector in the homogeneous or twist form `m` of size n takes.
fn padded(n: usize, v: [i8; 3]) -> (Mx, String) {
    let f = v.map(f64::from);
    match n {
        4 => (
            Mx::of(4, 1, &[f[0], f[1], f[2], 1.0]),
            format!("({}, {}, {}, 1)", v[0], v[1], v[2]),
        ),
        6 => (
            Mx::of(6, 1, &[f[0], f[1], f[2], f[2], f[0], f[1]]),
            format!(
                "({}, {}, {}, {}, {}, {})",
                v[0], v[1], v[2], v[2], v[0], v[1]
            ),
        ),
        _ => (vec_mx(v), vec_src(v)),
    }
}

impl Out {
    fn source(&self) -> String {
        match self {
            Out::M(m) => m.source(),
            Out::Apply(m, v) => format!("({} * {})", m.source(), padded(m.size(), *v).1),
            Out::Cross(x, y, v) => format!(
                "cross({} * {p}, {} * {p})",
                x.source(),
                y.source(),
                p = vec_src(*v)
            ),
            Out::Dot(x, y, v) => format!(
                "dot({} * {p}, {} * {p})",
                x.source(),
                y.source(),
                p = vec_src(*v)
            ),
            Out::Entry(m, i, j) => format!("({})[{i}, {j}]", m.source()),
            Out::Trace(m) => format!("trace({})", m.source()),
            Out::Lie(l) => l.source(),
        }
    }

    /// The reference; None where it is not trustworthy.
    fn eval(&self, at: &At, by: By) -> Option<Mx> {
        Some(match self {
            Out::Lie(l) => l.eval(at, by)?,
            Out::M(m) => m.eval(at, by),
            Out::Apply(m, v) => m.eval(at, by).mul(&padded(m.size(), *v).0),
            Out::Cross(x, y, v) => {
                let (u, w) = (
                    x.eval(at, by).mul(&vec_mx(*v)),
                    y.eval(at, by).mul(&vec_mx(*v)),
                );
                hat(&u).mul(&w)
            }
            Out::Dot(x, y, v) => {
                let (u, w) = (
                    x.eval(at, by).mul(&vec_mx(*v)),
                    y.eval(at, by).mul(&vec_mx(*v)),
                );
                u.t().mul(&w)
            }
            Out::Entry(m, i, j) => {
                let x = m.eval(at, by);
                if *i as usize > x.r || *j as usize > x.c {
                    // (refused: the index is out of range)
                    return None;
                }
                let x = x.at(*i as usize - 1, *j as usize - 1);
                Mx {
                    r: 1,
                    c: 1,
                    x: vec![x],
                }
            }
            Out::Trace(m) => {
                let x = m.eval(at, by);
                let mut s = x.at(0, 0);
                for i in 1..x.r {
                    s = s.add(x.at(i, i));
                }
                Mx {
                    r: 1,
                    c: 1,
                    x: vec![s],
                }
            }
        })
    }

    fn matrices(&self) -> Vec<&M> {
        match self {
            Out::M(m) | Out::Apply(m, _) | Out::Entry(m, ..) | Out::Trace(m) => vec![m],
            Out::Cross(x, y, _) | Out::Dot(x, y, _) => vec![x, y],
            Out::Lie(l) => l.matrices(),
        }
    }
}

/// The scalar arguments: angles (π offsets, decimals), symbols, small
/// sums and products, and now and then a power of a sum (whose expanded
/// form cancels).
fn scalar() -> impl Strategy<Value = T> {
    let angle = (
        any::<bool>(),
        prop::array::uniform4(-2..3i8),
        (-12..13i8, 1..13u8),
        prop::option::of((-300..300i64, 1..4u32)),
    )
        .prop_map(|(s, k, pd, off)| T::Angle(s, k, pd, off));
    let leaf = prop_oneof![
        3 => (0..3usize).prop_map(T::Sym),
        1 => Just(T::Time),
        2 => (0..2usize, 0..2u8).prop_map(|(i, d)| T::Q(i, d)),
        1 => (-999..1000i64, 1..4u32).prop_map(|(m, k)| T::Dec(m, k)),
        2 => angle.clone(),
    ];
    let small = leaf.prop_recursive(2, 6, 2, |inner| {
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(x, y)| T::Add(b(x), b(y))),
            (inner.clone(), inner.clone()).prop_map(|(x, y)| T::Mul(b(x), b(y))),
            inner.clone().prop_map(|x| T::Neg(b(x))),
            inner.clone().prop_map(|x| T::Sin(b(x))),
            (inner, 2..4i32).prop_map(|(x, n)| T::Pow(b(x), n)),
        ]
    });
    let power =
        (angle.clone(), angle, 8..16i32).prop_map(|(x, y, n)| T::Pow(b(T::Add(b(x), b(y))), n));
    prop_oneof![12 => small, 1 => power]
}

fn rotation() -> impl Strategy<Value = M> {
    let axis = prop::array::uniform3(-2..3i8).prop_filter("a nonzero axis", |w| *w != [0, 0, 0]);
    let leaf = prop_oneof![
        6 => (0..3u8, scalar()).prop_map(|(k, s)| M::Rot(k, s)),
        2 => (axis, scalar()).prop_map(|(w, s)| M::RotW(w, s)),
        2 => (0..6usize, scalar()).prop_map(|(k, s)| M::ExpW(k, s)),
        3 => lie::more_rotations(scalar().boxed()),
    ];
    leaf.prop_recursive(2, 4, 2, |inner| {
        prop_oneof![
            6 => (inner.clone(), inner.clone()).prop_map(|(x, y)| M::Mul(b(x), b(y))),
            2 => (inner.clone(), any::<bool>()).prop_map(|(x, d)| M::Tr(b(x), d)),
            2 => inner.clone().prop_map(|x| M::Inv(b(x))),
            1 => inner.clone().prop_map(|x| M::G(b(G::InvB(b(x))))),
            1 => inner.prop_map(|x| M::G(b(G::Tag(b(x))))),
        ]
    })
}

fn transform() -> impl Strategy<Value = M> {
    let v = prop::array::uniform3(-2..3i8);
    let leaf = prop_oneof![
        4 => (0..6usize, v.clone(), scalar()).prop_map(|(k, v, s)| M::ExpS(k, v, s)),
        2 => (rotation(), v).prop_map(|(r, p)| M::Rp(b(r), p)),
        2 => lie::more_transforms(scalar().boxed()),
    ];
    leaf.prop_recursive(1, 3, 2, |inner| {
        prop_oneof![
            4 => (inner.clone(), inner.clone()).prop_map(|(x, y)| M::Mul(b(x), b(y))),
            2 => inner.clone().prop_map(|x| M::Inv(b(x))),
            1 => inner.clone().prop_map(|x| M::G(b(G::InvB(b(x))))),
            1 => (inner.clone(), inner).prop_map(|(x, y)| M::G(b(G::Disp(b(x), b(y))))),
        ]
    })
}

fn matrix() -> impl Strategy<Value = M> {
    let c = (101..400i64, 2..3u32);
    prop_oneof![
        8 => rotation(),
        6 => transform(),
        2 => transform().prop_map(|t| M::Ad(b(t))),
        2 => (scalar(), prop_oneof![rotation(), transform()]).prop_map(|(s, m)| M::Scale(s, b(m))),
        2 => lie::general(scalar().boxed()),
        1 => lie::planar(scalar().boxed()),
        1 => (prop_oneof![rotation(), transform()], c).prop_map(|(m, c)| M::G(b(G::Proj(b(m), c)))),
        1 => prop_oneof![rotation(), transform()].prop_map(|m| M::G(b(G::Deg(b(m))))),
    ]
}

fn out() -> impl Strategy<Value = Out> {
    let v = prop::array::uniform3(-2..3i8);
    let lie = lie::outputs(
        scalar().boxed(),
        rotation().boxed(),
        transform().boxed(),
        lie::general(scalar().boxed()),
        lie::planar(scalar().boxed()),
    );
    prop_oneof![
        3 => matrix().prop_map(Out::M),
        2 => (matrix(), v.clone()).prop_map(|(m, v)| Out::Apply(m, v)),
        1 => (rotation(), rotation(), v.clone()).prop_map(|(x, y, v)| Out::Cross(x, y, v)),
        1 => (rotation(), rotation(), v).prop_map(|(x, y, v)| Out::Dot(x, y, v)),
        1 => (matrix(), 1..4u8, 1..4u8).prop_map(|(m, i, j)| Out::Entry(m, i, j)),
        1 => matrix().prop_map(Out::Trace),
        8 => lie.prop_map(Out::Lie),
    ]
}

fn wrap() -> impl Strategy<Value = Wrap> {
    let by = prop_oneof![
        Just(By::Time),
        (0..3usize).prop_map(By::Sym),
        (0..2usize, 0..2u8).prop_map(|(i, d)| By::Q(i, d)),
    ];
    prop_oneof![
        3 => Just(Wrap::None),
        4 => by.prop_map(Wrap::Diff),
        1 => (0..3usize, -999..1000i64).prop_map(|(s, v)| Wrap::Subs(s, v)),
        1 => Just(Wrap::Simplify),
        1 => Just(Wrap::Expand),
    ]
}

/// A random vector or matrix computation, what is done to it, and a point.
pub fn case() -> impl Strategy<Value = (Out, Wrap, Point)> {
    (out(), wrap(), super::point())
}

/// The numbers of a value, row by row; a tuple's parts one after the
/// other as a column, a bool as 1 or 0.
fn entries(v: &Value) -> Option<(usize, usize, Vec<f64>)> {
    match v {
        Value::Num { m, .. } => {
            let (r, c) = m.shape();
            Some((r, c, (0..r).flat_map(|i| m.row(i)).collect()))
        }
        Value::Bool(x) => Some((1, 1, vec![if *x { 1.0 } else { 0.0 }])),
        Value::Tuple(parts) => {
            let mut xs = Vec::new();
            for p in parts {
                xs.extend(entries(p)?.2);
            }
            Some((xs.len(), 1, xs))
        }
        _ => None,
    }
}

/// Checks one case: bound later (and typed first, where that can be
/// written) against the reference, entry by entry within 64 ε times the
/// largest entry's rounding bound (a derivative's by forward mode).
pub fn check((o, w, p): &(Out, Wrap, Point)) -> Result<(), String> {
    // (a derivative inside has no derivative in the reference)
    let none = Wrap::None;
    let w = match (o, w) {
        (Out::Lie(l), Wrap::Diff(_)) if l.inner_diff() || l.is_bool() => &none,
        _ => w,
    };
    let mut at = p.at(p.t);
    let by = match w {
        Wrap::Diff(by) => *by,
        _ => By::Time,
    };
    if let Wrap::Subs(i, v) = w {
        at.syms[*i] = dec(*v, 2);
    }
    let Some(mut want) = o.eval(&at, by) else {
        return Ok(());
    };
    if let Out::Lie(l) = o
        && want.c > 1
        && !matches!(l, L::Log3(..) | L::Log6(..) | L::Log2(..) | L::AdOf(..))
    {
        // (a tuple's parts are compared as one column)
        want = Mx {
            r: want.r * want.c,
            c: 1,
            x: want.x,
        };
    }
    let diffed = matches!(w, Wrap::Diff(_));
    let reference: Vec<(f64, f64)> = want
        .x
        .iter()
        .map(|s| if diffed { (s.d, s.ed) } else { (s.v, s.e) })
        .collect();
    // (the scalar arguments' own domains: a pole of tan inside, …)
    let ill = o
        .matrices()
        .iter()
        .flat_map(|m| m.scalars())
        .any(|t| !t.eval(&at).0.is_finite());
    if ill
        || at.ill.get()
        || reference
            .iter()
            .any(|(v, e)| !v.is_finite() || !e.is_finite())
    {
        return Ok(());
    }
    let src = o.source();
    let src = match w {
        Wrap::None => src,
        Wrap::Diff(by) => {
            let by = match by {
                By::Time => "t".to_string(),
                By::Sym(i) => SYMS[*i].to_string(),
                By::Q(i, d) => format!("{}{}", QS[*i], "'".repeat(*d as usize)),
            };
            format!("diff({src}, {by})")
        }
        Wrap::Subs(i, v) => format!("subs({src}, {}, {})", SYMS[*i], dec_src(*v, 2)),
        Wrap::Simplify => format!("simplify({src})"),
        Wrap::Expand => format!("expand({src})"),
    };
    let decl = "given a, b, c : scalar\ngiven q1(t), q2(t) : scalar\n";
    let later = format!("{decl}x = {src}\n{}y = x\n", bindings(&p.at(p.t)));
    let compare = |got: &Value, how: &str, script: &str| -> Result<(), String> {
        let (r, c, xs) =
            entries(got).ok_or_else(|| format!("{how}: not numbers: {got:?}\n{script}"))?;
        if (r, c) != (want.r, want.c) {
            return Err(format!(
                "{how}: {r}×{c}, not {}×{}\n{script}",
                want.r, want.c
            ));
        }
        // (norm-wise: an entry that is exactly 0 in the reference, a sum of
        // products that cancel, may be a rounding residue of the other
        // entries' size where the language computes it by another formula,
        // dAd = Ad·ad(…) for the product rule — seed 1726: 4.8e-17 for 0)
        let scale = reference.iter().fold(0.0f64, |m, (_, e)| m.max(*e));
        for (k, (g, (v, e))) in xs.iter().zip(&reference).enumerate() {
            let tol = 64.0 * f64::EPSILON * e.max(scale) + 1e-300;
            if (g - v).abs() > tol {
                return Err(format!(
                    "{how}: entry {} is {g:e}, the reference {v:e} (tolerance {tol:e})\n{script}",
                    k + 1
                ));
            }
        }
        Ok(())
    };
    if std::env::var_os("CHASLES_DIFF_SHOW").is_some() {
        eprintln!("{later}");
    }
    let (s, n, msg) = session(&later);
    if n > 0 {
        // a refusal is an answer (not a wrong one)
        if std::env::var_os("CHASLES_DIFF_VERBOSE").is_some() {
            eprintln!("refused: {src}\n{msg}");
        }
        return Ok(());
    }
    let y = s
        .env
        .get("y")
        .and_then(|b| b.val.clone())
        .ok_or_else(|| format!("no value\n{later}"))?;
    compare(&y, "bound later", &later)?;
    // (typed first, a diff or subs by a symbol that has a number reads the
    // symbol: src/eval/hold.rs)
    {
        let first = format!("{}x = {src}\n", bindings(&p.at(p.t)));
        let (s, n, _) = session(&first);
        if n == 0
            && let Some(x) = s.env.get("x").and_then(|b| b.val.clone())
        {
            compare(&x, "typed first", &first)?;
        }
    }
    Ok(())
}
