//! Hardening (issue 6): whatever a user types or a script contains gives a
//! result or a clear error — never a panic, a stack overflow, a hang or an
//! out-of-memory abort.
//!
//! - property tests: token soup and mutated example scripts through the
//!   Session in both modes never panic;
//! - limits: deep nesting, huge sizes, huge powers, recursion, long lines
//!   and files, through the real binary with a timeout;
//! - numbers: NaN, inf and out-of-domain inputs have a defined answer;
//! - files and streams: missing, directory, unreadable, non-UTF-8, empty,
//!   closed stdout;
//! - a Session keeps its bindings after every kind of error.

use std::io::Read;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::time::{Duration, Instant};

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};
use proptest::prelude::*;

mod common;
use common::{Out, bounded, chasles, command};

// ---------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------

/// `chasles -e SRC`.
fn eval(src: &str) -> Out {
    bounded(&["-e", src])
}

/// Asserts a clean failure: `code`, the `needle` in stderr, no panic.
fn assert_fails(out: &Out, code: i32, needle: &str) {
    assert_eq!(out.code, Some(code), "{out:#?}");
    assert!(
        out.stderr.contains(needle),
        "expected {needle:?} in {out:#?}"
    );
    assert!(!out.stderr.contains("panicked"), "{out:#?}");
}

/// A scratch directory for generated files, removed at the end.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Scratch {
        let dir =
            std::env::temp_dir().join(format!("chasles-hardening-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("temp dir");
        Scratch(dir)
    }
    fn file(&self, name: &str, bytes: &[u8]) -> String {
        let p = self.0.join(name);
        std::fs::write(&p, bytes).expect("write temp file");
        p.to_string_lossy().into_owned()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Runs `src` through a fresh Session in both modes; Err(report) on a panic.
fn session_survives(src: &str) -> Result<(), String> {
    for mode in [Mode::Check, Mode::Run] {
        let result = catch_unwind(AssertUnwindSafe(|| {
            let mut s = Session::new(Settings::default());
            s.run_to_strings("<prop>", src, mode, true)
        }));
        if result.is_err() {
            return Err(format!("panic in {mode:?} mode on input:\n{src:?}"));
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// Property tests: never a panic
// ---------------------------------------------------------------------------

fn examples() -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut scripts = Vec::new();
    for dir in ["examples".to_string()].into_iter().chain(
        ["syntax", "name", "type", "frame", "domain", "arity"].map(|k| format!("tests/errors/{k}")),
    ) {
        let Ok(entries) = std::fs::read_dir(root.join(dir)) else {
            continue;
        };
        for e in entries.flatten() {
            if e.path().extension().is_some_and(|x| x == "chs") {
                scripts.push(std::fs::read_to_string(e.path()).expect("a readable example"));
            }
        }
    }
    scripts.sort();
    scripts
}

fn token() -> BoxedStrategy<String> {
    let fixed: Vec<&'static str> = vec![
        "(",
        ")",
        "[",
        "]",
        ",",
        ";",
        "+",
        "-",
        "*",
        "/",
        "^",
        ".",
        "'",
        " deg",
        "°",
        "pi",
        "π",
        "\n",
        " ",
        "=",
        ":",
        "{",
        "}",
        "#",
        "given ",
        "derive ",
        "assert ",
        "==",
        "~=",
        "≈",
        "mech <",
        ">",
        "links 4",
        "joints R R R R",
        "joints 4R",
        "planar",
        "spatial",
        "spherical",
        "legs 6 UPS",
        "T_ab",
        "T_bc",
        "T_sb",
        "R_sb",
        "p_b",
        "V_b",
        "F_a",
        "S_a",
        "theta",
        "θ",
        "x",
        "f",
        "T_{cam,w}",
        "1",
        "0",
        "2",
        ".5",
        "1e-3",
        "1e308",
        "inf",
        "100000000",
        "-1",
        "SE3",
        "SO3",
        "twist",
        "wrench",
        "screw",
        "scalar",
        ".T",
        ".R",
        ".p",
        ".w",
        ".v",
        "true",
        "ans",
    ];
    let names: Vec<&'static str> = chasles::builtins::all_names();
    prop_oneof![
        4 => proptest::sample::select(fixed).prop_map(str::to_string),
        2 => proptest::sample::select(names).prop_map(str::to_string),
        1 => (0u32..40).prop_map(|n| n.to_string()),
    ]
    .boxed()
}

/// A mutation of a script: delete, duplicate or swap lines, or delete,
/// duplicate or insert characters.
#[derive(Debug, Clone)]
enum Mutation {
    DeleteLine(usize),
    DuplicateLine(usize),
    SwapLines(usize, usize),
    DeleteChar(usize),
    DuplicateChar(usize),
    InsertChar(usize, char),
}

fn mutate(src: &str, muts: &[Mutation]) -> String {
    let mut lines: Vec<String> = src.lines().map(str::to_string).collect();
    let mut chars: Vec<char>;
    for m in muts {
        match *m {
            Mutation::DeleteLine(i) if !lines.is_empty() => {
                lines.remove(i % lines.len());
            }
            Mutation::DuplicateLine(i) if !lines.is_empty() => {
                let l = lines[i % lines.len()].clone();
                lines.insert(i % lines.len(), l);
            }
            Mutation::SwapLines(i, j) if !lines.is_empty() => {
                let n = lines.len();
                lines.swap(i % n, j % n);
            }
            Mutation::DeleteChar(i) | Mutation::DuplicateChar(i) | Mutation::InsertChar(i, _)
                if !lines.is_empty() =>
            {
                let n = lines.len();
                let line = &mut lines[i % n];
                chars = line.chars().collect();
                let at = if chars.is_empty() {
                    0
                } else {
                    (i / n) % chars.len()
                };
                match *m {
                    Mutation::DeleteChar(_) if !chars.is_empty() => {
                        chars.remove(at);
                    }
                    Mutation::DuplicateChar(_) if !chars.is_empty() => {
                        chars.insert(at, chars[at]);
                    }
                    Mutation::InsertChar(_, c) => chars.insert(at, c),
                    _ => {}
                }
                *line = chars.iter().collect();
            }
            _ => {}
        }
    }
    lines.join("\n")
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let any = 0usize..10_000;
    let special = proptest::sample::select(vec![
        '(', ')', '[', ']', ',', ';', '^', '*', '-', '_', '\'', '.', '0', '9', 'e', '°', ' ', '\n',
        '#', '=', 'θ', '{', '}', '<', '>',
    ]);
    prop_oneof![
        any.clone().prop_map(Mutation::DeleteLine),
        any.clone().prop_map(Mutation::DuplicateLine),
        (any.clone(), any.clone()).prop_map(|(i, j)| Mutation::SwapLines(i, j)),
        any.clone().prop_map(Mutation::DeleteChar),
        any.clone().prop_map(Mutation::DuplicateChar),
        (any, special).prop_map(|(i, c)| Mutation::InsertChar(i, c)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn token_soup_never_panics(tokens in proptest::collection::vec(token(), 0..40)) {
        let src = tokens.join(" ");
        let glued = tokens.concat();
        prop_assert_eq!(session_survives(&src), Ok(()));
        prop_assert_eq!(session_survives(&glued), Ok(()));
    }

    #[test]
    fn mutated_examples_never_panic(
        pick in 0usize..1000,
        muts in proptest::collection::vec(mutation(), 1..8),
    ) {
        let scripts = examples();
        prop_assume!(!scripts.is_empty());
        let src = mutate(&scripts[pick % scripts.len()], &muts);
        prop_assert_eq!(session_survives(&src), Ok(()));
    }
}

#[test]
fn the_property_tests_have_material() {
    // The examples are found (else the mutation test would test nothing).
    assert!(examples().len() >= 30, "found {} scripts", examples().len());
    assert!(chasles::builtins::all_names().contains(&"MatrixExp6"));
    // The mutations do mutate.
    assert_eq!(mutate("a\nb\nc", &[Mutation::DeleteLine(1)]), "a\nc");
    assert_eq!(mutate("a\nb", &[Mutation::SwapLines(0, 1)]), "b\na");
    assert_eq!(mutate("ab", &[Mutation::InsertChar(0, '(')]), "(ab");
}

/// Fuzz findings, kept as regression cases (the same inputs also live as
/// scripts under tests/errors/).
#[test]
fn fuzz_findings_do_not_panic() {
    for src in ["#  reetmatrix_exp6\nlog([ ])\n", "[]", "[ ]; x = [\n]"] {
        assert_eq!(session_survives(src), Ok(()));
    }
    let mut s = Session::new(Settings::default());
    let (_, err, n) = s.run_to_strings("<t>", "log([ ])", Mode::Run, false);
    assert_eq!(n, 1);
    assert!(err.contains("syntax error: empty brackets"), "{err}");
}

// ---------------------------------------------------------------------------
// Limits instead of crashes
// ---------------------------------------------------------------------------

#[test]
fn deep_nesting_is_a_syntax_error_in_every_mode() {
    let n = 10_000;
    let parens = format!("{}1{}", "(".repeat(n), ")".repeat(n));
    let brackets = format!("{}1{}", "[".repeat(n), "]".repeat(n));
    let calls = format!("{}1{}", "Rotz(".repeat(n), ")".repeat(n));
    let dir = Scratch::new("deep");
    for (i, src) in [parens, brackets, calls].iter().enumerate() {
        let out = eval(src);
        assert_fails(
            &out,
            1,
            "syntax error: expression nested too deeply (limit 200)",
        );
        let f = dir.file(&format!("deep{i}.chs"), src.as_bytes());
        assert_fails(&bounded(&["check", &f]), 1, "expression nested too deeply");
        assert_fails(&bounded(&["run", &f]), 1, "expression nested too deeply");
    }
}

/// The checker and evaluator recurse over the tree: at the deepest nesting
/// the parser accepts, they must fit a 2 MB thread (the REPL and library
/// users run on ordinary threads).
#[test]
fn deepest_accepted_nesting_checks_and_runs_on_a_small_stack() {
    let n = chasles::syntax::MAX_DEPTH;
    let srcs = [
        format!("{}1{}", "(".repeat(n), ")".repeat(n)),
        format!("{}1{}", "[".repeat(n - 1), "]".repeat(n - 1)),
        format!("{}1{}", "abs(".repeat(n - 1), ")".repeat(n - 1)),
        vec!["1"; n].join("+"),
        format!("{}1", "-".repeat(n - 1)),
    ];
    let worker = std::thread::Builder::new()
        .stack_size(2 * 1024 * 1024)
        .spawn(move || {
            let mut outs = Vec::new();
            for src in &srcs {
                for mode in [Mode::Check, Mode::Run] {
                    let mut s = Session::new(Settings::default());
                    outs.push(s.run_to_strings("<deep>", src, mode, false));
                }
            }
            outs
        })
        .expect("spawn");
    let outs = worker.join().expect("no stack overflow or panic");
    // Run mode values: (((1))) = 1, [[1]] = 1, abs(..) = 1, 1+…+1 = n, -…-1 = -1.
    let values: Vec<&str> = outs.iter().skip(1).step_by(2).map(|o| o.0.trim()).collect();
    assert_eq!(values[0], "1");
    assert_eq!(values[1], "1");
    assert_eq!(values[2], "1");
    assert_eq!(values[3], n.to_string());
    assert_eq!(values[4], "-1");
    for (out, err, errors) in &outs {
        assert_eq!(*errors, 0, "{out} {err}");
    }
}

/// Exact forms wait as recipes until asked for (`values::exact`): a
/// script that adds 0.1 five thousand times builds a chain of them. It
/// must stay exact (`x == 500.1` is true: decimals are exact) and neither
/// working the form out nor dropping the chain may overflow a 2 MB thread.
#[test]
fn a_long_chain_of_exact_operations_fits_a_small_stack() {
    let mut src = String::from("x = 0.1\n");
    for _ in 0..5000 {
        src.push_str("x = x + 0.1\n");
    }
    src.push_str("x == 500.1\nx == 500.2\n");
    let worker = std::thread::Builder::new()
        .stack_size(2 * 1024 * 1024)
        .spawn(move || {
            let mut s = Session::new(Settings::default());
            let out = s.run_to_strings("<chain>", &src, Mode::Run, false);
            drop(s);
            out
        })
        .expect("spawn");
    let (out, err, errors) = worker.join().expect("no stack overflow or panic");
    assert_eq!(errors, 0, "{err}");
    let last: Vec<&str> = out.lines().rev().take(2).collect();
    assert_eq!(last, ["false", "true"], "{err}");
}

/// User functions nest the tree: 64 calls deep, each 190 brackets deep,
/// on a 2 MB thread (the stack grows on the heap instead of overflowing).
#[test]
fn deep_trees_inside_recursive_functions_do_not_overflow() {
    let n = 190;
    let srcs = [
        format!("f(x) = {}f(x){}\nf(1)", "[".repeat(n), "]".repeat(n)),
        format!("f(x) = {}f(x){}\nf(1)", "abs(".repeat(n), ")".repeat(n)),
    ];
    let worker = std::thread::Builder::new()
        .stack_size(2 * 1024 * 1024)
        .spawn(move || {
            srcs.iter()
                .map(|src| {
                    let mut s = Session::new(Settings::default());
                    s.run_to_strings("<rec>", src, Mode::Run, true)
                })
                .collect::<Vec<_>>()
        })
        .expect("spawn");
    for (_, err, errors) in worker.join().expect("no stack overflow or panic") {
        assert_eq!(errors, 1, "{err}");
        assert!(
            err.contains("domain error: function calls nested deeper than 64"),
            "{err}"
        );
    }
}

/// `x = x * x + t` doubles a symbolic expression: refused at a size limit
/// instead of exhausting memory (40 doublings took 6 GB and a minute).
#[test]
fn symbolic_blowup_is_a_domain_error() {
    let src = format!(
        "given t : scalar\nx = t\n{}x\n",
        "x = x * x + t\n".repeat(40)
    );
    let out = eval(&src);
    assert_fails(
        &out,
        1,
        "<-e>:12:7: domain error: symbolic expression too large",
    );
    // sin(t) is a canonical form; sin(sin(t)) a call, nested at most 100 deep
    let src = format!("given t : scalar\nx = t\n{}", "x = sin(x)\n".repeat(1500));
    assert_fails(
        &eval(&src),
        1,
        "<-e>:104:5: domain error: symbolic expression too large",
    );
    // Bindings made before the limit stay usable.
    let out = eval("given t : scalar; x = t * t + t; x");
    assert_eq!(out.code, Some(0), "{out:#?}");
    assert!(out.stdout.ends_with("t + t^2\n"), "{out:#?}");
}

#[test]
fn huge_sizes_are_domain_errors() {
    assert_fails(
        &eval("zeros(100000000, 100000000)"),
        1,
        "domain error: a side of 100000000 is too large",
    );
    assert_fails(&eval("zeros(10000, 10000)"), 1, "domain error");
    assert_fails(&eval("eye(1e300)"), 1, "domain error");
}

#[test]
fn huge_powers_and_products_stay_bounded() {
    // Rotz(1)^1e9 = Rotz(1e9 mod 2π) by repeated squaring.
    let out = eval("R = Rotz(1)^1000000000; R[1, 1] - cos(1000000000)");
    assert_eq!(out.code, Some(0), "{out:#?}");
    let diff: f64 = out
        .stdout
        .lines()
        .last()
        .and_then(|l| l.split_whitespace().next())
        .and_then(|x| x.parse().ok())
        .expect("a number");
    assert!(diff.abs() < 1e-4, "{out:#?}");
    let out = eval("2^1e308");
    assert_eq!(out.code, Some(0), "{out:#?}");
    assert_eq!(out.stdout.trim(), "inf");
    assert!(
        out.stderr.contains("warning: the result is infinite"),
        "{out:#?}"
    );
    let out = eval("eye(3)^-1000000000");
    assert_eq!(out.code, Some(0), "{out:#?}");
    assert!(out.stdout.contains(": SO(3)"), "{out:#?}");
    assert_fails(&eval("[1,2;3,4]^1e300"), 1, "domain error");
    let out = eval("[1,2;3,4]^1000000000");
    assert_eq!(out.code, Some(0), "{out:#?}");
    assert!(
        out.stderr.contains("warning: the result has NaN entries"),
        "{out:#?}"
    );
    // Products whose work would take minutes are refused.
    assert_fails(
        &eval("eye(1500) * eye(1500)"),
        1,
        "domain error: too much work: 3.4e9 multiply-adds",
    );
    assert_fails(
        &eval("eye(2000)^1000000000"),
        1,
        "domain error: too much work: 4.8e11 multiply-adds",
    );
    assert_fails(
        &eval("inv(2 * eye(2000))"),
        1,
        "domain error: too much work: 8.0e9 multiply-adds (the inverse of a 2000×2000 matrix",
    );
    assert_fails(
        &eval("det(eye(2000))"),
        1,
        "domain error: too much work: 2.7e9 multiply-adds (the determinant of a 2000×2000 matrix",
    );
    assert_fails(
        &eval("exp(zeros(600, 600))"),
        1,
        "domain error: too much work: 1.7e9 multiply-adds (exp of a 600×600 matrix: about 8 products",
    );
    // The squarings of a large norm count too: ‖A‖₁ = 1e6 needs 18, so a
    // 350×350 exp that is cheap at norm 0 is refused at norm 1e6.
    let out = eval("trace(exp(zeros(350, 350)))");
    assert_eq!(out.stdout.trim(), "350", "{out:#?}");
    assert_fails(
        &eval("exp(1e6 * eye(350))"),
        1,
        "domain error: too much work: 1.1e9 multiply-adds (exp of a 350×350 matrix: about 26 products",
    );
    // An exp that overflows says so.
    assert_fails(
        &eval("exp(1e3 * eye(3))"),
        1,
        "domain error: exp of this matrix overflows",
    );
    // The limit of the determinant is n³/3 ≤ 1e9 multiply-adds: 1443 is
    // the first side refused, before any work is done …
    assert_fails(
        &eval("det(eye(1443))"),
        1,
        "domain error: too much work: 1.0e9 multiply-adds (the determinant of a 1443×1443 matrix",
    );
    // … and below it the LU runs. (A 1000×1000 LU takes 15–50 s in a debug
    // build; 300×300 goes the same way in well under a second.)
    let out = eval("det(2 * eye(300))");
    assert_eq!(out.code, Some(0), "{out:#?}");
    assert_eq!(out.stdout.trim(), "2.037e90", "{out:#?}");
    // A long product of transforms is evaluated in linear time.
    let product = format!("T = Trans((1, 0, 0)); {}", vec!["T"; 150].join(" * "));
    let out = eval(&product);
    assert_eq!(out.code, Some(0), "{out:#?}");
    assert!(out.stdout.contains("150"), "{out:#?}");
}

#[test]
fn runaway_recursion_is_an_error() {
    for src in [
        "f(x) = f(x) + 1; f(1)",
        "g(x) = h(x); h(x) = g(x); g(1)",
        "f(x) = f(f(x)); f(1)",
    ] {
        assert_fails(
            &eval(src),
            1,
            "domain error: function calls nested deeper than 64",
        );
    }
}

#[test]
fn long_lines_are_refused_and_long_files_run() {
    let dir = Scratch::new("long");
    // A 2 MB statement: refused quickly with a syntax error.
    let long = format!("x = 1{}\ny = 2\ny\n", " + 1".repeat(500_000));
    let f = dir.file("long_line.chs", long.as_bytes());
    let out = bounded(&["run", "--keep-going", &f]);
    assert_fails(&out, 1, "syntax error: statement too long (2000005 bytes");
    assert!(out.stdout.contains("y = 2"), "{out:#?}");
    // A long comment is fine.
    let f = dir.file(
        "long_comment.chs",
        format!("x = 1 # {}\nx\n", "c".repeat(3_000_000)).as_bytes(),
    );
    let out = bounded(&["run", &f]);
    assert_eq!(out.code, Some(0), "{out:#?}");
    assert_eq!(out.stdout, "x = 1\n1\n");
    // Many statements: linear, all run, the line numbers right at the end.
    let mut many = "y = 2\n".repeat(50_000);
    many.push_str("T_ab * T_cb\n");
    let f = dir.file("many.chs", many.as_bytes());
    let out = bounded(&["check", &f]);
    assert_fails(&out, 1, "many.chs:50001:1: name error");
}

#[test]
fn files_over_100_mb_are_refused() {
    let dir = Scratch::new("big");
    let path = dir.0.join("big.chs");
    let f = std::fs::File::create(&path).expect("create");
    f.set_len(100 * 1024 * 1024 + 1).expect("sparse file");
    let path = path.to_string_lossy().into_owned();
    let out = bounded(&["run", &path]);
    assert_fails(
        &out,
        2,
        "is 104857601 bytes; scripts are limited to 104857600 bytes",
    );
    assert!(out.stdout.is_empty());
}

// ---------------------------------------------------------------------------
// Numbers: every case has a defined answer
// ---------------------------------------------------------------------------

#[test]
fn numbers_outside_the_domain_are_domain_errors() {
    let cases: &[(&str, &str)] = &[
        ("1/0", "domain error: division by zero"),
        ("0/0", "domain error: division by zero"),
        (
            "sqrt(-1)",
            "domain error: sqrt(-1): the square root of a negative number",
        ),
        (
            "acos(2)",
            "domain error: acos(2): the argument must be in [−1, 1]",
        ),
        (
            "log(-1)",
            "domain error: log of -1: the logarithm needs a positive number",
        ),
        ("(-1)^0.5", "domain error: (-1)^(1/2) is not a real number"),
        (
            "inv([1, 2; 2, 4])",
            "domain error: the matrix is singular (determinant 0)",
        ),
        (
            "Normalize((0, 0, 0))",
            "domain error: cannot normalize the zero vector",
        ),
        (
            "Normalize((inf, 0, 0))",
            "domain error: cannot normalize a vector with entries that are not finite",
        ),
        (
            "inv([inf, 0; 0, 1])",
            "domain error: the matrix has entries that are not finite",
        ),
        (
            "log([1,2,3; 4,5,6; 7,8,10])",
            "domain error: not a rotation matrix: det = -3",
        ),
        (
            "exp([inf, 0; 0, 0])",
            "domain error: exp of a matrix with entries that are not finite",
        ),
        (
            "exp([1, 0; 0, 1] * 1e308 * 10)",
            "domain error: exp of a matrix with entries that are not finite",
        ),
        (
            "MatrixLog3([inf - inf, 0, 0; 0, 1, 0; 0, 0, 1])",
            "domain error: not a rotation matrix: it has entries that are not finite",
        ),
        (
            "MatrixLog6([inf, 0, 0, 0; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1])",
            "domain error",
        ),
        (
            "Rotz(inf)",
            "domain error: Rotz gives no finite SO(3): an argument is inf or NaN",
        ),
        ("Rot((1, 0, 0), inf - inf)", "domain error"),
        ("MatrixExp3((1, 2, 3) * inf)", "domain error"),
    ];
    for (src, needle) in cases {
        assert_fails(&eval(src), 1, needle);
    }
}

#[test]
fn ieee_values_come_with_a_warning() {
    for (src, value, warning) in [
        ("inf", "inf", "warning: the result is infinite"),
        ("1e400", "inf", "warning: the result is infinite"),
        ("-2^1e308", "-inf", "warning: the result is infinite"),
        ("inf - inf", "NaN", "warning: the result has NaN entries"),
        ("0 * inf", "NaN", "warning: the result has NaN entries"),
    ] {
        let out = eval(src);
        assert_eq!(out.code, Some(0), "{out:#?}");
        assert_eq!(out.stdout.trim(), value, "{src}: {out:#?}");
        assert!(out.stderr.contains(warning), "{src}: {out:#?}");
    }
    // Finite results have no warning.
    let out = eval("exp(1)");
    assert_eq!(out.stdout.trim(), "2.7183");
    assert!(out.stderr.is_empty(), "{out:#?}");
}

// ---------------------------------------------------------------------------
// Files and streams
// ---------------------------------------------------------------------------

#[test]
fn missing_and_directory_exit_2() {
    let dir = Scratch::new("files");
    let missing = dir.0.join("missing.chs").to_string_lossy().into_owned();
    assert_fails(&bounded(&["run", &missing]), 2, "no such file");
    assert_fails(&bounded(&["check", &missing]), 2, "no such file");
    let d = dir.0.to_string_lossy().into_owned();
    assert_fails(&bounded(&["run", &d]), 2, "it is a directory");
    // Each file runs on its own (LANGUAGE.md §1): an unreadable one is
    // reported, the others still run, and the exit code is 2.
    let ok = dir.file("ok.chs", b"x = 1\n");
    let out = bounded(&["run", &missing, &ok]);
    assert_fails(&out, 2, "no such file");
    assert_eq!(out.stdout, "x = 1\n", "{out:#?}");
}

#[test]
fn unreadable_file_exits_2() {
    use std::os::unix::fs::PermissionsExt;
    let dir = Scratch::new("perm");
    let f = dir.file("secret.chs", b"x = 1\n");
    std::fs::set_permissions(&f, std::fs::Permissions::from_mode(0o000)).expect("chmod");
    if std::fs::read(&f).is_ok() {
        // Running as root: permissions do not apply; the file runs.
        let out = bounded(&["run", &f]);
        assert_eq!(out.code, Some(0), "{out:#?}");
        assert_eq!(out.stdout, "x = 1\n");
    } else {
        assert_fails(&bounded(&["run", &f]), 2, "permission denied");
    }
}

#[test]
fn non_utf8_is_an_error_with_the_byte_offset() {
    let dir = Scratch::new("utf8");
    let f = dir.file("latin1.chs", b"x = 1\ny = \xe9\n");
    let out = bounded(&["run", &f]);
    assert_fails(&out, 2, "is not UTF-8 text: invalid byte at offset 10");
    assert!(out.stdout.is_empty(), "{out:#?}");
    let out = chasles(&["run", "-"], Some(b"x = 1\n\xff\xfe"));
    assert_fails(
        &out,
        2,
        "standard input is not UTF-8 text: invalid byte at offset 6",
    );
    let out = chasles(&[], Some(b"\x80"));
    assert_fails(&out, 2, "invalid byte at offset 0");
}

#[test]
fn empty_file_runs_nothing() {
    let dir = Scratch::new("empty");
    let f = dir.file("empty.chs", b"");
    let out = bounded(&["run", &f]);
    assert_eq!(out.code, Some(0), "{out:#?}");
    assert_eq!(out.stdout, "");
    assert_eq!(out.stderr, "");
    let f = dir.file("blank.chs", b"\n\n# only a comment\n  \n");
    let out = bounded(&["run", &f]);
    assert_eq!((out.code, out.stdout.as_str()), (Some(0), ""), "{out:#?}");
    let out = chasles(&[], Some(b""));
    assert_eq!((out.code, out.stdout.as_str()), (Some(0), ""), "{out:#?}");
}

#[test]
fn closed_stdout_ends_quietly() {
    let dir = Scratch::new("pipe");
    let script = "Rotz(1)\n".repeat(20_000);
    let f = dir.file("big.chs", script.as_bytes());
    let mut child = command(&["run", &f])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start");
    {
        // Read one line's worth, then close the read end.
        let mut stdout = child.stdout.take().expect("piped");
        let mut first = [0u8; 16];
        stdout.read_exact(&mut first).expect("some output");
        assert!(
            first.starts_with(b"[0.5403"),
            "{:?}",
            String::from_utf8_lossy(&first)
        );
    }
    let mut stderr = String::new();
    child
        .stderr
        .take()
        .expect("piped")
        .read_to_string(&mut stderr)
        .expect("stderr");
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break s;
        }
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "hang after a closed pipe"
        );
        std::thread::sleep(Duration::from_millis(20));
    };
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(stderr.is_empty(), "{stderr}");
    assert_eq!(status.code(), Some(0));
}

// ---------------------------------------------------------------------------
// Bindings survive errors
// ---------------------------------------------------------------------------

#[test]
fn session_keeps_bindings_after_every_kind_of_error() {
    let mut s = Session::new(Settings::default());
    let (out, err, n) = s.run_to_strings(
        "<t>",
        "T_ab = [0, -1, 0, 1; 1, 0, 0, 2; 0, 0, 1, 3; 0, 0, 0, 1]",
        Mode::Run,
        false,
    );
    assert_eq!((n, err.as_str()), (0, ""), "{out}");
    let before = s.run_to_strings("<t>", "T_ab", Mode::Run, false).0;
    assert!(before.contains("SE(3) {a}←{b}"), "{before}");
    for (bad, kind) in [
        ("T_ab = (1, 2", "syntax error"),
        ("T_ab = T_nope * 2", "name error"),
        ("T_ab = T_ab + Rotz(1)", "type error"),
        ("T_ab = T_ab * T_ab", "frame error"),
        ("T_ab = inv([1, 2; 2, 4])", "domain error"),
        ("T_ab = Rotz(1, 2)", "arity error"),
        ("(T_ab, x) = (Rotz(1), 2, 3)", "arity error"),
    ] {
        let (_, err, n) = s.run_to_strings("<t>", bad, Mode::Run, false);
        assert_eq!(n, 1, "{bad} should fail");
        assert!(err.contains(kind), "{bad}: expected {kind} in {err}");
        let (after, err, n) = s.run_to_strings("<t>", "T_ab", Mode::Run, false);
        assert_eq!((n, err.as_str()), (0, ""), "after {bad}");
        assert_eq!(after, before, "T_ab changed after {bad}");
    }
    let (out, _, _) = s.run_to_strings("<t>", "T_ab[1, 4] + T_ab[3, 4]", Mode::Run, false);
    assert_eq!(out.trim(), "4");
}
