//! The names of the parts of the builtins that return tuples, as the book
//! names them (section 3.6): `AxisAng3` gives (ω̂, θ), `screw_params` the
//! point q, direction ŝ and pitch h of a screw axis (§3.3.2.2). A bare call
//! prints each part under its name (`q = …`, `s = …`, `h = …`); JSON keeps
//! the schema's plain list.

/// The names of the parts of `builtin`'s result (its book name), if it
/// returns a tuple with named parts.
pub fn part_names(builtin: &str) -> Option<&'static [&'static str]> {
    Some(match builtin {
        "AxisAng3" => &["w", "theta"],
        "AxisAng6" => &["S", "theta"],
        "TransToRp" => &["R", "p"],
        "screw_params" => &["q", "s", "h"],
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every named builtin exists and returns as many parts as it names.
    #[test]
    fn names_match_the_table() {
        for name in ["AxisAng3", "AxisAng6", "TransToRp", "screw_params"] {
            let b = crate::builtins::lookup(name).expect("a builtin");
            let Some(parts) = part_names(b.name) else {
                panic!("{name} has no part names");
            };
            let arg = crate::check::ty::Ty::plain(crate::check::ty::Kind::Unknown);
            let ty = b.check(&[arg]).expect("typed");
            match ty.kind {
                crate::check::ty::Kind::Tuple(ks) => assert_eq!(ks.len(), parts.len(), "{name}"),
                k => panic!("{name} returns {k:?}"),
            }
        }
    }
}
