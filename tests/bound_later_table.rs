//! Bound later is typed first, for every builtin (LANGUAGE.md §7, issue
//! 21): "once every symbol of a value has a number, the value *is* a
//! number, typed by what it is — exactly as if the numbers had been typed
//! first". A differential test driven by the one builtin table
//! (`chasles::builtins::table()`): each row's runnable example, with one
//! of its numbers made a symbol `a`, is run twice —
//!
//! - typed first: `a = v`, then `y = example(a)`, then `y`;
//! - bound later: `given a`, `y = example(a)`, `a = v`, then `y`;
//!
//! and the last statements must print the same text (12 decimals, and
//! under `--exact`), the same `--json` record (value, type, frames), and
//! the same warnings (typed first at the call, bound later where the value
//! becomes a number), or both refuse with the same message. The same for
//! every operator that takes a scalar. A builtin added to the table is
//! covered without a line here. `CHASLES_BOUND_CASES=N` runs N random
//! values per number (default 2) beside the example's own and the special
//! ones (0, 1, 90°).

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};

mod common;

/// How a script's statement ended: what it printed on stdout, its
/// diagnostics (message and help lines, without places), and whether it
/// failed.
#[derive(Debug, Clone, PartialEq)]
struct Said {
    out: String,
    notes: Vec<String>,
    failed: bool,
}

/// The diagnostics of stderr as `kind: message` and `help:` lines, without
/// file, line and column (they differ between the two scripts).
fn diagnostics(err: &str) -> Vec<String> {
    let mut v = Vec::new();
    for l in err.lines() {
        let l = l.trim();
        if let Some(h) = l.strip_prefix("= help:") {
            v.push(format!("help:{h}"));
            continue;
        }
        // `t.chs:2:5: warning: …`
        let mut parts = l.splitn(4, ':');
        if let (Some("t.chs"), Some(_), Some(_), Some(rest)) =
            (parts.next(), parts.next(), parts.next(), parts.next())
        {
            v.push(rest.trim().to_string());
        }
    }
    v
}

/// The three ways a value is shown: text at 12 decimals, `--exact`, JSON.
fn settings() -> [Settings; 3] {
    [
        Settings {
            digits: 12,
            ..Settings::default()
        },
        Settings {
            exact: true,
            ..Settings::default()
        },
        Settings {
            json: true,
            ..Settings::default()
        },
    ]
}

/// Runs `steps` one statement at a time in one session: what each said.
fn run(set: &Settings, steps: &[String]) -> Vec<Said> {
    let mut s = Session::new(*set);
    let mut said = Vec::new();
    for st in steps {
        let (out, err, n) = s.run_to_strings("t.chs", st, Mode::Run, false);
        said.push(Said {
            out,
            notes: diagnostics(&err),
            failed: n > 0,
        });
        if n > 0 {
            break;
        }
    }
    said
}

/// A statement made of `expr` with `a` in it, and the names it binds
/// (`(w, th) = AxisAng3(…)` binds two; anything else binds `y`).
struct Case {
    def: String,
    reads: Vec<String>,
}

impl Case {
    fn new(expr: &str) -> Case {
        // `(w, theta) = AxisAng3(…)`: keep the destructuring
        if let Some((lhs, rhs)) = expr.split_once(") = ")
            && lhs.starts_with('(')
        {
            let names: Vec<String> = lhs[1..].split(',').map(|n| n.trim().to_string()).collect();
            return Case {
                def: format!("{lhs}) = {rhs}"),
                reads: names,
            };
        }
        Case {
            def: format!("y = {expr}"),
            reads: vec!["y".to_string()],
        }
    }
}

/// The difference between typed first and bound later for `case` at
/// a = `v`, if any (None: they agree, or both refuse alike).
fn differ(case: &Case, v: &str) -> Option<String> {
    for set in settings() {
        let mut first = vec![format!("a = {v}"), case.def.clone()];
        first.extend(case.reads.iter().cloned());
        let mut later = vec!["given a".to_string(), case.def.clone(), format!("a = {v}")];
        later.extend(case.reads.iter().cloned());
        let f = run(&set, &first);
        let l = run(&set, &later);
        let what = if set.json {
            "--json"
        } else if set.exact {
            "--exact"
        } else {
            "text"
        };
        let show = || {
            format!(
                "[{what}] a = {v}: {}\n  typed first: {f:#?}\n  bound later: {l:#?}",
                case.def
            )
        };
        if f[0].failed {
            return None; // (the value itself is refused: nothing to compare)
        }
        // an honest refusal where the value needs numbers to exist (a
        // range's length, a picture, a count) or an order of free symbols
        // that cannot be decided (§7: said, never guessed)
        let honest = l.len() > 1
            && l[1].failed
            && l[1].notes.first().is_some_and(|m| {
                ["needs numbers", "not the symbol", "cannot decide"]
                    .iter()
                    .any(|k| m.contains(k))
            });
        if f[1].failed {
            if honest {
                return None;
            }
            // typed first refuses the call: bound later must refuse it too,
            // with the same message, where the numbers arrive (or earlier)
            let refused = l.iter().skip(1).find(|s| s.failed);
            let same = refused.is_some_and(|s| {
                s.notes
                    .first()
                    .zip(f[1].notes.first())
                    .is_some_and(|(b, a)| {
                        b.ends_with(a.split_once(": ").map_or(a.as_str(), |x| x.1))
                    })
            });
            return (!same).then(show);
        }
        if l[1].failed {
            return (!honest)
                .then(|| format!("refused with a symbol, not typed first: {}", show()));
        }
        if l.len() < later.len() || l.iter().any(|s| s.failed) {
            return Some(show());
        }
        // the values read, each as typed first shows it
        let reads = case.reads.len();
        for i in 0..reads {
            let (a, b) = (&f[2 + i], &l[3 + i]);
            if a.out != b.out {
                return Some(show());
            }
        }
        // warnings: typed first's at the call and reads, bound later's at
        // the reads (the symbolic call's own notes are about the formula)
        let mut want: Vec<String> = f[1..].iter().flat_map(|s| s.notes.clone()).collect();
        let mut got: Vec<String> = l[3..].iter().flat_map(|s| s.notes.clone()).collect();
        want.dedup();
        got.dedup();
        if want != got {
            return Some(format!("warnings differ: {}", show()));
        }
    }
    None
}

/// The numbers of an example as they are written (their byte ranges),
/// not those inside names (`Rotz`, `t2`, `1e-7` is one number).
fn numbers(src: &str) -> Vec<(usize, usize)> {
    let b = src.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    let mut in_string = false;
    while i < b.len() {
        let c = b[i];
        if c == b'"' {
            in_string = !in_string;
        }
        let word_before = i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_');
        if !in_string && c.is_ascii_digit() && !word_before {
            let start = i;
            while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
                i += 1;
            }
            if i + 1 < b.len() && b[i] == b'e' && (b[i + 1] == b'-' || b[i + 1].is_ascii_digit()) {
                i += 2;
                while i < b.len() && b[i].is_ascii_digit() {
                    i += 1;
                }
            }
            out.push((start, i));
            continue;
        }
        i += 1;
    }
    out
}

/// The values `a` takes for a number written `lit`: itself, the special
/// ones (0, 1, 90, π/2) and `n` random ones near it.
fn values(lit: &str, n: usize, rng: &mut common::Rng) -> Vec<String> {
    let x: f64 = lit.parse().unwrap_or(1.0);
    let mut vs = vec![
        lit.to_string(),
        "0".into(),
        "1".into(),
        "90".into(),
        "pi/2".into(),
    ];
    for _ in 0..n {
        let r = x * (1.0 + 0.5 * rng.next()) + 0.3 * rng.next();
        vs.push(format!("{r:.6}"));
    }
    vs
}

/// Builtins whose results read their operands' symbols, not values
/// (`diff(x, t)`, `subs`): with numbers typed first there is nothing to
/// differentiate; and builtins that write files or make pictures.
fn reads_symbols(name: &str, example: &str) -> bool {
    matches!(name, "diff" | "subs" | "save") || example.contains("given")
}

/// Differences known and kept, with the reason: a matrix literal whose
/// symbolic entry makes it SE(2) for every value of the symbol is refused
/// by `SO3(…)` at once, though at a = 0 it would be a rotation.
const KNOWN: &[(&str, &str)] = &[("SO3", "0")];

/// The cases of the table: each builtin's example with each of its numbers
/// (up to four) made the symbol `a`.
fn table_cases() -> Vec<(String, Case, String)> {
    let mut out = Vec::new();
    for b in chasles::builtins::table() {
        if reads_symbols(b.name, b.example) {
            continue;
        }
        let ex = b.example;
        for (s, e) in numbers(ex).into_iter().take(4) {
            let expr = format!("{}a{}", &ex[..s], &ex[e..]);
            out.push((b.name.to_string(), Case::new(&expr), ex[s..e].to_string()));
        }
    }
    out
}

/// Every operator that takes a scalar, with `a` among its operands.
const OPERATORS: &[&str] = &[
    "a + 1",
    "1 - a",
    "2 a",
    "a * a",
    "1 / a",
    "a / a",
    "(a - 1)/(a - 1)",
    "a * 0 / a",
    "a ^ 3",
    "a ^ -1",
    "2 ^ a",
    "a ^ 0.5",
    "-a",
    "a deg",
    "(a, 1, 2)",
    "(1, 2, 3) * a",
    "[a, 0; 0, 1]",
    "[(0, 0, a)]",
    "[(0, 0, a, 1, 0, 0)]",
    "[a, 0; 0, 1]^-1",
    "(a, 2, 3)[1]",
    "(a, 2, 3).T",
    "a == 2",
    "a == 0",
    "a ~= 2",
    "a < 2",
    "a <= 0",
    "a > 1",
    "a >= 90",
    "a^2 == a*a",
    "sin(a)/sin(a)",
    "cos(a) == 1/2",
    "sqrt(a) sqrt(a)",
    "Rotz(a) * (1, 0, 0)",
    "exp([(0, 0, 1)] a)",
    "exp([(0, 0, 1, 0, a, 0)] 1)",
];

#[test]
fn every_builtin_bound_later_is_typed_first() {
    let n: usize = std::env::var("CHASLES_BOUND_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2);
    let mut rng = common::Rng(0x9e37_79b9_7f4a_7c15);
    let mut found = Vec::new();
    let mut ran = 0;
    let cases = table_cases();
    let builtins: std::collections::BTreeSet<&str> = cases.iter().map(|c| c.0.as_str()).collect();
    assert!(
        builtins.len() > 60,
        "the table gave {} builtins",
        builtins.len()
    );
    for (name, case, lit) in &cases {
        for v in values(lit, n, &mut rng) {
            ran += 1;
            if KNOWN.contains(&(name.as_str(), v.as_str())) {
                continue;
            }
            if let Some(d) = differ(case, &v) {
                found.push(format!("{name}: {d}"));
            }
        }
    }
    assert!(
        found.is_empty(),
        "{} of {ran} cases differ:\n{}",
        found.len(),
        found.join("\n\n")
    );
}

#[test]
fn every_operator_bound_later_is_typed_first() {
    let mut found = Vec::new();
    let mut rng = common::Rng(0x2545_f491_4f6c_dd1d);
    for op in OPERATORS {
        let case = Case::new(op);
        for v in values("2", 2, &mut rng) {
            if let Some(d) = differ(&case, &v) {
                found.push(d);
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n\n"));
}
