//! Trial 18 (issue 35, a fresh student trial of chapter 3's symbolic
//! homework): each wrong answer or first-try failure it found, now right,
//! refused with the fix named, or an honest "cannot decide".

mod common;
use common::outputs;

/// The last line `src` prints.
fn last(src: &str) -> String {
    let (out, _) = outputs(src);
    out.lines().last().unwrap_or_default().trim().to_string()
}

/// Exercise 3.31's wrench through a transform at an exact half turn: the
/// adjoint of an exact transform is exact (Definition 3.6), so a symbolic
/// wrench carried by it prints no `1.2246e-16 fz` and `==` decides.
#[test]
fn the_adjoint_of_an_exact_transform_carries_no_rounding_into_symbols() {
    let pre = "given fz\nF_e = (0, 0, 0, 0, 0, fz)\nT_ge = [Rotx(pi), (0, 0, 1); 0, 1]\n";
    assert_eq!(
        last(&format!("{pre}F_g = Ad(inv(T_ge)).T F_e")),
        "F_g = (0, 0, 0, 0, 0, -fz)  : wrench {g}"
    );
    assert_eq!(
        last("given fz\nAd([Rotx(pi), (0, 0, 1); 0, 1]).T (0, 0, 0, 0, 0, fz)"),
        "(0, 0, 0, 0, 0, -fz)  : wrench"
    );
    assert_eq!(
        last(&format!("{pre}Ad(inv(T_ge)).T F_e == (0, 0, 0, 0, 0, -fz)")),
        "true"
    );
    assert_eq!(
        last(&format!("{pre}Ad(inv(T_ge)).T F_e == (0, 0, 0, 0, 0, fz)")),
        "false"
    );
    // a transform at an angle with no exact form stays a float, and then
    // its rounding never decides `==`
    let (out, err) = outputs(
        "given fz\nF = (0, 0, 0, 0, 0, fz)\nT = [Rotx(1), (0, 0, 1); 0, 1]\nAd(T).T F == Ad(T).T F",
    );
    assert_eq!(out.lines().last(), Some("true"), "{out}{err}");
}
