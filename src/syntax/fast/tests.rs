//! The fast path against pest: every statement of the examples and
//! error scripts, chosen statements, and random token strings and
//! expressions must give the same tree (or the fast path must give up).

use crate::syntax::{FAST_DEPTH, parser, rewrite, spacing, split, statements, statements_split};
use proptest::prelude::*;

/// Checks every statement of `src` the fast path takes against pest;
/// returns how many statements it took and how many pest parsed.
fn agree(src: &str) -> (usize, usize) {
    let split = split::split(src);
    let (mut fast, mut ok) = (0, 0);
    for chunk in split.chunks.iter().filter(|c| c.error.is_none()) {
        let text = &split.text[chunk.span.start..chunk.span.end];
        let slow = parser::parse_chunk(text, chunk.span);
        ok += usize::from(slow.is_ok());
        if chunk.depth > FAST_DEPTH {
            continue;
        }
        let mut stack = super::Stack::default();
        if let Some(stmt) = super::parse_statement_with(text, chunk.span, &mut stack) {
            fast += 1;
            // The passes the fast path skips would have done nothing.
            if !stack.passes.spacing {
                assert!(spacing::check(&stmt, &split.text).is_ok(), "{src:?}");
            }
            if !stack.passes.rewrite {
                let mut rewritten = stmt.clone();
                rewrite::stmt(&mut rewritten);
                assert_eq!(rewritten, stmt, "{src:?}");
            }
            assert_eq!(Ok(stmt), slow, "{src:?}");
        }
    }
    (fast, ok)
}

fn scripts() -> Vec<String> {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut dirs = vec![root.join("examples")];
    if let Ok(kinds) = std::fs::read_dir(root.join("tests/errors")) {
        dirs.extend(kinds.flatten().map(|k| k.path()));
    }
    let mut out = Vec::new();
    for dir in dirs {
        for f in std::fs::read_dir(dir).into_iter().flatten().flatten() {
            if f.path().extension().is_some_and(|e| e == "chs") {
                out.extend(std::fs::read_to_string(f.path()));
            }
        }
    }
    out
}

/// Reading statements straight from the source gives what splitting
/// them off first gives, errors included.
fn fused_agrees(src: &str) {
    let fused: Vec<_> = statements(src).collect();
    let split: Vec<_> = statements_split(src).collect();
    assert_eq!(fused, split, "{src:?}");
}

#[test]
fn fused_reading_agrees_with_splitting() {
    for src in scripts() {
        fused_agrees(&src);
    }
    for src in [
        "x = 1 # one\n# two\n\n;; y = x; z = [1, 2\n 3] # three",
        "x = 1#c\ny = 2\r\n  z = (1,\n 2)\nw = f(x) \"s\"",
        "a = (1\nb = 2\nc = 3)\nd = 4",
        "a = ((((((((((((((((((1))))))))))))))))))\nb = 1",
        "a = [[1 2] [3 4]]\ngiven x : scalar\nb = x.T # c",
        "mech < links 4 >\nx = 1; ; ;\n  ",
        "",
        "x = 1 +\n 2",
    ] {
        fused_agrees(src);
    }
}

#[test]
fn fast_path_agrees_with_pest() {
    let (mut fast, mut ok) = (0, 0);
    let scripts = scripts();
    assert!(!scripts.is_empty());
    for src in &scripts {
        let (f, o) = agree(src);
        fast += f;
        ok += o;
    }
    // Most statements of the examples take the fast path.
    assert!(fast * 10 >= ok * 8, "fast path took {fast} of {ok}");
    for src in [
        "T_sb = RpToTrans(Rotz(30 deg), (1, 2, 0))",
        "p_s = T_sb * (1, 0, 0)",
        "x = 2 * 3 + 1",
        "w = MatrixLog3(Rotz(0.1) * Rotx(0.2))",
        "V_s = Ad(T_sb) * (0, 0, 1, 1, 0, 0)",
        "f(x, y) = -x^2 + y'",
        "(w, theta) = axis_ang3(expc)",
        "M = [R, p; 0, 0, 0, 1]\n[1, 2,\n 3]",
        "exp([S] theta) * M[1, :] .T + 2 pi - 30° / θ(1) + true",
        "assert T_ce ≈ T_ce_book",
        "assert(x == 1 ~= y)\nb = x == -y",
        "ok = [1, 2] ~= (1, 2)",
        // The book's notation (issue 13).
        "R_sb = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]",
        "R = [[ 0. -1.  0.] [ 1.  0.  0.] [ 0.  0.  1.]]",
        "R = [[ 0. -1.  0.]\n [ 1.  0.  0.]\n [ 0.  0.  1.]]",
        "R = [0 -1 0; 1 0 0; 0 0 1]",
        "x = [1.e-3 -2.5E+2 +3 .5]",
        "[1, 2,\n 3, 4,\n]",
        "R^T * V_b^T + Ad(T_sb)^T - [w]^T",
        "Rᵀ * R^{-1} + R^{T} + X^-1 + Rᵀᵀ + R⁻¹ + [w]² - x¹⁰ᵀ",
        "e^(A t) + e^([w] θ)",
        "exp([S1] θ1) exp([S2] θ2) M",
        "T_sb T_bc + Ad(T_sb) V_b + sin(θ) W",
        "I + sin θ [w] + (1 - cos θ)[w]^2",
        "cos 30° + sqrt 2 + tan pi + asin x deg + acos θ_1'",
        "cot t + sec θ [w] + csc 30° + cot(x) + sec_1 + csc'",
        "ans / deg",
        "I + sin θ [w] + (1 − cos θ)[w]² − −x + [1 −2 3] − [1 − x]",
        "T_01 * T_12 * T_s1",
        // Plain numbers and names as list elements.
        "v = g(x', 2.5e3, 7, T_ab, 1.)[1] + [a, b, 1; 2, c', 3] + h(0.1,2)",
    ] {
        let (f, o) = agree(src);
        assert!(f == o && o > 0, "{src:?} takes the slow path");
    }
    // Names that nothing continues, read at once (`name_operand`), beside
    // names that a call, a postfix, `sin θ` or a keyword continues.
    for src in [
        "y = true' + x; y = false\t; y = true",
        "z = sin; w = sin -x; v = sin x; u = sqrt\t2",
        "a = x .T + f (x) * y [1] + x deg + x ° + xᵀ + x²",
        "b = T_ab *T_bc^T/ x - y == z ~= w",
        "c = x'; d = (x, y'); e = [x_1 y]; g = {x}",
        "h = pi; k = π; m = mech; n = T_{a,b}; o = x_{1}",
    ] {
        let (f, _) = agree(src);
        assert!(f > 0, "{src:?}");
    }
}

const TOKENS: &[&str] = &[
    "(", ")", "[", "]", ",", ";", "+", "-", "*", "/", "^", ".", "'", "deg", "°", "pi", "π", "1",
    "2.5", ".5", "1e", "1e-3", "T_ab", "x", "θ", "=", "==", ":", "true", "false", "given",
    "derive", "mech", "assert", "explain", "~=", "≈", "<", ">", "\n", " ", "\t", "_{", "}", "f(",
    "**", ".T", "_", // The book's notation.
    "ᵀ", "^T", "^{", "sin", "cos ", "sqrt", "cot", "sec ", "csc", "e^", "0.", "1.e", "-1.", "[[",
    "]]", "I", "T_01", "²", "−", " −", "⁻¹", "⁻", // Issue 22's forms.
    "√", "·", "ŵ·", "×", "<=", ">=", "≤", "≥", "end", "for", "in", "^T (", "R (", "links",
    "joints", "legs", "sliding", "6 ",
];

fn tokens() -> impl Strategy<Value = String> {
    prop::collection::vec((prop::sample::select(TOKENS), prop::bool::ANY), 0..24).prop_map(
        |parts| {
            parts
                .into_iter()
                .map(|(t, space)| {
                    if space {
                        format!("{t} ")
                    } else {
                        t.to_string()
                    }
                })
                .collect()
        },
    )
}

/// Mostly well-formed expressions.
fn expr() -> impl Strategy<Value = String> {
    let atom = prop::sample::select(
        &[
            "1",
            "2.5",
            ".5",
            "3e2",
            "pi",
            "π",
            "x",
            "T_sb'",
            "θ",
            "true",
            "30 deg",
            "30°",
            "M[1, :]",
            "v.T",
            "v .R",
            "f()",
            "Rᵀ",
            "sin θ",
            "cos 30°",
            "sqrt 2",
            "deg",
            "0.",
            "[1 -2 3]",
            "[[1. 2.] [3. 4.]]",
            "√2",
            "√(x + 1)",
            "R^T (p)",
            "n (n - 1)",
            "S[1:3]",
            "v[end]",
        ][..],
    )
    .prop_map(str::to_string);
    atom.prop_recursive(4, 32, 3, |inner| {
        let op = prop::sample::select(
            &[
                "+", "-", "*", "/", "^", " ", "", "^-", " - -", "^T", "^{T}", " [w] ", ",\n",
                " == ", "~=", "≈", " < ", "<=", " ≥ ", "·", " × ",
            ][..],
        );
        prop_oneof![
            (inner.clone(), op, inner.clone()).prop_map(|(a, o, b)| format!("{a}{o}{b}")),
            prop::collection::vec(inner.clone(), 1..3).prop_map(|v| format!("({})", v.join(", "))),
            prop::collection::vec(inner.clone(), 0..3).prop_map(|v| format!("[{}]", v.join("; "))),
            prop::collection::vec(inner.clone(), 0..3)
                .prop_map(|v| format!("g ({},)", v.join(","))),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("{a}[{b}] deg")),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("{a}^{{{b}}}")),
            prop::collection::vec(inner, 1..4).prop_map(|v| format!("[{}]", v.join(" "))),
        ]
    })
}

fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(2000)
}

proptest! {
    // 2000 cases, or PROPTEST_CASES when set (the environment variable
    // does not override an explicit count by itself).
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn random_tokens_agree(src in tokens()) {
        agree(&src);
        fused_agrees(&src);
    }

    #[test]
    fn random_expressions_agree(e in expr(), form in 0..6usize) {
        let src = match form {
            0 => e,
            4 => format!("assert {e}"),
            5 => format!("explain {e}"),
            1 => format!("y_1 = {e}"),
            2 => format!("h(a, b) = {e}"),
            _ => format!("(a, b) = {e}"),
        };
        agree(&src);
        fused_agrees(&format!("{src}\n{src} # c;\n;{src}"));
    }
}

#[test]
fn numbers_in_one_pass_are_the_numbers_in_two() {
    let texts = [
        "1",
        "0",
        "9",
        "7e2",
        "8E",
        "4.",
        "3.x",
        "12",
        "0.25",
        ".5",
        "2.",
        "1.e-3",
        "1e",
        "1e5",
        "3E+2",
        ".",
        "123456789012345",
        "1234567890123456",
        "12345678.9012345",
        "1234567.89012345",
        "0.1",
        "0.2",
        "007",
        "1.5.3",
        "2.x",
        "9007199254740993",
    ];
    for text in texts {
        for tail in ["", ",", ")", " deg", ".T", "x", "_", "°", "[1]"] {
            let src = format!("{text}{tail}");
            let mut stack = super::Stack::default();
            let p = super::P {
                stack: &mut stack,
                src: &src,
                s: src.as_bytes(),
                pos: 0,
                off: 0,
                budget: super::BUDGET,
                sup: false,
            };
            let two = p
                .number_at(0)
                .and_then(|end| Some((super::atoms::number_value(&src[..end])?, end)));
            assert_eq!(p.number_value_at(0), two, "{src:?}");
        }
    }
}
