//! Pictures as file contents: SVG as drawn, PNG rendered from the SVG by
//! resvg (with the system's fonts for the labels). The file itself is
//! written by the effects gate (`crate::effects`), atomically.

use crate::values::value::Picture;

/// SVG or PNG, by the file name's ending.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// A `.svg` file: the picture as drawn, vector graphics.
    Svg,
    /// A `.png` file: the SVG rendered to pixels.
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

/// The bytes of `p` as the file `name` asks for: SVG as drawn, or PNG.
/// Writing them is the effects gate's work (`crate::effects`), never this
/// layer's.
pub fn bytes(p: &Picture, name: &str) -> Result<Vec<u8>, String> {
    let format = format_of(name)?;
    let (svg, _) = super::svg(p)?;
    Ok(match format {
        Format::Svg => svg.into_bytes(),
        Format::Png => png(&svg)?,
    })
}

/// The comment an SVG file chasles writes carries after its `<svg …>` tag:
/// how the effects gate knows a printed picture of an earlier run (which
/// a rerun replaces) from a file of the user's (which it never replaces).
pub const MARK: &str = "<!-- drawn by chasles -->";

/// The SVG text with [`MARK`] after its opening tag.
pub(super) fn marked(mut svg: String) -> String {
    if let Some(end) = svg.find('>') {
        svg.insert_str(end + 1, &format!("\n{MARK}"));
    }
    svg
}

/// Whether `head` (the start of a file) is an SVG chasles wrote.
pub fn is_marked(head: &[u8]) -> bool {
    head.windows(MARK.len()).any(|w| w == MARK.as_bytes())
}
