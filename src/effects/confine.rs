//! `--write-dir DIR`: every name a script or command asks to write is
//! resolved inside DIR. Absolute names and `..` are refused as written;
//! symbolic links are followed only as far as the folder the file goes in,
//! whose real path (canonical, after every link) must still lie inside
//! DIR's real path; a link as the file itself is refused. The file is then
//! written under that real folder, so the check and the write name the
//! same place.

use std::path::{Component, Path, PathBuf};

/// The folder writes are confined to.
#[derive(Debug, Clone)]
pub struct Root {
    /// DIR's canonical path (every link resolved).
    real: PathBuf,
    /// DIR as given on the command line, for messages and printed names.
    shown: PathBuf,
}

/// A path as shown to the user: `./` dropped, control characters escaped.
pub fn show(p: &Path) -> String {
    let s = p.to_string_lossy();
    crate::diagnostics::escape::controls(s.strip_prefix("./").unwrap_or(&s)).into_owned()
}

impl Root {
    /// DIR, created when missing; Err is the message for exit code 2.
    pub fn new(dir: &Path) -> Result<Root, String> {
        let fail = |e: std::io::Error| {
            format!(
                "cannot use --write-dir '{}': {}",
                show(dir),
                super::atomic::reason(&e)
            )
        };
        std::fs::create_dir_all(dir).map_err(fail)?;
        let real = std::fs::canonicalize(dir).map_err(fail)?;
        Ok(Root {
            real,
            shown: dir.to_path_buf(),
        })
    }

    /// DIR as given.
    pub fn shown(&self) -> &Path {
        &self.shown
    }

    /// Checks a name against the two rules that need no file system: not
    /// absolute, no `..`.
    fn relative<'a>(&self, name: &'a Path) -> Result<&'a Path, String> {
        let refuse = |why: &str| {
            Err(format!(
                "cannot write '{}': writes are confined to '{}' (--write-dir), and {why}",
                show(name),
                show(&self.shown)
            ))
        };
        if name.as_os_str().is_empty() {
            return refuse("an empty name is no file");
        }
        for c in name.components() {
            match c {
                Component::Prefix(_) | Component::RootDir => {
                    return refuse("an absolute path leads out of it");
                }
                Component::ParentDir => return refuse("'..' leads out of it"),
                Component::CurDir | Component::Normal(_) => {}
            }
        }
        Ok(name)
    }

    /// The folder `sub` inside DIR (for `--draw-dir`), created when
    /// missing; Err is the message for exit code 2.
    pub fn folder(&self, sub: &Path) -> Result<PathBuf, String> {
        let fail = |m: String| format!("cannot use --draw-dir '{}': {m}", show(sub));
        let sub = self.relative(sub).map_err(|_| {
            fail(format!(
                "with --write-dir it is a folder inside '{}' (no absolute path, no '..')",
                show(&self.shown)
            ))
        })?;
        let full = self.real.join(sub);
        std::fs::create_dir_all(&full).map_err(|e| fail(super::atomic::reason(&e)))?;
        let real = std::fs::canonicalize(&full).map_err(|e| fail(super::atomic::reason(&e)))?;
        if !real.starts_with(&self.real) {
            return Err(fail(format!(
                "it leads out of '{}' through a symbolic link",
                show(&self.shown)
            )));
        }
        Ok(sub.to_path_buf())
    }

    /// Where a file the front end keeps for itself (the REPL's history,
    /// LANGUAGE.md §11) may be written: a relative `path` inside DIR, an
    /// absolute one only where its folder already lies inside DIR's real
    /// path. Err when it would lead out.
    pub fn inside(&self, path: &Path) -> Result<PathBuf, String> {
        let name = if path.is_absolute() {
            let outside = || format!("'{}' is not inside '{}'", show(path), show(&self.shown));
            let folder = path.parent().ok_or_else(outside)?;
            let real = std::fs::canonicalize(folder).map_err(|_| outside())?;
            let sub = real.strip_prefix(&self.real).map_err(|_| outside())?;
            sub.join(path.file_name().ok_or_else(outside)?)
        } else {
            path.to_path_buf()
        };
        if let Some(sub) = name.parent().filter(|s| !s.as_os_str().is_empty()) {
            self.folder(sub)?;
        }
        self.resolve(Path::new(""), &name).map(|(real, _)| real)
    }

    /// Where `name` (inside the folder `sub` of DIR) is written: its real
    /// path, and the path to show (DIR as given, then `sub`, then `name`).
    pub fn resolve(&self, sub: &Path, name: &Path) -> Result<(PathBuf, String), String> {
        let name = self.relative(name)?;
        let inner = sub.join(name);
        let full = self.real.join(&inner);
        let shown = show(&self.shown.join(&inner));
        let file = match full.file_name() {
            Some(f) if name.file_name().is_some() => f.to_owned(),
            _ => return Err(format!("cannot write '{shown}': it is no file name")),
        };
        let parent = full.parent().unwrap_or(&self.real);
        let real_parent = std::fs::canonicalize(parent)
            .map_err(|e| format!("cannot write '{shown}': {}", super::atomic::reason(&e)))?;
        if !real_parent.starts_with(&self.real) {
            return Err(format!(
                "cannot write '{shown}': it leads out of '{}' through a symbolic link (--write-dir)",
                show(&self.shown)
            ));
        }
        let real = real_parent.join(file);
        if std::fs::symlink_metadata(&real).is_ok_and(|m| m.file_type().is_symlink()) {
            return Err(format!(
                "cannot write '{shown}': it is a symbolic link, and writes under --write-dir neither follow nor replace links"
            ));
        }
        Ok((real, shown))
    }
}
