//! Properties of the frame algebra (issue 11, LANGUAGE.md §6): every
//! bracketing of a random product of framed factors — transforms between
//! moved and unmoved frames, their inverses, displacements, one-frame
//! operators, transposed transforms, and a vector at the end — gets the same
//! kind and frames, or the same kind of error; and conjugating a one-frame
//! quantity by a transform gives a one-frame quantity.

use chasles::check::rules::{self, Operands};
use chasles::check::ty::{Frame, Frames, Kind, Ty};
use proptest::prelude::*;

/// The outcome of a product: its type, or the kind of its error.
type Outcome = Result<Ty, String>;

fn mul(l: &Outcome, r: &Outcome) -> Outcome {
    match (l, r) {
        (Ok(a), Ok(b)) => rules::mul(a, b, Operands::default()).map_err(|e| {
            e.kind
                .map_or("type".to_string(), |k| k.as_str().to_string())
        }),
        (Err(e), _) | (_, Err(e)) => Err(e.clone()),
    }
}

/// The outcome of every bracketing of `factors[i..j]`, deduplicated.
fn all_bracketings(factors: &[Ty]) -> Vec<Outcome> {
    let n = factors.len();
    // table[i][j]: outcomes of factors[i..=j].
    let mut table: Vec<Vec<Vec<Outcome>>> = vec![vec![Vec::new(); n]; n];
    for (i, f) in factors.iter().enumerate() {
        table[i][i] = vec![Ok(*f)];
    }
    for len in 2..=n {
        for i in 0..=n - len {
            let j = i + len - 1;
            let mut outs: Vec<Outcome> = Vec::new();
            for k in i..j {
                for l in &table[i][k] {
                    for r in &table[k + 1][j] {
                        let o = mul(l, r);
                        if !outs.contains(&o) {
                            outs.push(o);
                        }
                    }
                }
            }
            table[i][j] = outs;
        }
    }
    table[0][n - 1].clone()
}

fn frame() -> impl Strategy<Value = Frame> {
    (prop::sample::select(vec!["a", "b", "c"]), 0u32..3).prop_map(|(n, k)| Frame::at(n, k))
}

/// A 4×4 factor: a transform (maybe between moved frames), a displacement,
/// a one-frame se(3) matrix, an untagged transform, or a transposed one.
fn operator(untagged: bool) -> impl Strategy<Value = Ty> {
    let pair = (frame(), frame()).prop_map(|(a, b)| Ty::new(Kind::SE3, Frames::Pair(a, b)));
    let disp = frame().prop_map(|a| Ty::new(Kind::SE3, Frames::Disp(a)));
    let one = frame().prop_map(|a| Ty::new(Kind::Se3, Frames::One(a)));
    let transposed = (frame(), frame())
        .prop_map(|(a, b)| Ty::new(Kind::Matrix(Some(4), Some(4)), Frames::Transposed(a, b)));
    let plain = prop_oneof![
        Just(Ty::new(Kind::SE3, Frames::None)),
        Just(Ty::new(Kind::Se3, Frames::None)),
    ];
    prop_oneof![
        6 => pair,
        3 => disp,
        2 => one,
        1 => transposed,
        (if untagged { 2 } else { 0 }) => plain,
    ]
}

/// A point at the end of a chain, tagged or not.
fn point() -> impl Strategy<Value = Ty> {
    prop_oneof![
        3 => frame().prop_map(|a| Ty::new(Kind::Vector(Some(3)), Frames::One(a))),
        1 => Just(Ty::new(Kind::Vector(Some(3)), Frames::None)),
    ]
}

fn chain(untagged: bool) -> impl Strategy<Value = Vec<Ty>> {
    (
        prop::collection::vec(operator(untagged), 2..7),
        prop::bool::ANY,
        point(),
    )
        .prop_map(|(mut ops, with_point, p)| {
            if with_point {
                ops.push(p);
            }
            ops
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Framed factors: every bracketing, the same kind and frames (primes
    /// included) or the same kind of error.
    #[test]
    fn products_of_framed_factors_are_associative(factors in chain(false)) {
        let outs = all_bracketings(&factors);
        prop_assert_eq!(outs.len(), 1, "{:?}\n gives {:?}", factors, outs);
    }

    /// With untagged factors too (an untagged transform displaces the frame
    /// it meets, an untagged se(3) matrix is in the frame it meets).
    #[test]
    fn untagged_factors_are_associative_too(factors in chain(true)) {
        let outs = all_bracketings(&factors);
        prop_assert_eq!(outs.len(), 1, "{:?}\n gives {:?}", factors, outs);
    }

    /// T_ab [V_b] inv(T_ab) is [V_a] in {a} (3.77), R_ab [ω_b] R_abᵀ is
    /// [ω_a] in {a} (Prop. 3.5), under both bracketings, for any frames
    /// (moved or not).
    #[test]
    fn conjugation_closes_on_one_frame(a in frame(), b in frame(), rotation in prop::bool::ANY) {
        let (group, algebra) = if rotation { (Kind::SO3, Kind::So3) } else { (Kind::SE3, Kind::Se3) };
        let x = Ty::new(group, Frames::Pair(a, b));
        let q = Ty::new(algebra, Frames::One(b));
        let inv = if rotation { rules::transpose(&x) } else { rules::inverse(&x) }.unwrap();
        let outs = all_bracketings(&[x, q, inv]);
        prop_assert_eq!(outs.len(), 1);
        let t = outs[0].clone().unwrap();
        prop_assert_eq!(&t.frames, &Frames::One(a));
        prop_assert_eq!(rules::settled(&t).kind, algebra);
    }

    /// X^n has the frames of X·X·…·X (or the same kind of error).
    #[test]
    fn powers_are_products(x in operator(false), n in 2i64..6) {
        let product = all_bracketings(&vec![x; n as usize]);
        prop_assert_eq!(product.len(), 1);
        let power = rules::pow(&x, &Ty::scalar(), Some(n as f64)).map_err(|e| {
            e.kind.map_or("type".to_string(), |k| k.as_str().to_string())
        });
        prop_assert_eq!(power, product[0].clone(), "{:?}^{}", x, n);
    }

    /// And a one-frame quantity in the wrong frame is refused.
    #[test]
    fn conjugation_in_the_wrong_frame_is_refused(a in frame(), b in frame(), k in 0u32..3) {
        // A frame with another name than {b}.
        let c = Frame::at(format!("{}x", b.name), k);
        let x = Ty::new(Kind::SE3, Frames::Pair(a, b));
        let q = Ty::new(Kind::Se3, Frames::One(c));
        let inv = rules::inverse(&x).unwrap();
        let outs = all_bracketings(&[x, q, inv]);
        prop_assert_eq!(outs, vec![Err("frame".to_string())]);
    }
}

#[test]
fn the_books_products_in_every_bracketing() {
    fn f(s: &str) -> Frame {
        Frame::named(s)
    }
    let t = |a: &str, b: &str| Ty::new(Kind::SE3, Frames::Pair(f(a), f(b)));
    let disp = |a: &str| Ty::new(Kind::SE3, Frames::Disp(f(a)));
    let inv = |x: Ty| rules::inverse(&x).unwrap();
    for (factors, want) in [
        // exp([S_a] t) T_ab T_bc: {c} moves with {b}.
        (
            vec![disp("a"), t("a", "b"), t("b", "c")],
            Frames::Pair(f("a"), f("c'")),
        ),
        // T_ab exp([B_b] t) T_bc.
        (
            vec![t("a", "b"), disp("b"), t("b", "c")],
            Frames::Pair(f("a"), f("c'")),
        ),
        // inv(T_ab) exp([S_a] t) T_ab = exp([B_b] t), a displacement in {b}.
        (
            vec![inv(t("a", "b")), disp("a"), t("a", "b")],
            Frames::Pair(f("b"), f("b'")),
        ),
        // The body-form product of exponentials (4.16): T_ab e^[B]t1 e^[B]t2.
        (
            vec![t("a", "b"), disp("b"), disp("b")],
            Frames::Pair(f("a"), f("b''")),
        ),
        // T_sb' T_b'c: the named moved frame cancels.
        (
            vec![t("s", "b'"), t("b'", "c")],
            Frames::Pair(f("s"), f("c")),
        ),
    ] {
        let outs = all_bracketings(&factors);
        assert_eq!(outs, vec![Ok(Ty::new(Kind::SE3, want))], "{factors:?}");
    }
}

// The same property through the interpreter: scripts with numbers (run) and
// with symbols only (check) give every bracketing the same type and frames.

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};

const PRELUDE_RUN: &str = "T_ab = RpToTrans(Rotz(0.3), (1, 2, 0))\nT_bc = RpToTrans(Rotx(0.2), (0, 1, 0))\n\
T_ca = inv(T_ab * T_bc)\nS_a = (0, 0, 1, 0, 1, 0)\nB_b = (1, 0, 0, 0, 0, 1)\nV_b = (0, 0, 1, 1, 0, 0)\n\
T_ab' = exp([S_a] 0.4) * T_ab\np_b = (1, 2, 3)\n";
const PRELUDE_CHECK: &str = "given T_ab, T_bc, T_ca, T_ab' : SE3\ngiven S_a, B_b : screw\n\
given V_b : twist\ngiven p_b : vec3\n";

/// Every bracketing of `factors` joined by `*`, as source text.
fn bracketings(factors: &[&str]) -> Vec<String> {
    if factors.len() == 1 {
        return vec![factors[0].to_string()];
    }
    let mut out = Vec::new();
    for k in 1..factors.len() {
        for l in bracketings(&factors[..k]) {
            for r in bracketings(&factors[k..]) {
                out.push(format!("({l}) * ({r})"));
            }
        }
    }
    out
}

/// The type and frames of each JSON line, or the error's kind.
fn outcomes(prelude: &str, lines: &[String], mode: Mode) -> Vec<String> {
    let mut s = Session::new(Settings {
        json: true,
        ..Settings::default()
    });
    let src = format!("{prelude}{}\n", lines.join("\n"));
    let (out, _, _) = s.run_to_strings("t.chs", &src, mode, true);
    out.lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap())
        .filter(|v| v["line"].as_u64().unwrap_or(0) as usize > prelude.lines().count())
        .map(|v| match v.get("error") {
            Some(e) => format!("error {}", e["kind"]),
            None => format!("{} {}", v["type"], v["frames"]),
        })
        .collect()
}

fn script_factor() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec![
        "T_ab",
        "T_bc",
        "T_ca",
        "inv(T_ab)",
        "inv(T_bc)",
        "exp([S_a] 0.3)",
        "exp([B_b] 0.2)",
        "T_ab'",
        "inv(T_ab')",
        "[V_b]",
        "T_ab.T",
        "Trans((1, 0, 0))",
        "[(0, 0, 1, 1, 0, 0)]",
    ])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn scripts_give_every_bracketing_the_same_frames(
        mut factors in prop::collection::vec(script_factor(), 2..5),
        point in prop::sample::select(vec!["", "p_b", "(1, 2, 3)"]),
    ) {
        if !point.is_empty() {
            factors.push(point);
        }
        let lines = bracketings(&factors);
        for (prelude, mode) in [(PRELUDE_RUN, Mode::Run), (PRELUDE_CHECK, Mode::Check)] {
            let outs = outcomes(prelude, &lines, mode);
            prop_assert_eq!(outs.len(), lines.len());
            for o in &outs {
                prop_assert_eq!(o, &outs[0], "{:?} in {:?}: {:?}", factors, mode, outs);
            }
        }
    }
}
