//! A student's first tries at chapter 3 (issue 35, "First tries"): the
//! book's transform written as a block over symbols (3.62), `solve` of
//! one unknown (Exercise 2.7), and first-try errors that name the fix.

mod common;
use common::{json_lines, run};

/// The `--json` lines of `chasles --json -e SRC`.
fn json(src: &str) -> Vec<serde_json::Value> {
    json_lines(&run(&["--json", "-e", src]).1)
}

/// `[R, p; 0, 1]` over a given rotation and vector is in SE(3) (3.62), and
/// its inverse is the book's (3.64).
#[test]
fn a_symbolic_block_transform_is_in_se3() {
    let j = json(
        "given R : SO3\ngiven p : vec3\nT = [R, p; 0, 1]\ninv(T) == [R^T, -R^T p; 0, 1]\n\
         inv(T) == [R, p; 0, 1]\nT.R\nT.p\nAd(T)\nlog(T)\nU = [R, p; 0, 0, 0, 1]\ninv(U)",
    );
    assert_eq!(j[0]["kind"], "SE3", "{:?}", j[0]);
    assert_eq!(j[1]["value"], true, "{:?}", j[1]);
    // not the same as T itself: undecided without numbers, never true
    assert_ne!(j[2]["value"], true, "{:?}", j[2]);
    assert_eq!(j[3]["kind"], "SO3");
    assert_eq!(j[4]["kind"], "vector");
    assert_eq!(j[5]["kind"], "adjoint");
    assert_eq!(j[6]["kind"], "se3");
    assert_eq!(j[7]["kind"], "SE3");
    assert_eq!(j[8]["value"], "[R.T, (-R.T) p; 0, 0, 0, 1]", "{:?}", j[8]);
}

/// A block that is not the book's transform keeps its matrix kind: a
/// last row other than `0, 1`, or a top-left block that is not a rotation.
#[test]
fn other_blocks_stay_matrices() {
    let j = json(
        "given R : SO3\ngiven p : vec3\ngiven W : so3\n[R, p; 0, 2]\n[W, p; 0, 1]\n[R, p; 1, 1]",
    );
    for line in &j {
        assert_eq!(line["kind"], "matrix", "{line:?}");
    }
}

/// With numbers bound later, the block and its inverse are the values
/// typed first (LANGUAGE.md §7): the lone 0 is the zero row.
#[test]
fn numbers_bound_later_agree_with_typed_first() {
    let later = json(
        "given R : SO3\ngiven p : vec3\nT = [R, p; 0, 1]\nV = inv(T)\n\
         R = Rotz(0.3)\np = (1, 2, 3)\nT\nV\nAd(T)",
    );
    let first = json("R = Rotz(0.3)\np = (1, 2, 3)\nT = [R, p; 0, 1]\ninv(T)\nAd(T)");
    assert_eq!(later[4]["type"], "SE3", "{:?}", later[4]);
    assert_eq!(later[4]["value"], first[2]["value"]);
    assert_eq!(later[5]["type"], "SE3", "{:?}", later[5]);
    let (a, b) = (&later[5]["value"], &first[3]["value"]);
    for i in 0..4 {
        for k in 0..4 {
            let (x, y) = (a[i][k].as_f64().unwrap(), b[i][k].as_f64().unwrap());
            assert!((x - y).abs() < 1e-14, "{i},{k}: {x} vs {y}");
        }
    }
    // p_new = -Rᵀ p: the last column of inv(Rotz(0.3), (1, 2, 3))
    let c = 0.3f64.cos();
    let s = 0.3f64.sin();
    assert!((a[0][3].as_f64().unwrap() - (-(c * 1.0 + s * 2.0))).abs() < 1e-14);
    assert!((a[2][3].as_f64().unwrap() + 3.0).abs() < 1e-14);
    assert_eq!(later[6]["type"], first[4]["type"]);
}

/// `[Rotz(t), (1, 2, 3); 0, 1]`: a symbolic rotation and numbers (the
/// trial's "rows of the bracket have different widths: 4 and 2"): the
/// lone 0 is the zero row, the block is in SE(3), and its inverse is
/// the book's (3.64), the value typed first once t = 0.3.
#[test]
fn a_symbolic_rotation_in_a_block() {
    let j = json(
        "given t\nU = [Rotz(t), (1, 2, 3); 0, 1]\ninv(U)\ninv(U) * U\nt = 0.3\ninv(U)\n\
         inv([Rotz(0.3), (1, 2, 3); 0, 1])",
    );
    assert_eq!(j[0]["kind"], "SE3", "{:?}", j[0]);
    assert_eq!(
        j[1]["value"],
        "[cos(t), sin(t), 0, -cos(t) - 2 sin(t); -sin(t), cos(t), 0, -2 cos(t) + sin(t); \
         0, 0, 1, -3; 0, 0, 0, 1]"
    );
    assert_eq!(
        j[2]["value"],
        serde_json::json!([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    );
    assert_eq!(j[4]["type"], "SE3");
    assert_eq!(j[4]["value"], j[5]["value"]);
}
