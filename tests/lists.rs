//! Ranges, lists and list comprehensions (LANGUAGE.md §12): how the
//! grammar reads them, what they evaluate to and print, and that a list of
//! frames keeps its frames with and without numbers.

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};

#[test]
fn ranges_lists_and_comprehensions() {
    let mut s = Session::new(Settings::default());
    let (out, err, n) = s.run_to_strings(
        "t",
        "r = 0:pi/8:pi\nlen(r)\nr[9] - pi\n[a * 10 + b for a in 1:2, b in 1:3]\n(x, y, z) = [k^2 for k in 1:3]\nz\nsum([k for k in 1:100])\n(min(r), max(0:3))\n5:-1:1\nlen(1:0)\n0:0.1:0.3\n",
        Mode::Run,
        false,
    );
    assert_eq!(n, 0, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines[1], "9");
    assert_eq!(lines[2], "0");
    assert_eq!(lines[3], "[11, 12, 13, 21, 22, 23]  : list of 6 numbers");
    assert!(out.contains("z = 9"), "{out}");
    assert!(out.contains("\n5050\n"), "{out}");
    assert!(out.contains("(0, 3)"), "{out}");
    assert!(out.contains("[5, 4, 3, 2, 1]"), "{out}");
    assert!(out.contains("\n0\n[0, 0.1, 0.2, 0.3]"), "{out}");
    // A user function reaches the elements only through a comprehension.
    let (_, err, n) = s.run_to_strings("t", "f(x) = 2 * x\nf(0:3)\n", Mode::Run, false);
    assert_eq!(n, 1);
    assert!(err.contains("no arithmetic on a list"), "{err}");
    let (out, _, n) = s.run_to_strings("t", "[f(x) for x in 0:3]\n", Mode::Run, false);
    assert_eq!((n, out.trim()), (0, "[0, 2, 4, 6]  : list of 4 numbers"));
    // JSON: a list is an array of values, typed "list".
    let mut j = Session::new(Settings {
        json: true,
        ..Settings::default()
    });
    let (out, _, _) = j.run_to_strings("t", "1:3\n", Mode::Run, false);
    assert!(
        out.contains("\"type\":\"list\"") && out.contains("\"value\":[1,2,3]"),
        "{out}"
    );
}

#[test]
fn lists_of_frames_keep_their_frames_and_check_without_numbers() {
    let src = "T_sb = Trans((2, 0, 0))\nS = ScrewToAxis((0, 2, 0), (0, 0, 1), 2)\npath = [exp([S] * k) * T_sb for k in 0:4]\nT_2 = path[3]\ndraw(path, S)\n";
    let mut s = Session::new(Settings::default());
    let (out, err, n) = s.run_to_strings("t", src, Mode::Run, false);
    assert_eq!(n, 0, "{err}");
    assert!(out.contains("list of 5 SE(3) {s}←{b'}"), "{out}");
    assert!(
        out.contains("picture: 5 frames and 1 screw axis in {s}"),
        "{out}"
    );
    let mut c = Session::new(Settings::default());
    let (out, err, n) = c.run_to_strings("t", src, Mode::Check, true);
    assert_eq!(n, 0, "{err}");
    assert!(out.contains("path : list of SE(3) {s}←{b'}"), "{out}");
}

#[test]
fn the_grammar_reads_ranges_comprehensions_and_strings() {
    use chasles::syntax::ast::{ExprKind, StmtKind};
    use chasles::syntax::parse_program;
    let one = |src: &str| {
        let mut all = parse_program(src);
        assert_eq!(all.len(), 1, "{src}");
        all.remove(0)
    };
    let value = |src: &str| match one(src).expect("parses").kind {
        StmtKind::Assign { value, .. } => value.kind,
        StmtKind::Expr(e) => e.kind,
        k => panic!("{k:?}"),
    };
    // `:` is looser than `+`: 1:n+1 is 1:(n+1); a:s:b takes three parts.
    let ExprKind::Range { start, step, end } = value("r = 1:n+1") else {
        panic!()
    };
    assert!(matches!(start.kind, ExprKind::Number(x) if x == 1.0));
    assert!(step.is_none());
    assert!(matches!(end.kind, ExprKind::Binary { .. }));
    let ExprKind::Range { step, .. } = value("0:pi/8:pi") else {
        panic!()
    };
    assert!(step.is_some());
    // The grid: the first variable is outermost.
    let ExprKind::Comprehension { body, vars } = value("[f(a, b) for a in 0:2, b in xs]") else {
        panic!()
    };
    assert!(matches!(body.kind, ExprKind::Call { .. }));
    let names: Vec<&str> = vars.iter().map(|(n, _)| n.name.as_str()).collect();
    assert_eq!(names, ["a", "b"]);
    assert!(matches!(
        value("save(p, \"a b.svg\")"),
        ExprKind::Call { .. }
    ));
    assert!(matches!(value("\"x; y # z\""), ExprKind::Str(t) if t == "x; y # z"));
    // Errors name the fix.
    for (src, want) in [
        ("0:1:2:3", "a range has at most two colons"),
        (
            "[1, 2 for k in 0:4]",
            "a list comprehension takes one expression before `for`",
        ),
        ("for = 2", "expected"),
    ] {
        let e = one(src).expect_err(src);
        assert!(e.message.contains(want), "{src}: {}", e.message);
    }
    // Indexing and `given` keep their colons.
    assert!(one("M[:, 1]").is_ok() && one("given T_ab : SE3").is_ok());
}

#[test]
fn a_sum_of_group_elements_is_a_plain_matrix_as_with_plus() {
    let run = |src: &str| {
        let mut s = Session::new(Settings::default());
        s.run_to_strings("t", src, Mode::Run, false)
    };
    // SO(3), SE(3) and the adjoints are not closed under addition: `sum`
    // gives what `+` gives (Rotz(0) + Rotz(1) is a 3×3 matrix).
    for (src, want) in [
        ("sum([Rotz(k) for k in 0:1])", "2]  : 3×3 matrix"),
        ("Rotz(0) + Rotz(1)", "2]  : 3×3 matrix"),
        ("sum([Trans((1, 0, 0)) for k in 1:3])", "3]  : 4×4 matrix"),
        (
            "sum([Ad(Trans((0, 0, k))) for k in 1:2])",
            "2]  : 6×6 matrix",
        ),
        (
            "Ad(Trans((0, 0, 1))) + Ad(Trans((0, 0, 2)))",
            "2]  : 6×6 matrix",
        ),
        // Twists keep what `+` keeps, and their frame; screws sum to a twist.
        (
            "V_s = (1, 0, 0, 0, 0, 1)\nsum([V_s for k in 1:2])",
            "(2, 0, 0, 0, 0, 2)  : twist {s}",
        ),
        (
            "S = (0, 0, 1, 0, 0, 0)\nsum([S for k in 1:3])",
            "(0, 0, 3, 0, 0, 0)  : twist",
        ),
    ] {
        let (out, err, n) = run(src);
        assert_eq!(n, 0, "{src}: {err}");
        assert!(out.trim_end().ends_with(want), "{src}: {out}");
    }
    // So the log of such a sum is the log of the same literal matrix: a
    // domain error with the distance, not a number.
    let (out, err, n) = run("MatrixLog3(sum([Rotz(k) for k in 0:1]))");
    assert_eq!((n, out.as_str()), (1, ""), "{err}");
    assert!(err.contains("distance from SO(3) is 4.2021"), "{err}");
    let (_, err, n) = run("R_sb = sum([Rotz(k) for k in 0:1])");
    assert_eq!(n, 1);
    assert!(err.contains("is 4.2021 from SO(3)"), "{err}");
    // JSON names the kind "matrix", not "SO3".
    let mut j = Session::new(Settings {
        json: true,
        ..Settings::default()
    });
    let (out, _, _) = j.run_to_strings("t", "sum([Rotz(k) for k in 0:1])\n", Mode::Run, false);
    assert!(out.contains("\"type\":\"matrix\""), "{out}");
}

/// The items of a range, a comprehension over a vector, a destructured
/// vector and `sum`, `min`, `max` are exact as the same numbers written
/// out are (LANGUAGE.md §7: "exact numbers stay exact"): each line is
/// true, as its typed-out twin is. They were false, with a note that the
/// sides differ by rounding only (`(0:0.1:1)[4]` was the float
/// 0.30000000000000004 with no exact form, `max([1 + 1e-20, 1])` the
/// float 1).
#[test]
fn list_items_are_exact_as_the_numbers_written_out() {
    let lines = [
        // typed out: 0.1·3 == 0.3, k = 2; sqrt(k)^2 == 2
        "r = 0:0.1:1; r[4] == 0.3",
        "[sqrt(k) for k in 1:4][2]^2 == 2",
        "(-0.3:0.1:0.3)[4] == 0",
        "[x^2 for x in (sqrt(2), 1)][1] == 2",
        "(x, y) = (sqrt(2), 1); x^2 == 2",
        "sum([0.1 for k in 1:10]) == 1",
        "sum(0:0.1:1) == 5.5",
        "sum((sqrt(2), sqrt(2)))^2 == 8",
        "min([sqrt(2), 2])^2 == 2",
        "max((sqrt(3), 1))^2 == 3",
        "max([1 + 1e-20, 1]) == 1 + 1e-20",
        "(max([1 + 1e-20, 1]) == 1) == false",
        "min([1 + 1e-20, 1]) == 1",
        // (floats far from their exact values: tan(2π) is −2.4e-16 for 0)
        "max([tan(2*pi), -1e-20]) == 0",
        "min([-tan(2*pi), 1e-20]) == 0",
        // (long lists: the extreme among 8,001 items, by mpmath at 50
        // digits sin(7.854), then sin(1.571), sin(1.570); least sin(4.712))
        "max([sin(t) for t in 0:0.001:8]) == sin(7.854)",
        "min([sin(t) for t in 0:0.001:8]) == sin(4.712)",
        "max([sin(t) for t in 0:0.001:3]) == sin(1.571)",
        "sum([k*pi/4 for k in 1:4]) == 5*pi/2",
        // bound later, as typed first
        "given h; r = 0:h:1; h = 0.1; r[4] == 0.3",
        "given h; s = sum(0:h:1); h = 0.1; s == 5.5",
    ];
    for line in lines {
        let mut s = Session::new(Settings::default());
        let (out, err, n) = s.run_to_strings("t", &format!("{line}\n"), Mode::Run, false);
        assert_eq!(n, 0, "{line}: {err}");
        assert_eq!(out.lines().last(), Some("true"), "{line}: {out}{err}");
    }
    // The floats stay those of the sum written out (JSON's full precision).
    let mut j = Session::new(Settings {
        json: true,
        ..Settings::default()
    });
    let (out, _, _) = j.run_to_strings("t", "0:0.1:0.3\n", Mode::Run, false);
    assert!(out.contains("[0,0.1,0.2,0.30000000000000004]"), "{out}");
}

/// A range of exact bounds ends where its exact numbers say (LANGUAGE.md
/// §12: the end is included "within a rounding tolerance", and exact
/// numbers have no rounding): `1:0.5:1.9999999999` was [1, 1.5, 2], its
/// last item past its end, as was 0.3 in `0:0.1:0.29999999999`. Ends that
/// floats reach only within rounding (π by π/8) are still reached.
#[test]
fn a_range_of_exact_bounds_ends_exactly() {
    let cases = [
        ("1:0.5:1.9999999999", "[1, 1.5]  : list of 2 numbers"),
        ("1:0.5:2.0000000001", "[1, 1.5, 2]  : list of 3 numbers"),
        ("0:0.1:0.29999999999", "[0, 0.1, 0.2]  : list of 3 numbers"),
        ("0:0.1:0.3", "[0, 0.1, 0.2, 0.3]  : list of 4 numbers"),
        ("len(0:pi/8:pi)", "9"),
        ("len(0:pi/3:2*pi)", "7"),
        ("len(0:1/3:1)", "4"),
        ("len(0:0.1:pi)", "32"),
        ("10:-2.5:0", "[10, 7.5, 5, 2.5, 0]  : list of 5 numbers"),
        (
            "given h; r = 0:h:1.9999999999; h = 0.5; r",
            "[0, 0.5, 1, 1.5]  : list of 4 numbers",
        ),
    ];
    for (line, want) in cases {
        let mut s = Session::new(Settings::default());
        let (out, err, n) = s.run_to_strings("t", &format!("{line}\n"), Mode::Run, false);
        assert_eq!(n, 0, "{line}: {err}");
        assert_eq!(out.lines().last(), Some(want), "{line}: {out}");
    }
}

/// A range whose bounds have no exact form is counted in floats, its end
/// included within 1e-10 of a step count; no item passes the end: where
/// the last sum does, the last item is the end itself, as MATLAB's colon
/// makes it. `a:(b - a)/3:b` (a = sin(19/37)/5, b = a + exp(19/37)) ended
/// at a + 3h = b + 2.2e-16, past b. Exact bounds are counted exactly
/// (0:pi/10:pi 11 items, 0:0.1:0.3 4, 1:-0.1:0.7 4, each ending at its end).
#[test]
fn no_item_of_a_float_range_passes_its_end() {
    let setup = "a = sin(19/37)/5\nb = a + exp(19/37)\nh = (b - a)/3\n";
    for (line, want) in [
        ("(a:h:b)[end] - b", "0"),
        ("(a:h:b)[end] > b", "false"),
        ("len(a:h:b)", "4"),
        ("(a:h:b)[end] == b", "true"),
        ("(a:h:b)[3] == a + 2*h", "true"),
        ("[acos((x - a)/(b - a)) for x in a:h:b][end]", "0"),
        // a descending range, and one whose end is off a step count by
        // 1e-13 (within 1e-10: reached, and the end is the last item)
        ("len(b:-h:a)", "4"),
        ("(b:-h:a)[end] >= a", "true"),
        ("len(a:h:b*(1 - 1e-13))", "4"),
        ("(a:h:b*(1 - 1e-13))[end] == b*(1 - 1e-13)", "true"),
        // off by more than 1e-10 of a step: not reached
        ("len(a:h:b - 1e-9)", "3"),
        ("len(0:pi/10:pi)", "11"),
        ("(0:pi/10:pi)[end] == pi", "true"),
        ("len(0:0.1:0.3)", "4"),
        ("1:-0.1:0.7", "[1, 0.9, 0.8, 0.7]  : list of 4 numbers"),
        ("(1:-0.1:0.7)[end] == 0.7", "true"),
    ] {
        let mut s = Session::new(Settings::default());
        let (out, err, n) = s.run_to_strings("t", &format!("{setup}{line}\n"), Mode::Run, false);
        assert_eq!(n, 0, "{line}: {err}");
        assert_eq!(out.lines().last(), Some(want), "{line}: {out}");
    }
}

/// The sum of no items is the zero of their kind, as the sum of the items
/// would be typed (a 3-vector, a twist in {s}): it was the number 0, so
/// that `sum([(1, 0, 0) for k in 1:0]) + (1, 2, 3)` was a type error.
#[test]
fn an_empty_sum_is_the_zero_of_its_kind() {
    let cases = [
        (
            "s = sum([(1, 0, 0) for k in 1:0]); s + (1, 2, 3)",
            "(1, 2, 3)  : 3-vector",
        ),
        (
            "V_s = (0, 0, 1, 0, 0, 0); sum([V_s for k in 1:0])",
            "(0, 0, 0, 0, 0, 0)  : twist {s}",
        ),
        ("sum(1:0)", "0"),
    ];
    for (line, want) in cases {
        let mut s = Session::new(Settings::default());
        let (out, err, n) = s.run_to_strings("t", &format!("{line}\n"), Mode::Run, false);
        assert_eq!(n, 0, "{line}: {err}");
        assert_eq!(out.lines().last(), Some(want), "{line}: {out}");
    }
}

/// The first error's message of `src` in `mode`, None when it is clean.
fn first_error(src: &str, mode: Mode) -> Option<String> {
    let mut s = Session::new(Settings::default());
    let (_, err, n) = s.run_to_strings("t.chs", src, mode, false);
    (n > 0).then_some(err)
}

/// A list of tuples keeps its items' parts' frames (`zs[1][1] * T_cb` ran
/// T_ab * T_cb, the items' parts untagged), through an index, `end`, a
/// comprehension over it and destructuring; and `check` gives an item
/// picked by `end` the list's frames, as `run` does (it gave none).
#[test]
fn items_of_a_list_keep_their_frames() {
    let setup = "T_ab = Trans((1, 0, 0))\nT_bc = RpToTrans(Rotz(0.3), (0, 1, 0))\nT_cb = inv(T_bc)\n\
                 zs = [(T_ab, T_cb) for k in 1:2]\nps = [T_ab * (k, 0, 0) for k in 1:3]\n";
    for x in [
        "zs[1][1] * zs[1][2]",
        "z = zs[2]; z[1] * z[2]",
        "zs[end][1] * zs[end][2]",
        "[z[1] * z[2] for z in zs]",
        "(A, B) = zs[1]; A * B",
        "T_cb * ps[end]",
        "T_cb * ps[2]",
    ] {
        let src = format!("{setup}{x}\n");
        for mode in [Mode::Run, Mode::Check] {
            let e = first_error(&src, mode).unwrap_or_else(|| panic!("{x}: {mode:?} ran it"));
            assert!(e.contains("frames do not cancel"), "{x} ({mode:?}): {e}");
        }
    }
    let src = format!(
        "{setup}ws = [(T_ab, T_bc) for k in 1:2]\n[w[1] * w[2] for w in ws][2] == T_ab * T_bc\n"
    );
    let mut s = Session::new(Settings::default());
    let (out, err, n) = s.run_to_strings("t.chs", &src, Mode::Run, false);
    assert_eq!(n, 0, "{err}");
    assert_eq!(out.lines().last(), Some("true"), "{out}");
    for mode in [Mode::Run, Mode::Check] {
        assert_eq!(
            first_error(&format!("{setup}inv(T_ab) * ps[end]\n"), mode),
            None
        );
    }
}

/// Fractions of fractions and of numbers as typed are made at once and
/// held inline (no recipe keeps the operands: `[k/100 for k in
/// 1:100000]` held 380 bytes an item), and stay exact: they compare, sum
/// and print (`--exact`) as before, 37/100 of integers as a fraction and
/// 0.1·3 as the decimal 0.3.
#[test]
fn fractions_in_lists_stay_exact_and_print_as_before() {
    let lines = [
        "sum([k/100 for k in 1:100]) == 101/2",
        "sum([k/100 for k in 1:100]) == 50.5",
        "[k/100 for k in 1:100][37] == 0.37",
        "[k/3 for k in 1:9][2] == 2/3",
        "[k/3 for k in 1:9][2] * 3 == 2",
        "([k/3 for k in 1:9][1] == 0.3333333333333333) == false",
        "sum([k/3 for k in 1:3]) == 2",
        "(0:1/3:1)[2] + (0:1/3:1)[3] == 1",
        "(1e13 + 0.1) - 1e13 == 0.1",
        "x = (1e13 + 0.1) - 1e13; x == 0.1",
        "k = 7; (k/100 - 0.07) == 0",
        "max([k/7 for k in 1:10]) == 10/7",
        "min([k/7 - 1 for k in 1:10]) == -6/7",
        "[RpToTrans(Rotz(k/100), (k/1000, 0, 0)) for k in 1:3][2][1, 4] == 0.002",
    ];
    for line in lines {
        let mut s = Session::new(Settings::default());
        let (out, err, n) = s.run_to_strings("t", &format!("{line}\n"), Mode::Run, false);
        assert_eq!(n, 0, "{line}: {err}");
        assert_eq!(out.lines().last(), Some("true"), "{line}: {out}{err}");
    }
    let mut e = Session::new(Settings {
        exact: true,
        ..Settings::default()
    });
    let src = "[k/100 for k in 1:3]\n[k/3 for k in 1:3]\n0.1*3\n1/16\n0.0625*1\n(0:0.1:1)[4]\n(1e13 + 0.1) - 1e13\n";
    let (out, err, n) = e.run_to_strings("t", src, Mode::Run, false);
    assert_eq!(n, 0, "{err}");
    assert_eq!(
        out,
        "[1/100, 1/50, 3/100]  : list of 3 numbers\n[1/3, 2/3, 1]  : list of 3 numbers\n0.3\n1/16\n0.0625\n0.3\n0.1\n"
    );
}

/// A 3-vector written of fractions and numbers as typed (`(k/1000, 0, 0)`,
/// a position p of (3.62)) holds its entries' fractions at once, not a
/// recipe over copies of its entries: it compares exactly, prints its
/// fractions under `--exact`, and a transform made of it keeps its exact
/// entries, as when the recipe made them; with a symbol or a float entry
/// it is what it was.
#[test]
fn vectors_of_fractions_stay_exact_and_print_as_before() {
    let lines = [
        "k = 7; (k/1000, 0, 0) == (0.007, 0, 0)",
        "k = 7; (k/1000, 0, 0) == (7/1000, 0, 0)",
        "k = 7; ((k/1000, 0, 0) == (0.0070000000000000001, 0, 0)) == false",
        "k = 7; ((k/1000, 0, 0) == (7/1000, 0, 1e-30)) == false",
        "k = 7; (k/3, 1, 0.5) == (7/3, 1, 1/2)",
        "k = 7; (k/3, 1, 0.5)[1] * 3 == 7",
        "k = 7; (k/3, 0.1, 1e-13) == (7/3, 1/10, 1/10000000000000)",
        "k = 7; (-k/3, 0, 0) == -(k/3, 0, 0)",
        "k = 7; (k/1000, 0, 0) + (0.1, 0.2, 0) == (0.107, 0.2, 0)",
        "k = 7; norm((3/5 * k/7, 4/5, 0)) == 1",
        "k = 7; RpToTrans(Rotz(k/100), (k/1000, 0, 0))[1, 4] == k/1000",
        "k = 7; RpToTrans(Rotz(k/100), (k/1000, 0, 0)).p == (k/1000, 0, 0)",
        "k = 7; RpToTrans(Rotz(k/100), (k/1000, 0, 0)) == RpToTrans(Rotz(0.07), (0.007, 0, 0))",
        "k = 7; (RpToTrans(Rotz(k/100), (k/1000, 0, 0)) == RpToTrans(Rotz(0.07), (0.0070000000000000001, 0, 0))) == false",
        "[RpToTrans(Rotz(k/100), (k/1000, 0, 0)) for k in 1:3][2][1, 4] == 2/1000",
        "[(k/100, 1/3, 0) for k in 1:3][2] == (0.02, 1/3, 0)",
        "k = 7; (k/3, exp(0), 0) == (7/3, 1, 0)",
        "k = 7; ((k/3, 1, 0) == (7/3 + 1e-20, 1, 0)) == false",
    ];
    for line in lines {
        let mut s = Session::new(Settings::default());
        let (out, err, n) = s.run_to_strings("t", &format!("{line}\n"), Mode::Run, false);
        assert_eq!(n, 0, "{line}: {err}");
        assert_eq!(out.lines().last(), Some("true"), "{line}: {out}{err}");
    }
    let mut e = Session::new(Settings {
        exact: true,
        ..Settings::default()
    });
    let src = "k = 7\n(k/1000, 0, 0)\n(k/3, 0.1, 1e-13)\n[(k/100, 1/3, 0) for k in 1:3]\n\
               RpToTrans(Rotz(pi/6), (k/1000, 1/3, 0))\n(0.1, 0.2, 0) + (k/1000, 0, 0)\n\
               given a\n(k/1000, a, 0) + (a, 0, 1/3)\n";
    let (out, err, n) = e.run_to_strings("t", src, Mode::Run, false);
    assert_eq!(n, 0, "{err}");
    assert_eq!(
        out,
        "k = 7\n(7/1000, 0, 0)  : 3-vector\n(7/3, 0.1, 1e-13)  : 3-vector\n\
         [(1/100, 1/3, 0), (1/50, 1/3, 0), (3/100, 1/3, 0)]  : list of 3 3-vectors\n\
         [√3/2, -1/2, 0, 7/1000\n  1/2, √3/2, 0,    1/3\n    0,    0, 1,      0\n    0,    0, 0,      1]  : SE(3)\n\
         (0.107, 0.2, 0)  : 3-vector\n(7/1000 + a, a, 1/3)  : 3-vector\n"
    );
}

/// A list made of given names (or of tuples of them) has their kind, in
/// `run` as in `check`:
/// `[R_ab for k in 1:2]` was a list of "values" when running, so its item
/// took any operation (`Ad(xs[1])` printed `Ad(R_ab)`, an SE(3) times an
/// so(3) ran) where `check` and the numbers refuse. Bound later, the items
/// are the numbers.
#[test]
fn a_list_of_given_names_has_their_kind() {
    let setup = "given R_ab : SO3\ngiven T_bc : SE3\ngiven M : so3\nxs = [R_ab for k in 1:2]\n";
    for (x, want) in [
        (
            "Ad(xs[1])",
            "argument 1 of Adjoint must be an SE(3), not an SO(3)",
        ),
        (
            "[Ad(x) for x in xs]",
            "argument 1 of Adjoint must be an SE(3), not an SO(3)",
        ),
        (
            "[T_bc for k in 1:2][2] * M",
            "cannot multiply an SE(3) by an so(3)",
        ),
        // (a tuple of them: it was a "(value, value)")
        (
            "T_ac = [(T_bc, T_bc) for k in 1:2][1]",
            "T_ac names a transform, in SE(3) or SE(2), but the value is a (SE(3), SE(3))",
        ),
    ] {
        let src = format!("{setup}{x}\n");
        for mode in [Mode::Run, Mode::Check] {
            let e = first_error(&src, mode).unwrap_or_else(|| panic!("{x}: {mode:?} ran it"));
            assert!(e.contains(want), "{x} ({mode:?}): {e}");
        }
    }
    let src = format!("{setup}xs[2].T * xs[1]\nR_ab = Rotz(0.3)\nxs[2] == Rotz(0.3)\n");
    let mut s = Session::new(Settings::default());
    let (out, err, n) = s.run_to_strings("t.chs", &src, Mode::Run, false);
    assert_eq!(n, 0, "{err}");
    // (it printed `R_ab.T R_ab  : value {b}←{b}`)
    assert!(out.contains("\nI  : SO(3) {b}←{b}\n"), "{out}");
    assert_eq!(out.lines().last(), Some("true"), "{out}");
}

/// `check` knows a list's length where it is written with literals — a
/// range of whole literal bounds, a comprehension over such ranges or
/// literal vectors, a slice by literal positions — and refuses an index
/// outside it in the words `run` uses: `(0:4)[9]` and
/// `ys = [k^2 for k in 1:3]; ys[4]` passed `check` while `run` refused
/// them. An index inside, or a length bound later, still passes.
#[test]
fn check_knows_a_literal_lists_length() {
    for src in [
        "(0:4)[9]",
        "(0:4)[0]",
        "(5:-1:1)[6]",
        "(1:0)[1]",
        "ys = [k^2 for k in 1:3]\nys[4]",
        "ys = [j * k for k in 1:3, j in [1, 2]]\nys[7]",
        "zs = [[k, k] for k in 0:2:6]\nzs[5]",
        "(0:4)[2:9]",
        "(0:4)[end + 1]",
        "xs = (0:4)[2:end]\nxs[5]",
    ] {
        let src = format!("{src}\n");
        let run = first_error(&src, Mode::Run).unwrap_or_else(|| panic!("{src}: run ran it"));
        let check =
            first_error(&src, Mode::Check).unwrap_or_else(|| panic!("{src}: check passed it"));
        let message = |e: &str| e.lines().next().map(|l| l.to_string());
        assert_eq!(message(&check), message(&run), "{src}");
        assert!(run.contains("outside"), "{src}: {run}");
    }
    for src in [
        "(0:4)[5]",
        "ys = [j * k for k in 1:3, j in [1, 2]]\nys[6]",
        "xs = (0:4)[2:end]\nxs[4]",
        "given n\nxs = 1:n\nn = 2\nxs[2]",
    ] {
        let src = format!("{src}\n");
        for mode in [Mode::Run, Mode::Check] {
            assert_eq!(first_error(&src, mode), None, "{src} ({mode:?})");
        }
    }
}

/// A list of given names' symbols prints the kind of its items as a list
/// of their numbers does: `[R_ab for k in 1:2]` with `R_ab : SO3` printed
/// `list of 2 values {a}←{b}` (with `R_ab = Rotz(0.3)`: `list of 2 SO(3)
/// {a}←{b}`), and a list of tuples of them `list of 2 (value, value)s`.
#[test]
fn a_list_of_given_names_prints_their_kind() {
    for (src, want) in [
        (
            "given R_ab : SO3\n[R_ab for k in 1:2]\n",
            "[R_ab, R_ab]  : list of 2 SO(3) {a}←{b}",
        ),
        (
            "given R_ab : SO3\n[R_ab for k in 1:1]\n",
            "[R_ab]  : list of 1 SO(3) {a}←{b}",
        ),
        (
            "given T_bc : SE3\n[(T_bc, 1) for k in 1:2]\n",
            "[(T_bc, 1), (T_bc, 1)]  : list of 2 (SE(3), scalar)s",
        ),
        ("given a\n[a for k in 1:1]\n", "[a]  : list of 1 number"),
    ] {
        let mut s = Session::new(Settings::default());
        let (out, err, n) = s.run_to_strings("t.chs", src, Mode::Run, false);
        assert_eq!(n, 0, "{src}: {err}");
        assert_eq!(out.lines().last(), Some(want), "{src}: {out}");
    }
    // as with the numbers
    let mut s = Session::new(Settings::default());
    let src = "R_ab = Rotz(0.3);\n[R_ab for k in 1:2]\n";
    let (out, _, _) = s.run_to_strings("t.chs", src, Mode::Run, false);
    assert!(out.starts_with("list of 2 SO(3) {a}←{b}:"), "{out}");
}

/// A range waiting for numbers has no items to slice: `(1:n)[2:3]` with
/// `given n` printed `(1, n)` (the range's step and end, not its items:
/// with n = 4 they are 2 and 3), `(1:2:n)[end]` printed `n` (with n = 4
/// it is 3) and `(1:n)[2:9]` said 'index 4 is outside 1..3 (the
/// entries)'; each is refused as `(1:n)[2]` is. Bound first, the slice is
/// of the items.
#[test]
fn a_range_waiting_for_numbers_has_no_slices() {
    for x in ["(1:n)[2:3]", "(1:2:n)[end]", "(1:n)[2:9]", "(1:n)[2]"] {
        let src = format!("given n\n{x}\n");
        let e = first_error(&src, Mode::Run).unwrap_or_else(|| panic!("{x}: ran"));
        assert!(e.contains("has no items until n has a number"), "{x}: {e}");
    }
    let mut s = Session::new(Settings::default());
    let src = "given n\nxs = 1:2:n;\nn = 8;\nxs[2:3]\nxs[end]\n";
    let (out, err, n) = s.run_to_strings("t.chs", src, Mode::Run, false);
    assert_eq!(n, 0, "{err}");
    assert_eq!(
        out.lines().collect::<Vec<_>>(),
        ["[3, 5]  : list of 2 numbers", "7"],
        "{out}"
    );
}

/// `subs` of a list acts on each item, as of a tuple:
/// `subs([cos(k*a + b) for k in 1:3], a, 0.37)` was kept as a call
/// (`subs([cos(a + b), …], a, 0.37)`, never numbers, even once b had its
/// number; found by the differential sweep, session 32).
#[test]
fn subs_of_a_list_acts_on_each_item() {
    let run = |src: &str| {
        let mut s = Session::new(Settings::default());
        let (out, err, n) = s.run_to_strings("t", src, Mode::Run, false);
        assert_eq!(n, 0, "{src}\n{err}");
        out.lines().last().unwrap_or_default().to_string()
    };
    let later = run("given a, b\nX = subs([cos(k*a + b) for k in 1:3], a, 0.37)\nb = 1\nX");
    let first = run("a = 0.37\nb = 1\n[cos(k*a + b) for k in 1:3]");
    assert_eq!(later, first);
    assert_eq!(
        run("given a\nsubs([(2*a) * k for k in 1:3], a, 1)"),
        "[2, 4, 6]  : list of 3 numbers"
    );
}
