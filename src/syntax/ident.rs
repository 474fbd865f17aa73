//! Frame subscripts read from names (LANGUAGE.md §2).
//!
//! The part of a name after its last `_` is a frame subscript when it splits
//! into one or two frame names, each a letter followed by digits and/or
//! primes: `T_sb` → ({s}, {b}), `T_sb'` → ({s}, {b'}), `T_b1c` → ({b1}, {c}),
//! `p_b` → {b}, `ω_s` → {s}. Braces allow long names: `T_{world,cam}`,
//! `p_{cam}`. An all-digit subscript (`theta_1`) is an index and a subscript
//! of three or more letters (`x_max`) is part of a plain name: both give
//! [`NameFrames::None`].

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
    match split_subscript(name) {
        Some((base, _)) => base,
        None => name,
    }
}

/// The name with base `base` and frame subscript `frames` (outer first), as
/// [`name_frames`] reads it back: `T` + (s, b) → `T_sb`, `T` + (b1, c) →
/// `T_b1c`, but `T` + (world, cam) → `T_{world,cam}`: braces as soon as one
/// frame is not a single letter with digits and primes.
pub fn tagged_name(base: &str, frames: &[&str]) -> String {
    let short = |f: &&str| {
        let mut chars = f.chars();
        matches!(chars.next(), Some(c) if c.is_alphabetic())
            && chars.all(|c| c.is_numeric() || c == '\'')
    };
    if frames.iter().all(short) {
        format!("{base}_{}", frames.concat())
    } else {
        format!("{base}_{{{}}}", frames.join(","))
    }
}

/// Splits `name` into its base and frame subscript, if it has one.
fn split_subscript(name: &str) -> Option<(&str, NameFrames)> {
    // Braced form: `T_{world,cam}`, optionally followed by primes.
    if let Some(open) = name.rfind("_{") {
        let rest = &name[open + 2..];
        let close = rest.find('}')?;
        let primes = &rest[close + 1..];
        if !primes.chars().all(|c| c == '\'') {
            return None;
        }
        let parts: Vec<&str> = rest[..close].split(',').map(str::trim).collect();
        if !parts.iter().all(|p| is_long_frame(p)) {
            return None;
        }
        let base = &name[..open];
        return match parts.as_slice() {
            [a] => Some((base, NameFrames::One(format!("{a}{primes}")))),
            [a, b] => Some((
                base,
                NameFrames::Pair(a.to_string(), format!("{b}{primes}")),
            )),
            _ => None,
        };
    }

    let underscore = name.rfind('_')?;
    let base = &name[..underscore];
    let sub = &name[underscore + 1..];
    if base.is_empty() {
        return None;
    }
    let frames = short_frames(sub)?;
    match frames.as_slice() {
        [a] => Some((base, NameFrames::One(a.clone()))),
        [a, b] => Some((base, NameFrames::Pair(a.clone(), b.clone()))),
        _ => None,
    }
}

/// `sb'` → ["s", "b'"]; `b1c` → ["b1", "c"]; None unless the text is a
/// sequence of frame names (a letter, then digits and primes).
fn short_frames(sub: &str) -> Option<Vec<String>> {
    let mut frames: Vec<String> = Vec::new();
    for c in sub.chars() {
        if c.is_alphabetic() {
            frames.push(c.to_string());
        } else if c.is_numeric() || c == '\'' {
            // Digits and primes extend the current frame; none yet means the
            // subscript starts with a digit: an index, not a frame.
            frames.last_mut()?.push(c);
        } else {
            return None;
        }
    }
    if frames.is_empty() {
        None
    } else {
        Some(frames)
    }
}

/// A braced frame name: a letter, then letters, digits, `_` or primes.
fn is_long_frame(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_alphabetic())
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
            ("T_{a,b,c}", NameFrames::None),
            ("T_{}", NameFrames::None),
        ];
        for (name, want) in table {
            assert_eq!(name_frames(name), want, "{name}");
        }
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
