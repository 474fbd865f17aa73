//! Wrong answers a student could get by binding numbers later (issue 21:
//! "never a wrong answer"). Each test binds the numbers after the value
//! is made and asserts what the same statements give with the numbers
//! typed first: the same refusal, or the same value.

mod common;

use common::{error, last_numbers};

/// `(a² − b²)/(a − b)` cancels to `a + b` symbolically; at a = b the
/// division it was made by is by zero, so it is refused, as typed first.
#[test]
fn a_cancelled_factor_bound_to_zero_is_refused() {
    let first = error("a = 0.3\nb = 0.3\n(a^2 - b^2)/(a - b)");
    assert!(first.contains("division by zero"), "{first}");
    let later = error("given a, b\ny = (a^2 - b^2)/(a - b)\na = 0.3\nb = 0.3\ny");
    assert!(later.contains("division by zero"), "{later}");
    // away from the cancelled zero, the value is a + b
    let v = last_numbers("given a, b\ny = (a^2 - b^2)/(a - b)\na = 0.3\nb = -1.1\ny");
    assert!((v[0] - (0.3 - 1.1)).abs() < 1e-15, "{v:?}");
}

/// `cot u` at u = 0 and `tan t` at t = π/2 are infinite: refused when
/// bound later as when typed first, not `inf` or 1.6e16.
#[test]
fn poles_bound_later_are_refused() {
    let later = error("given u\nc = cot(u)\nu = 0\nc");
    assert!(later.contains("cotangent is infinite"), "{later}");
    let later = error("given t\nz = tan(t)\nt = pi/2\nz");
    assert!(later.contains("tangent is infinite"), "{later}");
    let later = error("given t\nz = 2 sec(t) + 1\nt = pi/2\nz");
    assert!(later.contains("infinite"), "{later}");
}

/// `subs(x, a, 1)` of `(a² − 1)/(a − 1)` is the value of the division at
/// a = 1 — by zero, refused — not `1 + a` at 1; elsewhere the value.
#[test]
fn subs_of_a_cancelled_factor_at_its_zero_is_refused() {
    let e = error("given a\ny = (a^2 - 1)/(a - 1)\nsubs(y, a, 1)");
    assert!(e.contains("division by zero"), "{e}");
    let e = error("given a\nsubs((a^2 - 1)/(a - 1), a, 1)");
    assert!(e.contains("division by zero"), "{e}");
    let v = last_numbers("given a\ny = (a^2 - 1)/(a - 1)\nsubs(y, a, 3)");
    assert_eq!(v, vec![4.0]);
}

/// `Rot(w, θ)` over a symbolic axis bound later to the zero vector has no
/// value, as `Rot((0, 0, 0), 0.9)` has none: refused, not left printed as
/// an unevaluated rotation.
#[test]
fn a_symbolic_call_that_fails_with_its_numbers_is_refused() {
    let first = error("Rot((0, 0, 0), 0.9)");
    assert!(first.contains("zero vector"), "{first}");
    let later = error("given w : vec3\ngiven t\nR = Rot(w, t)\nw = (0, 0, 0)\nt = 0.9\nR");
    assert!(later.contains("zero vector"), "{later}");
}

/// Offsets of π/5 and π/7 are roots of unity: sums of them can vanish
/// (the five cosines of t + 2πk/5 add to 0) though the canonical form
/// keeps them apart. `==` says `cannot decide` there, never a wrong
/// `false`; it says `false` only with a point where the sides differ.
#[test]
fn cyclotomic_identities_are_never_false() {
    let fifths = "given t\ncos(t) + cos(t + 2 pi/5) + cos(t + 4 pi/5) + cos(t + 6 pi/5) + cos(t + 8 pi/5) == 0";
    let e = error(fifths);
    assert!(e.contains("cannot decide"), "{e}");
    let sevenths = "given t\ncos(t + pi/7) + cos(t + 3 pi/7) + cos(t + 5 pi/7) + cos(t + pi) + cos(t + 9 pi/7) + cos(t + 11 pi/7) + cos(t + 13 pi/7) == 0";
    let e = error(sevenths);
    assert!(e.contains("cannot decide"), "{e}");
    // cos A + cos B = 2 cos((A+B)/2) cos((A−B)/2): here 2 cos(π/5) ≠ 1, so false
    let v = last_numbers("given t\ncos(t + pi/5) + cos(t + 3 pi/5) == cos(t + 2 pi/5)");
    assert_eq!(v, vec![0.0], "{v:?}");
    // true, but cos(π/5) typed as a number is a float: not decided, not false
    let e = error("given t\ncos(t + pi/5) + cos(t + 3 pi/5) == 2 cos(pi/5) cos(t + 2 pi/5)");
    assert!(e.contains("cannot decide"), "{e}");
}

/// A decimal phase on one side and its float cosine on the other
/// (t1 bound to 0.3 first): the sides are equal but for rounding, so `==`
/// is `cannot decide`, never `false`; a real difference is still `false`.
#[test]
fn a_phase_against_its_float_is_never_false() {
    let e = error(
        "given t2\nt1 = 0.3\ncos(t1 + 0.3) cos(t2) - sin(t1 + 0.3) sin(t2) == cos(t1 + t2 + 0.3)",
    );
    assert!(e.contains("cannot decide"), "{e}");
    let v = last_numbers("given t2\ncos(t2 + 0.6) == cos(t2 + 0.5)");
    assert_eq!(v, vec![0.0], "{v:?}");
}
