//! Symbolic scalars and matrices (LANGUAGE.md §7, issue 15): the canonical
//! form agrees with numbers, equal forms mean equal functions, the book's
//! closed forms come out, frames are checked as for numbers, and the UR5
//! product of exponentials agrees with the numeric one.

use chasles::eval::env::Mode;
use chasles::eval::value::Value;
use chasles::session::{Session, Settings};
use chasles::sym::coef::{Coef, Rat};
use chasles::sym::matrix::{self, Mat};
use chasles::sym::{Expr, Symbol};
use num_traits::One;
use proptest::prelude::*;

// ---------------------------------------------------------------- engine

/// A random expression over the supported operations, with its direct
/// numeric meaning alongside its canonical form.
#[derive(Debug, Clone)]
enum E {
    Var(usize),
    Int(i64),
    Half,
    Sqrt2,
    Pi,
    Add(Box<E>, Box<E>),
    Sub(Box<E>, Box<E>),
    Mul(Box<E>, Box<E>),
    Pow(Box<E>, u8),
    /// sin or cos of an integer combination of the variables plus q·π/d
    /// plus a decimal offset in tenths (π/5, 0.3: phase variables).
    Trig(bool, [i8; 3], u8, u8, i8),
    SqrtOf(u8),
}

const NAMES: [&str; 3] = ["a", "b", "c"];

impl E {
    fn build(&self) -> Expr {
        match self {
            E::Var(i) => Expr::symbol(Symbol::new(NAMES[*i])),
            E::Int(n) => Expr::int(*n),
            E::Half => Expr::num(0.5),
            E::Sqrt2 => Expr::sqrt(&Expr::int(2)),
            E::Pi => Expr::pi(),
            E::Add(x, y) => x.build().add(&y.build()),
            E::Sub(x, y) => x.build().sub(&y.build()),
            E::Mul(x, y) => x.build().mul(&y.build()),
            E::Pow(x, n) => x.build().powi(i64::from(*n)).unwrap(),
            E::Trig(sin, k, q, d, tenths) => {
                let mut arg = Expr::pi()
                    .scale(&Coef::rat(
                        Rat::new(i128::from(*q), i128::from(*d)).unwrap(),
                    ))
                    .add(&Expr::typed(f64::from(*tenths) / 10.0));
                for (i, c) in k.iter().enumerate() {
                    let v = Expr::symbol(Symbol::new(NAMES[i]));
                    arg = arg.add(&v.scale(&Coef::int(i64::from(*c))));
                }
                if *sin {
                    Expr::sin(&arg)
                } else {
                    Expr::cos(&arg)
                }
            }
            E::SqrtOf(n) => Expr::sqrt(&Expr::int(i64::from(*n))),
        }
    }
    fn eval(&self, at: &[f64; 3]) -> f64 {
        match self {
            E::Var(i) => at[*i],
            E::Int(n) => *n as f64,
            E::Half => 0.5,
            E::Sqrt2 => 2f64.sqrt(),
            E::Pi => std::f64::consts::PI,
            E::Add(x, y) => x.eval(at) + y.eval(at),
            E::Sub(x, y) => x.eval(at) - y.eval(at),
            E::Mul(x, y) => x.eval(at) * y.eval(at),
            E::Pow(x, n) => x.eval(at).powi(i32::from(*n)),
            E::Trig(sin, k, q, d, tenths) => {
                let arg: f64 = std::f64::consts::PI * f64::from(*q) / f64::from(*d)
                    + f64::from(*tenths) / 10.0
                    + k.iter()
                        .zip(at)
                        .map(|(c, x)| f64::from(*c) * x)
                        .sum::<f64>();
                if *sin { arg.sin() } else { arg.cos() }
            }
            E::SqrtOf(n) => f64::from(*n).sqrt(),
        }
    }
    /// A bound on the size of the terms the expression expands into (every
    /// sum and difference taken with absolute values, sines and cosines
    /// as 1): evaluating an expanded form in floating point loses up to a
    /// few ulps of this, however small the value is. `(√3 − √2)^9` is
    /// 3.3e-5, but its exact canonical form a + b√2 + c√3 + d√6 has terms
    /// near 3e4 that cancel.
    fn scale(&self, at: &[f64; 3]) -> f64 {
        match self {
            E::Add(x, y) | E::Sub(x, y) => x.scale(at) + y.scale(at),
            E::Mul(x, y) => x.scale(at) * y.scale(at),
            E::Pow(x, n) => x.scale(at).powi(i32::from(*n)),
            E::Trig(..) => 1.0,
            leaf => leaf.eval(at).abs(),
        }
    }
}

impl E {
    /// The expression as chasles source, fully parenthesized.
    fn source(&self) -> String {
        match self {
            E::Var(i) => NAMES[*i].to_string(),
            E::Int(n) => format!("({n})"),
            E::Half => "0.5".into(),
            E::Sqrt2 => "sqrt(2)".into(),
            E::Pi => "pi".into(),
            E::Add(x, y) => format!("({} + {})", x.source(), y.source()),
            E::Sub(x, y) => format!("({} - {})", x.source(), y.source()),
            E::Mul(x, y) => format!("({} * {})", x.source(), y.source()),
            E::Pow(x, n) => format!("({})^{n}", x.source()),
            E::Trig(sin, k, q, d, tenths) => {
                let arg: Vec<String> = k
                    .iter()
                    .zip(NAMES)
                    .map(|(c, n)| format!("({c}) * {n}"))
                    .collect();
                let f = if *sin { "sin" } else { "cos" };
                format!(
                    "{f}({} + {q} * pi / {d} + ({tenths}) / 10)",
                    arg.join(" + ")
                )
            }
            E::SqrtOf(n) => format!("sqrt({n})"),
        }
    }
}

fn expr() -> impl Strategy<Value = E> {
    let leaf = prop_oneof![
        (0..3usize).prop_map(E::Var),
        (-3..4i64).prop_map(E::Int),
        Just(E::Half),
        Just(E::Sqrt2),
        Just(E::Pi),
        (
            any::<bool>(),
            prop::array::uniform3(-2..3i8),
            0..8u8,
            prop::sample::select(vec![4u8, 4, 5, 7, 9]),
            prop::sample::select(vec![0i8, 0, 0, 3, -7])
        )
            .prop_map(|(s, k, q, d, x)| E::Trig(s, k, q, d, x)),
        (0..13u8).prop_map(E::SqrtOf),
    ];
    leaf.prop_recursive(4, 24, 2, |inner| {
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(x, y)| E::Add(Box::new(x), Box::new(y))),
            (inner.clone(), inner.clone()).prop_map(|(x, y)| E::Sub(Box::new(x), Box::new(y))),
            (inner.clone(), inner.clone()).prop_map(|(x, y)| E::Mul(Box::new(x), Box::new(y))),
            (inner, 0..4u8).prop_map(|(x, n)| E::Pow(Box::new(x), n)),
        ]
    })
}

fn point() -> impl Strategy<Value = [f64; 3]> {
    prop::array::uniform3(-3.0..3.0f64)
}

fn at(p: &[f64; 3]) -> impl Fn(&Symbol) -> Option<f64> + '_ {
    move |s: &Symbol| NAMES.iter().position(|n| **n == *s.name).map(|i| p[i])
}

/// Equal to 1e-12 relative to the larger of the two and `scale` (the size
/// of the terms that cancel, [`E::scale`]).
fn close(x: f64, y: f64, scale: f64) -> bool {
    (x - y).abs() <= 1e-12 * x.abs().max(y.abs()).max(scale).max(1.0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// The canonical form evaluated at a point is the expression's value.
    #[test]
    fn canonical_form_evaluates_like_the_expression(e in expr(), p in point()) {
        let want = e.eval(&p);
        let got = e.build().eval(&at(&p)).unwrap();
        prop_assume!(want.abs() < 1e6);
        prop_assert!(close(got, want, e.scale(&p)), "{got} vs {want} for {e:?}");
    }

    /// Equal canonical forms never differ numerically.
    #[test]
    fn equal_forms_are_equal_functions(x in expr(), y in expr(), p in point()) {
        let (a, b) = (x.build(), y.build());
        if a == b {
            let (u, v) = (x.eval(&p), y.eval(&p));
            prop_assume!(u.abs() < 1e6);
            prop_assert!((u - v).abs() <= 1e-9 * u.abs().max(1.0), "{x:?} == {y:?}");
        }
    }

    /// `x == y` in the language never says true for expressions that
    /// differ at a point (an undecided comparison is an error, not true).
    #[test]
    fn language_equality_is_never_wrongly_true(x in expr(), y in expr(), p in point()) {
        let src = format!("given a, b, c : scalar\n{} == {}", x.source(), y.source());
        let mut s = Session::new(Settings { json: true, ..Settings::default() });
        let (out, _, _) = s.run_to_strings("t.chs", &src, Mode::Run, false);
        let last: serde_json::Value = serde_json::from_str(out.lines().last().unwrap()).unwrap();
        if last["value"] == serde_json::Value::Bool(true) {
            let (u, v) = (x.eval(&p), y.eval(&p));
            prop_assume!(u.abs() < 1e6);
            prop_assert!((u - v).abs() <= 1e-9 * u.abs().max(1.0), "{src}");
        }
        // an expression always equals itself
        let same = format!("given a, b, c : scalar\n{} == {}", x.source(), x.source());
        let mut s = Session::new(Settings { json: true, ..Settings::default() });
        let (out, _, _) = s.run_to_strings("t.chs", &same, Mode::Run, false);
        let last: serde_json::Value = serde_json::from_str(out.lines().last().unwrap()).unwrap();
        prop_assert_eq!(&last["value"], &serde_json::Value::Bool(true), "{}", same);
    }

    /// Known identities are decided true, with no numbers.
    #[test]
    fn identities_are_recognized(p in point(), k in 1..4i64) {
        let v = |i: usize| Expr::symbol(Symbol::new(NAMES[i]));
        let (a, b) = (v(0), v(1));
        let sq = |e: Expr| e.powi(2).unwrap();
        prop_assert_eq!(sq(Expr::sin(&a)).add(&sq(Expr::cos(&a))), Expr::one());
        let ka = a.scale(&Coef::int(k));
        prop_assert_eq!(
            Expr::sin(&a.add(&b)),
            Expr::sin(&a).mul(&Expr::cos(&b)).add(&Expr::cos(&a).mul(&Expr::sin(&b)))
        );
        prop_assert_eq!(
            Expr::sin(&ka.scale(&Coef::int(2))),
            Expr::sin(&ka).mul(&Expr::cos(&ka)).scale(&Coef::int(2))
        );
        // cos 3a in powers of cos a
        let c = Expr::cos(&a);
        prop_assert_eq!(
            Expr::cos(&a.scale(&Coef::int(3))),
            c.powi(3).unwrap().scale(&Coef::int(4)).sub(&c.scale(&Coef::int(3)))
        );
        // offsets that are no multiple of π/12 fold as angles do
        let off = |q: i128, d: i128, x: f64| {
            Expr::pi()
                .scale(&Coef::rat(Rat::new(q, d).unwrap()))
                .add(&Expr::typed(x))
        };
        let a5 = a.add(&off(k as i128, 5, 0.3));
        prop_assert_eq!(sq(Expr::sin(&a5)).add(&sq(Expr::cos(&a5))), Expr::one());
        prop_assert_eq!(
            Expr::cos(&a5.add(&b)),
            Expr::cos(&a5).mul(&Expr::cos(&b)).sub(&Expr::sin(&a5).mul(&Expr::sin(&b)))
        );
        // π/5 + π/12 = 17π/60: the exact part and the phase split alike
        let (a17, a12) = (a.add(&off(17, 60, 0.0)), off(1, 12, 0.0));
        let a5 = a.add(&off(1, 5, 0.0));
        prop_assert_eq!(
            Expr::sin(&a17),
            Expr::sin(&a5).mul(&Expr::cos(&a12)).add(&Expr::cos(&a5).mul(&Expr::sin(&a12)))
        );
        // 10 (π/5) is a whole turn
        prop_assert_eq!(
            Expr::cos(&a5.scale(&Coef::int(10))),
            Expr::cos(&a.scale(&Coef::int(10)))
        );
        let _ = p;
    }

    /// Rodrigues' rotation times its transpose is I for any rational axis,
    /// and exponentials of one screw add their angles.
    #[test]
    fn rotation_identities((x, y, z) in prop::sample::select(exact_axes())) {
        // the axis exactly: c/√(x² + y² + z²) (no closed form is guessed from floats)
        let n = Expr::sqrt(&Expr::int(x * x + y * y + z * z));
        let w: Vec<Expr> = [x, y, z].iter().map(|c| Expr::int(*c).div(&n).unwrap()).collect();
        let t = Expr::symbol(Symbol::new("a"));
        let r = matrix::rodrigues(&w, &t);
        prop_assert_eq!(r.mul(&r.transpose()).unwrap(), Mat::identity(3));
        let s = Expr::symbol(Symbol::new("b"));
        let r2 = matrix::rodrigues(&w, &s);
        prop_assert_eq!(r.mul(&r2).unwrap(), matrix::rodrigues(&w, &t.add(&s)));
    }
}

/// Integer axes (x, y, z), z > 0, whose length is exact in ℚ(√2, √3):
/// |w|² = k² times 1, 2, 3 or 6.
fn exact_axes() -> Vec<(i64, i64, i64)> {
    let mut axes = Vec::new();
    for x in -5..6i64 {
        for y in -5..6i64 {
            for z in 1..6i64 {
                let n2 = x * x + y * y + z * z;
                if (1..=20).any(|k| [1, 2, 3, 6].iter().any(|r| k * k * r == n2)) {
                    axes.push((x, y, z));
                }
            }
        }
    }
    axes
}

// ---------------------------------------------------------------- language

/// Identities of chapter 3 that `==` decides true with no numbers.
#[test]
fn equality_decides_the_books_identities() {
    let w = "(0, 0.6, 0.8)";
    let s1 = "(0, 0, 1, 0, -2, 0.5)";
    let s2 = "(1, 0, 0, 0, 0, 1)";
    let pairs = [
        ("cos(a)^2 + sin(a)^2".to_string(), "1".to_string()),
        ("cos(a + b)".into(), "cos(a) cos(b) - sin(a) sin(b)".into()),
        ("sin(2 a)".into(), "2 sin(a) cos(a)".into()),
        ("Rotz(a) Rotz(b)".into(), "Rotz(a + b)".into()),
        (
            "Rot((1, 2, 2)/3, a) Rot((1, 2, 2)/3, a)^T".into(),
            "I".into(),
        ),
        ("det(Rot((1, 2, 2)/3, a))".into(), "1".into()),
        (
            format!("exp([{w}] a) exp([{w}] b)"),
            format!("exp([{w}] (a + b))"),
        ),
        (
            format!("Ad(exp([{s1}] a) exp([{s2}] b))"),
            format!("Ad(exp([{s1}] a)) Ad(exp([{s2}] b))"),
        ),
        (format!("inv(exp([{s1}] a)) exp([{s1}] a)"), "I".into()),
        ("diff(sin(a)^2, a)".into(), "2 sin(a) cos(a)".into()),
        ("trace(Rotz(a))".into(), "1 + 2 cos(a)".into()),
        (
            "cross((cos(a), sin(a), 0), (0, 0, 1))".into(),
            "(sin(a), -cos(a), 0)".into(),
        ),
    ];
    for (l, r) in pairs {
        let src = format!("given a, b : scalar\n{l} == {r}");
        let out = run(&mut session(), &src);
        assert_eq!(out.trim_end(), "true", "{src}");
    }
    let out = run(&mut session(), "given a : scalar\ncos(a) == sin(a)");
    assert_eq!(out.trim_end(), "false");
}

fn session() -> Session {
    Session::new(Settings::default())
}

/// Runs `src`, failing on any error; returns stdout.
fn run(s: &mut Session, src: &str) -> String {
    let (out, err, n) = s.run_to_strings("t.chs", src, Mode::Run, false);
    assert_eq!(n, 0, "{src}\n{err}");
    out
}

fn run_with(settings: Settings, src: &str) -> String {
    let mut s = Session::new(settings);
    run(&mut s, src)
}

fn formula(s: &Session, name: &str) -> Mat {
    match s.env.get(name).and_then(|b| b.val.clone()) {
        Some(Value::Formula { m, .. }) => m,
        other => panic!("{name} is not symbolic: {other:?}"),
    }
}

#[test]
fn planar_2r_arm_is_the_books_closed_form() {
    let src = "given t1, t2, L1, L2 : scalar
        S1 = (0, 0, 1, 0, 0, 0)
        S2 = (0, 0, 1, 0, -L1, 0)
        M = [1, 0, 0, L1 + L2; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1]
        T = exp([S1] * t1) * exp([S2] * t2) * M";
    let out = run(&mut session(), src);
    assert!(out.contains("L1 cos(t1) + L2 cos(t1 + t2)"), "{out}");
    assert!(out.contains("L1 sin(t1) + L2 sin(t1 + t2)"), "{out}");
    assert!(out.contains("cos(t1 + t2), -sin(t1 + t2), 0"), "{out}");
    assert!(out.contains(": SE(3)"), "{out}");
    let short = run_with(
        Settings {
            sym: chasles::sym::print::Mode::Short,
            ..Settings::default()
        },
        src,
    );
    assert!(short.contains("L1 c₁ + L2 c₁₂"), "{short}");
}

#[test]
fn latex_of_the_2r_arm_is_a_well_formed_bmatrix() {
    let src = "given theta1, theta2, L1, L2 : scalar
        T = exp([(0, 0, 1, 0, 0, 0)] * theta1) * exp([(0, 0, 1, 0, -L1, 0)] * theta2) * [1, 0, 0, L1 + L2; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1]";
    let out = run_with(
        Settings {
            sym: chasles::sym::print::Mode::Latex,
            ..Settings::default()
        },
        src,
    );
    let line = out.lines().last().unwrap();
    let body = line
        .split_once("\\begin{bmatrix}")
        .and_then(|(_, r)| r.split_once("\\end{bmatrix}"))
        .map(|(b, _)| b)
        .expect("a bmatrix");
    let mut depth = 0i32;
    for c in line.chars() {
        depth += match c {
            '{' => 1,
            '}' => -1,
            _ => 0,
        };
        assert!(depth >= 0, "{line}");
    }
    assert_eq!(depth, 0, "{line}");
    let rows: Vec<&str> = body.split("\\\\").collect();
    assert_eq!(rows.len(), 4, "{body}");
    for r in &rows {
        assert_eq!(r.matches('&').count(), 3, "{r}");
    }
    assert!(line.starts_with("T = \\begin{bmatrix}"), "{line}");
    let named = run_with(
        Settings {
            sym: chasles::sym::print::Mode::Latex,
            ..Settings::default()
        },
        "given theta1 : scalar\nR_sb = Rotz(theta1)",
    );
    assert!(
        named.starts_with("R_{sb} = \\begin{bmatrix} \\cos\\theta_1"),
        "{named}"
    );
    assert!(named.trim_end().ends_with("% SO(3) {s}←{b}"), "{named}");
    assert!(
        body.contains("L_1 \\cos\\theta_1 + L_2 \\cos(\\theta_1 + \\theta_2)"),
        "{body}"
    );
}

#[test]
fn json_carries_text_and_latex() {
    let out = run_with(
        Settings {
            json: true,
            ..Settings::default()
        },
        "given theta : scalar\nRotz(theta)",
    );
    let v: serde_json::Value = serde_json::from_str(out.lines().last().unwrap()).unwrap();
    assert_eq!(v["type"], "symbolic");
    assert_eq!(v["kind"], "SO3");
    assert_eq!(
        v["value"],
        "[cos(theta), -sin(theta), 0; sin(theta), cos(theta), 0; 0, 0, 1]"
    );
    assert_eq!(
        v["latex"],
        "\\begin{bmatrix} \\cos\\theta & -\\sin\\theta & 0 \\\\ \\sin\\theta & \\cos\\theta & 0 \\\\ 0 & 0 & 1 \\end{bmatrix}"
    );
}

#[test]
fn frames_are_checked_for_symbolic_values_as_for_numbers() {
    let mut s = session();
    run(&mut s, "given t : scalar\nR_sb = Rotz(t)\nR_sc = Roty(t)");
    let (_, err, n) = s.run_to_strings("t.chs", "R_sb * R_sc", Mode::Run, false);
    assert_eq!(n, 1);
    assert!(
        err.contains("frame error") && err.contains("{b}") && err.contains("{s}"),
        "{err}"
    );
    let out = run(&mut s, "R_sb.T * R_sc");
    assert!(out.contains("SO(3) {b}←{c}"), "{out}");
    // the same statements with numbers give the same frames
    let mut n = session();
    run(&mut n, "t = 0.3\nR_sb = Rotz(t)\nR_sc = Roty(t)");
    assert!(run(&mut n, "R_sb.T * R_sc").contains("SO(3) {b}←{c}"));
    let (_, _, errs) = n.run_to_strings("t.chs", "R_sb * R_sc", Mode::Run, false);
    assert_eq!(errs, 1);
}

#[test]
fn angular_velocity_from_r_dot_r_transpose() {
    let mut s = session();
    let out = run(
        &mut s,
        "given theta(t) : scalar
         R_sb = Rot((1, 2, 2)/3, theta)
         W = diff(R_sb, t) R_sb^T
         so3ToVec(W)
         so3ToVec(R_sb^T diff(R_sb, t))
         theta'",
    );
    // [ω_s] = Ṙ Rᵀ in {s} (§3.2.2), [ω_b] = Rᵀ Ṙ in {b}
    let w = "((1/3) θ̇, (2/3) θ̇, (2/3) θ̇)  : 3-vector";
    assert!(out.contains(&format!("{w} {{s}}")), "{out}");
    assert!(out.contains(&format!("{w} {{b}}")), "{out}");
    assert!(out.contains(": so(3) {s}"), "{out}");
    assert!(out.trim_end().ends_with("θ̇"), "{out}");
}

#[test]
fn numbers_bound_later_make_symbolic_values_numeric() {
    let mut s = session();
    run(
        &mut s,
        "given t, L : scalar\nT = [Rotz(t), (L * cos(t), L * sin(t), 0); 0, 0, 0, 1]",
    );
    let out = run(&mut s, "t = 30 deg\nL = 2\nT");
    assert!(out.contains("[0.866, -0.5,   0, 1.7321"), "{out}");
    assert!(out.contains(": SE(3)"), "{out}");
}

#[test]
fn repl_toggles_short_and_latex() {
    use chasles::repl::commands::execute;
    let mut s = session();
    run(&mut s, "given t1, t2 : scalar");
    assert_eq!(execute(&mut s, ":short").out.trim(), "short: on");
    assert!(execute(&mut s, "cos(t1 + t2)").out.contains("c₁₂"));
    assert_eq!(execute(&mut s, ":latex").out.trim(), "latex: on");
    assert!(
        execute(&mut s, "cos(t1 + t2)")
            .out
            .contains("\\cos(t_1 + t_2)")
    );
    assert_eq!(execute(&mut s, ":latex off").out.trim(), "latex: off");
    assert!(execute(&mut s, "cos(t1 + t2)").out.contains("cos(t1 + t2)"));
}

#[test]
fn powers_and_numbers_print_exactly() {
    let out = run(
        &mut session(),
        "given t : scalar\n(t + 1)^5\n(t + 0.1)^2\n0.12345 t + 0.425\ncos(t + 1e300)\nt/sqrt(2)",
    );
    assert_eq!(
        out,
        "1 + 5 t + 10 t^2 + 10 t^3 + 5 t^4 + t^5\n0.01 + (1/5) t + t^2\n0.425 + 0.12345 t\n\
         cos(1e300 + t)\n(1/√2) t\n"
    );
}

#[test]
fn derive_multiplies_symbolic_transforms() {
    let out = run(
        &mut session(),
        "given t : scalar\nT_ab = RpToTrans(Rotz(t), (1, 0, 0))\nT_bc = RpToTrans(Rotx(t), (0, 0, 0))\nderive T_ca",
    );
    assert!(out.contains("T_ca = inv(T_bc) * inv(T_ab)\n"), "{out}");
    assert!(out.contains("sin(t)^2,        -(1/2) sin(2 t)"), "{out}");
    assert!(out.trim_end().ends_with(": SE(3) {c}←{a}"), "{out}");
}

/// Every builtin on symbolic arguments of every shape answers (a value or
/// an error) and never panics.
#[test]
fn every_builtin_takes_symbolic_arguments_without_panicking() {
    let args = [
        "t",
        "(t, 0, 1)",
        "Rotz(t)",
        "RpToTrans(Rotx(t), (t, 1, 0))",
        "(t, 0, 0, 1)",
        "(0, 0, 1, t, 0, 0)",
        "[t, 1; 0, t]",
    ];
    for b in chasles::builtins::table() {
        let (lo, hi) = b.arity();
        for n in lo..=hi.min(3) {
            let pool = if n == 3 { &args[..3] } else { &args[..] };
            let mut idx = vec![0usize; n];
            loop {
                let call: Vec<&str> = idx.iter().map(|&i| pool[i]).collect();
                let src = format!("given t : scalar\n{}({})", b.name, call.join(", "));
                let mut s = session();
                let _ = s.run_to_strings("t.chs", &src, Mode::Run, false);
                // the next combination
                let mut k = 0;
                while k < n {
                    idx[k] += 1;
                    if idx[k] < pool.len() {
                        break;
                    }
                    idx[k] = 0;
                    k += 1;
                }
                if k == n {
                    break;
                }
            }
        }
    }
}

#[test]
fn expression_limit_is_a_domain_error() {
    let mut s = session();
    let (_, err, n) = s.run_to_strings(
        "t.chs",
        "given a, b : scalar\nx = (a + b)^5000",
        Mode::Run,
        false,
    );
    assert_eq!(n, 1);
    assert!(err.contains("too large"), "{err}");
}

// ---------------------------------------------------------------- UR5

/// The UR5 of chapter 4 (`shared/data/ur5.md`) with symbolic joint angles.
const UR5: &str = include_str!("../benches/ur5.chs");

/// Types each printed entry of the top three rows of `T` (after `src`)
/// back in and asks `==` against the entry; returns the entries printed
/// with a factor taken out, and those with one nested inside another.
fn entries_read_back(src: &str) -> (usize, usize) {
    let mut s = session();
    run(&mut s, src);
    let (mut factored, mut nested) = (0, 0);
    for i in 1..=3 {
        for j in 1..=4 {
            let text = run(&mut s, &format!("T[{i}, {j}]"));
            let text = text.trim();
            factored += usize::from(text.contains(") cos(") || text.contains(") sin("));
            nested += usize::from(text.contains("(("));
            let back = run(&mut s, &format!("({text}) == T[{i}, {j}]"));
            assert_eq!(back.trim(), "true", "T[{i}, {j}] = {text}");
        }
    }
    (factored, nested)
}

#[test]
fn factored_entries_read_back_to_the_same_form() {
    // Each printed entry of the UR5's T, common factors taken out, typed
    // back in is the same canonical form (`==` decides it exactly).
    let (factored, _) = entries_read_back(UR5);
    assert!(factored >= 6, "{factored} entries factored");
    // A chain with tilted axes: long entries, factors taken out again
    // inside each group, `((…) cos(t3) + …) sin(t2)`.
    let tilted = "given t1, t2, t3, t4 : scalar
        S1 = (0, 0, 1, 0, 0, 0)
        S2 = (0, 0.6, 0.8, -0.12, -0.08, 0.06)
        S3 = (0.6, 0, 0.8, 0, -0.12, 0)
        S4 = (0.8, 0.6, 0, -0.12, 0.16, 0.22)
        T = exp([S1] t1) exp([S2] t2) exp([S3] t3) exp([S4] t4)";
    let (factored, nested) = entries_read_back(tilted);
    assert!(
        factored >= 9 && nested >= 6,
        "{factored} factored, {nested} nested"
    );
}

#[test]
fn ur5_product_of_exponentials_matches_numbers() {
    use chasles::lie::{Vec6, se3};
    let mut s = session();
    let out = run(&mut s, UR5);
    // SymPy's (1,4) entry (shared/data/ur5.md), its common factors cos(t1)
    // and sin(t1) taken out (issue 21: no more sin/cos calls than SymPy)
    for term in [
        "(0.425 cos(t2) + 0.392 cos(t2 + t3) + 0.082 cos(t2 + t3 + t4) sin(t5) \
         - 0.095 sin(t2 + t3 + t4)) cos(t1)",
        "- (0.109 + 0.082 cos(t5)) sin(t1)",
    ] {
        // (a long group is broken inside over two lines: read as one)
        let flat = out.split_whitespace().collect::<Vec<_>>().join(" ");
        let term = term.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(flat.contains(&term), "{term} missing:\n{out}");
    }
    let t = formula(&s, "T");
    let (w1, w2, l1, l2, h1, h2) = (0.109, 0.082, 0.425, 0.392, 0.089, 0.095);
    let screws = [
        [0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, -h1, 0.0, 0.0],
        [0.0, 1.0, 0.0, -h1, 0.0, l1],
        [0.0, 1.0, 0.0, -h1, 0.0, l1 + l2],
        [0.0, 0.0, -1.0, -w1, l1 + l2, 0.0],
        [0.0, 1.0, 0.0, h2 - h1, 0.0, l1 + l2],
    ];
    #[rustfmt::skip]
    let m = nalgebra::Matrix4::new(
        -1.0, 0.0, 0.0, l1 + l2,
        0.0, 0.0, 1.0, w1 + w2,
        0.0, 1.0, 0.0, h1 - h2,
        0.0, 0.0, 0.0, 1.0,
    );
    let mut rng = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 11) as f64 / (1u64 << 53) as f64 * 2.0 * std::f64::consts::PI - std::f64::consts::PI
    };
    for _ in 0..1000 {
        let q: Vec<f64> = (0..6).map(|_| next()).collect();
        let mut want: nalgebra::Matrix4<f64> = nalgebra::Matrix4::identity();
        for (s, th) in screws.iter().zip(&q) {
            want *= se3::exp(&(Vec6::from_row_slice(s) * *th));
        }
        want *= m;
        let at = |s: &Symbol| {
            let i: usize = s.name[1..].parse().ok()?;
            q.get(i - 1).copied()
        };
        for i in 0..4 {
            for j in 0..4 {
                let got = t.get(i, j).eval(&at).unwrap();
                assert!((got - want[(i, j)]).abs() < 1e-12, "({i},{j}) at {q:?}");
            }
        }
    }
}

#[test]
fn long_factored_groups_break_inside_under_their_first_terms() {
    // A tilted 4-joint chain: its entries' nested groups were printed on
    // one long line; now every line fits in 100 columns, broken
    // before a `+` or `-` inside the groups, under each group's first term.
    let tilted = "given t1, t2, t3, t4 : scalar
        S1 = (0, 0, 1, 0, 0, 0)
        S2 = (0, 0.6, 0.8, -0.12, -0.08, 0.06)
        S3 = (0.6, 0, 0.8, 0, -0.12, 0)
        S4 = (0.8, 0.6, 0, -0.12, 0.16, 0.22)
        T = exp([S1] t1) exp([S2] t2) exp([S3] t3) exp([S4] t4)";
    let mut s = session();
    let out = run(&mut s, tilted);
    let wide: Vec<&str> = out.lines().filter(|l| l.chars().count() > 100).collect();
    assert!(wide.is_empty(), "{wide:#?}");
    assert!(
        out.contains("T = [((0.2304 + (0.4096 + 0.2304 cos(t4) + 0.288 sin(t4)) cos(t3)"),
        "{out}"
    );
    // `+ 0.1296 cos(t4)` continues the group opened at column 6
    assert!(
        out.contains(
            " sin(t3)\n       + 0.1296 cos(t4) - 0.288 sin(t4)) cos(t2)\n      - ((0.56832"
        ),
        "{out}"
    );
}
