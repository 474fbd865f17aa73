//! Closed forms printed in the book's shape (issue 35; LANGUAGE.md §7):
//! Rodrigues' entries as (3.52), cθ + ω̂₁²(1 − cθ), not multiplied out;
//! common factors and integer content kept factored; a denominator that is
//! a power of a sum printed as that power (3.104); G(θ)v of Proposition 3.16
//! grouped by (1 − cos θ) and (θ − sin θ). Each printed form, text and
//! LaTeX, read back, is the value (`==` decides it exactly).

mod common;
use common::json;

#[path = "sym_differential/latex.rs"]
#[allow(dead_code)]
mod latex;

/// The JSON `value` and `latex` of the statement named `name` in `src`.
fn shown(src: &str, name: &str) -> (String, String) {
    let lines = json(src);
    let line = lines
        .iter()
        .find(|j| j["name"] == name)
        .unwrap_or_else(|| panic!("no {name} in {src}"));
    let text = line["value"].as_str().expect("a symbolic value");
    let tex = line["latex"].as_str().expect("its LaTeX");
    (text.to_string(), tex.to_string())
}

/// The last line `src` prints.
fn last(src: &str) -> String {
    common::printed(src)
        .lines()
        .last()
        .unwrap_or_default()
        .trim()
        .to_string()
}

/// The top-level terms of a printed sum: its `+` and `-` outside
/// parentheses, plus one.
fn top_terms(text: &str) -> usize {
    let (mut depth, mut n) = (0i32, 1);
    let b = text.as_bytes();
    for (i, c) in b.iter().enumerate() {
        match c {
            b'(' => depth += 1,
            b')' => depth -= 1,
            b'+' | b'-' if depth == 0 && i > 0 && b[i - 1] == b' ' => n += 1,
            _ => {}
        }
    }
    n
}

/// `entry` of `setup`, printed as text and as LaTeX, read back in the same
/// session (where the same assumptions hold) and compared with `==`: both
/// are the value. `names` binds the LaTeX names (`w_{1}` reads as `w1`).
fn reads_back(setup: &str, entry: &str, names: &str) -> String {
    let (text, tex) = shown(&format!("{setup}\nx = {entry}"), "x");
    let src = format!("{setup}\n{names}\n{entry} == {text}");
    assert_eq!(last(&src), "true", "text {text} is not {entry}\n{src}");
    let back = latex::source(&tex).unwrap_or_else(|| panic!("LaTeX {tex} does not read"));
    let src = format!("{setup}\n{names}\n{entry} == {back}");
    assert_eq!(last(&src), "true", "LaTeX {tex} is not {entry}\n{src}");
    text
}

const RODRIGUES: &str = "given t\ngiven w : vec3\nR = exp([w] t)";
const W: &str = "w1 = w[1]\nw2 = w[2]\nw3 = w[3]";

#[test]
fn rodrigues_prints_the_books_eighteen_terms() {
    let want = [
        [
            "cos(t) + w[1]^2 (1 - cos(t))",
            "w[1] w[2] (1 - cos(t)) - w[3] sin(t)",
            "w[1] w[3] (1 - cos(t)) + w[2] sin(t)",
        ],
        [
            "w[1] w[2] (1 - cos(t)) + w[3] sin(t)",
            "cos(t) + w[2]^2 (1 - cos(t))",
            "w[2] w[3] (1 - cos(t)) - w[1] sin(t)",
        ],
        [
            "w[1] w[3] (1 - cos(t)) - w[2] sin(t)",
            "w[1] sin(t) + w[2] w[3] (1 - cos(t))",
            "cos(t) + w[3]^2 (1 - cos(t))",
        ],
    ];
    let mut terms = 0;
    for (i, row) in want.iter().enumerate() {
        for (j, cell) in row.iter().enumerate() {
            let entry = format!("R[{}, {}]", i + 1, j + 1);
            // the symmetric form: r33 in w[3], as the book, though the
            // canonical form writes w[3]^2 as 1 - w[1]^2 - w[2]^2
            assert_eq!(reads_back(RODRIGUES, &entry, W), *cell, "{entry}");
            terms += top_terms(cell);
            // Rot(w, θ) is the same rotation, printed alike
            let rot = "given t\ngiven w : vec3\nR = Rot(w, t)";
            assert_eq!(shown(&format!("{rot}\nx = {entry}"), "x").0, *cell);
        }
    }
    assert_eq!(terms, 18);
    // the shorthand prints the same shape
    let short = common::run(&["--short", "-e", "given t\ngiven w : vec3\nexp([w] t)[3, 3]"]);
    assert!(short.1.contains("ct + w[3]^2 (1 - ct)"), "{short:?}");
}

#[test]
fn common_factors_stay_factored() {
    let setup = "given s\ngiven r : vec3";
    let text = reads_back(
        setup,
        "det(s*eye(3) - [r])",
        "r1 = r[1]\nr2 = r[2]\nr3 = r[3]",
    );
    assert_eq!(text, "s (r[1]^2 + r[2]^2 + r[3]^2 + s^2)");
    // integer content and a shared monomial, only where shorter
    let setup = "given x, y";
    for (entry, want) in [
        ("-8 x^2 - 8 y^2", "-8 (x^2 + y^2)"),
        ("x^2 + x^2 y", "x^2 (1 + y)"),
        ("x/2 + y/2", "(1/2) (x + y)"),
        ("(x + y)^2", "2 x y + x^2 + y^2"),
        ("x + 2 y", "x + 2 y"),
        ("2 x + 4 y", "2 x + 4 y"),
        // no Horner nesting of a polynomial: x (1/5 + x) is no shorter
        ("x/5 + x^2", "(1/5) x + x^2"),
        ("(1 + x)^4", "1 + 4 x + 6 x^2 + 4 x^3 + x^4"),
    ] {
        assert_eq!(reads_back(setup, entry, ""), want, "{entry}");
    }
    // a long expansion stays one: symbols shared by some of its terms are
    // not nested out of it (Horner's form of (a + … + f)^3 has fewer factors)
    let setup = "given a, b, c, d, e, f";
    let text = reads_back(setup, "(a + b + c + d + e + f)^3", "");
    assert!(!text.contains('('), "{text}");
    assert!(text.starts_with("6 a b c + 6 a b d"), "{text}");
}

#[test]
fn a_square_denominator_prints_as_the_square() {
    // Cayley's form (3.104)
    let setup = "given r : vec3\nR = eye(3) + 4*(1 - dot(r,r))/(1 + dot(r,r))^2 * [r] + 8/(1+dot(r,r))^2 * [r]^2";
    let names = "r1 = r[1]\nr2 = r[2]\nr3 = r[3]";
    let d = "(1 + r[1]^2 + r[2]^2 + r[3]^2)^2";
    let mut chars = 0;
    for i in 1..=3 {
        for j in 1..=3 {
            let text = reads_back(setup, &format!("R[{i}, {j}]"), names);
            assert!(text.ends_with(&format!("/{d}")), "{text}");
            chars += text.chars().count();
        }
    }
    assert_eq!(
        shown(&format!("{setup}\nx = R[1, 1]"), "x").0,
        format!("1 - 8 (r[2]^2 + r[3]^2)/{d}")
    );
    // 1,225 characters when every denominator was expanded
    assert!(chars < 700, "{chars}");
    // powers of other sums: a cube, a square of a trigonometric sum
    let setup = "given a, b, t";
    assert_eq!(reads_back(setup, "1/(1 + a b)^3", ""), "1/(1 + a b)^3");
    assert_eq!(
        reads_back(setup, "a/(1 + cos(t))^2", ""),
        "a/(1 + cos(t))^2"
    );
}

#[test]
fn the_screw_exponential_groups_as_proposition_3_16() {
    let setup = "given t\ngiven S : screw\nT = exp([S] t)";
    let names = "S1 = S[1]\nS2 = S[2]\nS3 = S[3]\nS4 = S[4]\nS5 = S[5]\nS6 = S[6]";
    let text = reads_back(setup, "T[1, 4]", names);
    assert_eq!(
        text,
        "S[1] (S[1] S[4] + S[2] S[5] + S[3] S[6]) (t - sin(t)) + (S[2] S[6] - S[3] S[5]) (1 - cos(t)) + S[4] sin(t)"
    );
    let text = reads_back(setup, "T[2, 4]", names);
    assert!(
        text.contains("(S[3] S[4] - S[1] S[6]) (1 - cos(t))"),
        "{text}"
    );
    assert_eq!(
        reads_back(setup, "T[1, 1]", names),
        "cos(t) + S[1]^2 (1 - cos(t))"
    );
}

#[test]
fn numeric_chains_keep_their_trigonometric_grouping() {
    // no symbols shared: the shape is the trigonometric factors' alone
    let src = "given t1, t2\nx = 0.425 cos(t1) + 0.392 cos(t1 + t2)";
    assert_eq!(shown(src, "x").0, "0.425 cos(t1) + 0.392 cos(t1 + t2)");
    let src = "given a, b, c\nx = sin(a) cos(c) + cos(b) cos(c) + sin(b)";
    assert_eq!(shown(src, "x").0, "(sin(a) + cos(b)) cos(c) + sin(b)");
}

/// What `src` prints with `--exact` (text output).
fn exact_text(src: &str) -> String {
    let mut s = chasles::session::Session::new(chasles::session::Settings {
        exact: true,
        digits: 17,
        ..chasles::session::Settings::default()
    });
    let (out, err, n) = s.run_to_strings("t.chs", src, chasles::eval::env::Mode::Run, false);
    assert_eq!(n, 0, "{src}\n{err}");
    out
}

#[test]
fn exact_fractions_print_as_fractions_and_typed_decimals_as_typed() {
    // 1/8 computed from integers printed `0.125` (a denominator dividing
    // a power of ten was taken for a typed decimal)
    let t = reads_back("given x", "diff(tan(x/2)/2, x)", "");
    assert!(t.contains("1/4") && !t.contains("0.125"), "{t}");
    let t = reads_back("given x", "x/8 + x^2/16", "");
    assert_eq!(t, "(1/8) x + (1/16) x^2");
    // a typed decimal prints as typed, and so does what arithmetic makes
    // of it (the book's lengths: 0.425/2 is 0.2125)
    let t = reads_back("given x\nL = 0.425", "L cos(x)/2 + 0.125 x", "");
    assert_eq!(t, "0.2125 cos(x) + 0.125 x");
    let t = reads_back("given x", "0.1 x + x/20", "");
    assert_eq!(t, "0.15 x");
    // exact numbers: SymPy's 1/16 is 1/16, a typed 0.0625 is 0.0625
    let out = exact_text(
        "simplify(cos(pi/9) cos(2 pi/9) cos(3 pi/9) cos(4 pi/9))\n1/8\n0.0625\n0.1 + 0.2\n",
    );
    assert_eq!(out, "1/16\n1/8\n0.0625\n0.3\n");
}

#[test]
fn half_angle_tangent_powers_print_as_powers() {
    // tan(x/2)^2 printed (1/2) (1/cos(x/2)^2 - cos(x)/cos(x/2)^2): the
    // canonical form folds sin(x/2)^2 into (1 - cos(x))/2
    for (entry, want) in [
        ("tan(x/2)^2", "tan(x/2)^2"),
        ("simplify(tan(x/2)^2)", "tan(x/2)^2"),
        ("tan(x/2)^3", "tan(x/2)^3"),
        ("cot(x/2)^3", "cot(x/2)^3"),
        ("a tan(x/2)^2 + b", "a tan(x/2)^2 + b"),
        ("tan(x/2)^2 + tan(x/2)", "tan(x/2) + tan(x/2)^2"),
        ("diff(tan(x/2), x)", "(1/2) (1 + tan(x/2)^2)"),
    ] {
        assert_eq!(reads_back("given x, a, b", entry, ""), want, "{entry}");
    }
    // a quotient that is no tangent's power stays as it was
    let t = reads_back("given x", "1/cos(x/2)^2", "");
    assert!(!t.contains("tan"), "{t}");
}

#[test]
fn a_sum_of_mixed_signs_keeps_its_own_sign() {
    // exp(-(-1/2 + √5/2) t): the sign pulled into the sum
    for (entry, want) in [
        ("exp(-(-1/2 + sqrt(5)/2) t)", "exp((1/2 - √5/2) t)"),
        ("exp(-(1/2 + sqrt(5)/2) t)", "exp(-(1/2 + √5/2) t)"),
        ("(1 - sqrt(2)) x", "(1 - √2) x"),
        ("y + (1 - sqrt(2)) x", "(1 - √2) x + y"),
    ] {
        assert_eq!(reads_back("given t, x, y", entry, ""), want, "{entry}");
    }
    // LaTeX names the exponential as the book does
    let (_, tex) = shown("given t\nx = exp(-(-1/2 + sqrt(5)/2) t)", "x");
    assert_eq!(
        tex,
        "\\exp\\left(\\left(\\frac{1}{2} - \\frac{\\sqrt{5}}{2}\\right) t\\right)"
    );
}

#[test]
fn irrational_angles_print_folded_as_eq_proves_them() {
    // sin(√6 x)^2 + cos(√6 x)^2 was proven == 1 but printed itself
    for (entry, want) in [
        ("sin(sqrt(6) x)^2 + cos(sqrt(6) x)^2", "1"),
        ("simplify(sin(sqrt(6) x)^2 + cos(sqrt(6) x)^2)", "1"),
        ("a sin(sqrt(2) x)^2 + a cos(sqrt(2) x)^2 + y", "a + y"),
        ("simplify(2 sin(sqrt(2) x) cos(sqrt(2) x))", "sin(2√2 x)"),
        (
            "simplify(cos(sqrt(2) x)^2 - sin(sqrt(2) x)^2)",
            "cos(2√2 x)",
        ),
        ("cos(x y)^2 + sin(x y)^2 + cos(y)", "1 + cos(y)"),
        // a plain angle beside an irrational one joins it
        (
            "sin(sqrt(2) x) cos(y) + cos(sqrt(2) x) sin(y)",
            "sin(√2 x + y)",
        ),
        ("cos(sqrt(2) x + pi/5)^2 + sin(sqrt(2) x + pi/5)^2", "1"),
    ] {
        assert_eq!(reads_back("given x, y, a", entry, ""), want, "{entry}");
    }
    // a constant offset with no exact sine (0.3) is not folded into
    // floats: the printed form reads back as the value
    let t = reads_back(
        "given x, y",
        "simplify(cos(sqrt(2) x) cos(y + 0.3) - sin(sqrt(2) x) sin(y + 0.3))",
        "",
    );
    assert!(t.contains("y + 0.3"), "{t}");
    // nothing shorter: kept as it is
    assert_eq!(reads_back("given x", "cos(sqrt(2) x)^2", ""), "cos(√2 x)^2");
}

#[test]
fn quotient_and_root_angles_fold_and_decide() {
    // Exercise 3.23: car 1 on a table of radius r turns through v1 t/r;
    // sin² + cos² of that angle printed itself, T_12's position kept it,
    // and == with the folded form was `cannot decide`
    for (entry, want) in [
        ("sin(a/b)^2 + cos(a/b)^2", "1"),
        ("sin(1/b)^2 + cos(1/b)^2", "1"),
        ("sin(a + 1/b)^2 + cos(a + 1/b)^2", "1"),
        ("sin(sqrt(a))^2 + cos(sqrt(a))^2", "1"),
        ("sin(a/(1 + b^2))^2 + cos(a/(1 + b^2))^2", "1"),
        ("r (sin(a/b) + sin(a/b)^2 + cos(a/b)^2)", "r (1 + sin(a/b))"),
    ] {
        assert_eq!(reads_back("given a, b, r", entry, ""), want, "{entry}");
    }
    let src = "given t, v1, v2, r\nphi = v1 t/r\n\
               T_01 = [Rotz(phi), (r cos(phi), r sin(phi), 0); 0, 1]\n\
               T_02 = [Rotz(pi/2), (0, v2 t - r, 0); 0, 1]\n\
               T_12 = inv(T_01) * T_02\n\
               T_12[1, 4] == v2 t sin(phi) - r sin(phi) - r";
    assert_eq!(last(src), "true");
}

/// The Pythagorean identity holds for any argument, not only for symbols
/// and products of them: `sin(sin a)^2 + cos(sin a)^2 == 1` was `cannot
/// decide` and printed itself (the argument sin a is a sum of e^{±ia},
/// no term of which is real alone, so none was renamed to a fresh angle;
/// now the whole trigonometric part of the argument is). Sines and
/// cosines of different arguments still differ.
#[test]
fn the_pythagorean_identity_holds_for_any_argument() {
    for (entry, want) in [
        ("sin(sin(a))^2 + cos(sin(a))^2", "1"),
        ("simplify(sin(sin(a))^2 + cos(sin(a))^2)", "1"),
        ("sin(sin(a) + b)^2 + cos(sin(a) + b)^2", "1"),
        ("sin(cos(a) sin(b))^2 + cos(cos(a) sin(b))^2", "1"),
        ("sin(a sin(a))^2 + cos(a sin(a))^2", "1"),
        ("r sin(sin(a)/2)^2 + r cos(sin(a)/2)^2 + b", "b + r"),
    ] {
        assert_eq!(reads_back("given a, b, r", entry, ""), want, "{entry}");
    }
    for (eq, want) in [
        ("sin(sin(a))^2 + cos(sin(a))^2 == 1", "true"),
        ("sin(sin(sin(a)))^2 + cos(sin(sin(a)))^2 == 1", "true"),
        ("2 sin(sin(a)) cos(sin(a)) == sin(2 sin(a))", "true"),
        ("cos(2 sin(a)) == 1 - 2 sin(sin(a))^2", "true"),
        ("sin(sin(a))^2 + cos(sin(a))^2 == 2", "false"),
        ("sin(a)^2 + cos(b)^2 == 1", "false"),
        ("sin(sin(a))^2 + cos(sin(b))^2 == 1", "false"),
        ("sin(sin(a))^2 + cos(cos(a))^2 == 1", "false"),
        ("cos(sin(a)) == cos(sin(b))", "false"),
    ] {
        assert_eq!(last(&format!("given a, b\n{eq}")), want, "{eq}");
    }
}
