//! A name's kind holds when its numbers come (LANGUAGE.md §5, §7): a
//! rotation or transform name (`R_sb`, `T_ab`) requires the group at the
//! binding — its shape first, then its distance — and a name declared by
//! `given x : kind` holds that kind when numbers are bound to it later, as
//! if they had been typed first. Before, `given R : SO3; y = R R^T;
//! R = [1, 2, 3; 4, 5, 6; 7, 8, 9]; y` printed I, and `given x : scalar;
//! y = 2 x; x = (1, 2, 3); y` printed 2: values worked out from the
//! declaration, silently wrong of the numbers.
//!
//! The oracle is the same value typed first: binding numbers to a declared
//! name is refused exactly when the same numbers typed under a name that
//! says that kind are (`given R_ab : SO3; R_ab = M` against `R_ab = M`),
//! or when the shapes differ.

mod common;
use common::{error, printed, run};

/// The values tried, as typed, with their sides (0 for a scalar or a
/// vector): rotations, near ones, far ones, transforms, other shapes.
const VALUES: [(&str, usize); 15] = [
    ("Rotz(1)", 3),
    ("eye(3)", 3),
    ("[0, -1, 0; 1, 0, 0; 0, 0, 1]", 3),
    ("[1.0001, 0, 0; 0, 1, 0; 0, 0, 1]", 3),
    ("[1.005, 0, 0; 0, 1, 0; 0, 0, 1]", 3),
    ("[-1, 0, 0; 0, 1, 0; 0, 0, 1]", 3),
    ("[1, 2, 3; 4, 5, 6; 7, 8, 9]", 3),
    ("[1, 2; 3, 4]", 2),
    ("[1, 2, 3; 4, 5, 6]", 0),
    ("Trans((1, 2, 3))", 4),
    ("RpToTrans(Rotz(1), (1, 2, 3))", 4),
    (
        "[1, 0, 0, 0; 0, 1, 0, 0; 0, 0, 1, 0.001; 0, 0, 0, 1.0001]",
        4,
    ),
    ("[1, 0, 0, 0; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 2]", 4),
    ("(1, 2, 3)", 0),
    ("5", 0),
];

/// Whether `src` runs without an error, and the kind of its first error
/// (`type` of "<-e>:1:8: type error: …").
fn verdict(src: &str) -> (bool, String) {
    let (code, _, err) = run(&["-e", src]);
    assert!(code == 0 || code == 1, "{src}: exit {code}\n{err}");
    let first = err
        .lines()
        .find(|l| l.contains(" error: "))
        .unwrap_or_default()
        .split(" error: ")
        .next()
        .unwrap_or_default()
        .rsplit(' ')
        .next()
        .unwrap_or_default()
        .to_string();
    (code == 0, first)
}

#[test]
fn a_rotation_or_transform_name_requires_its_group() {
    for (src, says) in [
        (
            "T_ab = [1, 2; 3, 4]",
            "T_ab names a transform, in SE(3) or SE(2), but the value is a 2×2 matrix",
        ),
        (
            "R_ab = [1, 2, 3; 4, 5, 6]",
            "R_ab names a rotation, in SO(3) or SO(2), but the value is a 2×3 matrix",
        ),
        (
            "R_ab = Trans((1, 2, 3))",
            "R_ab names a rotation, in SO(3) or SO(2), but the value is an SE(3)",
        ),
        (
            "R_sb = (1, 2, 3)",
            "R_sb names a rotation, in SO(3) or SO(2), but the value is a 3-vector",
        ),
        (
            "given T_ab : SE3\nT_ab = 5",
            "T_ab names a transform, in SE(3) or SE(2), but the value is a scalar",
        ),
        (
            "R_ab = [1, 2, 3; 4, 5, 6; 7, 8, 9]",
            "R_ab names a rotation matrix, but its determinant is 0 (a rotation's is 1)",
        ),
    ] {
        let err = error(src);
        assert!(err.contains(says), "{src}\n{err}");
    }
    // (the help names the way out)
    let err = error("T_ab = [1, 2; 3, 4]");
    assert!(
        err.contains(
            "give a 2×2 matrix another name (M_ab), or bind a transform (RpToTrans(R, p))"
        ),
        "{err}"
    );
    // A rotation under a transform's name is a pure rotation, as before.
    assert!(printed("T_ab = Rotz(1)").contains(": SO(3) {a}←{b}"));
    assert!(printed("T_ab = eye(4)").contains(": SE(3) {a}←{b}"));
    // `check` refuses it too: the rule is the checker's, for symbols alike.
    let dir = std::env::temp_dir().join(format!("chasles-declared-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let file = dir.join("t.chs");
    std::fs::write(&file, "given M : SE3\nT_ab = M\nR_ab = M\n").expect("the script");
    let (code, out, _) = run(&["check", file.to_str().expect("a UTF-8 path")]);
    assert_eq!(code, 1, "{out}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_declared_kind_holds_when_numbers_come() {
    for (src, says) in [
        (
            "given R : SO3\ny = R*R.T\nR = [1, 2, 3; 4, 5, 6; 7, 8, 9]",
            "R was declared an SO(3), but its determinant is 0",
        ),
        (
            "given R : SO3\ny = det(R)\nR = [2, 0, 0; 0, 1, 0; 0, 0, 1]",
            "R was declared an SO(3), but the matrix is 3 from SO(3)",
        ),
        (
            "given x : scalar\ny = 2*x\nx = (1, 2, 3)",
            "x was declared a scalar (given x : scalar), but the value is a 3-vector",
        ),
        (
            "given θ : scalar\ny = Rotz(θ)\nθ = (1, 2)",
            "θ was declared a scalar (given θ : scalar), but the value is a 2-vector",
        ),
        (
            "given x : scalar\ny = x + 1\nx = Rotz(1)",
            "x was declared a scalar (given x : scalar), but the value is an SO(3)",
        ),
        (
            "given u : vec3\ny = 2 u\nu = 5",
            "u was declared a 3-vector (given u : vec3), but the value is a scalar",
        ),
        (
            "given u : vec3\nu = (1, 2, 3)\nu = 4",
            "u was declared a 3-vector (given u : vec3), but the value is a scalar",
        ),
    ] {
        let err = error(src);
        assert!(err.contains(says), "{src}\n{err}");
    }
    // Numbers of the declared kind are bound, and the values recomputed.
    let out = printed(
        "given R : SO3\ny = R*R.T\nR = Rotz(1)\ny\ngiven x : vec3\nz = 2 x\nx = (1, 2, 3)\nz",
    );
    assert!(out.contains("I  : SO(3)"), "{out}");
    assert!(out.contains("(2, 4, 6)"), "{out}");
    // A near rotation is projected with the warning, as under `R_sb`.
    let (out, err) = common::outputs("given R : SO3\nR = [1.0001, 0, 0; 0, 1, 0; 0, 0, 1]");
    assert!(
        err.contains("R was declared an SO(3), and the matrix is"),
        "{err}"
    );
    assert!(
        out.starts_with("R = [1, 0, 0\n") && out.contains(": SO(3)"),
        "{out}"
    );
    // so(2) and se(2) are declared as the others (the kinds chasles prints)
    let out = printed("given X : so2\nE = exp(X)\nX = [0, -1; 1, 0]\nE\ngiven Y : se2\nY");
    assert!(out.contains("0.8415,  0.5403]  : SO(2)"), "{out}");
    assert!(out.contains("Y  : se(2)"), "{out}");
    let err = error("given X : so2\nX = 5");
    assert!(
        err.contains("X was declared an so(2) (given X : so2), but the value is a scalar"),
        "{err}"
    );
    // Declared again, the name takes the new kind.
    assert!(printed("given x : vec3\ngiven x : scalar\nx = 4").contains("x = 4"));
}

/// The differential: numbers of the declared shape bound later to
/// `given R_ab : SO3` (`T_ab : SE3`) are refused exactly when the same
/// numbers typed first under the name are, with the same kind of error
/// (the group's distance); numbers of another shape are a type error. A
/// plain name declared so (`given R : SO3`) agrees with the group name.
#[test]
fn bound_later_is_refused_as_typed_first() {
    for (name, kind, side) in [("R_ab", "SO3", 3), ("T_ab", "SE3", 4)] {
        for (v, sides) in VALUES {
            let later = verdict(&format!("given {name} : {kind}\n{name} = {v}"));
            if sides == side {
                let first = verdict(&format!("{name} = {v}"));
                assert_eq!(first, later, "{name} = {v}, typed first and bound later");
                let plain = verdict(&format!("given M : {kind}\nM = {v}"));
                assert_eq!(first, plain, "{name} = {v} and given M : {kind}; M = {v}");
            } else {
                assert!(!later.0, "given {name} : {kind}; {name} = {v}: bound");
            }
        }
    }
}

/// An unknown type after `given` is named as written: `SE3(3)` was
/// reported as 'SE33' (the parentheses of `SE(3)` dropped from it).
#[test]
fn an_unknown_given_type_is_named_as_written() {
    for (src, says) in [
        ("given X : SE3(3)", "type error: unknown type 'SE3(3)'"),
        ("given X : SE(4)", "type error: unknown type 'SE(4)'"),
        ("given X : 4-vector", "type error: unknown type '4-vector'"),
    ] {
        let err = error(src);
        assert!(err.contains(says), "{src}\n{err}");
    }
}
