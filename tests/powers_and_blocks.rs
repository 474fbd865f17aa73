//! Two symbolic gaps of issue 35. A power of an exponential held in a
//! name is the closed form of the multiple, (e^X)ⁿ = e^{nX} (3.51, 3.88),
//! as `exp(X)^n` written out is; and `==` of the book's transforms
//! `[R, p; 0, 1]` (3.62) decides the group's identities by the algebra of
//! their blocks: (T U)⁻¹ = U⁻¹ T⁻¹ (3.63, 3.64), Ad_{TU} = Ad_T Ad_U
//! (Definition 3.20), and never a perturbed one.

mod common;
use common::{json_lines, run};

/// The `--json` lines of `chasles --json -e SRC`.
fn json(src: &str) -> Vec<serde_json::Value> {
    json_lines(&run(&["--json", "-e", src]).1)
}

/// The numbers of a JSON matrix value.
fn numbers(v: &serde_json::Value) -> Vec<f64> {
    v.as_array()
        .expect("a matrix")
        .iter()
        .flat_map(|r| r.as_array().expect("a row").iter())
        .map(|x| x.as_f64().expect("a number"))
        .collect()
}

/// `E = exp(X); E^50` prints the closed form of `exp(50 X)` (Rodrigues at
/// the angle 50√14 x), not the 50th powers of its entries, and is equal
/// to it; `E^-1` is exp(−X).
#[test]
fn a_power_of_an_exponential_in_a_name_is_the_exponential_of_the_multiple() {
    let j = json(
        "given x\nX = [(1,2,3)] x\nE = exp(X)\nE^50\nexp(50 X)\nexp(X)^50\nE^50 == exp(50 X)\n\
         E^-1\nexp(-X)\nE^-1 == exp(-X)\nE^0",
    );
    let fifty = j[2]["value"].as_str().expect("a formula");
    assert_eq!(j[2]["value"], j[3]["value"], "{:?}", j[2]);
    assert_eq!(j[2]["value"], j[4]["value"]);
    assert!(fifty.contains("cos(50√14 x)"), "{fifty}");
    assert!(!fifty.contains('^'), "no powers of entries: {fifty}");
    assert_eq!(j[2]["kind"], "SO3");
    assert_eq!(j[5]["value"], true, "{:?}", j[5]);
    assert_eq!(j[6]["value"], j[7]["value"], "{:?}", j[6]);
    assert_eq!(j[8]["value"], true, "{:?}", j[8]);
    assert_eq!(
        j[9]["value"],
        serde_json::json!([[1, 0, 0], [0, 1, 0], [0, 0, 1]])
    );
}

/// The same through a copy, after the name of the exponent is bound to
/// something else (the value keeps what it was made of, never a name),
/// for the general 2×2 of Exercise 3.33 and a screw's exponential (3.88).
#[test]
fn the_power_follows_the_value_not_the_names() {
    let j = json(
        "given x\nX = [(1,2,3)] x\nE = exp(X)\nY = X\nX = [(0,0,1)] x\nH = E\nH^3\nexp(3 Y)\n\
         H^3 == exp(3 X)\n\
         given t\nA = [0, 1; -2, -3]\nF = exp(A t)\nF^3\nexp(3 A t)\n\
         S = (0, 0, 1, 0, 2, 0)\nG = exp([S] t)\nG^4\nexp(4 [S] t)\nG^-2 == exp(-2 [S] t)",
    );
    assert_eq!(j[5]["value"], j[6]["value"], "{:?}", j[5]);
    assert!(j[5]["value"].as_str().unwrap().contains("cos(3√14 x)"));
    // (X is now another matrix: the power is not exp(3 X))
    assert_ne!(j[7]["value"], true, "{:?}", j[7]);
    assert_eq!(j[10]["value"], j[11]["value"], "{:?}", j[10]);
    assert!(j[10]["value"].as_str().unwrap().contains("exp(-6 t)"));
    assert_eq!(j[14]["value"], j[15]["value"], "{:?}", j[14]);
    assert!(j[14]["value"].as_str().unwrap().contains("sin(4 t)"));
    assert_eq!(j[16]["value"], true, "{:?}", j[16]);
}

/// With numbers bound later the power is the value typed first: the
/// numbers of `exp(X)^50` at x = 0.3, and of the 50th power of the
/// numeric rotation.
#[test]
fn the_power_with_numbers_bound_later_is_the_power_typed_first() {
    let later = json("given x\nX = [(1,2,3)] x\nE = exp(X)\nP = E^50\nx = 0.3\nP");
    let first = json("x = 0.3\nX = [(1,2,3)] x\nE = exp(X)\nE^50");
    let (a, b) = (numbers(&later[4]["value"]), numbers(&first[3]["value"]));
    assert_eq!(a.len(), 9);
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y).abs() < 1e-9, "{a:?} against {b:?}");
    }
}

/// `(T U)⁻¹ = U⁻¹ T⁻¹` for the book's transforms over given rotations and
/// vectors (3.63, 3.64), `Ad_{TU} = Ad_T Ad_U`; the perturbed forms are
/// never `true`.
#[test]
fn the_inverse_and_adjoint_of_a_product_of_blocks_are_decided() {
    let j = json(
        "given R1, R2 : SO3\ngiven p1, p2 : vec3\nT = [R1, p1; 0, 1]\nU = [R2, p2; 0, 1]\n\
         inv(T U) == inv(U) inv(T)\nAd(T U) == Ad(T) Ad(U)\n(T U)^-1 == U^-1 T^-1\n\
         inv(T U T) == inv(T) inv(U) inv(T)",
    );
    assert_eq!(j[2]["value"], true, "{:?}", j[2]);
    assert_eq!(j[3]["value"], true, "{:?}", j[3]);
    assert_eq!(j[4]["value"], true, "{:?}", j[4]);
    assert_eq!(j[5]["value"], true, "{:?}", j[5]);
}

/// The perturbed identities are not `true` (undecided without numbers,
/// or false): the order of an inverse, of an adjoint, a sign, a rotation
/// that is not one.
#[test]
fn perturbed_block_identities_are_never_true() {
    for wrong in [
        "inv(T U) == inv(T) inv(U)",
        "Ad(T U) == Ad(U) Ad(T)",
        "inv(T U) == inv(U) T",
        "T U == U T",
        "inv(T U) == [R2^T R1^T, R2^T R1^T p1 - R2^T p2; 0, 1]",
        "inv(W U) == inv(U) [M^T, -M^T p1; 0, 1]",
    ] {
        let src = format!(
            "given R1, R2 : SO3\ngiven M : mat3\ngiven p1, p2 : vec3\nT = [R1, p1; 0, 1]\n\
             U = [R2, p2; 0, 1]\nW = [M, p1; 0, 1]\n{wrong}"
        );
        let j = json(&src);
        let last = j.last().expect("a line");
        assert_ne!(last["value"], true, "{wrong}: {last:?}");
    }
}

/// A block of symbolic blocks is as tall as its tallest entry in each row
/// and as wide as its widest in each column, as the same block of numbers
/// is (a lone `0` is a zero block): `[1, 0; 0, R]` is 4×4 and
/// `[R, 0; 0, R]` 6×6 (they were typed 2×2 and 4×4, so comparing them
/// with `eye(4)` or `eye(6)` was a false size error).
#[test]
fn a_block_of_symbolic_blocks_has_the_size_of_its_blocks() {
    let src = "given R : SO3\ngiven K : so3\ngiven p : vec3\nA = [1, 0; 0, R]\nB = [R, 0; 0, R]\n\
               C = [2, 0; 0, R^T (R + K) - R^T K]\nD = [R, p; 0, 0, 0, 1]";
    let text = run(&["-e", src]).1;
    for (name, size) in [
        ("A", "4×4 matrix"),
        ("B", "6×6 matrix"),
        ("C", "4×4 matrix"),
    ] {
        let line = text
            .lines()
            .find(|l| l.starts_with(&format!("{name} = ")))
            .unwrap_or_else(|| panic!("{name} in {text}"));
        assert!(line.ends_with(&format!(": {size}")), "{line}");
    }
    let j = json(&format!(
        "{src}\nA == [1, 0; 0, R]\nC == [2, 0; 0, eye(3)]\nB == eye(6)\nR = Rotz(0.3)\n\
         A == [1, 0, 0, 0; 0, R[1,1], R[1,2], R[1,3]; 0, R[2,1], R[2,2], R[2,3]; 0, R[3,1], R[3,2], R[3,3]]"
    ));
    assert_eq!(j[3]["kind"], "SE3", "{:?}", j[3]);
    assert_eq!(j[4]["value"], true, "{:?}", j[4]);
    // Same sizes: compared (C's corner is RᵀR = I; not decided over
    // differently cut blocks, never refused as a size mismatch).
    assert_eq!(j[5]["kind"], "bool", "{:?}", j[5]);
    assert_eq!(j[6]["kind"], "bool", "{:?}", j[6]);
    assert_eq!(j[8]["value"], true, "{:?}", j[8]);
}

/// An integer power of a `given` transform or rotation is the product it
/// is (Exercise 3.11's e^A e^A, written A^2): `A^2 == A A` was `cannot
/// decide`, as were `R^2 == R R` and `A^0 == I`; a wrong one stays
/// undecided, never true.
#[test]
fn integer_powers_of_given_matrices_are_their_products() {
    let j = json(
        "given A, B : SE3\ngiven R : SO3\nA^2 == A A\nA^3 == A A A\nA^2 A == A A^2\n\
         A^-2 == inv(A) inv(A)\nR^2 == R R\nA^0 == I\n(A B)^2 == A B A B\n\
         inv(A^2) == A^-1 A^-1\nA^2 == A\nA^2 B == A B A\nA^3 == A A\nA^-2 == A A",
    );
    assert_eq!(j.len(), 12, "{j:?}");
    for proven in &j[..8] {
        assert_eq!(proven["value"], true, "{proven:?}");
    }
    for wrong in &j[8..] {
        assert_ne!(wrong["value"], true, "{wrong:?}");
    }
}
