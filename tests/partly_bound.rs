//! Numbers bound while other symbols stay free (LANGUAGE.md §7): the value
//! is what the same statements give with those numbers typed first — a
//! formula in the free symbols, or the same refusal. A division by zero
//! or a call outside its domain is refused, never a term silently dropped
//! (`a/b + c` at b = 0 printed `c`), a NaN coefficient printed (`NaNe0 a`)
//! or a float zero's sign taken for an angle (`atan2(b, b)` at b = 0
//! printed −π).

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};

/// What `src` prints and its errors, running on after an error.
fn run(src: &str) -> (String, String) {
    let mut s = Session::new(Settings::default());
    let (out, err, _) = s.run_to_strings("t.chs", src, Mode::Run, true);
    (out, err)
}

/// The last line `src` prints, which must run with no error.
fn last(src: &str) -> String {
    let (out, err) = run(src);
    assert!(err.is_empty(), "{src}\n{err}");
    out.lines().last().unwrap_or_default().to_string()
}

/// `value` over `given a, b, c` with b bound after it is made is refused
/// with `why`, as `value` with b typed first is.
fn refused_both_ways(value: &str, b: &str, why: &str) {
    let later = format!("given a, b, c : scalar\ny = {value}\nb = {b}\ny");
    let (out, err) = run(&later);
    assert!(
        err.contains("domain error") && err.contains(why),
        "bound later, not refused ({why}):\n{later}\n{out}\n{err}"
    );
    assert!(!out.contains("NaN"), "{later}\n{out}");
    let first = format!("given a, c : scalar\nb = {b}\n{value}");
    let (out, err) = run(&first);
    assert!(
        err.contains("domain error") && err.contains(why),
        "typed first, not refused ({why}):\n{first}\n{out}\n{err}"
    );
}

#[test]
fn a_division_by_a_number_zero_is_refused_while_other_symbols_are_free() {
    refused_both_ways("a/b + c", "0", "division by zero");
    refused_both_ways("sin(a)/b", "0", "division by zero");
    refused_both_ways("a/(a*b)", "0", "division by zero");
    refused_both_ways("a/(b - 1)", "1", "division by zero");
    refused_both_ways("a/(b*b - 1)", "-1", "division by zero");
    refused_both_ways("a/sqrt(b)", "0", "division by zero");
    refused_both_ways("(b^2 - b)/b*a", "0", "division by zero");
}

#[test]
fn a_call_outside_its_domain_is_refused_while_other_symbols_are_free() {
    refused_both_ways("a*tan(b)", "pi/2", "the tangent is infinite");
    refused_both_ways("a*cot(b)", "0", "the cotangent is infinite");
    refused_both_ways("a*sqrt(b - 1)", "0", "sqrt(-1)");
    refused_both_ways("a + asin(b + 1)", "1", "asin(2)");
}

#[test]
fn atan2_of_zeros_bound_later_is_zero_as_typed_first() {
    let later = last("given a, b : scalar\ny = a + atan2(b, b)\nb = 0\ny");
    let first = last("given a : scalar\nb = 0\na + atan2(b, b)");
    assert_eq!(first, "a");
    assert_eq!(later, "a");
}

#[test]
fn subs_of_a_number_that_divides_by_zero_is_refused() {
    for x in ["a/b", "sin(a)/b", "a/(a*b)", "1/b + a"] {
        let src = format!("given a, b : scalar\nsubs({x}, b, 0)");
        let (out, err) = run(&src);
        assert!(
            err.contains("division by zero"),
            "not refused:\n{src}\n{out}\n{err}"
        );
    }
    let src = "given a, b : scalar\nsubs(a/(b - 1), b, 1)";
    let (out, err) = run(src);
    assert!(err.contains("division by zero"), "{src}\n{out}\n{err}");
    // a substitution that leaves a value keeps it
    assert_eq!(last("given a, b : scalar\nsubs(a/b, b, 2)"), "(1/2) a");
}

/// inf and NaN have no exact form: arithmetic of them with symbols is
/// refused (`a*inf` printed 0, `b*inf + a` printed a, `a + 0*inf`
/// `NaNe0 + a`), and an inf kept in a vector prints as a number.
#[test]
fn inf_with_symbols_is_refused_not_dropped() {
    for x in ["a*inf", "inf*a", "b*inf + a", "a + 0*inf", "a + inf"] {
        let src = format!("given a, b : scalar\n{x}");
        let (out, err) = run(&src);
        assert!(
            err.contains("inf or NaN with symbols has no closed form"),
            "not refused:\n{src}\n{out}\n{err}"
        );
    }
    assert_eq!(
        last("given a : scalar\n(a, inf, 0)"),
        "(a, inf, 0)  : 3-vector"
    );
    let (out, _) = run("a = 1\na*inf");
    assert_eq!(out.lines().last(), Some("inf"));
}

/// Symbols that cancel leave numbers, and a call of them outside its
/// domain is refused as typed first: `csc(a - a)` printed `csc(0)`,
/// `sqrt(a - a - 1)` `sqrt(-1)`, `log(a - a)` `log(0)`, `(a - a - 1)^(1/2)`
/// `(-1)^0.5`.
#[test]
fn a_call_of_symbols_that_cancelled_is_refused_outside_its_domain() {
    for (x, why) in [
        ("csc(a - a)", "cosecant is infinite"),
        ("cot(a*0)", "cotangent is infinite"),
        ("tan(a - a + pi/2)", "tangent is infinite"),
        ("sqrt(a - a - 1)", "sqrt(-1)"),
        ("asin(a - a + 2)", "asin(2)"),
        ("log(a - a)", "log of 0"),
        ("(a - a - 1)^(1/2)", "not a real number"),
        ("Rot((a - a, 0, 0), 1)", "zero vector"),
    ] {
        let src = format!("given a : scalar\n{x}");
        let (out, err) = run(&src);
        assert!(
            err.contains("domain error") && err.contains(why),
            "not refused ({why}):\n{src}\n{out}\n{err}"
        );
    }
    assert_eq!(last("given a : scalar\natan2(a - a, a - a)"), "0");
}

/// A comparison over symbols is decided again when some of them get
/// numbers, as typed first: `a*b == 0` is false over free a and b (no
/// identity) but `a*0 == 0` is true, and stayed false at b = 0.
#[test]
fn a_comparison_is_decided_again_with_some_numbers_bound() {
    let script = |x: &str, b: &str| format!("given a, b, c : scalar\ny = ({x})\nb = {b}\ny");
    let first = |x: &str, b: &str| format!("given a, c : scalar\nb = {b}\n{x}");
    for (x, b, want) in [
        ("a*b == 0", "0", "true"),
        ("a*b == a", "1", "true"),
        ("a*b == a", "0", "false"),
        ("sin(a)*b ≈ 0", "0", "true"),
        ("Rotz(a)*Rotz(b) == Rotz(a)", "0", "true"),
        ("Rotz(a)*Rotz(b) == Rotz(c)", "1", "false"),
    ] {
        assert_eq!(last(&first(x, b)), want, "typed first: {x} at b = {b}");
        assert_eq!(last(&script(x, b)), want, "bound later: {x} at b = {b}");
    }
    // a side with no value is refused, as typed first
    let (out, err) = run(&script("a/b == c", "0"));
    assert!(err.contains("division by zero"), "{out}\n{err}");
}

/// A tree over given names divided by a component that becomes 0 is
/// refused, as typed first: `a/u[1]` at u = (0, 0, 1) printed `a/0`.
#[test]
fn a_division_by_a_component_bound_to_zero_is_refused() {
    let src = "given u : vec3\ngiven a : scalar\ny = a/u[1]\nu = (0, 0, 1)\ny";
    let (out, err) = run(src);
    assert!(err.contains("division by zero"), "{out}\n{err}");
    assert!(!out.contains("a/0"), "{out}");
    let src = "given u : vec3\ngiven a : scalar\ny = a/u[3]\nu = (0, 0, 2)\ny";
    assert_eq!(last(src), "a/2");
}

/// A divisor that is 0 only once the numbers are in, over symbols still
/// free (`a b` at b = 0): its canonical form had cancelled the quotient
/// (`(a b)/(a b) + c` is `1 + c`), so only the operations made again with
/// the numbers see the division by zero typed first gives; a divisor the
/// numbers leave nonzero (`a + b` at b = 0 is a) is divided by as before.
#[test]
fn a_cancelled_divisor_that_the_numbers_make_zero_is_refused() {
    refused_both_ways("(a*b)/(a*b) + c", "0", "division by zero");
    refused_both_ways("(a*b - b)/(a*b - b) + c", "0", "division by zero");
    refused_both_ways("(sin(b)*a)/(sin(b)*a) + c", "0", "division by zero");
    assert_eq!(
        last("given a, b, c : scalar\ny = (a*b)/(a*b) + c\nb = 2\ny"),
        "1 + c"
    );
    assert_eq!(
        last("given a, b, c : scalar\ny = (a + b)/(a + b) + c\nb = 0\ny"),
        "1 + c"
    );
    assert_eq!(
        last("given a, b, c : scalar\ny = (1 + b)/(a + b) + c\nb = 0\ny"),
        "1/a + c"
    );
}

/// A divisor made in many steps is made again whole: `x = x + b a` 3,000
/// times, then `(a b)/(x − a) + c` at b = 0 divides by 3,000 b a = 0, as
/// typed first (a limit of 64 steps printed `1/3000 + c`). With b = 1 the
/// same read is a value.
#[test]
fn a_divisor_made_in_thousands_of_steps_is_made_again_whole() {
    let chain = |b: &str| {
        let mut src = String::from("given a, b, c : scalar\nx = a;\n");
        src.push_str(&"x = x + b*a;\n".repeat(3000));
        src.push_str(&format!("y = (a*b)/(x - a) + c;\nb = {b};\ny\n"));
        src
    };
    let (out, err) = run(&chain("0"));
    assert!(
        err.contains("domain error") && err.contains("division by zero"),
        "{out}\n{err}"
    );
    assert_eq!(last(&chain("1")), "1/3000 + c");
}

/// `subs` of a call kept over a given symbol, with the other numbers typed
/// first, is the call at the number put in: `b = 0.2; subs(MatrixExp3((c,
/// b, 2)), c, 0.5)` printed `subs(MatrixExp3((c, 0.2, 2)), c, 0.5)` (the
/// same with b given and bound after is the rotation). Found by the
/// differential sweep, session 32.
#[test]
fn subs_of_a_kept_call_with_a_number_is_the_call_at_that_number() {
    let cases = [
        (
            "subs(MatrixExp3((c, b, 2)), c, 0.5)",
            "MatrixExp3((0.5, 0.2, 2))",
        ),
        ("subs(Rot((c, 1, 2), c), c, 0)", "Rot((0, 1, 2), 0)"),
        (
            "subs(trace(Ad(exp(VecTose3((-1, 2, c, b, 0.25, 1))))), c, -1)",
            "trace(Ad(exp(VecTose3((-1, 2, -1, b, 0.25, 1)))))",
        ),
    ];
    for (x, typed) in cases {
        let got = last(&format!("given c\nb = 0.2\n{x}"));
        assert!(!got.contains("subs") && !got.contains('c'), "{x}: {got}");
        let (now, first) = (
            run(&format!("given c\nb = 0.2\n{x}")).0,
            run(&format!("b = 0.2\n{typed}")).0,
        );
        assert_eq!(
            now.lines().skip(1).collect::<Vec<_>>(),
            first.lines().skip(1).collect::<Vec<_>>(),
            "{x}"
        );
    }
}

/// `subs` of a closed form at a number off its branch, while another
/// symbol is free, is not the closed form there: `given a, c;
/// subs(MatrixLog6(RpToTrans(Rotz(c), (a, 1, 2))), c, 0)` printed (0, 0, 0,
/// 0, 0, 2) (its form for 1 − cos c > 0 at c = 0; the log of the pure
/// translation is (0, 0, 0, a, 1, 2)); at c = 2π it said "division by
/// zero". Both now say they cannot decide; with a typed first, or on the
/// branch (c = 0.5, and c = π, one of the book's two logs), a value.
/// Found by the differential sweep, session 32.
#[test]
fn subs_off_a_closed_forms_branch_with_symbols_free_cannot_decide() {
    let log6 = "MatrixLog6(RpToTrans(Rotz(c), (a, 1, 2)))";
    // (the branch's note goes with the errors)
    let last = |src: &str| run(src).0.lines().last().unwrap_or_default().to_string();
    for c in ["0", "2*pi"] {
        let (out, err) = run(&format!("given a, c\nsubs({log6}, c, {c})"));
        assert!(
            err.contains("cannot decide") && err.contains("branch") && !out.contains('('),
            "c = {c}: {out}\n{err}"
        );
    }
    assert_eq!(
        last(&format!("given c\na = 0.5\nsubs({log6}, c, 0)")),
        "(0, 0, 0, 0.5, 1, 2)  : 6-vector"
    );
    let both = |c: &str| {
        (
            last(&format!("given a, c\nX = subs({log6}, c, {c})\na = 0.5\nX")),
            last(&format!("given c\na = 0.5\nsubs({log6}, c, {c})")),
        )
    };
    for c in ["0.5", "pi"] {
        let (later, first) = both(c);
        assert_eq!(later, first, "c = {c}");
    }
}

/// The same closed form read with c bound and a free: `c = 0` then `X`
/// printed (0, 0, 0, 0, 0, 2); now it cannot decide until a has its number,
/// and then it is the log of the pure translation, as typed first.
#[test]
fn a_closed_form_read_off_its_branch_with_symbols_free_cannot_decide() {
    let src = "given a, c\nX = MatrixLog6(RpToTrans(Rotz(c), (a, 1, 2)))\nc = 0\nX";
    let (out, err) = run(src);
    assert!(
        err.contains("cannot decide") && err.contains("branch"),
        "{out}\n{err}"
    );
    let later = run(&format!("{src}\na = 0.5\nX")).0;
    assert_eq!(
        later.lines().last(),
        Some("(0, 0, 0, 0.5, 1, 2)  : 6-vector"),
        "{later}"
    );
    // on the branch, the form with a free, as before
    let on = run("given a, c\nX = MatrixLog6(RpToTrans(Rotz(c), (a, 1, 2)))\nc = 0.5\nX").0;
    assert!(on.lines().last().is_some_and(|l| l.contains('a')), "{on}");
}

/// A closed form singular at the numbers bound, where the expression as
/// typed is defined: the value is the expression made again with the
/// numbers, as typed first. `exp([S] a)^-1` with S = (a, 2a, a, a b, a, 2)
/// (a non-unit axis, θ' = √6 a²) has terms in 1/a; at a = 0, b free, it
/// said "division by zero", and typed first it is the identity. A
/// quotient the numbers make a division by zero is still refused.
#[test]
fn a_closed_form_singular_where_the_expression_is_defined_is_made_again() {
    let both = |value: &str, bound: &str| {
        let later = format!("given a, b : scalar\ny = {value}\n{bound}\ny");
        let first = format!("given a, b : scalar\n{bound}\n{value}");
        (last(&later), last(&first))
    };
    for (value, bound, want) in [
        ("exp([(a, 2a, a, a*b, a, 2)] a)^-1", "a = 0", None),
        ("inv(exp([(a, 2a, a, a*b, a, 2)] a))", "a = 0", None),
        ("exp([(a, 2a, 2a, b, 0, 0)] 1)", "a = 0", None),
        ("exp([(a, 2a, 2a, 1, 0, 0)] b)^-1", "a = 0", None),
        (
            "MatrixExp6(VecTose3((a, 2a, 2a, 1, 0, 0)*b))",
            "a = 0",
            None,
        ),
        ("exp([(a, 2a, 2a)] b)^-1 * Rotz(a)", "a = 0", None),
        ("Rot((1, a, a), b)^-1", "a = 0", None),
        ("(a^2 - b^2)/(a - b)", "a = 0", Some("b")),
    ] {
        let (later, first) = both(value, bound);
        assert_eq!(later, first, "{value} at {bound}");
        if let Some(want) = want {
            assert_eq!(later, want, "{value} at {bound}");
        }
    }
    let (later, first) = both("exp([(a, 2a, a, a*b, a, 2)] a)^-1", "a = 0");
    assert!(later.ends_with(": SE(3)") && first == later, "{later}");
    refused_both_ways("(a^2 - a*b)/b", "0", "division by zero");
    // `subs` of the number with b free, as typed first
    for value in [
        "exp([(a, 2a, a, a*b, a, 2)] a)^-1",
        "exp([(a, 2a, 2a, b, 0, 0)] 1)",
    ] {
        let (_, first) = both(value, "a = 0");
        assert_eq!(
            last(&format!("given a, b : scalar\nsubs({value}, a, 0)")),
            first,
            "subs({value}, a, 0)"
        );
    }
}

/// A product whose sizes the checker could not know (`eye(k) T_ab` over a
/// given k) is refused as typed first once the numbers make it one the
/// product's rule refuses: at k = 3 it printed a 3×3 times T_ab, labelled
/// an "n×4 matrix"; at k = 4 it is a value, as typed first.
#[test]
fn a_product_the_numbers_make_undefined_is_refused_as_typed_first() {
    for (x, why) in [
        ("eye(k) * T_ab", "cannot multiply an SO(3) by an SE(3)"),
        ("T_ab * eye(k)", "cannot multiply an SE(3) by an SO(3)"),
        ("T_ab * zeros(k, 2)", "cannot multiply"),
    ] {
        let later = format!("given k\ngiven T_ab : SE3\ny = {x}\nk = 3\ny");
        let (out, err) = run(&later);
        assert!(
            err.contains("domain error") && err.contains(why),
            "{later}\n{out}\n{err}"
        );
        let first = format!("given T_ab : SE3\nk = 3\n{x}");
        let (out, err) = run(&first);
        assert!(err.contains(why), "{first}\n{out}\n{err}");
    }
    let (_, err) = run("given k\ngiven T_ab : SE3\ny = eye(k) * T_ab\nk = 4\ny");
    assert!(err.is_empty(), "{err}");
}
