//! The values of a picture as marks in the reference frame: a transform as
//! its frame's axes at its pose (§3.3.1), a rotation as axes at the origin
//! (§3.2.1), a screw axis or twist as its axis line through q along ŝ with
//! the pitch h (§3.3.2.2, q = ω × v/‖ω‖², h = ωᵀv/‖ω‖²; a pure translation
//! as an arrow), a vector as an arrow, the points of a list as dots, and in
//! the plane a planar twist as its centre of rotation (§3.3.2.1).

use nalgebra::{DMatrix, Vector3};

use crate::check::ty::{Frames, Kind};
use crate::values::value::Value;
use crate::values::value::{Drawn, Panel, Style};

/// A point or direction in the reference frame's coordinates.
pub type P3 = Vector3<f64>;

/// One thing drawn, in reference-frame coordinates.
#[derive(Debug, Clone)]
pub enum Mark {
    /// A frame's axes: origin and the unit x̂, ŷ, ẑ (ẑ left out in the plane).
    Frame {
        /// The frame's origin: p of T = (R, p) (3.62); 0 for a rotation.
        origin: P3,
        /// The unit axes x̂, ŷ, ẑ: the columns of R.
        axes: [P3; 3],
        /// `{b}` for a value tagged {a}←{b}, or the name as written; may be
        /// empty.
        label: String,
    },
    /// A screw axis: the line through q along ŝ, with its pitch.
    Screw {
        /// A point on the axis, q = ω × v/‖ω‖² (§3.3.2.2); 0 for a pure
        /// translation.
        q: P3,
        /// The unit direction ŝ of the axis: ω/‖ω‖, or v/‖v‖ when ω = 0.
        s: P3,
        /// The pitch h = ωᵀv/‖ω‖²; infinite for a pure translation.
        pitch: f64,
        /// The label beside the axis; may be empty.
        label: String,
    },
    /// An arrow from `from` along `dir` (a vector, a pure translation).
    Arrow {
        /// The tail: the origin, or p of `arrow(p, v)`.
        from: P3,
        /// The arrow itself, tail to head.
        dir: P3,
        /// The label at the arrow; may be empty.
        label: String,
    },
    /// A point.
    Dot {
        /// Where the point is.
        at: P3,
        /// The label beside it; empty for an item of a list.
        label: String,
    },
    /// The fixed point of a planar motion.
    Centre {
        /// The point c in the plane with v = −ω × c, about which the planar
        /// twist rotates (§3.3.2.1).
        at: P3,
        /// `centre of V` (or `centre`).
        label: String,
    },
    /// The origins of a list of frames in order: the path they follow.
    Path {
        /// The frames' origins, in the list's order.
        points: Vec<P3>,
    },
}

/// A panel's marks, its reference frame and whether it lies in the plane.
#[derive(Debug, Clone)]
pub struct Scene {
    /// What is drawn, in the order given.
    pub marks: Vec<Mark>,
    /// The name of the reference frame drawn at the origin (`s`).
    pub reference: String,
    /// Only SE(2), SO(2), se(2) values and 2-vectors: drawn in the plane,
    /// seen from above.
    pub planar: bool,
    /// `view(az, el)`, radians, MATLAB's convention.
    pub view: Option<(f64, f64)>,
    /// The title written above the panel.
    pub title: Option<String>,
}

/// The frame a value is drawn in, and the frame it draws (for `T_sa`: s, a).
fn frame_names(f: &Frames) -> (Option<String>, Option<String>) {
    match f {
        Frames::None | Frames::Transposed(..) => (None, None),
        Frames::One(a) | Frames::Disp(a) => (Some(a.to_string()), None),
        Frames::Pair(a, b) => (Some(a.to_string()), Some(b.to_string())),
    }
}

fn subscript(n: usize) -> String {
    const DIGITS: [char; 10] = ['₀', '₁', '₂', '₃', '₄', '₅', '₆', '₇', '₈', '₉'];
    n.to_string()
        .chars()
        .map(|c| DIGITS[c.to_digit(10).unwrap_or(0) as usize])
        .collect()
}

/// A name as written is a label when it is one plain name (`w_hat`, `T`).
fn text_label(text: &str) -> String {
    let plain = !text.is_empty()
        && text.chars().count() <= 16
        && text.chars().all(|c| {
            c.is_alphanumeric() || c == '_' || c == '\'' || c == '{' || c == '}' || c == ','
        });
    if plain {
        text.to_string()
    } else {
        String::new()
    }
}

struct Builder {
    marks: Vec<Mark>,
    outer: Option<String>,
    planar: Option<bool>,
}

fn finite(m: &DMatrix<f64>) -> bool {
    m.iter().all(|x| x.is_finite())
}

impl Builder {
    /// The reference frame: the first outer frame given. Different outer
    /// frames were a frame error when `draw` was checked (or, under
    /// `--frames warn|off`, a warning or nothing).
    fn outer(&mut self, f: &Frames) {
        if let (Some(a), _) = frame_names(f) {
            self.outer.get_or_insert(a);
        }
    }

    fn plane(&mut self, planar: bool) {
        self.planar = Some(self.planar.unwrap_or(true) && planar);
    }

    /// A frame's axes at `origin` (in the plane when `planar`).
    fn frame(&mut self, planar: bool, origin: P3, axes: [P3; 3], label: String) {
        self.plane(planar);
        self.marks.push(Mark::Frame {
            origin,
            axes,
            label,
        });
    }

    /// One value; `label` names it, `in_list` says it is an item of a list
    /// (3-vectors are then points).
    fn value(&mut self, v: &Value, label: &str, style: Style, in_list: bool) -> Result<(), String> {
        match v {
            Value::List(items) => self.items(items, label, style),
            Value::Tuple(items) if style == Style::Arrow && items.len() == 2 => {
                let from = point(&items[0])?;
                let dir = point(&items[1])?;
                self.plane(is_planar_vec(&items[0]) && is_planar_vec(&items[1]));
                self.marks.push(Mark::Arrow {
                    from,
                    dir,
                    label: label.to_string(),
                });
                Ok(())
            }
            Value::Tuple(items) => self.items(items, label, style),
            Value::Num { kind, m, .. } => {
                let m = &*m.to_dmatrix();
                if !finite(m) {
                    return Err(format!(
                        "cannot draw {}: it has inf or NaN entries",
                        if label.is_empty() {
                            kind.a()
                        } else {
                            format!("'{label}'")
                        }
                    ));
                }
                self.num(kind, m, label, style, in_list)
            }
            Value::Picture(_) | Value::Str(_) => Ok(()),
            other => Err(format!("cannot draw {}", other.kind().a())),
        }
    }

    fn items(&mut self, items: &[Value], label: &str, style: Style) -> Result<(), String> {
        let first = self.marks.len();
        for (i, item) in items.iter().enumerate() {
            let l = if label.is_empty() {
                (i + 1).to_string()
            } else {
                format!("{label}{}", subscript(i + 1))
            };
            self.value(item, &l, style, true)?;
        }
        let points: Vec<P3> = self.marks[first..]
            .iter()
            .filter_map(|m| match m {
                Mark::Frame { origin, .. } => Some(*origin),
                _ => None,
            })
            .collect();
        if points.len() >= 2 {
            self.marks.push(Mark::Path { points });
        }
        Ok(())
    }

    fn num(
        &mut self,
        kind: &Kind,
        m: &DMatrix<f64>,
        label: &str,
        style: Style,
        in_list: bool,
    ) -> Result<(), String> {
        let label = label.to_string();
        let shape = m.shape();
        match (kind, shape) {
            (Kind::SE3 | Kind::Matrix(..) | Kind::Unknown, (4, 4)) if is_transform(m) => {
                let origin = P3::new(m[(0, 3)], m[(1, 3)], m[(2, 3)]);
                self.frame(false, origin, spatial_axes(m), label);
            }
            (Kind::SO3 | Kind::Matrix(..) | Kind::Unknown, (3, 3)) if is_rotation(m) => {
                self.frame(false, P3::zeros(), spatial_axes(m), label);
            }
            (Kind::SE2 | Kind::Matrix(..), (3, 3)) if is_planar_transform(m) => {
                let origin = P3::new(m[(0, 2)], m[(1, 2)], 0.0);
                self.frame(true, origin, planar_axes(m), label);
            }
            (Kind::SO2, (2, 2)) | (Kind::Matrix(..), (2, 2)) if is_rotation(m) => {
                self.frame(true, P3::zeros(), planar_axes(m), label);
            }
            (Kind::Se2, (3, 3)) => {
                // [V] = [0, −ω, vx; ω, 0, vy; 0, 0, 0]: the centre solves v = −ω × c.
                let (w, vx, vy) = (m[(1, 0)], m[(0, 2)], m[(1, 2)]);
                self.plane(true);
                if w.abs() > 1e-12 {
                    let at = P3::new(-vy / w, vx / w, 0.0);
                    self.marks.push(Mark::Centre {
                        at,
                        label: if label.is_empty() {
                            "centre".into()
                        } else {
                            format!("centre of {label}")
                        },
                    });
                } else if vx.hypot(vy) > 1e-12 {
                    self.marks.push(Mark::Arrow {
                        from: P3::zeros(),
                        dir: P3::new(vx, vy, 0.0),
                        label,
                    });
                } else {
                    return Err("a zero twist has no screw axis to draw".into());
                }
            }
            (_, (6, 1)) => {
                self.plane(false);
                let w = P3::new(m[0], m[1], m[2]);
                let v = P3::new(m[3], m[4], m[5]);
                let n = w.norm();
                if n > 1e-12 {
                    let q = w.cross(&v) / (n * n);
                    let pitch = w.dot(&v) / (n * n);
                    self.marks.push(Mark::Screw {
                        q,
                        s: w / n,
                        pitch,
                        label,
                    });
                } else if v.norm() > 1e-12 {
                    self.marks.push(Mark::Screw {
                        q: P3::zeros(),
                        s: v / v.norm(),
                        pitch: f64::INFINITY,
                        label,
                    });
                } else {
                    return Err("a zero twist has no screw axis to draw".into());
                }
            }
            (_, (3, 1)) | (_, (2, 1)) => {
                let p = point_of(m);
                self.plane(shape.0 == 2);
                if style == Style::Point || (in_list && style == Style::Natural) {
                    self.marks.push(Mark::Dot {
                        at: p,
                        label: if in_list { String::new() } else { label },
                    });
                } else {
                    self.marks.push(Mark::Arrow {
                        from: P3::zeros(),
                        dir: p,
                        label,
                    });
                }
            }
            _ => {
                return Err(format!(
                    "cannot draw {}: draw takes transforms, rotations, screw axes, twists, points and vectors",
                    kind.a()
                ));
            }
        }
        Ok(())
    }
}

fn point_of(m: &DMatrix<f64>) -> P3 {
    P3::new(m[0], m[1], if m.nrows() > 2 { m[2] } else { 0.0 })
}

fn is_planar_vec(v: &Value) -> bool {
    matches!(v, Value::Num { m, .. } if m.nrows() == 2)
}

fn point(v: &Value) -> Result<P3, String> {
    match v {
        Value::Num { m, .. } if m.ncols() == 1 && (m.nrows() == 2 || m.nrows() == 3) => {
            let m = &*m.to_dmatrix();
            if finite(m) {
                Ok(point_of(m))
            } else {
                Err("cannot draw an arrow with inf or NaN entries".into())
            }
        }
        other => Err(format!(
            "an arrow takes 2- or 3-vectors, not {}",
            other.kind().a()
        )),
    }
}

fn orthonormal(m: &DMatrix<f64>, n: usize) -> bool {
    let r = m.view((0, 0), (n, n)).into_owned();
    let e = &r.transpose() * &r - DMatrix::identity(n, n);
    e.iter().all(|x| x.abs() < 1e-6) && r.determinant() > 0.0
}

/// The columns x̂, ŷ, ẑ of a rotation, or of a transform's R block.
fn spatial_axes(m: &DMatrix<f64>) -> [P3; 3] {
    [0, 1, 2].map(|j| P3::new(m[(0, j)], m[(1, j)], m[(2, j)]))
}

/// The columns x̂, ŷ of a planar rotation (or a planar transform's block)
/// in the xy-plane, and ẑ out of it.
fn planar_axes(m: &DMatrix<f64>) -> [P3; 3] {
    [
        P3::new(m[(0, 0)], m[(1, 0)], 0.0),
        P3::new(m[(0, 1)], m[(1, 1)], 0.0),
        P3::z(),
    ]
}

fn is_rotation(m: &DMatrix<f64>) -> bool {
    m.is_square() && orthonormal(m, m.nrows())
}

fn is_transform(m: &DMatrix<f64>) -> bool {
    orthonormal(m, 3)
        && m[(3, 0)] == 0.0
        && m[(3, 1)] == 0.0
        && m[(3, 2)] == 0.0
        && m[(3, 3)] == 1.0
}

fn is_planar_transform(m: &DMatrix<f64>) -> bool {
    orthonormal(m, 2) && m[(2, 0)] == 0.0 && m[(2, 1)] == 0.0 && m[(2, 2)] == 1.0
}

/// The marks of one panel, or why it cannot be drawn.
pub fn scene(panel: &Panel) -> Result<Scene, String> {
    let mut b = Builder {
        marks: Vec::new(),
        outer: None,
        planar: None,
    };
    for d in &panel.items {
        b.drawn(d)?;
    }
    if b.marks.is_empty() {
        return Err("nothing to draw: draw takes transforms, rotations, screw axes, twists, points and vectors".into());
    }
    Ok(Scene {
        marks: b.marks,
        reference: b.outer.unwrap_or_else(|| "s".into()),
        planar: b.planar.unwrap_or(false),
        view: panel.view,
        title: panel.title.clone(),
    })
}

impl Builder {
    fn drawn(&mut self, d: &Drawn) -> Result<(), String> {
        self.outer(&d.ty.frames);
        let label = match frame_names(&d.ty.frames) {
            (_, Some(inner)) => format!("{{{inner}}}"),
            _ => text_label(&d.label),
        };
        self.value(&d.value, &label, d.style, false)
    }
}

/// What a picture shows: `5 frames and 1 screw axis in {s}`.
pub fn summary(scenes: &[Scene]) -> String {
    let mut counts = [0usize; 5];
    for s in scenes {
        for m in &s.marks {
            let i = match m {
                Mark::Frame { .. } => 0,
                Mark::Screw { .. } => 1,
                Mark::Arrow { .. } => 2,
                Mark::Dot { .. } => 3,
                Mark::Centre { .. } => 4,
                Mark::Path { .. } => continue,
            };
            counts[i] += 1;
        }
    }
    let names = [
        ("frame", "frames"),
        ("screw axis", "screw axes"),
        ("arrow", "arrows"),
        ("point", "points"),
        ("centre", "centres"),
    ];
    let parts: Vec<String> = counts
        .iter()
        .zip(names)
        .filter(|(n, _)| **n > 0)
        .map(|(n, (one, many))| format!("{n} {}", if *n == 1 { one } else { many }))
        .collect();
    let what = match parts.len() {
        0 => "nothing".to_string(),
        1 => parts[0].clone(),
        k => format!("{} and {}", parts[..k - 1].join(", "), parts[k - 1]),
    };
    let frames: Vec<String> = scenes
        .iter()
        .map(|s| format!("{{{}}}", s.reference))
        .collect();
    if scenes.len() == 1 {
        format!("{what} in {}", frames[0])
    } else {
        format!("{what} in {} panels ({})", scenes.len(), frames.join(", "))
    }
}
