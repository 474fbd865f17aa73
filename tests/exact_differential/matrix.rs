//! Random exact matrices as chasles source, with the oracle's value of
//! each entry: `Rotx`/`Roty`/`Rotz` of exact angles (p/q π, degrees) and
//! of decimals, `RpToTrans`, products, `inv`, transposes, and scalar
//! multiples — and pairs of them equal by an identity (Rotz(a) Rotz(b) =
//! Rotz(a + b), inv(R) = Rᵀ, inv(T) by (3.23), (AB)ᵀ = BᵀAᵀ, A A⁻¹ = I),
//! differing by a tiny exact amount, or unrelated.

use super::generator::{E, V, add, angle, expr, mul};
use proptest::prelude::*;

/// A random square matrix (3×3 or 4×4).
#[derive(Debug, Clone)]
pub enum M {
    /// Rotx (0), Roty (1), Rotz (2) of an angle.
    Rot(u8, E),
    /// RpToTrans(R, (a, b, c)).
    Trans(Box<M>, [E; 3]),
    Mul(Box<M>, Box<M>),
    Inv(Box<M>),
    T(Box<M>),
    Scale(E, Box<M>),
    /// eye(n).
    Eye(usize),
    /// Any text with a value (identities write their other side so).
    Text(String, Box<M>),
}

/// A matrix as the oracle knows it: its size, its entries row by row,
/// and whether it is a rotation or a transform (so that `inv` is by
/// transpose, (3.23)).
#[derive(Debug, Clone)]
pub struct Mv {
    pub n: usize,
    pub e: Vec<V>,
    pub group: bool,
}

fn b<T>(x: T) -> Box<T> {
    Box::new(x)
}

fn int(k: i64) -> V {
    E::Int(k).eval().expect("an integer")
}

impl M {
    /// The source text.
    pub fn src(&self) -> String {
        match self {
            M::Rot(a, t) => format!("Rot{}({})", ["x", "y", "z"][*a as usize % 3], t.src()),
            M::Trans(r, p) => format!(
                "RpToTrans({}, ({}, {}, {}))",
                r.src(),
                p[0].src(),
                p[1].src(),
                p[2].src()
            ),
            M::Mul(x, y) => format!("({} * {})", x.src(), y.src()),
            M::Inv(x) => format!("inv({})", x.src()),
            M::T(x) => format!("({}).T", x.src()),
            M::Scale(k, x) => format!("({} * {})", k.src(), x.src()),
            M::Eye(n) => format!("eye({n})"),
            M::Text(t, _) => t.clone(),
        }
    }

    /// The oracle's entries; None where an entry is out of the oracle's
    /// range or a product mixes sizes.
    pub fn eval(&self) -> Option<Mv> {
        Some(match self {
            M::Rot(axis, t) => {
                let s = E::Fn(0, b(t.clone())).eval()?;
                let c = E::Fn(1, b(t.clone())).eval()?;
                let ns = super::generator::neg(&s);
                let (o, z) = (int(1), int(0));
                let e = match axis % 3 {
                    0 => vec![o, z.clone(), z.clone(), z.clone(), c.clone(), ns, z, s, c],
                    1 => vec![c.clone(), z.clone(), s, z.clone(), o, z.clone(), ns, z, c],
                    _ => vec![c.clone(), ns, z.clone(), s, c, z.clone(), z.clone(), z, o],
                };
                Mv {
                    n: 3,
                    e,
                    group: true,
                }
            }
            M::Trans(r, p) => {
                let r = r.eval()?;
                if r.n != 3 || !r.group {
                    return None;
                }
                let p: Vec<V> = p.iter().map(E::eval).collect::<Option<_>>()?;
                let mut e = Vec::with_capacity(16);
                for (row, pi) in r.e.chunks(3).zip(&p) {
                    e.extend(row.iter().cloned());
                    e.push(pi.clone());
                }
                e.extend([int(0), int(0), int(0), int(1)]);
                Mv {
                    n: 4,
                    e,
                    group: true,
                }
            }
            M::Mul(x, y) => {
                let (x, y) = (x.eval()?, y.eval()?);
                if x.n != y.n {
                    return None;
                }
                let n = x.n;
                let mut e = Vec::with_capacity(n * n);
                for i in 0..n {
                    for j in 0..n {
                        let mut s = mul(&x.e[i * n], &y.e[j]);
                        for k in 1..n {
                            s = add(&s, &mul(&x.e[i * n + k], &y.e[k * n + j]), false);
                        }
                        e.push(s);
                    }
                }
                Mv {
                    n,
                    e,
                    group: x.group && y.group,
                }
            }
            M::Inv(x) => {
                let x = x.eval()?;
                if !x.group {
                    return None;
                }
                let t = transpose(&x);
                if x.n == 3 {
                    return Some(t);
                }
                // [Rᵀ, −Rᵀp; 0, 1]
                let mut e = Vec::with_capacity(16);
                for i in 0..3 {
                    e.extend((0..3).map(|j| x.e[4 * j + i].clone()));
                    let mut s = mul(&x.e[i], &x.e[3]);
                    for k in 1..3 {
                        s = add(&s, &mul(&x.e[4 * k + i], &x.e[4 * k + 3]), false);
                    }
                    e.push(super::generator::neg(&s));
                }
                e.extend([int(0), int(0), int(0), int(1)]);
                Mv {
                    n: 4,
                    e,
                    group: true,
                }
            }
            M::T(x) => {
                let x = x.eval()?;
                let mut t = transpose(&x);
                t.group = x.group && x.n == 3;
                t
            }
            M::Scale(k, x) => {
                let (k, x) = (k.eval()?, x.eval()?);
                Mv {
                    n: x.n,
                    e: x.e.iter().map(|v| mul(&k, v)).collect(),
                    group: false,
                }
            }
            M::Eye(n) => Mv {
                n: *n,
                e: (0..n * n)
                    .map(|k| int(i64::from(k % (n + 1) == 0)))
                    .collect(),
                group: true,
            },
            M::Text(_, x) => x.eval()?,
        })
    }
}

fn transpose(x: &Mv) -> Mv {
    let n = x.n;
    Mv {
        n,
        e: (0..n * n)
            .map(|k| x.e[(k % n) * n + k / n].clone())
            .collect(),
        group: x.group,
    }
}

/// A rotation: one of Rotx/y/z, or a product of two.
fn rotation() -> impl Strategy<Value = M> {
    let one = (0u8..3, angle()).prop_map(|(a, t)| M::Rot(a, t)).boxed();
    prop_oneof![
        3 => one.clone(),
        1 => (one.clone(), one).prop_map(|(x, y)| M::Mul(b(x), b(y))),
    ]
}

/// A point: exact numbers mostly.
fn point() -> impl Strategy<Value = [E; 3]> {
    let small = prop_oneof![
        3 => (-12i64..=12).prop_map(E::Int),
        2 => (-999i64..=999, 1u32..=3).prop_map(|(m, k)| E::Dec(m, k)),
        1 => expr(),
    ];
    [small.clone(), small.clone(), small]
}

/// A transform.
fn transform() -> impl Strategy<Value = M> {
    (rotation(), point()).prop_map(|(r, p)| M::Trans(b(r), p))
}

/// A matrix of size `n` (3 or 4) built from rotations or transforms.
fn square(n: usize) -> BoxedStrategy<M> {
    let base = if n == 3 {
        rotation().boxed()
    } else {
        transform().boxed()
    };
    base.prop_recursive(2, 6, 2, |inner| {
        prop_oneof![
            2 => (inner.clone(), inner.clone()).prop_map(|(x, y)| M::Mul(b(x), b(y))),
            1 => inner.clone().prop_map(|x| M::Inv(b(x))),
            1 => inner.clone().prop_map(|x| M::T(b(x))),
            1 => (expr(), inner).prop_map(|(k, x)| M::Scale(k, b(x))),
        ]
    })
    .boxed()
}

/// Pairs of matrices: equal by an identity, differing by a tiny exact
/// amount, or unrelated.
pub fn pair() -> impl Strategy<Value = (M, M)> {
    let m = prop_oneof![Just(3usize), Just(4usize)].prop_flat_map(square);
    prop_oneof![
        // Rot(a) Rot(b) = Rot(a + b)
        2 => (0u8..3, angle(), angle()).prop_map(|(ax, s, t)| (
            M::Mul(b(M::Rot(ax, s.clone())), b(M::Rot(ax, t.clone()))),
            M::Rot(ax, E::Add(b(s), b(t))),
        )),
        // inv(R) = Rᵀ; inv(T) = [Rᵀ, −Rᵀp; 0, 1] (3.23)
        2 => (rotation(), point(), any::<bool>()).prop_map(|(r, p, is_t)| {
            if !is_t {
                return (M::Inv(b(r.clone())), M::T(b(r)));
            }
            let t = M::Trans(b(r.clone()), p.clone());
            let rt = format!("({}).T", r.src());
            let text = format!(
                "RpToTrans({rt}, -({rt}) * ({}, {}, {}))",
                p[0].src(),
                p[1].src(),
                p[2].src()
            );
            (M::Inv(b(t.clone())), M::Text(text, b(M::Inv(b(t)))))
        }),
        // (AB)ᵀ = BᵀAᵀ, A A⁻¹ = I (A a rotation or transform)
        2 => (prop_oneof![Just(3usize), Just(4usize)], any::<bool>())
            .prop_flat_map(|(n, which)| {
                let g = if n == 3 { rotation().boxed() } else { transform().boxed() };
                (g.clone(), g, Just(which), Just(n))
            })
            .prop_map(|(x, y, which, n)| {
                if which {
                    (
                        M::T(b(M::Mul(b(x.clone()), b(y.clone())))),
                        M::Mul(b(M::T(b(y))), b(M::T(b(x)))),
                    )
                } else {
                    (M::Mul(b(x.clone()), b(M::Inv(b(x)))), M::Eye(n))
                }
            }),
        // T(R, p) against T(R, p + (δ, 0, 0)); Rot(a) against Rot(a + δ)
        2 => (transform(), 0u8..3, angle(), prop_oneof![Just(13u32), Just(16), Just(20)])
            .prop_map(|(t, ax, a, k)| match t {
                M::Trans(r, p) if k != 16 => {
                    let mut q = p.clone();
                    q[0] = E::Add(b(q[0].clone()), b(E::Tiny(k)));
                    (M::Trans(r.clone(), p), M::Trans(r, q))
                }
                _ => (
                    M::Rot(ax, a.clone()),
                    M::Rot(ax, E::Add(b(a), b(E::Tiny(k)))),
                ),
            }),
        // unrelated, and a matrix against itself
        2 => (prop_oneof![Just(3usize), Just(4usize)])
            .prop_flat_map(|n| (square(n), square(n))),
        1 => m.prop_map(|x| (x.clone(), x)),
    ]
}
