//! Matrices of certified balls ([`super::ball`]) and the builtins on
//! them (LANGUAGE.md §7, issue 21): what [`super::certify`] evaluates a
//! recipe's steps with — the scalar functions, the rotations about the
//! axes and Rodrigues' formula (3.51), [ω] (3.30), the transforms of
//! §3.3 ([R, p; 0, 1], their inverse 3.64, [V] 3.71), products, dot,
//! cross, norm, trace and det.

use super::ball::{self, Ball};

/// A matrix of balls, row by row.
#[derive(Clone)]
pub(crate) struct Balls {
    pub(crate) rows: usize,
    pub(crate) cols: usize,
    pub(crate) data: Vec<Ball>,
}

impl Balls {
    pub(crate) fn scalar(b: Ball) -> Balls {
        Balls {
            rows: 1,
            cols: 1,
            data: vec![b],
        }
    }
    pub(crate) fn at(&self, i: usize, j: usize) -> &Ball {
        &self.data[i * self.cols + j]
    }
    pub(crate) fn one(&self) -> Option<&Ball> {
        (self.data.len() == 1).then(|| &self.data[0])
    }
    pub(crate) fn map(&self, f: impl Fn(&Ball) -> Option<Ball>) -> Option<Balls> {
        Some(Balls {
            rows: self.rows,
            cols: self.cols,
            data: self.data.iter().map(f).collect::<Option<_>>()?,
        })
    }
    pub(crate) fn transpose(&self) -> Balls {
        let data = (0..self.cols)
            .flat_map(|j| (0..self.rows).map(move |i| (i, j)))
            .map(|(i, j)| self.at(i, j).clone())
            .collect();
        Balls {
            rows: self.cols,
            cols: self.rows,
            data,
        }
    }
    pub(crate) fn column(data: Vec<Ball>) -> Balls {
        Balls {
            rows: data.len(),
            cols: 1,
            data,
        }
    }
}

/// The matrix product `a b`.
pub(crate) fn product(a: &Balls, b: &Balls, prec: usize) -> Option<Balls> {
    if a.cols != b.rows {
        return None;
    }
    let mut data = Vec::with_capacity(a.rows * b.cols);
    for i in 0..a.rows {
        for j in 0..b.cols {
            let mut s = ball::mul(a.at(i, 0), b.at(0, j), prec)?;
            for k in 1..a.cols {
                s = ball::add(&s, &ball::mul(a.at(i, k), b.at(k, j), prec)?, prec)?;
            }
            data.push(s);
        }
    }
    Some(Balls {
        rows: a.rows,
        cols: b.cols,
        data,
    })
}

/// [ω] of ω = (x, y, z) (3.30).
pub(crate) fn hat(w: &[Ball]) -> Balls {
    let z = Ball::exact(dashu_float::Repr::zero());
    let n = ball::neg;
    Balls {
        rows: 3,
        cols: 3,
        data: vec![
            z.clone(),
            n(&w[2]),
            w[1].clone(),
            w[2].clone(),
            z.clone(),
            n(&w[0]),
            n(&w[1]),
            w[0].clone(),
            z,
        ],
    }
}

/// [R, p; 0, 1] (3.62).
fn transform(r: &Balls, p: &Balls) -> Balls {
    let zero = || Ball::exact(dashu_float::Repr::zero());
    let mut data = Vec::with_capacity(16);
    for i in 0..3 {
        data.extend((0..3).map(|j| r.at(i, j).clone()));
        data.push(p.data[i].clone());
    }
    data.extend([
        zero(),
        zero(),
        zero(),
        Ball::exact(dashu_float::Repr::one()),
    ]);
    Balls {
        rows: 4,
        cols: 4,
        data,
    }
}

/// A builtin on balls: the scalar functions, the rotations about the
/// axes, and the vector and matrix operations of the exact path.
pub(crate) fn call(name: &str, args: &[Balls], prec: usize) -> Option<Balls> {
    let row = crate::builtins::lookup(name)?;
    let one = |i: usize| args.get(i).and_then(Balls::one);
    let scalar = |f: fn(&Ball, usize) -> Option<Ball>| {
        (args.len() == 1).then(|| args[0].map(|x| f(x, prec)))?
    };
    let recip = |f: fn(&Ball, usize) -> Option<Ball>| {
        scalar(f)?.map(|y| ball::div(&ball::int(&1.into()), y, prec))
    };
    let zero = || Ball::exact(dashu_float::Repr::zero());
    let unit = || Ball::exact(dashu_float::Repr::one());
    match row.name {
        "sqrt" => scalar(ball::sqrt),
        "abs" => scalar(|x, _| Some(ball::abs(x))),
        "sin" => scalar(ball::sin),
        "cos" => scalar(ball::cos),
        "tan" => scalar(ball::tan),
        "cot" => recip(ball::tan),
        "sec" => recip(ball::cos),
        "csc" => recip(ball::sin),
        "exp" if args.first()?.data.len() == 1 => scalar(ball::exp),
        "log" if args.first()?.data.len() == 1 => scalar(ball::ln),
        "atan" => scalar(ball::atan),
        "asin" => scalar(ball::asin),
        "acos" => scalar(ball::acos),
        "atan2" if args.len() == 2 => Some(Balls::scalar(ball::atan2(one(0)?, one(1)?, prec)?)),
        "Rotx" | "Roty" | "Rotz" => {
            let t = one(0)?;
            let (c, s) = (ball::cos(t, prec)?, ball::sin(t, prec)?);
            let ms = ball::neg(&s);
            let (o, z) = (unit(), zero());
            let data = match row.name {
                "Rotx" => vec![o, z.clone(), z.clone(), z.clone(), c.clone(), ms, z, s, c],
                "Roty" => vec![c.clone(), z.clone(), s, z.clone(), o, z.clone(), ms, z, c],
                _ => vec![c.clone(), ms, z.clone(), s, c, z.clone(), z.clone(), z, o],
            };
            Some(Balls {
                rows: 3,
                cols: 3,
                data,
            })
        }
        "Rot" => {
            // (Rodrigues, 3.51, about the axis normalized)
            let (w, t) = (args.first()?, one(1)?);
            if (w.rows, w.cols) != (3, 1) {
                return None;
            }
            let n = call("norm", &args[..1], prec)?;
            let w = w.map(|x| ball::div(x, n.one()?, prec))?;
            let k = hat(&w.data);
            let k2 = product(&k, &k, prec)?;
            let (s, c) = (ball::sin(t, prec)?, ball::cos(t, prec)?);
            let vc = ball::sub(&unit(), &c, prec)?;
            let mut data = Vec::with_capacity(9);
            for i in 0..3 {
                for j in 0..3 {
                    let d = if i == j { unit() } else { zero() };
                    let x = ball::add(&d, &ball::mul(&s, k.at(i, j), prec)?, prec)?;
                    data.push(ball::add(&x, &ball::mul(&vc, k2.at(i, j), prec)?, prec)?);
                }
            }
            Some(Balls {
                rows: 3,
                cols: 3,
                data,
            })
        }
        "transpose" | "RotInv" => Some(args.first()?.transpose()),
        "RpToTrans" => {
            let (r, p) = (args.first()?, args.get(1)?);
            ((r.rows, r.cols, p.rows, p.cols) == (3, 3, 3, 1)).then(|| transform(r, p))
        }
        "TransInv" => {
            // (3.64: [Rᵀ, −Rᵀp; 0, 1])
            let t = args.first()?;
            if (t.rows, t.cols) != (4, 4) {
                return None;
            }
            let rt = Balls {
                rows: 3,
                cols: 3,
                data: (0..3)
                    .flat_map(|i| (0..3).map(move |j| (i, j)))
                    .map(|(i, j)| t.at(j, i).clone())
                    .collect(),
            };
            let p = Balls::column((0..3).map(|i| t.at(i, 3).clone()).collect());
            let q = product(&rt, &p, prec)?.map(|x| Some(ball::neg(x)))?;
            Some(transform(&rt, &q))
        }
        "VecTose3" => {
            // (3.71: [[ω], v; 0, 0])
            let v = args.first()?;
            if (v.rows, v.cols) != (6, 1) {
                return None;
            }
            let w = hat(&v.data[..3]);
            let mut data = Vec::with_capacity(16);
            for i in 0..3 {
                data.extend((0..3).map(|j| w.at(i, j).clone()));
                data.push(v.data[3 + i].clone());
            }
            data.extend((0..4).map(|_| zero()));
            Some(Balls {
                rows: 4,
                cols: 4,
                data,
            })
        }
        "se3ToVec" => {
            let m = args.first()?;
            ((m.rows, m.cols) == (4, 4)).then(|| {
                Balls::column(vec![
                    m.at(2, 1).clone(),
                    m.at(0, 2).clone(),
                    m.at(1, 0).clone(),
                    m.at(0, 3).clone(),
                    m.at(1, 3).clone(),
                    m.at(2, 3).clone(),
                ])
            })
        }
        "VecToso3" => {
            let w = args.first()?;
            ((w.rows, w.cols) == (3, 1)).then(|| hat(&w.data))
        }
        "so3ToVec" => {
            let m = args.first()?;
            ((m.rows, m.cols) == (3, 3)).then(|| {
                Balls::column(vec![
                    m.at(2, 1).clone(),
                    m.at(0, 2).clone(),
                    m.at(1, 0).clone(),
                ])
            })
        }
        "dot" => {
            let (a, b) = (args.first()?, args.get(1)?);
            if a.data.len() != b.data.len() || a.cols != 1 || b.cols != 1 {
                return None;
            }
            let mut s = zero();
            for (x, y) in a.data.iter().zip(&b.data) {
                s = ball::add(&s, &ball::mul(x, y, prec)?, prec)?;
            }
            Some(Balls::scalar(s))
        }
        "cross" => {
            let (a, b) = (args.first()?, args.get(1)?);
            if (a.rows, a.cols, b.rows, b.cols) != (3, 1, 3, 1) {
                return None;
            }
            product(&hat(&a.data), b, prec)
        }
        "norm" => {
            let a = args.first()?;
            if a.cols != 1 && a.rows != 1 {
                return None;
            }
            let mut s = zero();
            for x in &a.data {
                s = ball::add(&s, &ball::mul(x, x, prec)?, prec)?;
            }
            Some(Balls::scalar(ball::sqrt(&s, prec)?))
        }
        "trace" => {
            let a = args.first()?;
            if a.rows != a.cols {
                return None;
            }
            let mut s = zero();
            for i in 0..a.rows {
                s = ball::add(&s, a.at(i, i), prec)?;
            }
            Some(Balls::scalar(s))
        }
        "det" => {
            let a = args.first()?;
            let m = |i, j| a.at(i, j);
            let d2 = |a: &Ball, b: &Ball, c: &Ball, d: &Ball| {
                ball::sub(&ball::mul(a, d, prec)?, &ball::mul(b, c, prec)?, prec)
            };
            match (a.rows, a.cols) {
                (1, 1) => Some(a.clone()),
                (2, 2) => Some(Balls::scalar(d2(m(0, 0), m(0, 1), m(1, 0), m(1, 1))?)),
                (3, 3) => {
                    let t0 = ball::mul(m(0, 0), &d2(m(1, 1), m(1, 2), m(2, 1), m(2, 2))?, prec)?;
                    let t1 = ball::mul(m(0, 1), &d2(m(1, 0), m(1, 2), m(2, 0), m(2, 2))?, prec)?;
                    let t2 = ball::mul(m(0, 2), &d2(m(1, 0), m(1, 1), m(2, 0), m(2, 1))?, prec)?;
                    let s = ball::add(&ball::sub(&t0, &t1, prec)?, &t2, prec)?;
                    Some(Balls::scalar(s))
                }
                _ => None,
            }
        }
        _ => None,
    }
}
