//! Every operation's type-and-frame rule is in `Op::rule` (issue 14's one
//! operation seam): a builtin call's (its table row's check, then one
//! frame for a vector or Lie-algebra result), the inverse's and the
//! brackets' too, checked without numbers.

use chasles::builtins::lookup;
use chasles::check::ty::{Frame, Frames, Kind, Ty};
use chasles::diagnostics::ErrorKind;
use chasles::seam::apply::{Hints, Op};

fn pair(a: &str, b: &str) -> Frames {
    Frames::Pair(Frame::named(a), Frame::named(b))
}

fn one(a: &str) -> Frames {
    Frames::One(Frame::named(a))
}

#[test]
fn a_call_s_rule_is_its_table_row_then_one_frame() {
    let t_ab = Ty::new(Kind::SE3, pair("a", "b"));
    // inv(T_ab) = T_ba (3.64), by the builtin and by the inverse alike.
    let inv = lookup("inv").expect("inv");
    for op in [Op::Call(inv, "inv"), Op::Inverse] {
        let t = op.rule(&[&t_ab], Hints::default()).expect("a rule");
        assert_eq!((t.kind, t.frames), (Kind::SE3, pair("b", "a")));
    }
    // [Ad_T_ab] maps twists in {b} to {a} (3.83).
    let ad = lookup("Ad").expect("Ad");
    let t = Op::Call(ad, "Ad")
        .rule(&[&t_ab], Hints::default())
        .expect("a rule");
    assert_eq!(
        (t.kind, t.frames),
        (Kind::Adjoint { transposed: false }, pair("a", "b"))
    );
    // A refusal names the argument, with the signature as help.
    let v_b = Ty::new(Kind::Twist, one("b"));
    let e = Op::Call(ad, "Ad")
        .rule(&[&v_b], Hints::default())
        .expect_err("a twist is no transform");
    assert_eq!((e.arg, e.kind), (Some(0), Some(ErrorKind::Type)));
    assert_eq!(e.help, Some(format!("signature: {}", ad.signature)));
    let e = Op::Call(ad, "Ad")
        .rule(&[&t_ab, &t_ab], Hints::default())
        .expect_err("one argument");
    assert_eq!((e.arg, e.kind), (None, Some(ErrorKind::Arity)));
    // se3ToVec(T_ab [V_b]): a twist is in one frame, not a map {b}→{a}.
    let to_vec = lookup("se3ToVec").expect("se3ToVec");
    let e = Op::Call(to_vec, "se3ToVec")
        .rule(&[&Ty::new(Kind::Se3, pair("a", "b"))], Hints::default())
        .expect_err("a frame error");
    assert_eq!((e.arg, e.kind), (None, Some(ErrorKind::Frame)));
    let t = Op::Call(to_vec, "se3ToVec")
        .rule(&[&Ty::new(Kind::Se3, one("b"))], Hints::default())
        .expect("a rule");
    assert_eq!((t.kind, t.frames), (Kind::Twist, one("b")));
}

#[test]
fn brackets_have_their_rule_too() {
    // [V_b] ∈ se(3), in {b} (3.70); [ω_s] ∈ so(3) (3.30).
    let v_b = Ty::new(Kind::Twist, one("b"));
    let t = Op::Block(&[1])
        .rule(&[&v_b], Hints::default())
        .expect("a rule");
    assert_eq!((t.kind, t.frames), (Kind::Se3, one("b")));
    let w_s = Ty::new(Kind::Vector(Some(3)), one("s"));
    let t = Op::Block(&[1])
        .rule(&[&w_s], Hints::default())
        .expect("a rule");
    assert_eq!((t.kind, t.frames), (Kind::So3, one("s")));
    // [R_sb, p_sb; 0, 0, 0, 1] is a 4×4 {s}←{b} (3.62).
    let (r, p, x) = (
        Ty::new(Kind::SO3, pair("s", "b")),
        Ty::new(Kind::Vector(Some(3)), one("s")),
        Ty::scalar(),
    );
    let t = Op::Block(&[2, 4])
        .rule(&[&r, &p, &x, &x, &x, &x], Hints::default())
        .expect("a rule");
    assert_eq!(
        (t.kind, t.frames),
        (Kind::Matrix(Some(4), Some(4)), pair("s", "b"))
    );
    // One row of numbers is a column vector; [1, 2; 3, 4] a 2×2.
    let t = Op::Block(&[3])
        .rule(&[&x, &x, &x], Hints::default())
        .expect("a rule");
    assert_eq!(t.kind, Kind::Vector(Some(3)));
    let t = Op::Block(&[2, 2])
        .rule(&[&x, &x, &x, &x], Hints::default())
        .expect("a rule");
    assert_eq!(t.kind, Kind::Matrix(Some(2), Some(2)));
}

#[test]
fn brackets_on_numbers_take_their_entries_row_by_row() {
    use chasles::values::value::Value;
    let xs: Vec<Value> = (1..=4).map(|i| Value::scalar(f64::from(i))).collect();
    let refs: Vec<&Value> = xs.iter().collect();
    let m = Op::Block(&[2, 2]).numeric(&refs, None).expect("a 2×2");
    let m = m.as_matrix().expect("numbers");
    assert_eq!(m.shape(), (2, 2));
    assert_eq!((m[(0, 1)], m[(1, 0)]), (2.0, 3.0));
    // [1, 2; 3] joins rows of different widths: the user's message.
    let e = Op::Block(&[2, 1])
        .numeric(&refs[..3], None)
        .expect_err("ragged rows");
    assert_eq!(
        e.to_string(),
        "rows of the bracket have different widths: 2 and 1 (row 2)"
    );
}
