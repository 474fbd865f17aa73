//! The reference that ships with the code: `docs/builtins.md` is what the
//! builtin table generates (rewrite it with `UPDATE_DOCS=1 cargo test
//! --test docs`), the README, docs/ and examples/README.md link only files
//! of the repository and cite the language reference by its name here
//! (`docs/language.md`, not the contract's `LANGUAGE.md`), and
//! examples/README.md lists every example script.

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
    let mut files = vec![root().join("README.md"), root().join("examples/README.md")];
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

/// The user's documents, and what `:help` shows (the builtin table), name
/// the language reference as it is in a clone: `docs/language.md`.
#[test]
fn the_language_reference_is_cited_by_its_file() {
    let mut texts = vec![(
        "docs/builtins.md (generated)".to_string(),
        builtins_markdown(),
    )];
    for f in [
        "README.md",
        "examples/README.md",
        "docs/language.md",
        "docs/builtins.md",
    ] {
        texts.push((
            f.to_string(),
            std::fs::read_to_string(root().join(f)).expect(f),
        ));
    }
    for (name, text) in texts {
        for (n, line) in text.lines().enumerate() {
            assert!(
                !line.contains("LANGUAGE.md"),
                "{name}:{}: cites LANGUAGE.md, which is docs/language.md in this repository: {line}",
                n + 1
            );
        }
    }
}

/// examples/README.md lists every script of examples/ (as `NAME.chs`), and
/// only scripts that exist.
#[test]
fn every_example_is_listed() {
    let readme = std::fs::read_to_string(root().join("examples/README.md")).expect("readable");
    let mut scripts = Vec::new();
    for e in std::fs::read_dir(root().join("examples")).expect("examples/") {
        let p = e.expect("an entry").path();
        if p.extension().is_some_and(|x| x == "chs") {
            scripts.push(p.file_name().unwrap().to_string_lossy().into_owned());
        }
    }
    assert!(scripts.len() > 40, "{scripts:?}");
    let missing: Vec<&String> = scripts
        .iter()
        .filter(|s| !readme.contains(&format!("`{s}`")))
        .collect();
    assert!(
        missing.is_empty(),
        "examples/README.md does not list {missing:?}"
    );
    for (i, _) in readme.match_indices(".chs`") {
        let start = readme[..i].rfind('`').expect("an opening backquote") + 1;
        let name = format!("{}.chs", &readme[start..i]);
        assert!(
            name.contains(' ') || scripts.contains(&name),
            "examples/README.md lists {name}, which is not in examples/"
        );
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
