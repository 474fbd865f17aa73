//! The reference that ships with the code: `docs/builtins.md` is what the
//! builtin table generates (rewrite it with `UPDATE_DOCS=1 cargo test
//! --test docs`), and the README and docs link only files of the
//! repository.

use chasles::repl::reference::{REGENERATE, builtins_markdown};

fn root() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn builtins_md_is_current() {
    let path = root().join("docs/builtins.md");
    let want = builtins_markdown();
    if std::env::var_os("UPDATE_DOCS").is_some() {
        std::fs::write(&path, &want).expect("docs/builtins.md is writable");
        return;
    }
    let have = std::fs::read_to_string(&path).unwrap_or_default();
    if have != want {
        let line = have
            .lines()
            .zip(want.lines())
            .position(|(a, b)| a != b)
            .map_or(have.lines().count().min(want.lines().count()) + 1, |i| {
                i + 1
            });
        panic!(
            "docs/builtins.md is not what the builtin table generates (first difference at line {line}); \
             regenerate it with `{REGENERATE}` and commit it"
        );
    }
}

#[test]
fn builtins_md_names_the_book_functions() {
    let md = builtins_markdown();
    for name in ["MatrixExp6", "MatrixLog3", "Adjoint", "ScrewToAxis", "draw"] {
        assert!(md.contains(&format!("### {name}\n")), "{name} has no entry");
    }
    assert!(md.contains("Also: `matrix_log3`"), "aliases are listed");
}

/// Every relative link of the README and docs/ names a file that exists in
/// a clone (the old `../shared/LANGUAGE.md` link did not).
#[test]
fn links_stay_inside_the_repository() {
    let mut files = vec![root().join("README.md")];
    for e in std::fs::read_dir(root().join("docs")).expect("docs/ exists") {
        let p = e.expect("a docs entry").path();
        if p.extension().is_some_and(|x| x == "md") {
            files.push(p);
        }
    }
    for f in files {
        let text = std::fs::read_to_string(&f).expect("readable");
        assert!(
            !text.contains("../shared"),
            "{} links ../shared",
            f.display()
        );
        for (i, _) in text.match_indices("](") {
            let rest = &text[i + 2..];
            let Some(end) = rest.find(')') else { continue };
            let target = rest[..end].split('#').next().unwrap_or("");
            if target.is_empty() || target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let dir = f.parent().expect("a folder");
            assert!(
                dir.join(target).exists(),
                "{} links {target}, which is not in the repository",
                f.display()
            );
        }
    }
}

/// Every difference from the book's Python library (issue 36) is a row of
/// the README's table and is said by `:help` of its function.
#[test]
fn differences_from_the_python_library_are_in_the_readme_and_help() {
    use chasles::builtins::python::DIFFERENCES;
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    assert!(DIFFERENCES.len() >= 8);
    for d in DIFFERENCES {
        let row = format!("| `{}` | {} |", d.name, d.text);
        assert!(readme.contains(&row), "README lacks the row {row}");
        let help = chasles::repl::help::help(d.name, &Default::default()).unwrap();
        assert!(
            help.contains(&format!("unlike the book's Python library: {}", d.text)),
            "{help}"
        );
    }
    // the book's own note (§3.6): MatrixLog3 returns exponential coordinates
    let help = chasles::repl::help::help("MatrixLog3", &Default::default()).unwrap();
    assert!(help.contains("Python returns the so(3) matrix"), "{help}");
}
