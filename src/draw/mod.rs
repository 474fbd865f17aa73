//! Pictures (LANGUAGE.md §12): what `draw` makes, as the book's figures
//! draw it. [`marks`] turns the values of a [`Picture`] into marks in the
//! reference frame (frames, screw axes, arrows, points), [`render`]
//! projects and lays them out as SVG through plotters, and `file` turns
//! them into SVG or PNG bytes (rendered by resvg) — which only the effects
//! gate (`crate::effects`) writes to a file. This module reads the value
//! types of [`crate::eval`] and the core of [`crate::lie`]; only the session
//! and the front ends use it, never the layers below.

mod clear;
pub mod file;
mod layout;
pub mod marks;
pub mod render;

use std::rc::Rc;

use crate::values::value::Picture;
pub use render::{AXIS_RGB, PANEL_H, PANEL_W, Probe, REF_RGB};

/// The scenes of a picture (one per panel) and what it shows, or why it
/// cannot be drawn.
pub fn scenes(p: &Picture) -> Result<(Vec<marks::Scene>, String), String> {
    let scenes = p
        .panels
        .iter()
        .map(marks::scene)
        .collect::<Result<Vec<_>, _>>()?;
    let summary = marks::summary(&scenes);
    Ok((scenes, summary))
}

/// The SVG text of a picture and the pixels where axis colours must show.
pub fn svg(p: &Picture) -> Result<(String, Vec<Probe>), String> {
    let (scenes, _) = scenes(p)?;
    let (svg, probes) = render::svg(&scenes)?;
    Ok((file::marked(svg), probes))
}

/// The picture with its summary filled in (checks that it can be drawn).
pub fn described(p: &Rc<Picture>) -> Result<Rc<Picture>, String> {
    if p.is_view_only() {
        return Ok(p.clone());
    }
    let (_, summary) = scenes(p)?;
    let mut q = (**p).clone();
    q.summary = summary;
    Ok(Rc::new(q))
}
