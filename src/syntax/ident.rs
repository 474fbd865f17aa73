//! Frame subscripts read from names (LANGUAGE.md §2).
//!
//! The part of a name after its last `_` is a frame subscript when it splits
//! into one or two frame names, each a letter followed by digits and/or
//! primes: `T_sb` → ({s}, {b}), `T_sb'` → ({s}, {b'}), `T_b1c` → ({b1}, {c}),
//! `p_b` → {b}, `ω_s` → {s}. Braces allow long names: `T_{world,cam}`,
//! `p_{cam}`, and name numbered frames: `T_{0,1}`, `p_{1}`. An all-digit
//! subscript on a one-frame name (`theta_1`, `S_1`) is an index and a
//! subscript of three or more letters (`x_max`) is part of a plain name:
//! both give [`NameFrames::None`].
//!
//! Two-frame names (rotations, transforms, adjoints: `R_`, `T_`, `Ad_`)
//! also take numbered frames: the subscript is read as letter-with-digits
//! tokens when that gives two frames (`T_b1c` = {b1}←{c}), else character
//! by character when that gives two (`T_01` = {0}←{1}, `T_s1`, `T_1s`);
//! anything else with a digit in it (`T_123`, `T_a12`) is refused by
//! [`name_error`], which asks for braces.

/// The frames named by a name's subscript.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum NameFrames {
    /// No frame subscript.
    None,
    /// One frame: `p_b`, `V_s`, `p_{cam}`.
    One(String),
    /// Two frames, outer then inner: `T_sb` → ("s", "b").
    Pair(String, String),
}

/// The frame subscript of `name`; see the module documentation.
pub fn name_frames(name: &str) -> NameFrames {
    match split_subscript(name) {
        Some((_, frames)) => frames,
        None => NameFrames::None,
    }
}

/// The part of `name` before its frame subscript: `T_sb` → `T`,
/// `T_{world,cam}` → `T`. A name without a frame subscript (`theta_1`,
/// `x_max`, `alpha`) is returned whole.
pub fn base_name(name: &str) -> &str {
    match split_raw(name) {
        Some((base, _, _)) => base,
        None => name,
    }
}

/// The name with base `base` and frame subscript `frames` (outer first), as
/// [`name_frames`] reads it back: `T` + (s, b) → `T_sb`, `T` + (b1, c) →
/// `T_b1c`, `T` + (0, 1) → `T_01`, but `T` + (world, cam) →
/// `T_{world,cam}`: braces as soon as the short form reads back otherwise.
pub fn tagged_name(base: &str, frames: &[&str]) -> String {
    let short = format!("{base}_{}", frames.concat());
    let want = match frames {
        [a] => NameFrames::One(a.to_string()),
        [a, b] => NameFrames::Pair(a.to_string(), b.to_string()),
        _ => NameFrames::None,
    };
    if want != NameFrames::None && name_frames(&short) == want {
        short
    } else {
        format!("{base}_{{{}}}", frames.join(","))
    }
}

/// Whether names with this base carry two frames (LANGUAGE.md §2):
/// rotations, transforms and adjoints.
fn two_frame_base(base: &str) -> bool {
    matches!(base, "R" | "T" | "Ad")
}

/// Why `name` is not a valid name, if it is not: a two-frame name whose
/// numbered subscript does not split into two frames (`T_123`, `T_a12`).
pub fn name_error(name: &str) -> Option<String> {
    // Most names have no digit at all (a non-ASCII character may be one).
    if !name.bytes().any(|b| b.is_ascii_digit() || !b.is_ascii()) {
        return None;
    }
    if name.contains("_{") {
        return None;
    }
    let underscore = name.rfind('_')?;
    let (base, sub) = (&name[..underscore], &name[underscore + 1..]);
    if !two_frame_base(base) || !sub.chars().any(char::is_numeric) {
        return None;
    }
    if sub.chars().count() == 1 || split_subscript(name).is_some() {
        return None;
    }
    Some(format!(
        "`{name}`: the subscript of {base}_ names two frames, and `{sub}` does not split into two"
    ))
}

/// Splits `name` into its base and frame subscript, if it has one.
fn split_subscript(name: &str) -> Option<(&str, NameFrames)> {
    let (base, frames, primes) = split_raw(name)?;
    match frames.as_slice() {
        [a] => Some((base, NameFrames::One(format!("{a}{primes}")))),
        [a, b] => Some((
            base,
            NameFrames::Pair(a.to_string(), format!("{b}{primes}")),
        )),
        _ => None,
    }
}

/// [`split_subscript`] without allocating: the base, the frames as slices
/// of the name, and the primes after a braced subscript (`T_{a,b}''`),
/// which belong to its last frame.
fn split_raw(name: &str) -> Option<(&str, Runs<'_>, &str)> {
    // Braced form: `T_{world,cam}`, optionally followed by primes.
    if let Some(open) = name.rfind("_{") {
        let rest = &name[open + 2..];
        let close = rest.find('}')?;
        let primes = &rest[close + 1..];
        if !primes.chars().all(|c| c == '\'') {
            return None;
        }
        let mut parts = Runs {
            n: 0,
            first: ["", ""],
        };
        for p in rest[..close].split(',').map(str::trim) {
            if !is_long_frame(p) {
                return None;
            }
            if parts.n < 2 {
                parts.first[parts.n] = p;
            }
            parts.n = (parts.n + 1).min(3);
        }
        let base = &name[..open];
        return matches!(parts.n, 1 | 2).then_some((base, parts, primes));
    }

    let underscore = name.rfind('_')?;
    let base = &name[..underscore];
    let sub = &name[underscore + 1..];
    if base.is_empty() {
        return None;
    }
    let mut frames = short_frames(sub);
    if two_frame_base(base) && frames.is_none_or(|f| f.len() != 2) {
        // `T_01`, `T_s1`, `T_1s`: one frame per character.
        if let Some(chars) = char_frames(sub) {
            frames = Some(chars);
        } else if sub.chars().any(char::is_numeric) {
            return None;
        }
    }
    frames
        .filter(|f| matches!(f.len(), 1 | 2))
        .map(|f| (base, f, ""))
}

/// The frames of a subscript, as slices of it: each frame is a run of
/// characters, so only their number (up to three, "more than two") and the
/// first two are kept — reading a name allocates nothing until its frames
/// are returned.
#[derive(Debug, Clone, Copy)]
struct Runs<'a> {
    n: usize,
    first: [&'a str; 2],
}

impl<'a> Runs<'a> {
    fn len(&self) -> usize {
        self.n
    }
    fn as_slice(&self) -> &[&'a str] {
        if self.n <= 2 {
            &self.first[..self.n]
        } else {
            &[]
        }
    }
}

/// Splits `sub` into runs, each starting at a character `starts` accepts
/// and extended by the characters `extends` accepts; None when a character
/// is neither, or the text starts with an extending character.
fn runs<'a>(
    sub: &'a str,
    starts: impl Fn(char) -> bool,
    extends: impl Fn(char) -> bool,
) -> Option<Runs<'a>> {
    let mut r = Runs {
        n: 0,
        first: ["", ""],
    };
    let mut begin = 0;
    for (i, c) in sub.char_indices() {
        if starts(c) {
            if r.n >= 1 && r.n <= 2 {
                r.first[r.n - 1] = &sub[begin..i];
            }
            r.n = (r.n + 1).min(3);
            begin = i;
        } else if extends(c) {
            if r.n == 0 {
                return None;
            }
        } else {
            return None;
        }
    }
    if r.n >= 1 && r.n <= 2 {
        r.first[r.n - 1] = &sub[begin..];
    }
    Some(r)
}

/// `sb'` → ["s", "b'"]; `b1c` → ["b1", "c"]; None unless the text is a
/// sequence of frame names (a letter, then digits and primes).
fn short_frames(sub: &str) -> Option<Runs<'_>> {
    // Digits and primes extend the current frame; none yet means the
    // subscript starts with a digit: an index, not a frame.
    let r = runs(sub, char::is_alphabetic, |c| c.is_numeric() || c == '\'')?;
    (r.len() > 0).then_some(r)
}

/// `01` → ["0", "1"], `s1'` → ["s", "1'"]: a frame per letter or digit,
/// primes attached; None unless that gives exactly two frames.
fn char_frames(sub: &str) -> Option<Runs<'_>> {
    let r = runs(sub, char::is_alphanumeric, |c| c == '\'')?;
    (r.len() == 2).then_some(r)
}

/// A braced frame name: a letter or digit, then letters, digits, `_` or
/// primes (`{cam}`, `{1}`, `{b2}`).
fn is_long_frame(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_alphanumeric())
        && chars.all(|c| c.is_alphanumeric() || c == '_' || c == '\'')
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(a: &str) -> NameFrames {
        NameFrames::One(a.into())
    }
    fn pair(a: &str, b: &str) -> NameFrames {
        NameFrames::Pair(a.into(), b.into())
    }

    #[test]
    fn tagged_names_read_back() {
        for (base, frames, want) in [
            ("T", vec!["s", "b"], "T_sb"),
            ("T", vec!["b1", "c"], "T_b1c"),
            ("T", vec!["s", "b'"], "T_sb'"),
            ("p", vec!["b"], "p_b"),
            ("T", vec!["world", "cam"], "T_{world,cam}"),
            ("T", vec!["s", "cam"], "T_{s,cam}"),
            ("p", vec!["cam"], "p_{cam}"),
        ] {
            let name = tagged_name(base, &frames);
            assert_eq!(name, want);
            let back = match frames.as_slice() {
                [a] => one(a),
                [a, b] => pair(a, b),
                _ => unreachable!(),
            };
            assert_eq!(name_frames(&name), back, "{name}");
        }
    }

    #[test]
    fn frames_table() {
        let table = [
            ("T_sb", pair("s", "b")),
            ("T_sb'", pair("s", "b'")),
            ("T_b1c", pair("b1", "c")),
            ("R_sa'", pair("s", "a'")),
            ("T_s'b", pair("s'", "b")),
            ("p_b", one("b")),
            ("V_s", one("s")),
            ("ω_s", one("s")),
            ("F_a", one("a")),
            ("T_{world,cam}", pair("world", "cam")),
            ("T_{world, cam}", pair("world", "cam")),
            ("p_{cam}", one("cam")),
            ("T_{a,b}'", pair("a", "b'")),
            ("theta_1", NameFrames::None),
            ("x_max", NameFrames::None),
            ("theta", NameFrames::None),
            ("T", NameFrames::None),
            ("_s", NameFrames::None),
            ("x_", NameFrames::None),
            ("S_1", NameFrames::None),
            ("x_1a", NameFrames::None),
            // Numbered frames (LANGUAGE.md §2).
            ("T_01", pair("0", "1")),
            ("T_12", pair("1", "2")),
            ("T_s1", pair("s", "1")),
            ("T_1s", pair("1", "s")),
            ("R_b1c", pair("b1", "c")),
            ("Ad_01", pair("0", "1")),
            ("T_01'", pair("0", "1'")),
            ("T_{0,1}", pair("0", "1")),
            ("p_{1}", one("1")),
            ("T_1", NameFrames::None),
            ("B_2", NameFrames::None),
            ("theta_12", NameFrames::None),
            ("T_123", NameFrames::None),
            ("T_a12", NameFrames::None),
            ("T_s", one("s")),
            ("T_{a,b,c}", NameFrames::None),
            ("T_{}", NameFrames::None),
        ];
        for (name, want) in table {
            assert_eq!(name_frames(name), want, "{name}");
        }
    }

    #[test]
    fn numbered_subscripts_that_do_not_split_ask_for_braces() {
        for bad in ["T_123", "T_a12", "R_1ab", "Ad_b12"] {
            assert!(name_error(bad).is_some(), "{bad}");
        }
        for good in [
            "T_01",
            "T_sb",
            "T_b1c",
            "T_1",
            "T_s",
            "theta_123",
            "T_{1,23}",
            "S_12",
        ] {
            assert_eq!(name_error(good), None, "{good}");
        }
        assert_eq!(tagged_name("T", &["0", "1"]), "T_01");
        assert_eq!(tagged_name("T", &["1", "23"]), "T_{1,23}");
        assert_eq!(tagged_name("p", &["1"]), "p_{1}");
    }

    #[test]
    fn base_names() {
        assert_eq!(base_name("T_sb"), "T");
        assert_eq!(base_name("T_sb'"), "T");
        assert_eq!(base_name("ω_s"), "ω");
        assert_eq!(base_name("T_{world,cam}"), "T");
        assert_eq!(base_name("theta_1"), "theta_1");
        assert_eq!(base_name("x_max"), "x_max");
        assert_eq!(base_name("V"), "V");
        assert_eq!(base_name("my_T_sb"), "my_T");
    }
}
