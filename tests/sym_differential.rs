//! The symbolic engine checked against numbers (LANGUAGE.md §7, issue 21):
//! fixed regressions for the wrong answers found so far, and a
//! differential test — random expressions over the engine's operations,
//! written as chasles source, evaluated by the language and by an
//! independent numeric evaluation of the same tree (and, bound later,
//! near machine precision: as if the numbers had been typed first).

use chasles::eval::env::Mode;
use chasles::eval::value::Value;
use chasles::session::{Session, Settings};

mod common;

/// Runs `src` in a fresh session; the session and the number of errors.
fn session(src: &str) -> (Session, usize, String) {
    let mut s = Session::new(Settings::default());
    let (_, err, n) = s.run_to_strings("t.chs", src, Mode::Run, false);
    (s, n, err)
}

/// The number bound to `name`, if it is one.
fn number(s: &Session, name: &str) -> Option<f64> {
    match s.env.get(name).and_then(|b| b.val.as_ref()) {
        Some(v @ Value::Num { .. }) => v.as_scalar(),
        _ => None,
    }
}

/// The text `src` prints (failing on an error).
fn prints(src: &str) -> String {
    common::printed(src).trim_end().to_string()
}

/// The last line `src` prints.
fn last(src: &str) -> String {
    prints(src).lines().last().unwrap_or_default().to_string()
}

// ------------------------------------------------------- fixed regressions

/// Issue 21, item 1: numbers bound later at angles outside the 15° family
/// give the number, as if typed first.
#[test]
fn numbers_bound_later_are_numbers() {
    for (angle, want) in [
        ("20 deg", 20f64.to_radians().cos()),
        ("10 deg", 10f64.to_radians().cos()),
        ("36 deg", 36f64.to_radians().cos()),
        ("0.1745", 0.1745f64.cos()),
    ] {
        let src = format!("given a : scalar\nc = cos(a)\na = {angle}\nx = c");
        let (s, n, err) = session(&src);
        assert_eq!(n, 0, "{err}");
        let x = number(&s, "x").unwrap_or_else(|| panic!("{src}: not a number"));
        assert!((x - want).abs() < 1e-14, "{src}: {x} ≠ {want}");
    }
    // a rotation is still a rotation, a plain matrix is not called one
    let out = prints("given a : scalar\nR = Rotz(a)\na = 20 deg\nR");
    assert!(out.ends_with(": SO(3)"), "{out}");
    let out = prints("given a : scalar\nM = [cos(a), 0; 0, 2]\na = 0.3\nM");
    assert!(!out.contains("SO(2)") && out.contains("0.9553"), "{out}");
    // partly bound: the other symbol stays, the number is right
    let (s, n, err) =
        session("given a, b : scalar\nc = cos(a + b)\na = 20 deg\nd = c\nb = 0.5\nx = d");
    assert_eq!(n, 0, "{err}");
    let x = number(&s, "x").expect("a number");
    assert!((x - (20f64.to_radians() + 0.5).cos()).abs() < 1e-14);
}

/// Issue 21, item 3: partial derivatives by a function of time or its
/// rate hold the other coordinates and rates fixed; by t, the chain rule.
#[test]
fn partial_derivatives_by_coordinates_and_rates() {
    let pre = "given q1(t), q2(t) : scalar\n";
    assert_eq!(last(&format!("{pre}diff(q1*q2, q1)")), "q2");
    assert_eq!(last(&format!("{pre}diff(q1', q1')")), "1");
    assert_eq!(last(&format!("{pre}diff(q1'^2 q2, q1')")), "2 q̇1 q2");
    assert_eq!(last(&format!("{pre}diff(q1*q2, t)")), "q1 q̇2 + q̇1 q2");
    assert_eq!(last(&format!("{pre}diff(sin(q1) q2', q1')")), "0");
    let lagrangian = "given q(t), m, g : scalar\nL = m q'^2/2 + m g cos(q)\n";
    assert_eq!(last(&format!("{lagrangian}diff(L, q')")), "m q̇");
    assert_eq!(last(&format!("{lagrangian}diff(L, q)")), "-g m sin(q)");
    assert_eq!(last(&format!("{lagrangian}diff(diff(L, q'), t)")), "m q̈");
    // and the bound values: ∂L/∂q̇ at m = 2, q̇ = 3
    let (s, n, err) = session(&format!(
        "{lagrangian}p = diff(L, q')\nm = 2\nq' = 3\nx = p"
    ));
    assert_eq!(n, 0, "{err}");
    assert_eq!(number(&s, "x"), Some(6.0));
}

/// Issue 21, item 4: declaring the time variable (or anything) later
/// changes nothing declared before.
#[test]
fn declaring_later_changes_nothing_before() {
    let out = last("given theta(t) : scalar\ngiven t : scalar\ndiff(sin(theta), t)");
    assert_eq!(out, "θ̇ cos(theta)");
    let out = last("given t : scalar\ngiven theta(t) : scalar\ndiff(t sin(theta), t)");
    assert_eq!(out, "sin(theta) + t θ̇ cos(theta)");
    let out = last("given theta(t) : scalar\nx = theta^2\ngiven theta : scalar\ndiff(x, t)");
    assert_eq!(out, "2 theta θ̇");
}

// ------------------------------------------------------ the differential test

use proptest::prelude::*;

#[path = "sym_differential/cases.rs"]
mod cases;
#[path = "sym_differential/latex.rs"]
mod latex;
#[path = "sym_differential/matrix.rs"]
mod matrix;
use std::f64::consts::PI;

/// Plain symbols.
const SYMS: [&str; 3] = ["a", "b", "c"];
/// Functions of time (of `t`).
const QS: [&str; 2] = ["q1", "q2"];

/// What a derivative is taken by.
#[derive(Debug, Clone, Copy)]
enum By {
    /// The time variable t: the total derivative.
    Time,
    /// A plain symbol.
    Sym(usize),
    /// A function of time q (`dots` 0) or its rate q̇ (`dots` 1): the
    /// partial derivative.
    Q(usize, u8),
}

/// A random expression over the engine's operations. Families the engine
/// gets wrong in another engineer's territory are left out of the
/// generator for now (see [`expr`]).
#[derive(Debug, Clone)]
enum T {
    Sym(usize),
    Time,
    /// q_i, q̇_i, q̈_i.
    Q(usize, u8),
    Int(i64),
    /// A decimal as typed, `m / 10^k`.
    Dec(i64, u32),
    Pi,
    Neg(Box<T>),
    Add(Box<T>, Box<T>),
    Sub(Box<T>, Box<T>),
    Mul(Box<T>, Box<T>),
    Div(Box<T>, Box<T>),
    Recip(Box<T>),
    Pow(Box<T>, i32),
    Sqrt(Box<T>),
    /// sin (true) or cos of an integer combination of a, b, t and q1, plus
    /// a multiple p/d of π (d ≤ 12), plus a decimal offset.
    Angle(bool, [i8; 4], (i8, u8), Option<(i64, u32)>),
    Sin(Box<T>),
    Cos(Box<T>),
    Tan(Box<T>),
    Asin(Box<T>),
    Acos(Box<T>),
    Atan(Box<T>),
    Atan2(Box<T>, Box<T>),
    Diff(Box<T>, By),
}

/// A point: a, b, c, t, and each q_i(τ) = Σ c_k τ^k / k! (so that q̇, q̈
/// are its derivatives at τ = t).
#[derive(Debug, Clone)]
struct Point {
    syms: [f64; 3],
    t: f64,
    q: [[f64; 5]; 2],
}

/// The values the leaves read: the point with its rates at time `t`, and
/// any overrides a finite difference makes.
#[derive(Debug, Clone)]
struct At {
    syms: [f64; 3],
    t: f64,
    /// q_i^{(k)} for k = 0..3.
    q: [[f64; 4]; 2],
    /// Set where the value is on a discontinuity (atan2 on its branch
    /// cut), where no rounding-free comparison is possible.
    ill: std::cell::Cell<bool>,
}

impl Point {
    fn at(&self, t: f64) -> At {
        let mut q = [[0.0; 4]; 2];
        for (i, c) in self.q.iter().enumerate() {
            for (k, out) in q[i].iter_mut().enumerate() {
                // d^k/dτ^k Σ c_j τ^j / j! = Σ_{j ≥ k} c_j τ^{j−k} / (j−k)!
                let mut fact = 1.0;
                for (j, cj) in c.iter().enumerate().skip(k) {
                    if j > k {
                        fact *= (j - k) as f64;
                    }
                    *out += cj * t.powi((j - k) as i32) / fact;
                }
            }
        }
        At {
            syms: self.syms,
            t,
            q,
            ill: std::cell::Cell::new(false),
        }
    }
}

fn dec(m: i64, k: u32) -> f64 {
    m as f64 / 10f64.powi(k as i32)
}

fn dec_src(m: i64, k: u32) -> String {
    let x = dec(m, k);
    format!("{x:.prec$}", prec = k as usize)
}

impl T {
    /// The value, evaluated directly in f64 (independent of the engine),
    /// and an estimate of its absolute rounding error in units of the
    /// machine epsilon — the size of the terms an expanded form adds up
    /// (products of sums expand; `(a − b)^9` at a ≈ b cancels), carried
    /// through the functions by their derivatives.
    fn eval(&self, at: &At) -> (f64, f64) {
        let (v, e) = self.eval_node(at);
        if v.is_infinite() {
            // an infinity inside (0^-1, t / inf) is no point to compare at
            at.ill.set(true);
        }
        (v, e)
    }

    fn eval_node(&self, at: &At) -> (f64, f64) {
        let un = |x: &T, f: &dyn Fn(f64) -> f64, df: &dyn Fn(f64) -> f64| {
            let (v, e) = x.eval(at);
            let y = f(v);
            (y, y.abs() + e * df(v).abs())
        };
        match self {
            T::Sym(i) => (at.syms[*i], at.syms[*i].abs()),
            T::Time => (at.t, at.t.abs()),
            T::Q(i, d) => {
                let v = at.q[*i][*d as usize];
                (v, v.abs())
            }
            T::Int(n) => (*n as f64, 0.0),
            T::Dec(m, k) => (dec(*m, *k), dec(*m, *k).abs()),
            T::Pi => (PI, PI),
            T::Neg(x) => {
                let (v, e) = x.eval(at);
                (-v, e)
            }
            T::Add(x, y) | T::Sub(x, y) => {
                let ((a, ea), (b, eb)) = (x.eval(at), y.eval(at));
                let v = if matches!(self, T::Add(..)) {
                    a + b
                } else {
                    a - b
                };
                (v, ea + eb)
            }
            T::Mul(x, y) => {
                let ((a, ea), (b, eb)) = (x.eval(at), y.eval(at));
                (a * b, ea * eb.max(b.abs()) + eb * ea.max(a.abs()))
            }
            T::Div(x, y) => {
                let ((a, ea), (b, eb)) = (x.eval(at), y.eval(at));
                let v = a / b;
                (v, (ea + v.abs() * eb) / b.abs() + v.abs())
            }
            T::Recip(x) => un(x, &|v| 1.0 / v, &|v| 1.0 / (v * v)),
            T::Pow(x, n) => {
                let (v, e) = x.eval(at);
                let y = v.powi(*n);
                let grow = if *n >= 0 {
                    e.max(v.abs()).powi(*n)
                } else {
                    y.abs() * (1.0 + (*n as f64).abs() * e / v.abs())
                };
                (y, grow + y.abs())
            }
            T::Sqrt(x) => un(x, &f64::sqrt, &|v| 0.5 / v.sqrt()),
            T::Angle(sin, k, (p, d), off) => {
                let (arg, _) = self.angle_arg(*k, *p, *d, *off, at);
                let v = if *sin { arg.sin() } else { arg.cos() };
                (v, 1.0 + arg.abs())
            }
            T::Sin(x) => un(x, &f64::sin, &f64::cos),
            T::Cos(x) => un(x, &f64::cos, &f64::sin),
            T::Tan(x) => un(x, &f64::tan, &|v| 1.0 + v.tan().powi(2)),
            T::Asin(x) => un(x, &f64::asin, &|v| 1.0 / (1.0 - v * v).sqrt()),
            T::Acos(x) => un(x, &f64::acos, &|v| 1.0 / (1.0 - v * v).sqrt()),
            T::Atan(x) => un(x, &f64::atan, &|v| 1.0 / (1.0 + v * v)),
            T::Atan2(y, x) => {
                let ((b, eb), (a, ea)) = (y.eval(at), x.eval(at));
                // an angle moves by at most the point's error over its radius
                let e = 1.0 + (ea + eb) / (a * a + b * b).sqrt();
                if a < 0.0 && b.abs() <= 1e-9 * (1.0 + eb) {
                    at.ill.set(true);
                }
                (b.atan2(a), e)
            }
            T::Diff(x, by) => x.derivative(*by, at),
        }
    }

    /// The value and a bound on the rounding error of evaluating the tree
    /// as written (each operation rounded once, errors carried to first
    /// order by the derivatives), in units of the machine epsilon: how far
    /// the same statements with the numbers typed first may be from the
    /// true value, so how far numbers bound later may be from them. (Not
    /// [`T::eval`]'s estimate, which allows for an expanded form's terms.)
    fn direct(&self, at: &At) -> (f64, f64) {
        let un = |x: &T, f: &dyn Fn(f64) -> f64, df: &dyn Fn(f64) -> f64| {
            let (v, e) = x.direct(at);
            let y = f(v);
            (y, y.abs() + e * df(v).abs())
        };
        match self {
            T::Int(_) => (self.eval(at).0, 0.0),
            // (a bound number is read as the decimal it prints as, exactly:
            // within half an ulp of the float, seed 906975: a + b at
            // a ≈ −b cancels to that half ulp, 7.5e-18 in 3.4e-4)
            T::Sym(_) | T::Time | T::Q(..) | T::Dec(..) | T::Pi => {
                let v = self.eval(at).0;
                (v, v.abs())
            }
            T::Neg(x) => {
                let (v, e) = x.direct(at);
                (-v, e)
            }
            T::Add(x, y) | T::Sub(x, y) => {
                let ((a, ea), (b, eb)) = (x.direct(at), y.direct(at));
                let v = if matches!(self, T::Add(..)) {
                    a + b
                } else {
                    a - b
                };
                (v, ea + eb + v.abs())
            }
            T::Mul(x, y) => {
                let ((a, ea), (b, eb)) = (x.direct(at), y.direct(at));
                let v = a * b;
                (v, ea * b.abs() + eb * a.abs() + v.abs())
            }
            T::Div(x, y) => {
                let ((a, ea), (b, eb)) = (x.direct(at), y.direct(at));
                let v = a / b;
                (v, (ea + v.abs() * eb) / b.abs() + v.abs())
            }
            T::Recip(x) => un(x, &|v| 1.0 / v, &|v| 1.0 / (v * v)),
            T::Pow(x, n) => {
                let (v, e) = x.direct(at);
                let y = v.powi(*n);
                let k = f64::from(n.abs());
                // each of the ~2 log2|n| products rounds once
                (
                    y,
                    k * (y / v).abs() * e + (1.0 + 2.0 * k.log2().max(1.0)) * y.abs(),
                )
            }
            T::Sqrt(x) => un(x, &f64::sqrt, &|v| 0.5 / v.sqrt()),
            T::Angle(sin, k, (p, d), off) => {
                let (arg, _) = self.angle_arg(*k, *p, *d, *off, at);
                let v = if *sin { arg.sin() } else { arg.cos() };
                // the argument is a sum of rounded terms
                (v, 1.0 + 4.0 * arg.abs())
            }
            T::Sin(x) => un(x, &f64::sin, &f64::cos),
            T::Cos(x) => un(x, &f64::cos, &f64::sin),
            T::Tan(x) => un(x, &f64::tan, &|v| 1.0 + v.tan().powi(2)),
            T::Asin(x) => un(x, &f64::asin, &|v| 1.0 / (1.0 - v * v).sqrt()),
            T::Acos(x) => un(x, &f64::acos, &|v| 1.0 / (1.0 - v * v).sqrt()),
            T::Atan(x) => un(x, &f64::atan, &|v| 1.0 / (1.0 + v * v)),
            T::Atan2(y, x) => {
                let ((b, eb), (a, ea)) = (y.direct(at), x.direct(at));
                let v = b.atan2(a);
                (v, v.abs() + (ea + eb) / (a * a + b * b).sqrt())
            }
            T::Diff(x, by) => {
                let (_, _, d, ed) = x.dual(at, *by);
                (d, ed)
            }
        }
    }

    /// The derivative by `by` of the tree written without derivatives,
    /// computed directly (forward mode: each node's value and derivative),
    /// with rounding bounds for both in units of the machine epsilon:
    /// (value, its bound, derivative, its bound).
    fn dual(&self, at: &At, by: By) -> (f64, f64, f64, f64) {
        // f(u) with f' and f'' at u
        let un = |x: &T, f: &dyn Fn(f64) -> (f64, f64, f64)| {
            let (u, eu, du, edu) = x.dual(at, by);
            let (v, d1, d2) = f(u);
            let d = d1 * du;
            (
                v,
                v.abs() + d1.abs() * eu,
                d,
                d1.abs() * edu + d2.abs() * eu * du.abs() + 2.0 * d.abs(),
            )
        };
        // how fast a leaf moves with `by`
        let rate = |leaf: &T| -> f64 {
            match (leaf, by) {
                (T::Sym(i), By::Sym(j)) if *i == j => 1.0,
                (T::Time, By::Time) => 1.0,
                (T::Q(i, k), By::Time) => at.q[*i][*k as usize + 1],
                (T::Q(i, k), By::Q(j, m)) if *i == j && *k == m => 1.0,
                _ => 0.0,
            }
        };
        match self {
            T::Sym(_) | T::Time | T::Q(..) | T::Int(_) | T::Dec(..) | T::Pi => {
                let (v, e) = self.direct(at);
                // (a rate of q is a bound number too)
                let d = rate(self);
                let ed = if matches!(self, T::Q(..)) {
                    d.abs()
                } else {
                    0.0
                };
                (v, e, d, ed)
            }
            T::Neg(x) => {
                let (v, e, d, ed) = x.dual(at, by);
                (-v, e, -d, ed)
            }
            T::Add(x, y) | T::Sub(x, y) => {
                let ((a, ea, da, eda), (b, eb, db, edb)) = (x.dual(at, by), y.dual(at, by));
                let s = if matches!(self, T::Add(..)) {
                    1.0
                } else {
                    -1.0
                };
                let (v, d) = (a + s * b, da + s * db);
                (v, ea + eb + v.abs(), d, eda + edb + d.abs())
            }
            T::Mul(x, y) => {
                let ((a, ea, da, eda), (b, eb, db, edb)) = (x.dual(at, by), y.dual(at, by));
                let (v, d) = (a * b, da * b + a * db);
                let ed = eda * b.abs() + da.abs() * eb + ea * db.abs() + a.abs() * edb;
                (
                    v,
                    ea * b.abs() + eb * a.abs() + v.abs(),
                    d,
                    ed + (da * b).abs() + (a * db).abs() + d.abs(),
                )
            }
            T::Div(x, y) => {
                let ((a, ea, da, eda), (b, eb, db, edb)) = (x.dual(at, by), y.dual(at, by));
                let v = a / b;
                let ev = (ea + v.abs() * eb) / b.abs() + v.abs();
                let d = (da - v * db) / b;
                let ed = (eda + ev * db.abs() + v.abs() * edb + (v * db).abs() + da.abs())
                    / b.abs()
                    + d.abs() * (eb / b.abs() + 3.0);
                (v, ev, d, ed)
            }
            T::Recip(x) => un(x, &|u| (1.0 / u, -1.0 / (u * u), 2.0 / (u * u * u))),
            T::Pow(x, n) => {
                let (n, k) = (*n, f64::from(*n));
                let (v, ev, d, ed) = un(x, &|u| {
                    (u.powi(n), k * u.powi(n - 1), k * (k - 1.0) * u.powi(n - 2))
                });
                // each of the ~2 log2|n| products rounds once
                let r = 1.0 + 2.0 * k.abs().log2().max(1.0);
                (v, ev + r * v.abs(), d, ed + r * d.abs())
            }
            T::Sqrt(x) => un(x, &|u| (u.sqrt(), 0.5 / u.sqrt(), -0.25 / (u * u.sqrt()))),
            T::Angle(sin, k, (p, d), off) => {
                let (arg, _) = self.angle_arg(*k, *p, *d, *off, at);
                let leaves = [T::Sym(0), T::Sym(1), T::Time, T::Q(0, 0)];
                let darg: f64 = k
                    .iter()
                    .zip(&leaves)
                    .map(|(c, l)| f64::from(*c) * rate(l))
                    .sum();
                let ea = 1.0 + 4.0 * arg.abs();
                let (v, d1) = if *sin {
                    (arg.sin(), arg.cos())
                } else {
                    (arg.cos(), -arg.sin())
                };
                let d = d1 * darg;
                (v, ea, d, ea * darg.abs() + 4.0 * d.abs())
            }
            T::Sin(x) => un(x, &|u| (u.sin(), u.cos(), -u.sin())),
            T::Cos(x) => un(x, &|u| (u.cos(), -u.sin(), -u.cos())),
            T::Tan(x) => un(x, &|u| {
                let s = 1.0 + u.tan().powi(2);
                (u.tan(), s, 2.0 * u.tan() * s)
            }),
            T::Asin(x) => un(x, &|u| {
                let r = 1.0 - u * u;
                (u.asin(), 1.0 / r.sqrt(), u / (r * r.sqrt()))
            }),
            T::Acos(x) => un(x, &|u| {
                let r = 1.0 - u * u;
                (u.acos(), -1.0 / r.sqrt(), -u / (r * r.sqrt()))
            }),
            T::Atan(x) => un(x, &|u| {
                let r = 1.0 + u * u;
                (u.atan(), 1.0 / r, -2.0 * u / (r * r))
            }),
            T::Atan2(y, x) => {
                let ((b, eb, db, edb), (a, ea, da, eda)) = (y.dual(at, by), x.dual(at, by));
                let r2 = a * a + b * b;
                let v = b.atan2(a);
                let d = (a * db - b * da) / r2;
                let ev = v.abs() + (ea + eb) / r2.sqrt();
                let ed = (a.abs() * edb
                    + db.abs() * ea
                    + b.abs() * eda
                    + da.abs() * eb
                    + (a * db).abs()
                    + (b * da).abs())
                    / r2
                    + d.abs() * (2.0 * (a.abs() * ea + b.abs() * eb) / r2 + 4.0);
                (v, ev, d, ed)
            }
            // (the generator writes no derivative inside a derivative)
            T::Diff(..) => (f64::NAN, f64::INFINITY, f64::NAN, f64::INFINITY),
        }
    }

    fn angle_arg(&self, k: [i8; 4], p: i8, d: u8, off: Option<(i64, u32)>, at: &At) -> (f64, ()) {
        let vars = [at.syms[0], at.syms[1], at.t, at.q[0][0]];
        let mut arg = PI * f64::from(p) / f64::from(d);
        arg += k
            .iter()
            .zip(vars)
            .map(|(c, v)| f64::from(*c) * v)
            .sum::<f64>();
        if let Some((m, e)) = off {
            arg += dec(m, e);
        }
        (arg, ())
    }

    /// The derivative by central differences (Richardson-extrapolated),
    /// with its error scale; NaN where two step sizes disagree (near a
    /// singularity, where no finite difference is trustworthy).
    fn derivative(&self, by: By, at: &At) -> (f64, f64) {
        let f = |h: f64| -> (f64, f64) {
            let mut p = at.clone();
            match by {
                By::Sym(i) => p.syms[i] += h,
                By::Q(i, d) => p.q[i][d as usize] += h,
                By::Time => {
                    p.t += h;
                    // q^{(k)}(t + h) by Taylor from the rates at t
                    for i in 0..2 {
                        let q = at.q[i];
                        for k in 0..4 {
                            let mut s = 0.0;
                            let mut fact = 1.0;
                            for (j, qj) in q.iter().enumerate().skip(k) {
                                if j > k {
                                    fact *= (j - k) as f64;
                                }
                                s += qj * h.powi((j - k) as i32) / fact;
                            }
                            p.q[i][k] = s;
                        }
                    }
                }
            }
            let v = self.eval(&p);
            if p.ill.get() {
                at.ill.set(true);
            }
            v
        };
        let d = |h: f64| (f(h).0 - f(-h).0) / (2.0 * h);
        let h = 1e-3;
        let (d1, d2) = (d(h), d(h / 2.0));
        let rich = (4.0 * d2 - d1) / 3.0;
        let (_, e) = f(0.0);
        if (d1 - d2).abs() > 1e-3 * (1.0 + rich.abs()) {
            return (f64::NAN, e);
        }
        (rich, e.max(rich.abs()))
    }

    /// The expression as chasles source, fully parenthesized.
    fn source(&self) -> String {
        let un = |f: &str, x: &T| format!("{f}({})", x.source());
        match self {
            T::Sym(i) => SYMS[*i].into(),
            T::Time => "t".into(),
            T::Q(i, d) => format!("{}{}", QS[*i], "'".repeat(*d as usize)),
            T::Int(n) => format!("({n})"),
            T::Dec(m, k) => format!("({})", dec_src(*m, *k)),
            T::Pi => "pi".into(),
            T::Neg(x) => format!("(-{})", x.source()),
            T::Add(x, y) => format!("({} + {})", x.source(), y.source()),
            T::Sub(x, y) => format!("({} - {})", x.source(), y.source()),
            T::Mul(x, y) => format!("({} * {})", x.source(), y.source()),
            T::Div(x, y) => format!("({} / {})", x.source(), y.source()),
            T::Recip(x) => format!("(1 / {})", x.source()),
            T::Pow(x, n) => format!("({}^({n}))", x.source()),
            T::Sqrt(x) => un("sqrt", x),
            T::Angle(sin, k, (p, d), off) => {
                let names = ["a", "b", "t", "q1"];
                let mut arg: Vec<String> = k
                    .iter()
                    .zip(names)
                    .filter(|(c, _)| **c != 0)
                    .map(|(c, n)| format!("({c}) * {n}"))
                    .collect();
                // (at d = 7, 10^15 whole turns more, exact: reduced exactly,
                // as the reference's angle without them, issue 35)
                match d {
                    7 => arg.push(format!("({p} + {} * 10^15) * pi / {d}", 2 * d)),
                    _ => arg.push(format!("({p}) * pi / {d}")),
                }
                if let Some((m, e)) = off {
                    arg.push(format!("({})", dec_src(*m, *e)));
                }
                format!("{}({})", if *sin { "sin" } else { "cos" }, arg.join(" + "))
            }
            T::Sin(x) => un("sin", x),
            T::Cos(x) => un("cos", x),
            T::Tan(x) => un("tan", x),
            T::Asin(x) => un("asin", x),
            T::Acos(x) => un("acos", x),
            T::Atan(x) => un("atan", x),
            T::Atan2(y, x) => format!("atan2({}, {})", y.source(), x.source()),
            T::Diff(x, by) => {
                let by = match by {
                    By::Time => "t".to_string(),
                    By::Sym(i) => SYMS[*i].to_string(),
                    By::Q(i, d) => format!("{}{}", QS[*i], "'".repeat(*d as usize)),
                };
                format!("diff({}, {by})", x.source())
            }
        }
    }
}

fn b<X>(x: X) -> Box<X> {
    Box::new(x)
}

/// Families the engine still gets wrong in another engineer's territory
/// (issue 21); left out of the generator until fixed there:
/// - `RECIPROCALS` (`exact`, item 2): 1/x, quotients and negative powers of
///   sums print 0, inf or NaN (`1/sin(t)`, `(cos(q1 - 10π/3))^-2`).
const RECIPROCALS: bool = true;

/// The generator (see the families left out above).
fn expr() -> impl Strategy<Value = T> {
    let offset = prop::option::of((-300..300i64, 1..4u32));
    let angle = (
        any::<bool>(),
        prop::array::uniform4(-2..3i8),
        (-12..13i8, 1..13u8),
        offset.clone(),
    )
        .prop_map(|(s, k, pd, off)| T::Angle(s, k, pd, off));
    // `(sin a + cos b)^30`: a high power of a sum, whose expanded form has
    // coefficients that cancel (1e16 and more) where the sum is small
    let power = (
        prop_oneof![angle.clone(), (0..3usize).prop_map(T::Sym)],
        angle.clone(),
        // (mostly up to 12, which shows the cancellation as well — the old
        // evaluation failed at 8 and 10 — and is cheaper to expand than 30)
        prop_oneof![6 => 8..13i32, 1 => 13..31i32],
    )
        .prop_map(|(x, y, n)| T::Pow(b(T::Add(b(x), b(y))), n));
    let leaf = prop_oneof![
        (0..3usize).prop_map(T::Sym),
        Just(T::Time),
        (0..2usize, 0..2u8).prop_map(|(i, d)| T::Q(i, d)),
        (-3..4i64).prop_map(T::Int),
        (-999..1000i64, 1..4u32).prop_map(|(m, k)| T::Dec(m, k)),
        Just(T::Pi),
        angle,
    ];
    let tree = leaf.prop_recursive(3, 16, 2, |inner| {
        prop_oneof![
            3 => (inner.clone(), inner.clone()).prop_map(|(x, y)| T::Add(b(x), b(y))),
            2 => (inner.clone(), inner.clone()).prop_map(|(x, y)| T::Sub(b(x), b(y))),
            3 => (inner.clone(), inner.clone()).prop_map(|(x, y)| T::Mul(b(x), b(y))),
            1 => (inner.clone(), inner.clone()).prop_map(|(x, y)| if RECIPROCALS {
                T::Div(b(x), b(y))
            } else {
                T::Mul(b(x), b(y))
            }),
            1 => inner.clone().prop_map(|x| if RECIPROCALS { T::Recip(b(x)) } else { T::Neg(b(x)) }),
            1 => inner.clone().prop_map(|x| T::Neg(b(x))),
            2 => (inner.clone(), if RECIPROCALS { -2..4i32 } else { 0..4i32 })
                .prop_map(|(x, n)| T::Pow(b(x), n)),
            1 => inner.clone().prop_map(|x| T::Sqrt(b(x))),
            1 => inner.clone().prop_map(|x| T::Sin(b(x))),
            1 => inner.clone().prop_map(|x| T::Cos(b(x))),
            1 => inner.clone().prop_map(|x| T::Tan(b(x))),
            1 => inner.clone().prop_map(|x| T::Asin(b(x))),
            1 => inner.clone().prop_map(|x| T::Acos(b(x))),
            1 => inner.clone().prop_map(|x| T::Atan(b(x))),
            1 => (inner.clone(), inner).prop_map(|(y, x)| T::Atan2(b(y), b(x))),
        ]
    });
    let by = prop_oneof![
        Just(By::Time),
        (0..3usize).prop_map(By::Sym),
        (0..2usize, 0..2u8).prop_map(|(i, d)| By::Q(i, d)),
    ];
    prop_oneof![
        48 => tree.clone(),
        16 => (tree.clone(), by.clone()).prop_map(|(x, by)| T::Diff(b(x), by)),
        14 => (tree.clone(), tree.clone(), by.clone()).prop_map(|(x, y, by)| T::Mul(b(x), b(T::Diff(b(y), by)))),
        1 => power.clone(),
        1 => (power.clone(), tree).prop_map(|(p, x)| T::Mul(b(p), b(x))),
        1 => (power, by).prop_map(|(p, by)| T::Diff(b(p), by)),
    ]
}

fn point() -> impl Strategy<Value = Point> {
    (
        prop::array::uniform3(-2.0..2.0f64),
        -1.0..1.0f64,
        prop::array::uniform2(prop::array::uniform5(-1.5..1.5f64)),
    )
        .prop_map(|(syms, t, q)| Point { syms, t, q })
}

/// The statements binding the point's numbers (q̈ too, which derivatives
/// by t bring in).
fn bindings(at: &At) -> String {
    let mut s = String::new();
    for (n, v) in SYMS.iter().zip(at.syms) {
        s += &format!("{n} = {v:?}\n");
    }
    s += &format!("t = {:?}\n", at.t);
    for (i, q) in QS.iter().enumerate() {
        for d in 0..3 {
            s += &format!("{q}{} = {:?}\n", "'".repeat(d), at.q[i][d]);
        }
    }
    s
}

/// What one case showed: checked, refused by the engine (an error), or
/// skipped (the reference is not finite or not trustworthy there).
#[derive(Debug, Default)]
struct Tally {
    checked: usize,
    refused: usize,
    skipped: usize,
    /// Printed forms (text and LaTeX) parsed back and found to be the value.
    printed: usize,
    /// Printed forms that do not run back as chasles source.
    unparsed: usize,
}

/// Checks one expression at one point; Err describes a wrong answer.
/// The value bound later must be within 16 ε times [`T::direct`]'s
/// rounding bound of the tree's direct value (a derivative's computed in
/// forward mode, [`T::dual`]), and without a derivative of the value with
/// the numbers typed first: near machine precision, so an expanded form
/// evaluated in floats (whose coefficients cancel) fails it.
fn check(e: &T, p: &Point, tally: &mut Tally) -> Result<(), String> {
    let at = p.at(p.t);
    // (marks the points on a branch cut or at an infinity)
    let _ = e.eval(&at);
    // The value is compared near machine precision: within a few times the
    // rounding of its direct evaluation (of the statements typed first).
    let (want, rounding) = e.direct(&at);
    let tol = 16.0 * f64::EPSILON * rounding;
    let meaningless = !tol.is_finite() || tol > 1e-6 * want.abs().max(1.0);
    if at.ill.get() || !want.is_finite() || meaningless {
        tally.skipped += 1;
        return Ok(());
    }
    let src = e.source();
    let decl = "given a, b, c : scalar\ngiven q1(t), q2(t) : scalar\n";
    let later = format!("{decl}x = {src}\n{}y = x\n", bindings(&at));
    if std::env::var_os("CHASLES_DIFF_SHOW").is_some() {
        eprintln!("{later}");
    }
    let (s, n, msg) = session(&later);
    if n > 0 {
        // a refusal is an answer; a wrong value is not
        if std::env::var_os("CHASLES_DIFF_VERBOSE").is_some() {
            eprintln!("refused: {src}\n{msg}");
        }
        tally.refused += 1;
        return Ok(());
    }
    let got = number(&s, "y").ok_or_else(|| {
        format!(
            "bound later, the value is not a number: {:?}\n{later}{msg}",
            s.env.get("y").and_then(|b| b.val.clone())
        )
    })?;
    if !((got - want).abs() <= tol || (got.is_nan() && want.is_nan())) {
        return Err(format!(
            "bound later: {got} but {want} (tolerance {tol:e})\n{later}"
        ));
    }
    // (typed first, a diff or subs by a symbol that has a number reads the
    // symbol: src/eval/hold.rs)
    {
        let first = format!("{}x = {src}\n", bindings(&at));
        let (s, n, msg) = session(&first);
        if n == 0 {
            let typed = number(&s, "x")
                .ok_or_else(|| format!("numbers first give no number\n{first}{msg}"))?;
            // both within the rounding of the direct evaluation of the
            // value; identical where no exact simplification intervenes
            if (typed - got).abs() > 2.0 * tol {
                return Err(format!(
                    "numbers first {typed}, bound later {got}\n{first}\n{later}"
                ));
            }
        }
    }
    printed_is_value(e, &src, &at, want, tally)?;
    tally.checked += 1;
    Ok(())
}

/// The printed text of the value over free symbols, and its LaTeX
/// ([`latex`]), parsed back and evaluated at the point, are the value
/// (issue 35: `1/tan(t)` printed `1/((cos(t)) sin(t))`, a different
/// function). A float coefficient prints with 4 digits, so a form is the
/// value within 1e-3 of the size of its terms; a wrong structure is off
/// by far more at almost every point.
fn printed_is_value(e: &T, src: &str, at: &At, want: f64, tally: &mut Tally) -> Result<(), String> {
    let decl = "given a, b, c : scalar\ngiven q1(t), q2(t) : scalar\n";
    let shown = format!("{decl}x = {src}\n");
    let mut s = Session::new(Settings {
        json: true,
        ..Settings::default()
    });
    let (out, _, n) = s.run_to_strings("t.chs", &shown, Mode::Run, false);
    let line = out
        .lines()
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .find(|j| j["name"] == "x");
    let Some(line) = line.filter(|_| n == 0) else {
        return Ok(());
    };
    let (Some(text), Some(tex)) = (line["value"].as_str(), line["latex"].as_str()) else {
        // (a number: nothing symbolic printed)
        return Ok(());
    };
    let mut text = text.to_string();
    for (i, q) in QS.iter().enumerate() {
        text = text.replace(&format!("q\u{308}{}", i + 1), &format!("{q}''"));
        text = text.replace(&format!("q\u{307}{}", i + 1), &format!("{q}'"));
    }
    let (_, terms) = e.eval(at);
    let tol = 1e-3 * (1.0 + want.abs() + terms);
    for (form, source) in [("text", Some(text)), ("LaTeX", latex::source(tex))] {
        let Some(source) = source else {
            tally.unparsed += 1;
            continue;
        };
        let back = format!("{decl}z = {source}\n{}w = z\n", bindings(at));
        let (s, n, msg) = session(&back);
        let got = (n == 0).then(|| number(&s, "w")).flatten();
        let Some(got) = got else {
            tally.unparsed += 1;
            if std::env::var_os("CHASLES_DIFF_VERBOSE").is_some() {
                eprintln!("printed {form} does not run back: {source}\n{msg}");
            }
            continue;
        };
        if (got - want).abs().is_nan() || (got - want).abs() > tol {
            return Err(format!(
                "the printed {form} is not the value: {source} is {got} at the point, the value {want}\n{shown}\n{back}"
            ));
        }
        tally.printed += 1;
    }
    Ok(())
}

/// `x` rewritten by an exact identity (the same function of the symbols,
/// written differently): `==` must say true. The identity is summed first,
/// so that floats in `x` see no rounding of their own (`==` on floats
/// summed in another order is `exact`'s, item 5).
fn identity(x: &T, which: usize) -> String {
    let x = x.source();
    match which % 5 {
        0 => format!("((sin(a - t)^2 + cos(a - t)^2 - 1) + {x})"),
        1 => format!("({x} * (cos(q1)^2 + sin(q1)^2))"),
        2 => format!("((sin(2 b) - 2 sin(b) cos(b)) + {x})"),
        3 => format!("(2 * {x} - {x})"),
        _ => format!("((cos(a + q2) - (cos(a) cos(q2) - sin(a) sin(q2))) + {x})"),
    }
}

/// What the `==` cases answered: on two random sides (`true`, `false`,
/// undecided) and on a side against an identity rewriting of it (`true`,
/// undecided: the second is a failure unless `CHASLES_DIFF_TALLY` is set,
/// which counts it and goes on, to measure).
#[derive(Debug, Default)]
struct Answers {
    sides: [usize; 3],
    identity: [usize; 2],
}

/// `==` on symbolic sides: never true where the point shows a
/// difference, true for `x` against an exact identity rewriting of it.
fn check_equal(x: &T, y: &T, which: usize, p: &Point, seen: &mut Answers) -> Result<(), String> {
    let at = p.at(p.t);
    let (u, eu) = x.eval(&at);
    let (v, ev) = y.eval(&at);
    if !(u.is_finite() && v.is_finite() && eu.is_finite() && ev.is_finite()) || at.ill.get() {
        // an infinity is no function to compare (inf − inf)
        return Ok(());
    }
    let decl = "given a, b, c : scalar\ngiven q1(t), q2(t) : scalar\n";
    let src = format!("{decl}e = {} == {}\n", x.source(), y.source());
    if std::env::var_os("CHASLES_DIFF_SHOW").is_some() {
        eprintln!("{src}e = {} == {}", x.source(), identity(x, which));
    }
    let (s, n, _) = session(&src);
    let differ = (u - v).abs() > 1e-6 * eu.max(ev).max(1.0);
    let answer = if n == 0 { value(&s, "e") } else { None };
    if matches!(answer, Some(Value::Bool(true))) && differ {
        return Err(format!("== says true, but {u} ≠ {v} at {p:?}\n{src}"));
    }
    match answer {
        Some(Value::Bool(true)) => seen.sides[0] += 1,
        Some(Value::Bool(false)) => seen.sides[1] += 1,
        Some(_) => seen.sides[2] += 1,
        None => {}
    }
    let src = format!("{decl}e = {} == {}\n", x.source(), identity(x, which));
    let (s, n, msg) = session(&src);
    if n == 0 {
        if matches!(value(&s, "e"), Some(Value::Bool(true))) {
            seen.identity[0] += 1;
        } else if std::env::var_os("CHASLES_DIFF_TALLY").is_some() {
            eprintln!("not true on an identity:\n{src}");
            seen.identity[1] += 1;
        } else {
            return Err(format!("== is not true on an identity\n{src}{msg}"));
        }
    }
    Ok(())
}

/// The value bound to `name` as it is shown (a comparison over symbols is
/// kept as a bool decided again once they have numbers: its bool).
fn value(s: &Session, name: &str) -> Option<Value> {
    let v = s.env.get(name).and_then(|b| b.val.clone())?;
    Some(chasles::eval::formula::constant_shown(&v).unwrap_or(v))
}

/// `==` over the same random expressions: `CHASLES_DIFF_CASES` / 4 cases
/// (500 by default), reproducible by seed ([`cases`]).
#[test]
fn equality_is_never_wrongly_true_and_sees_identities() {
    let seen = std::cell::RefCell::new(Answers::default());
    cases::run(
        "==",
        cases::count(500, 0.25),
        (expr(), expr(), 0..5usize, point()),
        |(x, y, k, p)| check_equal(x, y, *k, p, &mut seen.borrow_mut()),
    );
    let a = seen.into_inner();
    eprintln!(
        "== on two sides: true {}, false {}, cannot decide {}; on an identity: true {}, \
         cannot decide {}",
        a.sides[0], a.sides[1], a.sides[2], a.identity[0], a.identity[1]
    );
}

/// The differential test over vectors, matrices and the Lie builtins
/// ([`matrix`]), for release runs: `CHASLES_DIFF_CASES` × 0.15 cases
/// (3,000 by default), reproducible by seed ([`cases`]):
/// `cargo test --release --test sym_differential -- --ignored random_matrices`.
#[test]
#[ignore = "thousands of cases: run in release"]
fn random_matrices_agree_with_numbers() {
    cases::run(
        "matrices",
        cases::count(3000, 0.15),
        matrix::case(),
        matrix::check,
    );
}

/// The same generator in CI (debug): 100 cases from the seeds 0..100 (or
/// `CHASLES_DIFF_SEED` on), about 15 s of CPU.
#[test]
fn random_matrices_agree_with_numbers_in_ci() {
    cases::run("matrices (CI)", 100, matrix::case(), matrix::check);
}

/// The differential test: `CHASLES_DIFF_CASES` cases (2,000 by default),
/// reproducible by seed ([`cases`]).
#[test]
fn random_expressions_agree_with_numbers() {
    let tally = std::cell::RefCell::new(Tally::default());
    cases::run(
        "bound later",
        cases::count(2000, 1.0),
        (expr(), point()),
        |(e, p)| check(e, p, &mut tally.borrow_mut()),
    );
    let t = tally.into_inner();
    eprintln!(
        "checked {}, refused {}, skipped {}; printed forms run back {} (unparsed {})",
        t.checked, t.refused, t.skipped, t.printed, t.unparsed
    );
}
