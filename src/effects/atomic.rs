//! Writing one file atomically: the bytes go to a temporary file in the
//! same folder (a short name, `.chs<pid>-<n>.tmp`, so that any legal file
//! name can be written beside it; created exclusively, so it never follows
//! a link or clobbers another writer), are synced, and the temporary file
//! is then renamed over the name asked for — or, when overwriting is not
//! allowed, hard-linked to it, which fails if the name exists. A reader, a
//! parallel run or `kill -9` never sees half a file.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Why a write failed, in words for a message.
pub fn reason(e: &std::io::Error) -> String {
    use std::io::ErrorKind as K;
    match e.kind() {
        K::NotFound => "no such folder".into(),
        K::PermissionDenied => "permission denied".into(),
        K::AlreadyExists => "it exists".into(),
        K::IsADirectory => "it is a folder".into(),
        _ => e.to_string(),
    }
}

/// A fresh temporary name in `dir`, unique in this process (a counter) and
/// among processes (the process id).
fn temporary(dir: &Path) -> PathBuf {
    static NEXT: AtomicU64 = AtomicU64::new(0);
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    dir.join(format!(".chs{}-{n}.tmp", std::process::id()))
}

/// Writes `bytes` to `path` through a temporary file; with `overwrite`
/// false an existing `path` is kept and the error's kind is
/// `AlreadyExists`.
pub fn write(path: &Path, bytes: &[u8], overwrite: bool) -> std::io::Result<()> {
    if path.is_dir() {
        return Err(std::io::Error::new(
            std::io::ErrorKind::IsADirectory,
            "it is a folder",
        ));
    }
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    // A name taken by a stray file (or a link) is skipped, not opened.
    let mut attempt = 0;
    let (tmp, mut file) = loop {
        let tmp = temporary(dir);
        match std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&tmp)
        {
            Ok(f) => break (tmp, f),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && attempt < 8 => {
                attempt += 1;
            }
            Err(e) => return Err(e),
        }
    };
    let result = file
        .write_all(bytes)
        .and_then(|()| file.sync_all())
        .and_then(|()| {
            drop(file);
            if overwrite {
                std::fs::rename(&tmp, path)
            } else {
                std::fs::hard_link(&tmp, path)
            }
        });
    // After a rename the temporary name is gone already; after a link (or
    // a failure) it is removed here.
    let _ = std::fs::remove_file(&tmp);
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("chs-atomic-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn writes_replaces_or_keeps_and_leaves_no_temporary_file() {
        let d = dir("basic");
        let f = d.join("a.txt");
        write(&f, b"one", false).unwrap();
        assert_eq!(std::fs::read(&f).unwrap(), b"one");
        let e = write(&f, b"two", false).unwrap_err();
        assert_eq!(e.kind(), std::io::ErrorKind::AlreadyExists);
        assert_eq!(std::fs::read(&f).unwrap(), b"one");
        write(&f, b"three", true).unwrap();
        assert_eq!(std::fs::read(&f).unwrap(), b"three");
        assert_eq!(std::fs::read_dir(&d).unwrap().count(), 1);
        assert_eq!(
            reason(&write(&d, b"x", true).unwrap_err()),
            "it is a folder"
        );
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_name_of_255_bytes_can_be_written() {
        let d = dir("long");
        let name = format!("{}.svg", "n".repeat(251));
        assert_eq!(name.len(), 255);
        write(&d.join(&name), b"<svg/>", false).unwrap();
        assert!(d.join(&name).is_file());
        std::fs::remove_dir_all(&d).unwrap();
    }
}
