//! The builtin reference, `docs/builtins.md`, generated from the one
//! builtin table that `:help` and completion read (LANGUAGE.md §8): each
//! function's signature, book section, meaning, other names and example,
//! grouped by the areas of `:help`. `tests/docs.rs` checks that the
//! committed file is what this prints.

use super::help::area_key;
use crate::builtins::{self, Area};

/// The command that rewrites `docs/builtins.md` from the table.
pub const REGENERATE: &str = "UPDATE_DOCS=1 cargo test --test docs";

/// `docs/builtins.md`: every builtin by area, in table order.
pub fn builtins_markdown() -> String {
    let mut out = String::from("# Builtin functions\n\n");
    out.push_str(&format!(
        "<!-- Generated from the builtin table (src/builtins/) by `{REGENERATE}`; do not edit. -->\n\n"
    ));
    out.push_str(
        "Every function chasles knows, by area, as `:help NAME` shows it in the REPL \
         and Shift-Tab in a notebook. Book names (section 3.6) and their snake_case \
         forms both work. The language itself is in [language.md](language.md).\n\n",
    );
    // GitHub numbers a repeated heading's anchor: `SE2`, then `se2` is `se2-1`.
    let mut seen = std::collections::HashMap::new();
    for area in Area::ALL {
        let items: Vec<_> = in_area(area).collect();
        if items.is_empty() {
            continue;
        }
        let names: Vec<String> = items
            .iter()
            .map(|b| {
                let a = anchor(b.name);
                let n = seen.entry(a.clone()).or_insert(0);
                let a = if *n == 0 { a } else { format!("{a}-{n}") };
                *n += 1;
                format!("[`{}`](#{a})", b.name)
            })
            .collect();
        out.push_str(&format!(
            "- **{}** (`:help {}`): {}\n",
            area.title(),
            area_key(area),
            names.join(", ")
        ));
    }
    for area in Area::ALL {
        let items: Vec<_> = in_area(area).collect();
        if items.is_empty() {
            continue;
        }
        out.push_str(&format!("\n## {}\n", area.title()));
        for b in items {
            out.push_str(&format!("\n### {}\n\n", b.name));
            out.push_str(&format!("`{}`", b.signature));
            if !b.section.is_empty() && b.section != "—" {
                out.push_str(&format!(" — {}", b.section));
            }
            out.push_str(&format!("\n\n{}\n", b.doc));
            if let Some(d) = builtins::python::difference(b.name) {
                out.push_str(&format!("\nUnlike the book's Python library: {d}.\n"));
            }
            if !b.aliases.is_empty() {
                let also: Vec<String> = b.aliases.iter().map(|a| format!("`{a}`")).collect();
                out.push_str(&format!("\nAlso: {}.\n", also.join(", ")));
            }
            if !b.example.is_empty() {
                out.push_str(&format!("\n```\n{}\n```\n", b.example));
            }
        }
    }
    out
}

/// The builtins of an area, in table order (as `:help AREA` lists them).
fn in_area(area: Area) -> impl Iterator<Item = &'static builtins::Builtin> {
    builtins::table()
        .iter()
        .filter(move |b| b.area == area && !b.name.is_empty())
}

/// The anchor GitHub gives a `### NAME` heading: lower case, spaces as
/// `-`, other punctuation dropped.
fn anchor(name: &str) -> String {
    name.chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '_' || c == '-' => Some(c.to_lowercase().next()?),
            _ => None,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_builtin_has_a_heading() {
        let md = builtins_markdown();
        for b in builtins::table().iter().filter(|b| !b.name.is_empty()) {
            assert!(md.contains(&format!("\n### {}\n", b.name)), "{}", b.name);
        }
    }

    #[test]
    fn anchors_follow_github() {
        assert_eq!(anchor("MatrixLog3"), "matrixlog3");
        assert_eq!(anchor("rot_zyx"), "rot_zyx");
    }
}
