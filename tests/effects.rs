//! The effects gate (issue 23, LANGUAGE.md §§1, 11, 12): evaluation asks,
//! the front end writes. `--no-write` skips every write (a warning), `--write-dir`
//! confines them (absolute paths, `..` and links leading out are refused),
//! and the REPL's live preview writes nothing, whatever is typed.

use std::path::Path;

use chasles::effects::Gate;
use chasles::repl::commands::execute;
use chasles::repl::complete::{hint, preview};
use chasles::session::{Session, Settings};

mod common;
use common::{run_in, scratch};

/// Every file under `dir`, as paths relative to it, sorted.
fn files(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).expect("lists").flatten() {
            let p = e.path();
            if e.file_type().is_ok_and(|t| t.is_dir()) {
                todo.push(p.clone());
            }
            out.push(p.strip_prefix(dir).unwrap().to_string_lossy().into_owned());
        }
    }
    out.sort();
    out
}

#[test]
fn no_write_skips_every_write_with_a_warning_and_goes_on() {
    let dir = scratch("no-write");
    for (src, name) in [
        ("save(draw(Rotz(1)), \"keep.svg\")", "keep.svg"),
        ("draw(Rotz(1))", "draw-1.svg"),
        ("pic = draw(Rotz(1))", "pic.svg"),
        ("save(draw(Rotz(1)), \"k.png\")", "k.png"),
    ] {
        // The script goes on past the skipped write (LANGUAGE.md §1).
        let (code, out, err) = run_in(&["--no-write", "-e", &format!("{src}\n1 + 1")], &dir);
        assert_eq!(code, 0, "{src}: {out}{err}");
        assert!(out.ends_with("2\n"), "{src}: {out}");
        assert!(
            err.contains(&format!(
                "<-e>:1:1: warning: '{name}' not written: writing files is turned off (--no-write)"
            )),
            "{src}: {err}"
        );
        assert!(!err.contains("error"), "{src}: {err}");
        // JSON: the picture, with no file.
        let (code, out, _) = run_in(&["--no-write", "--json", "-e", src], &dir);
        assert_eq!(code, 0);
        assert!(out.contains("\"file\":null"), "{out}");
    }
    // Values that are no pictures print as before.
    let (code, out, _) = run_in(&["--no-write", "-e", "x = 2 + 2"], &dir);
    assert_eq!((code, out.as_str()), (0, "x = 4\n"));
    // --no-write with a folder to write into is bad usage.
    for flag in ["--write-dir", "--draw-dir"] {
        let (code, _, err) = run_in(&["--no-write", flag, "out", "-e", "1"], &dir);
        assert_eq!(code, 2, "{err}");
        assert!(err.contains("cannot be used with"), "{err}");
    }
    assert!(files(&dir).is_empty(), "{:?}", files(&dir));
}

#[test]
fn write_dir_confines_every_write_and_refuses_escapes() {
    let dir = scratch("write-dir");
    let outside = scratch("write-dir-outside");
    let jail = dir.join("jail");
    std::fs::create_dir_all(jail.join("sub")).unwrap();
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(&outside, jail.join("out")).unwrap();
        std::os::unix::fs::symlink(jail.join("sub"), jail.join("in")).unwrap();
        std::os::unix::fs::symlink(outside.join("t.svg"), jail.join("t.svg")).unwrap();
    }
    let abs = outside.join("abs.svg");
    let cases: Vec<(String, String)> = vec![
        ("../x.svg".into(), "'..' leads out of it".into()),
        ("sub/../../x.svg".into(), "'..' leads out of it".into()),
        (
            abs.display().to_string(),
            "an absolute path leads out of it".into(),
        ),
        #[cfg(unix)]
        (
            "out/x.svg".into(),
            "leads out of 'jail' through a symbolic link".into(),
        ),
        #[cfg(unix)]
        ("out/../x.svg".into(), "'..' leads out of it".into()),
        #[cfg(unix)]
        ("t.svg".into(), "is a symbolic link".into()),
        ("nope/x.svg".into(), "no such folder".into()),
    ];
    for (name, why) in &cases {
        let src = format!("save(draw(Rotz(1)), \"{name}\")");
        let (code, out, err) = run_in(&["--write-dir", "jail", "-e", &src], &dir);
        assert_eq!(code, 1, "{name}: {out}{err}");
        assert!(err.contains(why), "{name}: {err}");
        assert!(err.contains("cannot write '"), "{name}: {err}");
    }
    assert!(files(&outside).is_empty(), "{:?}", files(&outside));
    assert!(!dir.join("x.svg").exists());

    // What stays inside is written, named as DIR/…; printed pictures go
    // into DIR too, and --draw-dir is a folder inside it.
    let src =
        "pic = draw(Rotz(1))\nsave(pic, \"sub/a.svg\")\nsave(pic, \"in/b.svg\")\ndraw(Rotx(1))";
    let (code, out, err) = run_in(&["--write-dir", "jail", "-e", src], &dir);
    assert_eq!(code, 0, "{err}");
    for shown in [
        "→ jail/pic.svg",
        "→ jail/sub/a.svg",
        "→ jail/in/b.svg",
        "→ jail/draw-4.svg",
    ] {
        assert!(out.contains(shown), "{shown}: {out}");
    }
    let (code, out, err) = run_in(
        &[
            "--write-dir",
            "jail",
            "--draw-dir",
            "figs",
            "-e",
            "q = draw(Rotz(1))",
        ],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("→ jail/figs/q.svg"), "{out}");
    let inside = files(&jail);
    for f in [
        "pic.svg",
        "sub/a.svg",
        "sub/b.svg",
        "draw-4.svg",
        "figs/q.svg",
    ] {
        assert!(inside.contains(&f.to_string()), "{f}: {inside:?}");
    }
    // A --draw-dir leading out of the write dir is bad usage.
    for d in ["../figs", "/tmp", "out"] {
        let (code, _, err) = run_in(&["--write-dir", "jail", "--draw-dir", d, "-e", "1"], &dir);
        assert_eq!(code, 2, "{d}: {err}");
        assert!(err.contains("cannot use --draw-dir"), "{d}: {err}");
    }
    assert!(files(&outside).is_empty(), "{:?}", files(&outside));
    // The write dir is created when missing.
    let (code, _, err) = run_in(&["--write-dir", "new/deep", "-e", "draw(Rotz(1))"], &dir);
    assert_eq!(code, 0, "{err}");
    assert!(dir.join("new/deep/draw-1.svg").is_file());
}

#[test]
fn repl_save_goes_through_the_gate() {
    let dir = scratch("repl-save");
    let mut s = Session::new(Settings::default());
    s.gate = Gate::deny();
    execute(&mut s, "x = 1");
    let r = execute(&mut s, &format!(":save {}", dir.join("s.chs").display()));
    assert!(
        r.err.contains("writing files is turned off (--no-write)"),
        "{r:?}"
    );
    s.gate = Gate::within(&dir, None).unwrap();
    let r = execute(&mut s, ":save ../s.chs");
    assert!(r.err.contains("'..' leads out of it"), "{r:?}");
    let r = execute(&mut s, ":save s.chs");
    assert_eq!(r.out, "saved 1 statement to s.chs\n", "{r:?}");
    assert!(dir.join("s.chs").is_file());
    let r = execute(&mut s, ":save s.chs");
    assert!(
        r.err.contains("exists; :save! s.chs overwrites it"),
        "{r:?}"
    );
    assert!(execute(&mut s, ":save! s.chs").err.is_empty());
    // Pictures printed in the REPL go into the write dir, and :open knows.
    let r = execute(&mut s, "pic = draw(Rotz(1))");
    assert!(r.out.contains("→ "), "{r:?}");
    assert!(dir.join("pic.svg").is_file());
    assert_eq!(files(&dir), ["pic.svg", "s.chs"]);
}

#[test]
fn the_live_preview_writes_nothing() {
    let dir = scratch("preview");
    let mut s = Session::new(Settings::default());
    // The session itself would write pictures into `dir`.
    s.gate = Gate::anywhere(Some(dir.clone()));
    execute(&mut s, "T = Rotz(1)");
    let lines = [
        format!("save(draw(Rotz(1)), \"{}\")", dir.join("x.svg").display()),
        format!("save(draw(T), \"{}\")", dir.join("a.svg.svg").display()),
        format!("pic = save(draw(T), \"{}\")", dir.join("p.png").display()),
        "draw(Rotz(1))".to_string(),
        "pic = draw(Rotz(1))".to_string(),
    ];
    for line in &lines {
        // Every prefix, as it is typed.
        for (i, _) in line.char_indices().skip(1).chain([(line.len(), ' ')]) {
            let typed = &line[..i];
            let _ = preview(&s, typed);
            let _ = hint(&s, typed, typed.len());
        }
    }
    assert!(
        files(&dir).is_empty(),
        "the preview wrote {:?}",
        files(&dir)
    );
    // Enter runs it, and then it is written.
    execute(&mut s, &lines[0]);
    assert_eq!(files(&dir), ["x.svg"]);
}

#[test]
fn a_file_name_of_250_bytes_is_saved() {
    let dir = scratch("long-name");
    let name = format!("{}.svg", "n".repeat(246));
    assert_eq!(name.len(), 250);
    let src = format!("save(draw(Rotz(1)), \"{name}\")");
    let (code, out, err) = run_in(&["-e", &src], &dir);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains(&name), "{out}");
    assert_eq!(files(&dir), [name]);
    // Too long for the file system: a clear error, no panic.
    let src = format!("save(draw(Rotz(1)), \"{}.svg\")", "n".repeat(300));
    let (code, _, err) = run_in(&["-e", &src], &dir);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("domain error: cannot write"), "{err}");
}

/// The REPL's history is a write like any other (§§1, 11): none under
/// `--no-write`; under `--write-dir` only a file inside DIR (a relative
/// name is taken inside it); anywhere otherwise.
#[test]
fn history_is_kept_only_where_the_gate_allows() {
    let dir = scratch("history");
    let outside = scratch("history-outside").join("history.txt");
    assert_eq!(Gate::deny().history(&outside), None);
    assert_eq!(
        Gate::anywhere(Some(".".into())).history(&outside),
        Some(outside.clone())
    );
    let within = Gate::within(&dir, None).expect("a folder");
    let real = std::fs::canonicalize(&dir).expect("exists");
    assert_eq!(within.history(&outside), None);
    assert_eq!(within.history(std::path::Path::new("../h.txt")), None);
    assert_eq!(within.history(&dir.join("h.txt")), Some(real.join("h.txt")));
    assert_eq!(
        within.history(std::path::Path::new("sub/h.txt")),
        Some(real.join("sub").join("h.txt"))
    );
    assert!(real.join("sub").is_dir(), "its folder is made inside DIR");
}
