//! Projection, layout and SVG: an orthographic view from azimuth and
//! elevation in MATLAB's convention (`view(az, el)`; the default looks from
//! the +x, +y side so that x̂ points out of the page to the lower left, ŷ to
//! the right and ẑ up, as the book draws its frames), the scene fitted with
//! a margin, a light grid on the reference frame's xy-plane, marks drawn
//! far to near, and labels placed where they cover no other label, frame
//! origin or axis tip. Drawing goes through plotters' SVG backend, whose
//! integer pixel coordinates make the bytes deterministic.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::clear::Clear;
use super::layout::{Layout, PATH_RGB, Prim, TEXT_RGB, layout};
use super::marks::{P3, Scene};

/// The width of one panel in pixels (panels stand side by side).
pub const PANEL_W: u32 = 560;
/// The height of a picture in pixels.
pub const PANEL_H: u32 = 480;
const MARGIN: f64 = 40.0;
const TITLE_H: f64 = 26.0;
const FONT: f64 = 15.0;

/// The axis colours: x̂ red, ŷ green, ẑ blue.
pub const AXIS_RGB: [(u8, u8, u8); 3] = [(220, 30, 30), (20, 150, 40), (30, 70, 220)];
/// The reference frame's axes: the same hues, lighter.
pub const REF_RGB: [(u8, u8, u8); 3] = [(240, 140, 140), (130, 205, 140), (140, 165, 240)];
const GRID_RGB: (u8, u8, u8) = (226, 226, 226);

/// The default view (MATLAB's azimuth and elevation, radians).
pub const DEFAULT_VIEW: (f64, f64) = (
    120.0 * std::f64::consts::PI / 180.0,
    25.0 * std::f64::consts::PI / 180.0,
);

fn rgb(c: (u8, u8, u8)) -> RGBColor {
    RGBColor(c.0, c.1, c.2)
}

/// Screen axes of an orthographic camera.
struct Camera {
    right: P3,
    up: P3,
    toward: P3,
}

fn camera(scene: &Scene) -> Camera {
    if scene.planar && scene.view.is_none() {
        return Camera {
            right: P3::x(),
            up: P3::y(),
            toward: P3::z(),
        };
    }
    let (az, el) = scene.view.unwrap_or(DEFAULT_VIEW);
    let toward = P3::new(el.cos() * az.sin(), -el.cos() * az.cos(), el.sin());
    let right = P3::new(az.cos(), az.sin(), 0.0);
    let up = toward.cross(&right);
    Camera { right, up, toward }
}

/// A pixel where a colour must show: on an axis near a frame's origin or
/// near its tip (what the tests check in the rendered picture).
#[derive(Debug, Clone, PartialEq)]
pub struct Probe {
    /// Pixel column, from the picture's left edge.
    pub x: f64,
    /// Pixel row, from the top.
    pub y: f64,
    /// The axis colour that must show there.
    pub rgb: (u8, u8, u8),
    /// Which axis and where, for messages: `{a} x axis near its tip`.
    pub what: String,
}

/// Maps reference coordinates to the pixels of one panel.
struct Fit {
    cam: Camera,
    scale: f64,
    cu: f64,
    cv: f64,
    ox: f64,
    oy: f64,
}

impl Fit {
    fn px(&self, p: &P3) -> (f64, f64) {
        let u = p.dot(&self.cam.right);
        let v = p.dot(&self.cam.up);
        (
            self.ox + (u - self.cu) * self.scale,
            self.oy - (v - self.cv) * self.scale,
        )
    }
    fn depth(&self, p: &P3) -> f64 {
        p.dot(&self.cam.toward)
    }
}

fn fit(scene: &Scene, lay: &Layout, x0: f64, titled: bool) -> Fit {
    let cam = camera(scene);
    let mut pts: Vec<P3> = Vec::new();
    for p in &lay.prims {
        match p {
            Prim::Seg { a, b, .. } => pts.extend([*a, *b]),
            Prim::Head { tip, .. } => pts.push(*tip),
            Prim::Dot { at, .. } => pts.push(*at),
        }
    }
    for (a, b) in &lay.grid {
        pts.extend([*a, *b]);
    }
    for (a, b) in &lay.path {
        pts.extend([*a, *b]);
    }
    let (mut u0, mut u1, mut v0, mut v1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in &pts {
        let (u, v) = (p.dot(&cam.right), p.dot(&cam.up));
        u0 = u0.min(u);
        u1 = u1.max(u);
        v0 = v0.min(v);
        v1 = v1.max(v);
    }
    let top = if titled { TITLE_H } else { 0.0 };
    let w = f64::from(PANEL_W) - 2.0 * MARGIN;
    let h = f64::from(PANEL_H) - 2.0 * MARGIN - top;
    let scale = (w / (u1 - u0).max(1e-9)).min(h / (v1 - v0).max(1e-9));
    Fit {
        cam,
        scale,
        cu: (u0 + u1) / 2.0,
        cv: (v0 + v1) / 2.0,
        ox: x0 + f64::from(PANEL_W) / 2.0,
        oy: top + MARGIN + h / 2.0,
    }
}

type Area<'a> = DrawingArea<SVGBackend<'a>, plotters::coord::Shift>;

fn pt(p: (f64, f64)) -> (i32, i32) {
    (p.0.round() as i32, p.1.round() as i32)
}

fn text_width(text: &str) -> f64 {
    text.chars().count() as f64 * FONT * 0.6
}

/// Draws one panel starting at pixel column `x0`; returns its probes.
fn panel(area: &Area<'_>, scene: &Scene, x0: f64) -> Result<Vec<Probe>, String> {
    let lay = layout(scene);
    let fit = fit(scene, &lay, x0, scene.title.is_some());
    let err = |e: DrawingAreaErrorKind<_>| format!("drawing failed: {e}");
    let style = |c: (u8, u8, u8), w: u32| ShapeStyle {
        color: rgb(c).to_rgba(),
        filled: false,
        stroke_width: w,
    };
    for (a, b) in &lay.grid {
        area.draw(&PathElement::new(
            vec![pt(fit.px(a)), pt(fit.px(b))],
            style(GRID_RGB, 1),
        ))
        .map_err(err)?;
    }
    // The path of a list of frames, under the marks.
    for (a, b) in &lay.path {
        area.draw(&PathElement::new(
            vec![pt(fit.px(a)), pt(fit.px(b))],
            style(PATH_RGB, 1),
        ))
        .map_err(err)?;
    }
    // Far to near.
    let mut order: Vec<(f64, usize)> = lay
        .prims
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let d = match p {
                Prim::Seg { a, b, .. } => fit.depth(&((a + b) / 2.0)),
                Prim::Head { tip, .. } => fit.depth(tip),
                Prim::Dot { at, .. } => fit.depth(at),
            };
            (d, i)
        })
        .collect();
    order.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
    let mut dots_seen = std::collections::HashSet::new();
    for (_, i) in order {
        match &lay.prims[i] {
            Prim::Seg {
                a,
                b,
                rgb: c,
                width,
            } => {
                area.draw(&PathElement::new(
                    vec![pt(fit.px(a)), pt(fit.px(b))],
                    style(*c, *width),
                ))
                .map_err(err)?;
            }
            Prim::Head { tip, from, rgb: c } => {
                let (tx, ty) = fit.px(tip);
                let (fx, fy) = fit.px(from);
                let (dx, dy) = (tx - fx, ty - fy);
                let n = dx.hypot(dy);
                if n > 4.0 {
                    let (ux, uy) = (dx / n, dy / n);
                    let (bx, by) = (tx - 12.0 * ux, ty - 12.0 * uy);
                    let tri = vec![
                        pt((tx, ty)),
                        pt((bx - 5.0 * uy, by + 5.0 * ux)),
                        pt((bx + 5.0 * uy, by - 5.0 * ux)),
                    ];
                    area.draw(&Polygon::new(tri, rgb(*c).filled()))
                        .map_err(err)?;
                }
            }
            Prim::Dot { at, rgb: c, r } => {
                let p = pt(fit.px(at));
                // Points that land on the same pixel are drawn once.
                if dots_seen.insert((p, *r)) {
                    area.draw(&Circle::new(p, *r as i32, rgb(*c).filled()))
                        .map_err(err)?;
                }
            }
        }
    }
    // Probes: near each frame's origin and tip on every axis long enough.
    // What labels keep clear of is indexed by cells of the panel (linear
    // time in the number of marks).
    let mut probes = Vec::new();
    let mut clear = Clear::new((x0, 0.0, x0 + f64::from(PANEL_W), f64::from(PANEL_H)));
    let n_axes = if scene.planar { 2 } else { 3 };
    for (o, axes, reference, label) in &lay.frames {
        let po = fit.px(o);
        clear.point(po);
        for (j, a) in axes.iter().enumerate().take(n_axes) {
            let pa = fit.px(&(o + a));
            clear.point(pa);
            let len = (pa.0 - po.0).hypot(pa.1 - po.1);
            if len < 12.0 {
                continue;
            }
            let name = if *reference {
                "reference".to_string()
            } else {
                label.clone()
            };
            for (t, at) in [(0.15, "origin"), (0.85, "tip")] {
                let p = Probe {
                    x: po.0 + t * (pa.0 - po.0),
                    y: po.1 + t * (pa.1 - po.1),
                    rgb: if *reference { REF_RGB[j] } else { AXIS_RGB[j] },
                    what: format!("{name} {} axis near its {at}", ["x", "y", "z"][j]),
                };
                clear.point((p.x, p.y));
                probes.push(p);
            }
        }
    }
    // Labels: the first place that covers no earlier label, origin or tip,
    // nor (where one is free) any line drawn.
    for p in &lay.prims {
        if let Prim::Seg { a, b, .. } = p {
            clear.line(fit.px(a), fit.px(b));
        }
    }
    for l in &lay.labels {
        if crate::budget::stopped() {
            return Err("stopped by the evaluation budget".into());
        }
        let (ax, ay) = fit.px(&l.at);
        let w = text_width(&l.text);
        let h = FONT;
        let mut chosen = None;
        'search: for strict in [true, false] {
            for ring in [1.0, 2.0, 3.5] {
                let g = 8.0 * ring;
                let spots = [
                    (g, -g - h),
                    (g, g),
                    (-g - w, -g - h),
                    (-g - w, g),
                    (g + 2.0, -h / 2.0),
                    (-g - 2.0 - w, -h / 2.0),
                    (-w / 2.0, -g - 4.0 - h),
                    (-w / 2.0, g + 4.0),
                ];
                for (dx, dy) in spots {
                    let b = (ax + dx, ay + dy, ax + dx + w, ay + dy + h);
                    let inside = b.0 >= x0 + 2.0
                        && b.2 <= x0 + f64::from(PANEL_W) - 2.0
                        && b.1 >= 2.0
                        && b.3 <= f64::from(PANEL_H) - 2.0;
                    if inside && clear.is_free(b, strict) {
                        chosen = Some(b);
                        break 'search;
                    }
                }
            }
        }
        let Some(b) = chosen else { continue };
        clear.label(b);
        let font = ("sans-serif", FONT)
            .into_font()
            .color(&rgb(l.rgb))
            .pos(Pos::new(HPos::Left, VPos::Top));
        area.draw(&Text::new(l.text.clone(), pt((b.0, b.1)), font))
            .map_err(err)?;
    }
    if let Some(t) = &scene.title {
        let font = ("sans-serif", FONT + 1.0)
            .into_font()
            .color(&rgb(TEXT_RGB))
            .pos(Pos::new(HPos::Center, VPos::Top));
        area.draw(&Text::new(
            t.clone(),
            pt((x0 + f64::from(PANEL_W) / 2.0, 8.0)),
            font,
        ))
        .map_err(err)?;
    }
    Ok(probes)
}

/// The SVG text of scenes side by side, and the probes of every panel.
pub fn svg(scenes: &[Scene]) -> Result<(String, Vec<Probe>), String> {
    let mut buf = String::new();
    let mut probes = Vec::new();
    {
        let w = PANEL_W * scenes.len().max(1) as u32;
        let root = SVGBackend::with_string(&mut buf, (w, PANEL_H)).into_drawing_area();
        root.fill(&WHITE)
            .map_err(|e| format!("drawing failed: {e}"))?;
        for (i, s) in scenes.iter().enumerate() {
            probes.extend(panel(&root, s, f64::from(PANEL_W) * i as f64)?);
        }
        root.present().map_err(|e| format!("drawing failed: {e}"))?;
    }
    Ok((buf, probes))
}
