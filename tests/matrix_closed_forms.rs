//! Issue 35's matrix closed forms (LANGUAGE.md §7): `exp(A t)` of a small
//! matrix with exact eigenvalues (book §3.2.1, eq. 3.41–3.48; Exercise
//! 3.34), products of scalar exponentials folded (e^a e^b = e^{a+b}),
//! `exp(A)^n` = `exp(n A)`, the book's transform `[R, p; 0, 1]` of symbolic
//! blocks (3.62), and an assumption broken by numbers bound later. Each
//! closed form is checked three ways: it solves Ė = A E exactly (`==`
//! over symbols), it is I at t = 0, and with numbers it agrees with an
//! independent matrix exponential (Taylor series with scaling and
//! squaring, computed here).

mod common;
use common::{Rng, json, numbers, outputs, printed};

/// The last line `src` prints.
fn last(src: &str) -> String {
    printed(src)
        .lines()
        .last()
        .unwrap_or_default()
        .trim()
        .to_string()
}

/// A matrix literal of integer rows.
fn literal(n: usize, a: &[i64]) -> String {
    let rows: Vec<String> = a
        .chunks(n)
        .map(|r| r.iter().map(i64::to_string).collect::<Vec<_>>().join(", "))
        .collect();
    format!("[{}]", rows.join("; "))
}

fn matmul(n: usize, a: &[f64], b: &[f64]) -> Vec<f64> {
    let mut c = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            c[i * n + j] = (0..n).map(|k| a[i * n + k] * b[k * n + j]).sum();
        }
    }
    c
}

/// e^{M}: the Taylor series of M/2^s (‖M/2^s‖ ≤ 1/2) squared s times.
fn expm(n: usize, m: &[f64]) -> Vec<f64> {
    let norm: f64 = m.iter().map(|x| x.abs()).sum();
    let s = (norm * 2.0).log2().ceil().max(0.0) as i32;
    let x: Vec<f64> = m.iter().map(|v| v / 2f64.powi(s)).collect();
    let mut sum = vec![0.0; n * n];
    let mut term = vec![0.0; n * n];
    for i in 0..n {
        sum[i * n + i] = 1.0;
        term[i * n + i] = 1.0;
    }
    for k in 1..30 {
        term = matmul(n, &term, &x)
            .iter()
            .map(|v| v / f64::from(k))
            .collect();
        sum = sum.iter().zip(&term).map(|(a, b)| a + b).collect();
    }
    for _ in 0..s {
        sum = matmul(n, &sum, &sum);
    }
    sum
}

/// Checks e^{At} for the integer matrix A: a closed form (no call kept),
/// Ė = AE and E(0) = I proven, and the numbers at t = 0.37 and t = −0.8
/// those of [`expm`]. False when the eigenvalues are not exact (the call
/// is kept, as it must be).
fn check_closed_form(n: usize, a: &[i64]) -> bool {
    let lit = literal(n, a);
    let setup = format!("given t\nA = {lit}\nE = exp(A t)");
    let shown = printed(&format!("{setup}\nE"));
    if shown.contains("exp([") {
        return false;
    }
    assert_eq!(
        last(&format!("{setup}\ndiff(E, t) == A E")),
        "true",
        "{lit}"
    );
    assert_eq!(
        last(&format!("{setup}\nsubs(E, t, 0) == I")),
        "true",
        "{lit}"
    );
    for t in [0.37, -0.8] {
        let got = numbers(&json(&format!("{setup}\nt = {t}\nE")).last().unwrap()["value"]);
        let m: Vec<f64> = a.iter().map(|x| *x as f64 * t).collect();
        let want = expm(n, &m);
        assert_eq!(got.len(), n * n, "{lit}");
        for (g, w) in got.iter().zip(&want) {
            assert!(
                (g - w).abs() <= 1e-9 * w.abs().max(1.0),
                "{lit} at t = {t}: {got:?} against {want:?}\n{shown}"
            );
        }
    }
    true
}

#[test]
fn exercise_3_34_prints_the_closed_form_of_exp_a_t() {
    let out = printed("given t\nA = [0, 1; -2, -3]\nexp(A t)");
    assert_eq!(
        out.lines().collect::<Vec<_>>(),
        [
            "A = [ 0,  1",
            "     -2, -3]  : 2×2 matrix",
            "[2 exp(-t) - exp(-2 t),   exp(-t) - exp(-2 t)",
            " 2 (exp(-2 t) - exp(-t)), 2 exp(-2 t) - exp(-t)]  : 2×2 matrix",
        ]
    );
    assert!(check_closed_form(2, &[0, 1, -2, -3]));
}

#[test]
fn complex_and_repeated_eigenvalues_give_the_books_forms() {
    // α ± iβ = 1 ± i√6: e^{αt}(cos βt, sin βt)
    let out = printed("given t\nexp([1, -2; 3, 1] t)");
    assert!(out.starts_with("[cos(√6 t) exp(t),"), "{out}");
    assert!(out.contains("(√6/2) sin(√6 t) exp(t)"), "{out}");
    // a rotation's generator: the rotation
    assert_eq!(
        printed("given t\nexp([0, -1; 1, 0] t) == [cos(t), -sin(t); sin(t), cos(t)]"),
        "true\n"
    );
    // a repeated eigenvalue: t e^{2t}
    let out = printed("given t\nexp([2, 1; 0, 2] t)");
    assert!(out.starts_with("[exp(2 t), t exp(2 t)"), "{out}");
    for a in [
        [1, -2, 3, 1],
        [0, -1, 1, 0],
        [2, 1, 0, 2],
        [-1, 4, -1, -1],
        [1, 1, 1, 0],
    ] {
        assert!(check_closed_form(2, &a), "{a:?}");
    }
}

#[test]
fn three_by_three_with_exact_eigenvalues() {
    // the companion matrix of (s + 1)(s + 2)(s + 3)
    assert!(check_closed_form(3, &[0, 1, 0, 0, 0, 1, -6, -11, -6]));
    // a Jordan block, a rotation beside a growth, a double eigenvalue
    assert!(check_closed_form(3, &[2, 1, 0, 0, 2, 1, 0, 0, 2]));
    assert!(check_closed_form(3, &[0, 1, 0, -1, 0, 0, 0, 0, 2]));
    assert!(check_closed_form(3, &[1, 1, 0, 0, 1, 0, 0, 0, 3]));
    // z³ − 2 has no exact roots here: the call is kept, with its numbers
    assert!(!check_closed_form(3, &[0, 1, 0, 0, 0, 1, 2, 0, 0]));
    let got = numbers(
        &json("given t\nE = exp([0, 1, 0; 0, 0, 1; 2, 0, 0] t)\nt = 0.5\nE")
            .last()
            .unwrap()["value"],
    );
    let want = expm(3, &[0.0, 0.5, 0.0, 0.0, 0.0, 0.5, 1.0, 0.0, 0.0]);
    for (g, w) in got.iter().zip(&want) {
        assert!((g - w).abs() < 1e-9, "{got:?} {want:?}");
    }
}

/// The differential test over random exact A: every 2×2 of small integers,
/// and 3×3 with a rational eigenvalue made dense by a unimodular change of
/// basis, agree with the numeric exponential wherever a closed form is
/// given; the 2×2 always have one.
#[test]
fn random_exact_matrices_agree_with_the_numeric_exponential() {
    let mut rng = Rng(0x35_e4a7);
    let mut int = |k: f64| (rng.next() * k).round() as i64;
    for _ in 0..25 {
        let a: Vec<i64> = (0..4).map(|_| int(3.4)).collect();
        assert!(check_closed_form(2, &a), "{a:?}");
    }
    // U B U⁻¹ with B block-triangular (eigenvalue b₃₃) and U unimodular
    let u = [1, 1, 0, 0, 1, 1, 0, 0, 1];
    let u_inv = [1, -1, 1, 0, 1, -1, 0, 0, 1];
    let mul = |x: &[i64], y: &[i64]| -> Vec<i64> {
        (0..9)
            .map(|k| (0..3).map(|j| x[k / 3 * 3 + j] * y[j * 3 + k % 3]).sum())
            .collect()
    };
    let mut closed = 0;
    for _ in 0..12 {
        let mut b: Vec<i64> = (0..9).map(|_| int(2.4)).collect();
        b[6] = 0;
        b[7] = 0;
        let a = mul(&mul(&u, &b), &u_inv);
        closed += usize::from(check_closed_form(3, &a));
    }
    assert_eq!(closed, 12);
}

#[test]
fn products_of_exponentials_fold() {
    let out = printed(
        "given t, a, b\nexp(t)*exp(-t)\nexp(t)*exp(2*t)\nexp(0)\nexp(a) exp(b) == exp(a + b)\n1/exp(t)\nexp(t)^3\nexp(a + b) - exp(a) exp(b)",
    );
    assert_eq!(
        out.lines().collect::<Vec<_>>(),
        ["1", "exp(3 t)", "1", "true", "exp(-t)", "exp(3 t)", "0"]
    );
    // sound only: a sum is not a product, e^a + e^b stays
    assert_eq!(last("given a, b\nexp(a) + exp(b) == exp(a + b)"), "false");
}

#[test]
fn a_power_of_exp_is_exp_of_the_multiple() {
    let (out, _) = outputs("given x\nexp([(1,2,3)] x)^50");
    assert!(!out.contains("^50") && !out.contains("^48"), "{out}");
    assert!(out.starts_with("[1/14 + (13/14) cos(50√14 x),"), "{out}");
    assert_eq!(out.lines().count(), 9, "{out}");
    assert_eq!(
        last("given x\nexp([(1,2,3)] x)^50 == exp([(1,2,3)] 50 x)"),
        "true"
    );
    // negative and named integer powers; numbers bound later
    assert_eq!(last("given x\nexp([(0,0,1)] x)^-2 == Rotz(-2 x)"), "true");
    assert_eq!(
        last("given x\nn = 3\nexp([(0,0,1)] x)^n == Rotz(3 x)"),
        "true"
    );
    let got = numbers(
        &json("given x\nE = exp([(1,2,3)] x)^5\nx = 0.1\nE")
            .last()
            .unwrap()["value"],
    );
    let s = [0.0, -0.3, 0.2, 0.3, 0.0, -0.1, -0.2, 0.1, 0.0];
    let want = expm(3, &s.map(|v| v * 5.0));
    for (g, w) in got.iter().zip(&want) {
        assert!((g - w).abs() < 1e-9, "{got:?} {want:?}");
    }
}

/// The book's transform of symbolic blocks (3.62) and its algebra: the
/// inverse (3.64), products (3.63), the adjoint's inverse (Proposition
/// 3.20) and the parts; with numbers bound later, the numeric product.
#[test]
fn the_transform_of_symbolic_blocks() {
    let setup = "given R : SO3\ngiven p : vec3\nT = [R, p; 0, 1]";
    for (stmt, want) in [
        ("inv(Ad(T)) == Ad(inv(T))", "true"),
        ("inv(T) T == I", "true"),
        ("T inv(T) == I", "true"),
        ("inv(T) T", "I  : SE(3)"),
        ("T.R", "R  : SO(3)"),
        ("T.p", "p  : 3-vector"),
        ("inv(T).p", "(-R.T) p  : 3-vector"),
        ("inv(T) T T == T", "true"),
        ("inv(inv(T)) == T", "true"),
        ("inv(T)^-1", "[R, p; 0, 1]  : SE(3)"),
        ("given q : vec3\nT q", "R q + p  : 3-vector"),
        ("T inv(T) T == T", "true"),
    ] {
        assert_eq!(last(&format!("{setup}\n{stmt}")), want, "{stmt}");
    }
    let two = format!("{setup}\ngiven S : SO3\ngiven q : vec3\nU = [S, q; 0, 1]");
    assert_eq!(
        last(&format!("{two}\nT U")),
        "[R S, R q + p; 0, 1]  : SE(3)"
    );
    assert_eq!(last(&format!("{two}\n(T U).R")), "R S  : SO(3)");
    // numbers bound later: the numeric product of the numeric transforms
    let got = numbers(
        &json(&format!(
            "{two}\nV = T U\nR = Rotz(0.3)\np = (1, 2, 3)\nS = Roty(0.2)\nq = (0, 1, 0)\nV"
        ))
        .last()
        .unwrap()["value"],
    );
    let want = numbers(
        &json("[Rotz(0.3), (1, 2, 3); 0, 1] [Roty(0.2), (0, 1, 0); 0, 1]")
            .last()
            .unwrap()["value"],
    );
    assert_eq!(got.len(), 16);
    for (g, w) in got.iter().zip(&want) {
        assert!((g - w).abs() < 1e-12, "{got:?} {want:?}");
    }
    // a block that is not a transform is not inverted by transposing
    let m = "given R : SO3\ngiven p : vec3\nM = [2 R, p; 0, 1]";
    assert_eq!(
        last(&format!("{m}\ninv(M)")),
        "inv([2 R, p; 0, 1])  : 4×4 matrix"
    );
    assert_eq!(
        last(&format!("{m}\nM M")),
        "[2 R, p; 0, 1] [2 R, p; 0, 1]  : 4×4 matrix"
    );
}

/// A stated assumption broken by numbers bound later (LANGUAGE.md §7):
/// the value that relied on "u is a unit vector" is computed again with
/// the numbers and says so, naming the assumption and the numbers; with
/// a unit u it holds, silently.
#[test]
fn a_value_that_relied_on_a_unit_axis_says_so_when_numbers_break_it() {
    let setup = "given θ\ngiven u : vec3\nR = exp([u] θ)\nd = dot(u, u) == 1\ne = dot(u, u)\nc = [u]^3 == -[u]";
    let (out, err) = outputs(&format!("{setup}\nu = (1, 1, 0)\nd\ne\nc\nd"));
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        lines[lines.len() - 4..],
        ["false", "2", "false", "false"],
        "{out}"
    );
    for name in ["d", "e", "c"] {
        let said = format!(
            "{name} was computed assuming u is a unit vector, ‖u‖ = 1; u = (1, 1, 0) breaks it (‖u‖ = 1.4142)"
        );
        assert_eq!(err.matches(&said).count(), 1, "{name}: {err}");
    }
    // before the numbers, under the assumption: true, 1, true
    assert!(out.contains("d = true\ne = 1\nc = true\n"), "{out}");
    // a unit u keeps it: the same values, no warning
    let (out, err) = outputs(&format!("{setup}\nu = (0.6, 0, 0.8)\nd\ne\nc"));
    assert!(out.ends_with("true\n1\ntrue\n"), "{out}");
    assert!(!err.contains("computed assuming"), "{err}");
    // the bool is a bool: compared, put in a tuple, asserted
    let out = printed(&format!(
        "{setup}\nd == true\n(d, 1)\nassert d\nnot_d = d == false\nnot_d"
    ));
    assert!(
        out.ends_with("c = true\ntrue\ntrue\n1\nnot_d = false\nfalse\n"),
        "{out}"
    );
    // a value made without the assumption has nothing to say
    let (out, err) = outputs("given u : vec3\nv = 2 u\nu = (1, 1, 0)\nv");
    assert!(out.ends_with("(2, 2, 0)  : 3-vector\n"), "{out}");
    assert!(!err.contains("assuming"), "{err}");
}

/// The book's exercises on ẋ = Ax (chapter 3, Exercises 33 and 34 of the
/// seed): the closed forms as a student writes them, and the solutions
/// x(t) = e^{At} x₀ the exercise gives.
#[test]
fn exercises_33_and_34() {
    let out =
        printed("given t, x1, x2\nA = [-2, 1; 0, -1]\nexp(A t) (x1, x2)\nexp([2, -1; 1, 2] t)");
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        lines[2..],
        [
            "(exp(-2 t) (x1 - x2) + x2 exp(-t), x2 exp(-t))  : 2-vector",
            "[exp(2 t) cos(t), -exp(2 t) sin(t)",
            " exp(2 t) sin(t), exp(2 t) cos(t)]  : 2×2 matrix",
        ]
    );
    // A from its eigenvectors (1, −3) at −3 and (1, 1) at 1
    let setup = "given t\nP = [1, 1; -3, 1]\nA = P [-3, 0; 0, 1] inv(P)\nE = exp(A t)";
    let out = printed(&format!("{setup}\nE (1, -3)\nE (1, 1)"));
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        lines[lines.len() - 2..],
        [
            "(exp(-3 t), -3 exp(-3 t))  : 2-vector",
            "(exp(t), exp(t))  : 2-vector"
        ]
    );
    assert!(check_closed_form(2, &[0, 1, 3, -2]));
    assert!(check_closed_form(2, &[-2, 1, 0, -1]));
    assert!(check_closed_form(2, &[2, -1, 1, 2]));
}
