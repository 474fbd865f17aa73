//! The note "the two sides differ by rounding only" on a false `==`
//! (LANGUAGE.md §3, §7) appears only where the sides genuinely agree to
//! within rounding of floats with no exact form (exp and log of numbers
//! have none here), relative to the sides themselves: `exp(-40) ==
//! exp(-41)` differ by less than 1e-12 but not by rounding, and printed
//! the note (the tolerance was relative to max(1, |side|)).

mod common;

use common::outputs;

/// The printed answer and whether the rounding note came with it.
fn answer(src: &str) -> (String, bool) {
    let (out, err) = outputs(src);
    let last = out.lines().last().unwrap_or_default().to_string();
    (last, err.contains("differ by rounding only"))
}

#[test]
fn the_note_comes_with_floats_within_rounding() {
    for src in [
        "exp(log(5))^2 == 25",
        "given t\nexp(log(5))^2*t == 25*t",
        // small sides within rounding of each other
        "exp(-40)*exp(log(5))^2 == exp(-40)*25",
        "given t\nexp(-40)*exp(log(5))^2*t == exp(-40)*25*t",
    ] {
        assert_eq!(answer(src), ("false".into(), true), "{src}");
    }
}

#[test]
fn no_note_where_the_sides_really_differ() {
    for src in [
        "exp(-40) == exp(-41)",
        "exp(0)*1e-13 == exp(0)*2e-13",
        "1e-13 == exp(0) - 1",
        "given t\nexp(-40)*t == exp(-41)*t",
        "given t\n(exp(0)*1e-16)*t == 0*t",
        "given x\nx + 1e-13 == x",
        // exact sides: a difference below double precision is no rounding
        "sqrt(2) == 1.4142135623730951",
        "given t\nsqrt(2)*t == 1.4142135623730951*t",
    ] {
        assert_eq!(answer(src), ("false".into(), false), "{src}");
    }
}
