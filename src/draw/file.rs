//! Writing pictures: SVG as drawn, PNG rendered from the SVG by resvg (with
//! the system's fonts for the labels); always through a temporary file in
//! the same folder and a rename, so a failed write never leaves a broken
//! file under the name asked for.

use std::io::Write;
use std::path::{Path, PathBuf};

use crate::values::value::Picture;

/// SVG or PNG, by the file name's ending.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Svg,
    Png,
}

/// The format a file name asks for, or why it is not one.
pub fn format_of(name: &str) -> Result<Format, String> {
    let lower = name.to_ascii_lowercase();
    if lower.ends_with(".svg") {
        Ok(Format::Svg)
    } else if lower.ends_with(".png") {
        Ok(Format::Png)
    } else {
        Err(format!(
            "cannot save a picture as '{name}': the name must end in .svg or .png"
        ))
    }
}

/// The PNG bytes of an SVG text.
pub fn png(svg: &str) -> Result<Vec<u8>, String> {
    let mut opt = resvg::usvg::Options::default();
    let db = opt.fontdb_mut();
    db.load_system_fonts();
    // `sans-serif` is whichever sans face the system has (DejaVu Sans here).
    let families: Vec<String> = db
        .faces()
        .flat_map(|f| f.families.iter().map(|(n, _)| n.clone()))
        .collect();
    let sans = ["DejaVu Sans", "Liberation Sans", "Arial", "Helvetica"]
        .iter()
        .find(|want| families.iter().any(|f| f == *want))
        .map(|s| s.to_string())
        .or_else(|| families.iter().find(|f| f.contains("Sans")).cloned());
    if let Some(s) = sans {
        db.set_sans_serif_family(s);
    }
    let tree = resvg::usvg::Tree::from_str(svg, &opt).map_err(|e| format!("cannot render: {e}"))?;
    let size = tree.size().to_int_size();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or("cannot render: empty picture")?;
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::default(),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .map_err(|e| format!("cannot encode PNG: {e}"))
}

fn reason(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such folder".into(),
        std::io::ErrorKind::PermissionDenied => "permission denied".into(),
        _ => e.to_string(),
    }
}

/// Writes `bytes` to `path` atomically (a temporary file, then a rename).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), String> {
    let shown = path.display();
    if path.is_dir() {
        return Err(format!("cannot write '{shown}': it is a folder"));
    }
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_default();
    let tmp = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let result = std::fs::File::create(&tmp)
        .and_then(|mut f| {
            f.write_all(bytes)?;
            f.sync_all()
        })
        .and_then(|()| std::fs::rename(&tmp, path));
    if let Err(e) = result {
        let _ = std::fs::remove_file(&tmp);
        return Err(format!("cannot write '{shown}': {}", reason(&e)));
    }
    Ok(())
}

/// Draws `p` and writes it to `path` as SVG or PNG.
pub fn write(p: &Picture, path: &Path) -> Result<(), String> {
    let format = format_of(&path.to_string_lossy())?;
    let (svg, _) = super::svg(p)?;
    let bytes = match format {
        Format::Svg => svg.into_bytes(),
        Format::Png => png(&svg)?,
    };
    write_atomic(path, &bytes)
}
