//! A stated assumption broken by numbers bound later (LANGUAGE.md §7: "when
//! numbers are bound that break it, the value that relied on it says so").
//! Two kinds of assumption: a symbolic axis taken as a unit vector
//! (Rodrigues' formula 3.51, `R = exp([u] θ)`), and a closed form that
//! holds on a branch (`log(Rotz(θ))` is [ẑ] θ for θ in (−π, π), §3.2.3.3).
//! Each value, read with numbers that break its assumption, is the value
//! the same statements give with the numbers typed first (the oracle),
//! and its JSON line carries a warning naming what broke; numbers that keep
//! the assumption give the same value and no such warning.

mod common;
use common::{error, json, numbers};

/// The numbers and warning messages of the last statement of `src`.
fn last(src: &str) -> (Vec<f64>, Vec<String>) {
    let lines = json(src);
    let v = lines.last().expect("a statement");
    let warnings = v["warnings"]
        .as_array()
        .map(|ws| {
            ws.iter()
                .map(|w| w["message"].as_str().unwrap_or_default().to_string())
                .collect()
        })
        .unwrap_or_default();
    (numbers(&v["value"]), warnings)
}

/// `a` and `b` agree entry by entry within 1e-13.
fn close(a: &[f64], b: &[f64], what: &str) {
    assert_eq!(a.len(), b.len(), "{what}: {a:?} vs {b:?}");
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= 1e-13, "{what}: {a:?} vs {b:?}");
    }
}

/// A rotation (and what was made from it) put in closed form with u taken
/// as a unit vector: u = (1, 1, 0) breaks it, and the value read is the
/// exponential of the numbers, a turn of ‖u‖θ, with a warning; a unit u
/// keeps it, silently.
#[test]
fn a_rotation_over_an_axis_taken_as_unit_says_so_when_numbers_break_it() {
    let setup = "given θ\ngiven u : vec3\nR = exp([u] θ)\nQ = R * R\nt = trace(R)";
    for (name, first) in [
        ("R", "exp([u] θ)"),
        ("Q", "exp([u] θ) * exp([u] θ)"),
        ("t", "trace(exp([u] θ))"),
    ] {
        for (u, unit) in [("(1, 1, 0)", false), ("(0.6, 0, 0.8)", true)] {
            let bound = format!("{setup}\nu = {u}\nθ = 1.1\n{name}");
            let (got, warnings) = last(&bound);
            let (want, _) = last(&format!("u = {u}\nθ = 1.1\n{first}"));
            close(&got, &want, &bound);
            let said = warnings.iter().any(|w| {
                w.starts_with(&format!(
                    "{name} was computed assuming u is a unit vector, ‖u‖ = 1; u = {u} breaks it"
                ))
            });
            assert_eq!(said, !unit, "{bound}: {warnings:?}");
        }
    }
    // the numbers: u = (1, 1, 0) turns by √2 θ about (1, 1, 0)/√2
    let (r, _) = last(&format!("{setup}\nu = (1, 1, 0)\nθ = 1.1\nR"));
    let c = (2f64.sqrt() * 1.1).cos();
    close(&[r[0], r[8]], &[0.5 + 0.5 * c, c], "R[1,1], R[3,3]");
}

/// Closed forms on a branch, read with numbers off it: the value is the
/// book's (principal) one for the numbers, as typed first, and the
/// warning names the number that left the branch; on the branch, the same
/// value and no warning.
#[test]
fn a_closed_form_read_off_its_branch_says_so() {
    let cases = [
        ("given θ", "log(Rotz(θ))", "θ"),
        ("given θ", "MatrixLog3(Rotx(θ))", "θ"),
        ("given θ", "quat(Roty(θ))", "θ"),
        ("given θ", "MatrixLog6(RpToTrans(Rotz(θ), (1, 2, 3)))", "θ"),
        ("given θ", "log(RpToTrans(Rotz(θ), (1, 2, 3)))", "θ"),
        ("given θ", "euler_zyx(Rotz(θ))", "θ"),
        ("given θ", "rpy(Rotx(θ))", "θ"),
        ("given θ", "euler_zxz(Rotz(θ) Rotx(0.5))", "θ"),
        ("given θ", "cayley(Roty(θ))", "θ"),
        ("given θ", "atan2(2 sin(θ), 2 cos(θ))", "θ"),
    ];
    for (given, call, sym) in cases {
        for (x, off) in [("4", true), ("-3.5", true), ("1", false), ("-2.5", false)] {
            let bound = format!("{given}\nL = {call}\n{sym} = {x}\nL");
            let (got, warnings) = last(&bound);
            let (want, _) = last(&format!("{sym} = {x}\n{call}"));
            close(&got, &want, &bound);
            let said = warnings.iter().any(|w| {
                w.contains("which the numbers bound since leave")
                    && w.contains(&format!("{sym} = {x} is outside [−π, π]"))
            });
            assert_eq!(said, off, "{bound}: {warnings:?}");
        }
    }
}

/// The mark a closed form carries for its branch changes no derivative:
/// the rate of log(Rotz(θ)) is ẑ on every branch (off it the log is
/// ẑ(θ − 2π), of the same derivative), and no `==` over it.
#[test]
fn the_branch_mark_leaves_derivatives_and_identities_as_they_were() {
    for x in ["1", "4", "-3.5"] {
        let src = format!("given θ\nD = diff(MatrixLog3(Rotz(θ)), θ)\nθ = {x}\nD");
        let (d, _) = last(&src);
        close(&d, &[0.0, 0.0, 1.0], &src);
    }
    let (b, _) = last("given θ\nlog(Rotz(θ)) == [(0, 0, 1)] θ");
    assert_eq!(b, [1.0], "log(Rotz(θ)) == [ẑ] θ on its branch");
    let (b, _) = last("given θ\nexp(log(Rotz(θ))) == Rotz(θ)");
    assert_eq!(b, [1.0], "exp(log(Rotz(θ))) == Rotz(θ)");
}

/// The derivative of a closed form the chain rule cannot trace back to its
/// call (the Euler angles of `rot_quat`, which has no rule) holds on the
/// branch only: on it, its value; off it, a refusal. It was the closed
/// form's derivative everywhere, silently: at u = −0.688, off the branch
/// sin 2u > 0, (0, 2, 0), though there the angle is −2u, of rate −2.
#[test]
fn a_closed_form_derivative_the_chain_rule_cannot_reach_is_refused_off_its_branch() {
    let made = "given u
d = diff(euler_zxz(rot_quat((cos(u), -sin(u), 0, 0))), u)
";
    let (d, _) = last(&format!(
        "{made}u = 0.688
d"
    ));
    close(&d, &[0.0, 2.0, 0.0], "on the branch");
    let (d, _) = last(&format!("{made}subs(d, u, 0.688)"));
    close(&d, &[0.0, 2.0, 0.0], "subs on the branch");
    for off in [
        "u = -0.688
d",
        "subs(d, u, -0.688)",
    ] {
        let e = error(&format!("{made}{off}"));
        assert!(
            e.contains("the derivative of the closed form holds on the branch only"),
            "{off}: {e}"
        );
    }
}
