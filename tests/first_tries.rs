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
/// `[R, p; 1, 1]` is refused, as with numbers: only a lone 0 stretches to
/// the block that fits (LANGUAGE.md §3), so its rows are 4 and 2 wide.
#[test]
fn other_blocks_stay_matrices() {
    let j = json(
        "given R : SO3\ngiven p : vec3\ngiven W : so3\n[R, p; 0, 2]\n[W, p; 0, 1]\n[R, p; 1, 1]",
    );
    for line in &j[..2] {
        assert_eq!(line["kind"], "matrix", "{line:?}");
    }
    assert_eq!(j[2]["error"]["kind"], "type", "{:?}", j[2]);
    let message = j[2]["error"]["message"].as_str().unwrap_or("");
    assert!(message.contains("different widths: 4 and 2"), "{message}");
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

/// The error line of `chasles --json -e SRC` (the last line).
fn error(src: &str) -> serde_json::Value {
    json(src).pop().unwrap()["error"].clone()
}

/// Exercise 2.7: `solve(6 (1 − n) + n f == 6, f)` is 6, for n ≠ 0.
#[test]
fn solve_one_unknown_of_a_linear_equation() {
    let j = json(
        "given n, f, x, a : scalar\nsolve(6*(1 - n) + n*f == 6, f)\nsolve(2*x + 1, x)\n\
         solve(0.5*x == 3, x)\nsolve(x - a == 0, x)\ny = solve(3*x == 1, x); y * 3",
    );
    assert_eq!(j[0]["value"], 6, "{:?}", j[0]);
    assert_eq!(
        j[0]["warnings"][0]["message"],
        "for n ≠ 0: where n = 0 the equation does not fix f"
    );
    assert_eq!(j[1]["value"], -0.5);
    assert_eq!(j[2]["value"], 6);
    assert_eq!(j[3]["value"], "a");
    assert!(j[3].get("warnings").is_none(), "{:?}", j[3]);
    // the root is exact: 1/3 times 3 is 1
    assert_eq!(j[4]["value"], 1, "{:?}", j[4]);
}

/// A quadratic with exact numbers: its real roots in increasing order.
#[test]
fn solve_a_quadratic() {
    let j = json(
        "given x : scalar\nsolve(x^2 - 5*x + 6 == 0, x)\nsolve(x^2 == 2, x)\nsolve((x - 1)^2, x)\n\
         (p, q) = solve(x^2 == 2, x); (q^2 == 2, p == -sqrt(2))",
    );
    assert_eq!(j[0]["value"], serde_json::json!([2, 3]));
    let r = &j[1]["value"];
    assert!((r[0].as_f64().unwrap() + 2f64.sqrt()).abs() < 1e-15);
    assert!((r[1].as_f64().unwrap() - 2f64.sqrt()).abs() < 1e-15);
    assert_eq!(j[2]["value"], 1);
    assert_eq!(j[3]["value"], serde_json::json!([true, true]), "{:?}", j[3]);
}

/// Beyond reach, a refusal naming why (never a wrong root).
#[test]
fn solve_refuses_naming_why() {
    let cases = [
        ("solve(x^2 + 1 == 0, x)", "no real x solves it"),
        ("solve(x^3 == 1, x)", "degree 3"),
        ("solve(sin(x) == x, x)", "inside"),
        ("solve(a*x^2 == 1, x)", "symbolic or inexact coefficients"),
        ("solve(x == 1/x, x)", "in a denominator"),
        ("solve(exp(x) == 2, x)", "x is inside exp(…)"),
        ("solve(x == x, x)", "holds for every x"),
        ("solve(a == 1, x)", "x does not occur"),
        ("solve(x < 1, x)", "joined by =="),
        ("solve(x == 1, 3)", "`3` is not one"),
        ("solve((1, 2, 3) == x, x)", "scalar equations"),
    ];
    for (src, want) in cases {
        let e = error(&format!("given x, a : scalar\n{src}"));
        let msg = e["message"].as_str().unwrap_or_default();
        assert!(msg.contains(want), "{src}: {e:?}");
        assert!(e["help"].is_string(), "{src}: no help in {e:?}");
    }
}

/// First-try errors name the fix in their help (the trial's six kinds:
/// a name not declared, Python's boolean words, the member tried first).
#[test]
fn first_try_errors_name_the_fix() {
    let cases = [
        (
            "solve(6*(1 - n) + n*f == 6, f)",
            "give it a value first (f = ...) or declare it: given f : scalar",
        ),
        ("a = 1; a == 1 and a < 2", "chasles has no `and`"),
        ("a = 1; a == 1 or a < 2", "chasles has no `or`"),
        ("given R : SO3; R.inverse", "the inverse is inv(x)"),
        ("given R : SO3; R.inv", "the inverse is inv(x)"),
        (
            "p = (1, 2, 3); p.x",
            "an entry is v[1], v[2], v[3] (1-based)",
        ),
        ("M = eye(3); M.det", "det(x)"),
        ("given T_sb : SE3; T_sb.transpose", "the transpose is x.T"),
        ("given T : SE3; T * T_bc", "given T_bc : SE3"),
    ];
    for (src, want) in cases {
        let e = error(src);
        let help = e["help"].as_str().unwrap_or_default();
        assert!(help.contains(want), "{src}: {e:?}");
    }
}

/// `T^-1` of the transform block is its inverse in closed form too; a
/// block with another last row keeps its inverse as a call.
#[test]
fn the_power_minus_one_of_a_transform_block() {
    let j = json(
        "given R : SO3\ngiven p : vec3\nT = [R, p; 0, 1]\nT^-1\nT^-1 == inv(T)\n\
         M = [R, p; 0, 2]\nM^-1",
    );
    assert_eq!(j[1]["value"], "[R.T, (-R.T) p; 0, 1]");
    assert_eq!(j[2]["value"], true);
    assert_eq!(j[4]["value"], "inv([R, p; 0, 2])");
    assert_eq!(j[4]["kind"], "matrix");
}

/// `R R^T` of a given rotation prints `I` as `R inv(R)` does (Rᵀ = R⁻¹,
/// Prop. 3.3), where the transposed pair meets inside a product; a
/// transform's transpose is not its inverse, so `T T.T` stays.
#[test]
fn a_rotation_times_its_transpose_is_the_identity() {
    let j = json(
        "given R : SO3\ngiven R_ab : SO3\ngiven R_bc : SO3\ngiven T : SE3\nR R^T\nR.T R\n\
         R_ab R_bc R_bc^T R_ab^T\nR_ab R_bc R_bc.T\nT T.T",
    );
    assert_eq!(j[0]["value"], "I", "{:?}", j[0]);
    assert_eq!(j[1]["value"], "I", "{:?}", j[1]);
    assert_eq!(j[2]["value"], "I", "{:?}", j[2]);
    assert_eq!(j[2]["frames"], serde_json::json!(["a", "a"]), "{:?}", j[2]);
    assert_eq!(j[3]["value"], "R_ab", "{:?}", j[3]);
    assert_eq!(j[4]["value"], "T T.T", "{:?}", j[4]);
}

/// The book's `TransInv` of a block transform is its closed form (3.64), as
/// `inv` is: it printed the call `inv([R, p; 0, 1])`.
#[test]
fn trans_inv_of_a_block_is_the_books_inverse() {
    let j = json(
        "given R : SO3\ngiven p : vec3\nT = [R, p; 0, 1]\nTransInv(T)\nTransInv(T) == inv(T)\n\
         TransInv(T) T",
    );
    assert_eq!(j[1]["value"], "[R.T, (-R.T) p; 0, 1]", "{:?}", j[1]);
    assert_eq!(j[2]["value"], true, "{:?}", j[2]);
    assert_eq!(j[3]["value"], "I", "{:?}", j[3]);
}
