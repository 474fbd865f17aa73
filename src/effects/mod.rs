//! The one effects gate. Evaluation never touches the file system: a
//! statement that wants a file written — `save(pic, "f.svg")`, a picture
//! printed but not saved (`NAME.svg`, `draw-LINE.svg`, LANGUAGE.md §12), the
//! REPL's `:save` (§11) — returns an [`Effect`], and the front end's
//! [`Gate`] decides: write it (atomically, [`atomic`]), skip it
//! (`--no-write`: [`Done::Skipped`], a warning naming the file, and the
//! script goes on), confine it to a folder (`--write-dir`, [`confine`]), or
//! keep the picture in memory (a library session, a notebook, the REPL's
//! live preview, which never even asks the gate).
//!
//! A front end sets [`crate::session::Session::gate`] once; `Session::run`
//! then settles each statement's effects before its report is seen (a
//! written picture says where, `→ pic.svg`; a skipped write is the
//! statement's warning; a refused or failed write is its domain error), while `Session::evaluate` performs none.
//! Each report keeps its [`Effect`]s: a notebook, with
//! `Gate::anywhere(None)`, writes what `save` asks and finds every printed
//! picture among them (`PictureTo::Printed`) to show inline, as SVG from
//! `crate::draw::file::bytes(picture, "x.svg")`. The REPL's history file,
//! which the line editor appends itself, is kept only where
//! [`Gate::history`] allows.

pub mod atomic;
pub mod confine;

use std::path::{Path, PathBuf};
use std::rc::Rc;

use crate::values::value::Picture;
pub use confine::show;

/// A file a statement or command wants written.
#[derive(Debug, Clone)]
pub enum Effect {
    /// A picture: drawn as SVG, or rendered to PNG by the name's ending,
    /// only when the gate writes it.
    Picture {
        /// `save`'s name or the printed picture's file.
        to: PictureTo,
        /// The picture to draw.
        picture: Rc<Picture>,
    },
    /// Bytes as they are (the REPL's `:save`); without `overwrite` an
    /// existing file is kept and the write fails.
    Write {
        /// The file asked for (`~/` already expanded).
        path: PathBuf,
        /// The contents.
        bytes: Vec<u8>,
        /// Replace an existing file (`:save!`) rather than fail.
        overwrite: bool,
    },
}

/// Where a picture asks to go.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PictureTo {
    /// `save(pic, NAME)`: NAME as the script wrote it (relative to the
    /// working folder, or to `--write-dir`).
    Saved(PathBuf),
    /// A picture printed but not saved: `NAME.svg` or `draw-LINE.svg` in
    /// the folder for printed pictures.
    Printed(String),
}

impl Effect {
    /// The name asked for, as written.
    pub fn name(&self) -> PathBuf {
        match self {
            Effect::Picture {
                to: PictureTo::Saved(p),
                ..
            }
            | Effect::Write { path: p, .. } => p.clone(),
            Effect::Picture {
                to: PictureTo::Printed(f),
                ..
            } => PathBuf::from(f),
        }
    }
}

/// What a gate allows.
#[derive(Debug, Clone)]
enum Policy {
    /// Anything the user can write, names relative to the working folder.
    Anywhere,
    /// Nothing (`--no-write`): every write skipped with a warning.
    Deny,
    /// Only inside one folder (`--write-dir`).
    Within(confine::Root),
}

/// What happens to pictures.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Pictures {
    /// No picture is written, saved or printed (a library session's
    /// default: its callers take the picture from the value).
    InMemory,
    /// `save` writes; printed pictures stay in memory (a notebook shows
    /// them inline).
    Saved,
    /// `save` writes, and printed pictures go to this folder (`.` or
    /// `--draw-dir`; inside `--write-dir`, relative to it).
    All(PathBuf),
}

/// The front end's decision on every write; see the module's text.
#[derive(Debug, Clone)]
pub struct Gate {
    policy: Policy,
    pictures: Pictures,
}

/// A library session's gate: pictures stay in memory (no file for `save`
/// or a printed picture), other writes (`:save`) go where asked.
impl Default for Gate {
    fn default() -> Gate {
        Gate {
            policy: Policy::Anywhere,
            pictures: Pictures::InMemory,
        }
    }
}

impl Gate {
    /// Writes where asked (names relative to the working folder); printed
    /// pictures into `draw_dir`, or — with `None`, as a notebook wants —
    /// into no file.
    pub fn anywhere(draw_dir: Option<PathBuf>) -> Gate {
        Gate {
            policy: Policy::Anywhere,
            pictures: draw_dir.map_or(Pictures::Saved, Pictures::All),
        }
    }

    /// `--no-write` (LANGUAGE.md §1): every write (`save`, a printed
    /// picture, `:save`) is skipped, [`Done::Skipped`] naming the file, and
    /// the script goes on (a grader's script that draws is not failed).
    pub fn deny() -> Gate {
        Gate {
            policy: Policy::Deny,
            pictures: Pictures::All(PathBuf::from(".")),
        }
    }

    /// `--write-dir DIR` (created when missing): every write inside DIR;
    /// printed pictures in DIR, or in `draw_dir` taken inside DIR.
    /// Err is the message for exit code 2.
    pub fn within(dir: &Path, draw_dir: Option<&Path>) -> Result<Gate, String> {
        let root = confine::Root::new(dir)?;
        let draw = match draw_dir {
            Some(d) => root.folder(d)?,
            None => PathBuf::new(),
        };
        Ok(Gate {
            policy: Policy::Within(root),
            pictures: Pictures::All(draw),
        })
    }

    /// The same policy with printed pictures kept in memory, as a notebook
    /// wants (LANGUAGE.md §13: shown inline, no file unless `save` asks);
    /// `save` still writes, refused or confined as before.
    pub fn printed_in_memory(self) -> Gate {
        Gate {
            pictures: Pictures::Saved,
            ..self
        }
    }

    /// Whether this gate refuses every write (`--no-write`).
    pub fn denies(&self) -> bool {
        matches!(self.policy, Policy::Deny)
    }

    /// Where the REPL may keep its history file `path` (LANGUAGE.md §11):
    /// `None` under `--no-write`, and under `--write-dir` unless the file
    /// lies inside DIR (a relative `path` is taken inside it, as `save`'s
    /// names are). History is a convenience, so a refusal is silent.
    pub fn history(&self, path: &Path) -> Option<PathBuf> {
        match &self.policy {
            Policy::Deny => None,
            Policy::Anywhere => Some(path.to_path_buf()),
            Policy::Within(root) => root.inside(path).ok(),
        }
    }

    /// Performs `effect` if allowed: [`Done`] says whether it was written,
    /// kept in memory or skipped (`--no-write`); Err with the message
    /// (`cannot write 'x.svg': …`) when refused (`--write-dir`) or failed.
    pub fn perform(&self, effect: &Effect) -> Result<Done, WriteError> {
        let (folder, overwrite) = match effect {
            Effect::Picture { to, .. } => match (&self.pictures, to) {
                (Pictures::InMemory, _) | (Pictures::Saved, PictureTo::Printed(_)) => {
                    return Ok(Done::InMemory);
                }
                (Pictures::All(dir), PictureTo::Printed(_)) => (dir.as_path(), true),
                (_, PictureTo::Saved(_)) => (Path::new(""), true),
            },
            Effect::Write { overwrite, .. } => (Path::new(""), *overwrite),
        };
        let name = effect.name();
        let (real, shown) = match &self.policy {
            Policy::Deny => {
                return Ok(Done::Skipped(format!(
                    "'{}' not written: writing files is turned off (--no-write)",
                    show(&folder.join(&name))
                )));
            }
            Policy::Anywhere => {
                let real = folder.join(&name);
                let shown = show(&real);
                (real, shown)
            }
            Policy::Within(root) => root.resolve(folder, &name).map_err(WriteError::Refused)?,
        };
        // A printed picture replaces only a picture chasles printed there
        // before (a rerun); a file of the user's is kept and the picture
        // takes the next free name, `draw-3_2.svg` (issue 36).
        let (real, shown, overwrite) = match effect {
            Effect::Picture {
                to: PictureTo::Printed(_),
                ..
            } if foreign(&real) => self.free_name(folder, &name)?,
            _ => (real, shown, overwrite),
        };
        let bytes = match effect {
            Effect::Picture { picture, .. } => {
                crate::draw::file::bytes(picture, &name.to_string_lossy())
                    .map_err(WriteError::Refused)?
            }
            Effect::Write { bytes, .. } => bytes.clone(),
        };
        match atomic::write(&real, &bytes, overwrite) {
            Ok(()) => Ok(Done::Written(shown)),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
                Err(WriteError::Exists(shown))
            }
            Err(e) => Err(WriteError::Refused(format!(
                "cannot write '{shown}': {}",
                atomic::reason(&e)
            ))),
        }
    }
}

/// What the gate did with an effect it allowed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Done {
    /// Written: the path as shown (`→ pic.svg`).
    Written(String),
    /// Kept in memory (a library session, a notebook's printed picture).
    InMemory,
    /// Skipped under `--no-write`: the warning, naming the file.
    Skipped(String),
}

impl Gate {
    /// The first of `STEM_2.EXT`, `STEM_3.EXT`, … in `folder` that names no
    /// file or a picture chasles printed (a rerun's), where it lies under
    /// this gate's policy: (real path, shown path, whether it replaces).
    fn free_name(&self, folder: &Path, name: &Path) -> Result<(PathBuf, String, bool), WriteError> {
        let stem = name.file_stem().unwrap_or_default().to_string_lossy();
        let ext = name
            .extension()
            .map(|e| format!(".{}", e.to_string_lossy()))
            .unwrap_or_default();
        for k in 2..1000 {
            let other = name.with_file_name(format!("{stem}_{k}{ext}"));
            let (real, shown) = match &self.policy {
                Policy::Within(root) => {
                    root.resolve(folder, &other).map_err(WriteError::Refused)?
                }
                _ => {
                    let real = folder.join(&other);
                    let shown = show(&real);
                    (real, shown)
                }
            };
            if std::fs::symlink_metadata(&real).is_err() {
                return Ok((real, shown, false));
            }
            if !foreign(&real) {
                return Ok((real, shown, true));
            }
        }
        Err(WriteError::Refused(format!(
            "cannot write '{}': it exists, as do 998 other names for it",
            show(&folder.join(name))
        )))
    }
}

/// Whether `path` is taken by something other than an SVG chasles wrote
/// (a file of the user's, a folder, a link): a printed picture must not
/// replace it.
fn foreign(path: &Path) -> bool {
    use std::io::Read;
    let Ok(meta) = std::fs::symlink_metadata(path) else {
        return false;
    };
    if !meta.is_file() {
        return true;
    }
    let mut head = Vec::with_capacity(512);
    let read = std::fs::File::open(path).and_then(|f| f.take(512).read_to_end(&mut head));
    !(read.is_ok() && crate::draw::file::is_marked(&head))
}

/// Why a write did not happen.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum WriteError {
    /// The file exists and overwriting was not asked for (`:save`); the
    /// path shown.
    Exists(String),
    /// Refused by the gate, or failed: the whole message.
    Refused(String),
}

impl std::fmt::Display for WriteError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            WriteError::Exists(p) => write!(f, "cannot write '{p}': it exists"),
            WriteError::Refused(m) => f.write_str(m),
        }
    }
}
