//! One test per row of the tables of [`super`].

use super::*;

fn f(name: &str) -> Frame {
    Frame::named(name)
}
fn pair(a: &str, b: &str) -> Frames {
    Frames::Pair(f(a), f(b))
}
fn one(a: &str) -> Frames {
    Frames::One(f(a))
}
const SE3: Kind = Kind::SE3;
const SE3M: Kind = Kind::Se3;
const M4: Kind = Kind::Matrix(Some(4), Some(4));
const V3: Kind = Kind::Vector(Some(3));
const ROW: Kind = Kind::Matrix(Some(1), Some(6));

/// The frames of `l * r` with a result of kind `k`.
fn mul(l: (&Frames, &Kind), r: (&Frames, &Kind), k: &Kind) -> Result<Frames, Clash> {
    let ty = |(f, k): (&Frames, &Kind)| Ty::new(*k, *f);
    product(&ty(l), &ty(r), k).map(|(f, _)| f)
}

// First table: factors.

#[test]
fn row_pair_is_a_map() {
    assert_eq!(
        factor(&pair("a", "b"), Shape::Operator),
        Factor::Map(Arrow::new(End::At(f("a")), End::At(f("b"))))
    );
}

#[test]
fn row_one_frame_operator_maps_its_frame_to_itself() {
    assert_eq!(
        factor(&one("a"), Shape::Operator),
        Factor::Map(Arrow::new(End::At(f("a")), End::At(f("a"))))
    );
}

#[test]
fn row_displacement_maps_to_the_moved_frame() {
    assert_eq!(
        factor(&Frames::Disp(f("a")), Shape::Operator),
        Factor::Map(Arrow::new(End::At(f("a")), End::At(f("a'"))))
    );
}

#[test]
fn row_vectors_and_rows_end_on_the_line() {
    assert_eq!(
        factor(&one("a"), Shape::Column),
        Factor::Map(Arrow::new(End::At(f("a")), End::Line))
    );
    assert_eq!(
        factor(&one("a"), Shape::Row),
        Factor::Map(Arrow::new(End::Line, End::At(f("a"))))
    );
}

#[test]
fn row_untagged_operator_displaces_what_it_meets() {
    assert_eq!(factor(&Frames::None, Shape::Operator), Factor::Untagged(1));
    assert_eq!(
        mul((&Frames::None, &SE3), (&pair("a", "b"), &SE3), &SE3),
        Ok(pair("a", "b'"))
    );
    assert_eq!(
        mul((&pair("a", "b"), &SE3), (&Frames::None, &SE3), &SE3),
        Ok(pair("a", "b'"))
    );
}

#[test]
fn row_products_of_untagged_operators_count_their_displacements() {
    let u = Ty::new(SE3, Frames::None);
    let t = Ty::new(SE3, pair("a", "b"));
    let uu = Ty::new(SE3, Frames::None);
    let (f, moves) = product(&u, &uu, &SE3).unwrap();
    assert_eq!((f, moves), (Frames::None, Some(2)));
    let mut two = Ty::new(SE3, Frames::None);
    two.moves = Some(crate::check::ty::Moves::new(2));
    let left = product(&two, &t, &SE3).unwrap().0;
    let inner = Ty::new(SE3, product(&uu, &t, &SE3).unwrap().0);
    let right = product(&u, &inner, &SE3).unwrap().0;
    assert_eq!(left, pair("a", "b''"));
    assert_eq!(left, right);
}

#[test]
fn row_untagged_lie_algebra_matrix_is_in_the_frame_it_meets() {
    assert_eq!(factor(&Frames::None, Shape::of(&SE3M)), Factor::Untagged(0));
    let left = mul((&pair("a", "b"), &SE3), (&Frames::None, &SE3M), &M4).unwrap();
    assert_eq!(left, pair("a", "b"));
    assert_eq!(
        mul((&left, &M4), (&pair("b", "a"), &SE3), &M4),
        Ok(one("a"))
    );
}

#[test]
fn row_untagged_vector_matches_any_frame() {
    assert_eq!(
        mul((&pair("a", "b"), &SE3), (&Frames::None, &V3), &V3),
        Ok(one("a"))
    );
}

#[test]
fn row_transposed_transform_is_no_map() {
    let t = Frames::Transposed(f("b"), f("a"));
    assert_eq!(
        mul((&t, &M4), (&one("a"), &V3), &V3),
        Err(Clash::Transposed { left: true })
    );
    assert_eq!(
        mul((&pair("c", "b"), &SE3), (&t, &M4), &M4),
        Err(Clash::Transposed { left: false })
    );
}

// Second table: products.

#[test]
fn row_inner_frames_cancel() {
    assert_eq!(
        mul((&pair("a", "b"), &SE3), (&pair("b", "c"), &SE3), &SE3),
        Ok(pair("a", "c"))
    );
}

#[test]
fn row_frames_attached_to_a_moved_frame_move_with_it() {
    assert_eq!(
        mul((&pair("a", "b'"), &SE3), (&pair("b", "c"), &SE3), &SE3),
        Ok(pair("a", "c'"))
    );
}

#[test]
fn row_a_moved_outer_frame_moves_the_left_factor() {
    assert_eq!(
        mul((&pair("a", "b"), &SE3), (&pair("b'", "c"), &SE3), &SE3),
        Ok(pair("a'", "c"))
    );
}

#[test]
fn row_different_inner_frames_clash() {
    assert_eq!(
        mul((&pair("a", "b"), &SE3), (&pair("c", "d"), &SE3), &SE3),
        Err(Clash::Inner(f("b"), f("c")))
    );
    assert_eq!(
        mul((&pair("a", "b'"), &SE3), (&pair("c", "d"), &SE3), &SE3),
        Err(Clash::Inner(f("b'"), f("c")))
    );
}

#[test]
fn row_displacements_move_the_inner_frame() {
    let d = Frames::Disp(f("a"));
    assert_eq!(
        mul((&d, &SE3), (&pair("a", "b"), &SE3), &SE3),
        Ok(pair("a", "b'"))
    );
    assert_eq!(
        mul((&pair("b", "a"), &SE3), (&d, &SE3), &SE3),
        Ok(pair("b", "a'"))
    );
    // Two displacements in {a}: {a} moved twice.
    assert_eq!(mul((&d, &SE3), (&d, &SE3), &SE3), Ok(pair("a", "a''")));
}

#[test]
fn row_a_displacement_conjugated_is_a_displacement() {
    // inv(T_ab) exp([S_a] θ) T_ab = exp([B_b] θ), a displacement in {b}.
    let left = mul((&pair("b", "a"), &SE3), (&Frames::Disp(f("a")), &SE3), &SE3).unwrap();
    assert_eq!(
        mul((&left, &SE3), (&pair("a", "b"), &SE3), &SE3),
        Ok(pair("b", "b'"))
    );
}

#[test]
fn row_one_frame_operator_keeps_the_pair() {
    assert_eq!(
        mul((&pair("a", "b"), &SE3), (&one("b"), &SE3M), &M4),
        Ok(pair("a", "b"))
    );
}

#[test]
fn row_conjugation_gives_one_frame() {
    let left = mul((&pair("a", "b"), &SE3), (&one("b"), &SE3M), &M4).unwrap();
    assert_eq!(
        mul((&left, &M4), (&pair("b", "a"), &SE3), &SE3M),
        Ok(one("a"))
    );
}

#[test]
fn row_a_group_element_from_a_frame_to_itself_is_the_identity_pair() {
    assert_eq!(
        mul((&pair("b", "a"), &SE3), (&pair("a", "b"), &SE3), &SE3),
        Ok(pair("b", "b"))
    );
}

#[test]
fn row_operator_applied_to_a_vector() {
    assert_eq!(
        mul((&pair("a", "b"), &SE3), (&one("b"), &V3), &V3),
        Ok(one("a"))
    );
    // A point of the moved body, in {a}.
    assert_eq!(
        mul((&pair("a", "b'"), &SE3), (&one("b"), &V3), &V3),
        Ok(one("a"))
    );
}

#[test]
fn row_row_times_column_is_a_plain_scalar() {
    assert_eq!(
        mul((&one("b"), &ROW), (&one("b"), &Kind::Wrench), &Kind::Scalar),
        Ok(Frames::None)
    );
    assert_eq!(
        mul((&one("b"), &ROW), (&one("a"), &Kind::Wrench), &Kind::Scalar),
        Err(Clash::Inner(f("b"), f("a")))
    );
}

#[test]
fn row_column_times_row_is_a_map() {
    let col = Kind::Vector(Some(3));
    let row = Kind::Matrix(Some(1), Some(3));
    let k = Kind::Matrix(Some(3), Some(3));
    assert_eq!(
        mul((&one("a"), &col), (&one("b"), &row), &k),
        Ok(pair("a", "b"))
    );
}
