//! The marks of a scene as drawing primitives in reference-frame
//! coordinates: the reference frame at the origin with its axes named,
//! each frame's axes (scaled to the scene), screw axes as lines through q
//! with an arrowhead and the pitch beside them, arrows, dots, and the grid
//! on the reference xy-plane over the scene's footprint.

use super::marks::{Mark, P3, Scene};
use super::render::{AXIS_RGB, REF_RGB};
use crate::values::number::fmt_num;

pub(super) const SCREW_RGB: (u8, u8, u8) = (140, 60, 170);
pub(super) const ARROW_RGB: (u8, u8, u8) = (235, 125, 0);
pub(super) const DOT_RGB: (u8, u8, u8) = (70, 70, 70);
pub(super) const TEXT_RGB: (u8, u8, u8) = (20, 20, 20);
pub(super) const PATH_RGB: (u8, u8, u8) = (175, 175, 175);

/// A primitive in reference-frame coordinates.
pub(super) enum Prim {
    Seg {
        a: P3,
        b: P3,
        rgb: (u8, u8, u8),
        width: u32,
    },
    Head {
        tip: P3,
        from: P3,
        rgb: (u8, u8, u8),
    },
    Dot {
        at: P3,
        rgb: (u8, u8, u8),
        r: u32,
    },
}

pub(super) struct Label {
    /// The point labelled.
    pub at: P3,
    pub text: String,
    pub rgb: (u8, u8, u8),
}

/// A scene laid out: primitives, labels, probes and the projection.
pub(super) struct Layout {
    /// Lines, arrowheads and dots, drawn far to near.
    pub prims: Vec<Prim>,
    /// Labels, placed last.
    pub labels: Vec<Label>,
    /// The grid on the reference xy-plane.
    pub grid: Vec<(P3, P3)>,
    /// The path through a list of frames' origins, drawn under the marks.
    pub path: Vec<(P3, P3)>,
    /// Each frame: origin, scaled axes, whether it is the reference, label.
    pub frames: Vec<(P3, [P3; 3], bool, String)>,
}

fn nice_step(span: f64) -> f64 {
    let raw = (span / 8.0).max(1e-9);
    let p = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * p)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * p)
}

fn pitch_text(h: f64) -> String {
    if h.is_infinite() {
        "h = ∞".into()
    } else {
        format!("h = {}", fmt_num(h, 3))
    }
}

pub(super) fn layout(scene: &Scene) -> Layout {
    // How far from the origin things sit sets the length of the axes
    // (frames at the origin get unit axes, like the vectors beside them).
    let mut extent: f64 = 0.0;
    for m in &scene.marks {
        let p = match m {
            Mark::Frame { origin, .. } => origin,
            Mark::Screw { q, .. } => q,
            Mark::Arrow { from, .. } => from,
            Mark::Dot { at, .. } | Mark::Centre { at, .. } => at,
            Mark::Path { .. } => continue,
        };
        extent = extent.max(p.norm());
    }
    let axis = if extent < 1e-9 {
        1.0
    } else {
        (0.25 * extent).max(0.5 * extent.min(2.0))
    };
    let mut prims = Vec::new();
    let mut labels = Vec::new();
    let mut frames = Vec::new();
    let mut path = Vec::new();
    let planar = scene.planar;
    let n_axes = if planar { 2 } else { 3 };
    // The reference frame at the origin, with its axes named.
    let ref_axes = [P3::x(), P3::y(), P3::z()];
    frames.push((
        P3::zeros(),
        ref_axes,
        true,
        format!("{{{}}}", scene.reference),
    ));
    for (j, name) in ["x", "y", "z"].iter().enumerate().take(n_axes) {
        labels.push(Label {
            at: ref_axes[j] * axis * 1.08,
            text: format!("{name}{}", sub_name(&scene.reference)),
            rgb: REF_RGB[j],
        });
    }
    for m in &scene.marks {
        match m {
            Mark::Frame {
                origin,
                axes,
                label,
            } => {
                frames.push((*origin, *axes, false, label.clone()));
            }
            Mark::Screw { q, s, pitch, label } => {
                let text = if label.is_empty() {
                    pitch_text(*pitch)
                } else {
                    format!("{label}: {}", pitch_text(*pitch))
                };
                if pitch.is_infinite() {
                    let tip = q + s * axis * 2.0;
                    prims.push(Prim::Seg {
                        a: *q,
                        b: tip,
                        rgb: SCREW_RGB,
                        width: 2,
                    });
                    prims.push(Prim::Head {
                        tip,
                        from: *q,
                        rgb: SCREW_RGB,
                    });
                    labels.push(Label {
                        at: tip,
                        text,
                        rgb: SCREW_RGB,
                    });
                } else {
                    let half = 0.6 * extent + axis;
                    let (a, b) = (q - s * half, q + s * half);
                    prims.push(Prim::Seg {
                        a,
                        b,
                        rgb: SCREW_RGB,
                        width: 2,
                    });
                    prims.push(Prim::Head {
                        tip: b,
                        from: a,
                        rgb: SCREW_RGB,
                    });
                    prims.push(Prim::Dot {
                        at: *q,
                        rgb: SCREW_RGB,
                        r: 4,
                    });
                    labels.push(Label {
                        at: b,
                        text,
                        rgb: SCREW_RGB,
                    });
                }
            }
            Mark::Arrow { from, dir, label } => {
                let tip = from + dir;
                prims.push(Prim::Seg {
                    a: *from,
                    b: tip,
                    rgb: ARROW_RGB,
                    width: 2,
                });
                prims.push(Prim::Head {
                    tip,
                    from: *from,
                    rgb: ARROW_RGB,
                });
                if !label.is_empty() {
                    labels.push(Label {
                        at: tip,
                        text: label.clone(),
                        rgb: ARROW_RGB,
                    });
                }
            }
            Mark::Dot { at, label } => {
                prims.push(Prim::Dot {
                    at: *at,
                    rgb: DOT_RGB,
                    r: 2,
                });
                if !label.is_empty() {
                    labels.push(Label {
                        at: *at,
                        text: label.clone(),
                        rgb: DOT_RGB,
                    });
                }
            }
            Mark::Path { points } => {
                path.extend(points.windows(2).map(|w| (w[0], w[1])));
            }
            Mark::Centre { at, label } => {
                prims.push(Prim::Dot {
                    at: *at,
                    rgb: SCREW_RGB,
                    r: 5,
                });
                labels.push(Label {
                    at: *at,
                    text: label.clone(),
                    rgb: SCREW_RGB,
                });
            }
        }
    }
    for (origin, axes, reference, label) in &frames {
        for (j, a) in axes.iter().enumerate().take(n_axes) {
            let (rgb, width) = if *reference {
                (REF_RGB[j], 2)
            } else {
                (AXIS_RGB[j], 3)
            };
            prims.push(Prim::Seg {
                a: *origin,
                b: origin + a * axis,
                rgb,
                width,
            });
        }
        if !label.is_empty() {
            labels.push(Label {
                at: *origin,
                text: label.clone(),
                rgb: TEXT_RGB,
            });
        }
    }
    // The grid on the reference xy-plane, over the scene's footprint.
    let mut pts: Vec<P3> = vec![P3::zeros(), P3::new(axis, axis, 0.0)];
    for p in &prims {
        match p {
            Prim::Seg { a, b, .. } => pts.extend([*a, *b]),
            Prim::Head { tip, .. } => pts.push(*tip),
            Prim::Dot { at, .. } => pts.push(*at),
        }
    }
    let (mut x0, mut x1, mut y0, mut y1) = (0f64, 0f64, 0f64, 0f64);
    for p in &pts {
        x0 = x0.min(p.x);
        x1 = x1.max(p.x);
        y0 = y0.min(p.y);
        y1 = y1.max(p.y);
    }
    let step = nice_step((x1 - x0).max(y1 - y0));
    let (gx0, gx1) = ((x0 / step).floor() * step, (x1 / step).ceil() * step);
    let (gy0, gy1) = ((y0 / step).floor() * step, (y1 / step).ceil() * step);
    let mut grid = Vec::new();
    let mut k = 0.0;
    while gx0 + k * step <= gx1 + 1e-9 && k < 64.0 {
        let x = gx0 + k * step;
        grid.push((P3::new(x, gy0, 0.0), P3::new(x, gy1, 0.0)));
        k += 1.0;
    }
    k = 0.0;
    while gy0 + k * step <= gy1 + 1e-9 && k < 64.0 {
        let y = gy0 + k * step;
        grid.push((P3::new(gx0, y, 0.0), P3::new(gx1, y, 0.0)));
        k += 1.0;
    }
    Layout {
        prims,
        labels,
        grid,
        path,
        frames: frames
            .into_iter()
            .map(|(o, a, r, l)| (o, a.map(|v| v * axis), r, l))
            .collect(),
    }
}

/// `{s}` → `ₛ` where a subscript letter exists, else nothing.
fn sub_name(name: &str) -> String {
    let map = |c: char| match c {
        'a' => Some('ₐ'),
        'e' => Some('ₑ'),
        'o' => Some('ₒ'),
        'x' => Some('ₓ'),
        'h' => Some('ₕ'),
        'k' => Some('ₖ'),
        'l' => Some('ₗ'),
        'm' => Some('ₘ'),
        'n' => Some('ₙ'),
        'p' => Some('ₚ'),
        's' => Some('ₛ'),
        't' => Some('ₜ'),
        '0'..='9' => char::from_u32('₀' as u32 + c.to_digit(10).unwrap_or(0)),
        _ => None,
    };
    name.chars()
        .map(map)
        .collect::<Option<String>>()
        .unwrap_or_default()
}
