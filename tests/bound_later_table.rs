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

/// JSON lines without their `warnings` key: a statement's notes are
/// compared as [`Said::notes`], where bound later may say them at the read
/// rather than at the call (text output, whose stderr they are, is
/// compared the same way; issue 36 put them into JSON). Cut as text, the
/// key being the last: parsing and printing again could move a float by an
/// ulp.
fn without_warnings(out: String) -> String {
    if !out.contains("\"warnings\"") {
        return out;
    }
    out.lines()
        .filter_map(|l| match l.find(",\"warnings\":") {
            // (a statement that printed only its warnings)
            Some(_)
                if l.starts_with("{\"line\":")
                    && !l.contains("\"name\"")
                    && !l.contains("\"error\"") =>
            {
                None
            }
            Some(at) => Some(format!("{}}}\n", &l[..at])),
            None => Some(format!("{l}\n")),
        })
        .collect()
}

/// Runs `steps` one statement at a time in one session: what each said.
fn run(set: &Settings, steps: &[String]) -> Vec<Said> {
    let mut s = Session::new(*set);
    let mut said = Vec::new();
    for st in steps {
        let (out, err, n) = s.run_to_strings("t.chs", st, Mode::Run, false);
        said.push(Said {
            out: without_warnings(out),
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

/// What a statement of a script is for.
#[derive(Clone, Copy, PartialEq)]
enum Role {
    Setup,
    Def,
    Read(usize),
    /// The same name read again: typed first it warns no more (its
    /// warnings were given at the call), and bound later neither (once
    /// per binding of the numbers).
    Again(usize),
    /// `z = y` read back at the end: a value read while its symbols were
    /// (partly) free, that keeps following them.
    Alias,
}

/// The difference between typed first and bound later for `case` with
/// the numbers `binds` (`a`, then `b`), if any (None: they agree, or both
/// refuse alike). Bound later, `z = y` is read after the first number is
/// bound (partly bound with two symbols) and compared at the end too.
fn differ(case: &Case, binds: &[(&str, String)]) -> Option<String> {
    let names: Vec<&str> = binds.iter().map(|b| b.0).collect();
    differ_given(case, &format!("given {}", names.join(", ")), binds)
}

/// [`differ`] with the symbols declared by `given` (typed: `given R : SO3`).
fn differ_given(case: &Case, given: &str, binds: &[(&str, String)]) -> Option<String> {
    let single = case.reads == ["y"];
    let mut first: Vec<(String, Role)> = binds
        .iter()
        .map(|(n, v)| (format!("{n} = {v}"), Role::Setup))
        .collect();
    first.push((case.def.clone(), Role::Def));
    for (i, r) in case.reads.iter().enumerate() {
        first.push((r.clone(), Role::Read(i)));
    }
    for (i, r) in case.reads.iter().enumerate() {
        first.push((r.clone(), Role::Again(i)));
    }
    let mut later = vec![
        (given.to_string(), Role::Setup),
        (case.def.clone(), Role::Def),
    ];
    for (k, (n, v)) in binds.iter().enumerate() {
        later.push((format!("{n} = {v}"), Role::Setup));
        if k == 0 && single && binds.len() > 1 {
            later.push(("z = y".to_string(), Role::Setup));
        }
    }
    if single && binds.len() == 1 {
        later.insert(2, ("z = y".to_string(), Role::Setup));
    }
    for (i, r) in case.reads.iter().enumerate() {
        later.push((r.clone(), Role::Read(i)));
    }
    for (i, r) in case.reads.iter().enumerate() {
        later.push((r.clone(), Role::Again(i)));
    }
    if single {
        later.push(("z".to_string(), Role::Alias));
    }
    let at = |script: &[(String, Role)], role: Role| script.iter().position(|s| s.1 == role);
    let steps = |script: &[(String, Role)]| script.iter().map(|s| s.0.clone()).collect::<Vec<_>>();
    for set in settings() {
        let f = run(&set, &steps(&first));
        let l = run(&set, &steps(&later));
        let what = if set.json {
            "--json"
        } else if set.exact {
            "--exact"
        } else {
            "text"
        };
        let show = || {
            format!(
                "[{what}] {binds:?}: {}\n  typed first: {f:#?}\n  bound later: {l:#?}",
                case.def
            )
        };
        let (fd, ld) = (at(&first, Role::Def)?, at(&later, Role::Def)?);
        if f.len() <= fd {
            return None; // (a number itself is refused: nothing to compare)
        }
        // an honest refusal where the value needs numbers to exist (the
        // length of a range still waiting for them, a picture, a count);
        // an order of free symbols is no refusal: it waits for its numbers
        let honest = l.len() > ld
            && l[ld].failed
            && l[ld].notes.first().is_some_and(|m| {
                ["needs numbers", "not the symbol"]
                    .iter()
                    .any(|k| m.contains(k))
            });
        if f[fd].failed {
            if honest {
                return None;
            }
            // typed first refuses the call: bound later must refuse it too,
            // with the same message, where the numbers arrive (or earlier)
            let refused = l.iter().skip(ld).find(|s| s.failed);
            let same = refused.is_some_and(|s| {
                s.notes
                    .first()
                    .zip(f[fd].notes.first())
                    .is_some_and(|(b, a)| {
                        b.ends_with(a.split_once(": ").map_or(a.as_str(), |x| x.1))
                    })
            });
            return (!same).then(show);
        }
        if l.len() > ld && l[ld].failed {
            return (!honest)
                .then(|| format!("refused with a symbol, not typed first: {}", show()));
        }
        if l.len() < later.len() || l.iter().any(|s| s.failed) {
            return Some(show());
        }
        // the values read, each as typed first shows it
        for (i, _) in case.reads.iter().enumerate() {
            let (a, b) = (at(&first, Role::Read(i))?, at(&later, Role::Read(i))?);
            if f[a].out != l[b].out {
                return Some(show());
            }
        }
        if let (Some(a), Some(b)) = (at(&first, Role::Read(0)), at(&later, Role::Alias))
            && f[a].out != l[b].out
        {
            return Some(format!("read while free, then bound: {}", show()));
        }
        // a name read again prints the same and warns as typed first: no
        // more (bound later, once per binding of the numbers)
        for (i, _) in case.reads.iter().enumerate() {
            let (a, b) = (at(&first, Role::Again(i))?, at(&later, Role::Again(i))?);
            if f[a].out != l[b].out || f[a].notes != l[b].notes {
                return Some(format!("read again: {}", show()));
            }
        }
        // warnings: typed first's at the call and reads, bound later's at
        // the reads (the symbolic call's own notes are about the formula)
        let mut want: Vec<String> = f[fd..].iter().flat_map(|s| s.notes.clone()).collect();
        // (the alias read at the end is another value: not counted)
        let first_read = at(&later, Role::Read(0))?;
        let mut got: Vec<String> = l[first_read..]
            .iter()
            .zip(&later[first_read..])
            .filter(|(_, s)| s.1 != Role::Alias)
            .flat_map(|(s, _)| s.notes.clone())
            .collect();
        want.dedup();
        got.dedup();
        if want != got {
            return Some(format!("warnings differ: {}", show()));
        }
    }
    None
}

/// The values `a` takes for a number written `lit`: itself, the special
/// ones (0, 1, 90, π/2), exact ones (30°, 1/√2, −1/3) and `n` random ones
/// near it.
fn values(lit: &str, n: usize, rng: &mut common::Rng) -> Vec<String> {
    let x: f64 = lit.parse().unwrap_or(1.0);
    let mut vs = vec![
        lit.to_string(),
        "0".into(),
        "1".into(),
        "90".into(),
        "pi/2".into(),
        "30 deg".into(),
        "sqrt(2)/2".into(),
        "-1/3".into(),
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
fn table_cases() -> Vec<(String, Case, Vec<String>)> {
    let mut out = Vec::new();
    for b in chasles::builtins::table() {
        if reads_symbols(b.name, b.example) {
            continue;
        }
        let ex = b.example;
        let nums = common::literals(ex);
        for &(s, e) in nums.iter().take(4) {
            let expr = format!("{}a{}", &ex[..s], &ex[e..]);
            out.push((
                b.name.to_string(),
                Case::new(&expr),
                vec![ex[s..e].to_string()],
            ));
        }
        // two numbers made symbols `a` and `b`, bound one after the other
        if let [(s1, e1), (s2, e2), ..] = nums[..] {
            let expr = format!("{}a{}b{}", &ex[..s1], &ex[e1..s2], &ex[e2..]);
            let lits = vec![ex[s1..e1].to_string(), ex[s2..e2].to_string()];
            out.push((b.name.to_string(), Case::new(&expr), lits));
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
    // a transform times a point, homogeneous (§3.3.1), planar too
    "[Rotz(a), (1, 2, 3); 0, 1] * (1, 0, 0)",
    "SE2(a, 1, 2) * (1, 0)",
    "[cos(a), -sin(a), 1; sin(a), cos(a), 2; 0, 0, 1] * (1, a)",
    "exp([(0, 0, 1)] a)",
    "exp([(0, 0, 1, 0, a, 0)] 1)",
    // orders wait for their numbers (issue 21), exact numbers exactly
    "a < a + 1",
    "a - a < 1",
    "a^2 + 1 > 0",
    "sqrt(a) sqrt(a) <= a",
    "cos(a) >= 1/2",
    // ranges wait for their numbers, then are the list typed first gives
    "0:a:3",
    "a:5",
    "1:0.5:a",
    "(a - 1):a:(a + 3)",
    "len(0:a:3) + 1",
    "sum(a:5)",
    "max(1:0.5:a) < 10",
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
    for (name, case, lits) in &cases {
        let mut vals: Vec<Vec<String>> = lits.iter().map(|l| values(l, n, &mut rng)).collect();
        if let [va, vb] = &mut vals[..] {
            // two symbols: each value of a with a value of b
            vb.rotate_left(1);
            for (x, y) in va.iter().zip(vb.iter()) {
                ran += 1;
                if let Some(d) = differ(case, &[("a", x.clone()), ("b", y.clone())]) {
                    found.push(format!("{name}: {d}"));
                }
            }
            continue;
        }
        for v in vals.concat() {
            ran += 1;
            if KNOWN.contains(&(name.as_str(), v.as_str())) {
                continue;
            }
            if let Some(d) = differ(case, &[("a", v)]) {
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
            if let Some(d) = differ(&case, &[("a", v)]) {
                found.push(d);
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n\n"));
}

/// A `given` symbol of the type a parameter takes, and the numbers it is
/// bound to (unit axes: a symbolic axis is assumed unit, §7).
fn given_of(p: chasles::builtins::Param, i: usize) -> Option<(String, String, Vec<String>)> {
    use chasles::builtins::Param;
    let n = |s: &str| format!("{s}{i}");
    Some(match p {
        Param::Scalar => (
            n("s"),
            "scalar".into(),
            vec!["0.3".into(), "0".into(), "pi/2".into()],
        ),
        Param::Rot => (
            n("R"),
            "SO3".into(),
            vec![
                "Rotz(0.3) Rotx(-1.1)".into(),
                "Roty(pi/2)".into(),
                "Rotx(pi)".into(),
            ],
        ),
        Param::Trans => (
            n("T"),
            "SE3".into(),
            vec![
                "RpToTrans(Rotz(0.3), (1, 2, 3))".into(),
                "RpToTrans(Roty(pi/2), (0, 0, 1))".into(),
            ],
        ),
        Param::Vec(3) | Param::Expc3 => (
            n("w"),
            "vec3".into(),
            vec!["(0.6, 0, 0.8)".into(), "(0, 0, 1)".into()],
        ),
        Param::Vec(6) | Param::Expc6 => (
            n("V"),
            "vec6".into(),
            vec!["(0, 0.6, 0.8, 1, 2, 3)".into(), "(0, 0, 0, 1, 0, 0)".into()],
        ),
        _ => return None,
    })
}

/// Every builtin of fixed parameters called on `given` symbols of those
/// types (`Ad(T)` over `given T : SE3`), bound later to numbers: the value
/// is the one typed first.
#[test]
fn every_builtin_on_given_values_bound_later_is_typed_first() {
    use chasles::builtins::Typing;
    let mut found = Vec::new();
    let mut ran = 0;
    for b in chasles::builtins::table() {
        let Typing::Fixed { params, .. } = b.typing else {
            continue;
        };
        if params.is_empty() || reads_symbols(b.name, b.example) {
            continue;
        }
        let Some(gs): Option<Vec<_>> = params
            .iter()
            .enumerate()
            .map(|(i, p)| given_of(*p, i + 1))
            .collect()
        else {
            continue;
        };
        let given = gs
            .iter()
            .map(|(n, t, _)| format!("given {n} : {t}"))
            .collect::<Vec<_>>()
            .join("; ");
        let args: Vec<&str> = gs.iter().map(|g| g.0.as_str()).collect();
        let case = Case::new(&format!("{}({})", b.name, args.join(", ")));
        let most = gs.iter().map(|g| g.2.len()).max().unwrap_or(0);
        for k in 0..most {
            let binds: Vec<(&str, String)> = gs
                .iter()
                .map(|(n, _, vs)| (n.as_str(), vs[k % vs.len()].clone()))
                .collect();
            ran += 1;
            if let Some(d) = differ_given(&case, &given, &binds) {
                found.push(format!("{}: {d}", b.name));
            }
        }
    }
    assert!(ran > 30, "only {ran} cases");
    assert!(
        found.is_empty(),
        "{} of {ran} cases differ:\n{}",
        found.len(),
        found.join("\n\n")
    );
}
