//! Builtins that make pictures (LANGUAGE.md §12): `draw`, `view`, `save`,
//! `beside`, `arrow`, `point`. They build a [`Picture`] value — the values
//! with their kinds and frames — and check what can be checked here: that
//! every value is drawable and finite and that all share one outer frame
//! (a frame error otherwise, as for any other operation, §6). Marks,
//! projection and files belong to [`crate::draw`], which the session calls
//! when the picture is printed.

use std::rc::Rc;

use super::{Area, ArgError, Args, Builtin, Typing};
use crate::check::ty::{Frames, Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::values::value::Value;
use crate::values::value::{Drawn, Panel, Picture, Style};

/// Whether `draw` can show a value of kind `k`.
fn drawable(k: &Kind) -> bool {
    match k {
        Kind::SE3 | Kind::SO3 | Kind::SE2 | Kind::SO2 | Kind::Se2 => true,
        Kind::Twist | Kind::Screw | Kind::Picture | Kind::Text | Kind::Unknown => true,
        Kind::Vector(n) => n.is_none_or(|n| matches!(n, 2 | 3 | 6)),
        Kind::Matrix(r, c) => {
            matches!(
                (r, c),
                (Some(4), Some(4)) | (Some(3), Some(3)) | (Some(2), Some(2))
            ) || r.is_none()
                || c.is_none()
        }
        Kind::List(k, _) => drawable(k),
        Kind::Tuple(ks) => ks.iter().all(drawable),
        _ => false,
    }
}

/// One outer frame for all arguments from index `from` on.
fn common_frame(args: &[Ty], from: usize) -> Result<Frames, ArgError> {
    let mut outer: Option<(usize, String)> = None;
    for (i, t) in args.iter().enumerate().skip(from) {
        let Some(a) = t.frames.outer() else { continue };
        let a = a.to_string();
        match &outer {
            Some((j, o)) if *o != a => {
                return Err(ArgError {
                    arg: Some(i),
                    kind: ErrorKind::Frame,
                    message: format!(
                        "one picture has one reference frame, but argument {} is in {{{o}}} and argument {} in {{{a}}}: express both in one frame (T_sa * T_ab is {{b}} in {{s}})",
                        j + 1,
                        i + 1
                    ),
                });
            }
            Some(_) => {}
            None => outer = Some((i, a)),
        }
    }
    Ok(outer.map_or(Frames::None, |(_, a)| Frames::one(&a)))
}

fn draw_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    for (i, t) in args.iter().enumerate() {
        if !drawable(&t.kind) {
            return Err(ArgError::type_of(
                i,
                format!(
                    "cannot draw {}: draw takes transforms, rotations, screw axes, twists, points, vectors, lists of them and pictures",
                    t.kind.a()
                ),
            ));
        }
    }
    Ok(Ty::new(Kind::Picture, common_frame(args, 0)?))
}

fn picture_of(a: &Args, i: usize) -> Result<Rc<Picture>, Diagnostic> {
    match a.value(i) {
        Value::Picture(p) => Ok(p.clone()),
        v => Err(a.error(
            i,
            ErrorKind::Type,
            format!(
                "argument {} of {} must be a picture, not {}",
                i + 1,
                a.name,
                v.kind().a()
            ),
        )),
    }
}

/// Inf or NaN anywhere in a value.
fn not_finite(v: &Value) -> bool {
    match v {
        Value::Num { m, .. } => m.iter().any(|x| !x.is_finite()),
        Value::List(vs) => vs.iter().any(not_finite),
        Value::Tuple(vs) => vs.iter().any(not_finite),
        _ => false,
    }
}

fn drawn(a: &Args, i: usize, style: Style) -> Result<Drawn, Diagnostic> {
    let v = a.value(i).clone();
    if not_finite(&v) {
        return Err(a.error(
            i,
            ErrorKind::Domain,
            "cannot draw a value with inf or NaN entries",
        ));
    }
    let (ty, label) = a
        .typed
        .get(i)
        .cloned()
        .unwrap_or_else(|| (Ty::plain(v.kind()), String::new()));
    Ok(Drawn {
        value: v,
        ty,
        label,
        style,
    })
}

fn one_panel(panel: Panel) -> Value {
    Value::Picture(Rc::new(Picture {
        panels: vec![panel],
        ..Picture::default()
    }))
}

fn eval_draw(a: &mut Args) -> Result<Value, Diagnostic> {
    let mut panel = Panel::default();
    for i in 0..a.len() {
        match a.value(i) {
            Value::Picture(p) => {
                for q in &p.panels {
                    panel.items.extend(q.items.iter().cloned());
                    panel.view = q.view.or(panel.view);
                    panel.title = q.title.clone().or(panel.title.take());
                }
            }
            Value::Str(t) => panel.title = Some(t.to_string()),
            // A list of pictures (`[point(p) for p in ps]`): their marks.
            Value::List(vs)
                if !vs.is_empty() && vs.iter().all(|v| matches!(v, Value::Picture(_))) =>
            {
                for v in vs.iter() {
                    if let Value::Picture(p) = v {
                        for q in &p.panels {
                            panel.items.extend(q.items.iter().cloned());
                            panel.view = q.view.or(panel.view);
                        }
                    }
                }
            }
            _ => panel.items.push(drawn(a, i, Style::Natural)?),
        }
    }
    if panel.items.is_empty() {
        return Err(a.domain(
            "nothing to draw: give draw a transform, rotation, screw axis, twist, point or vector",
        ));
    }
    Ok(one_panel(panel))
}

fn angle_text(x: f64) -> String {
    crate::values::number::fmt_num(x.to_degrees(), 2)
}

fn view_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    let (first, frames) = match args.len() {
        3 => {
            if !matches!(args[0].kind, Kind::Picture | Kind::Unknown) {
                return Err(ArgError::type_of(
                    0,
                    format!(
                        "view(pic, az, el) takes a picture first, not {}",
                        args[0].kind.a()
                    ),
                ));
            }
            (1, args[0].frames)
        }
        _ => (0, Frames::None),
    };
    for (i, t) in args.iter().enumerate().skip(first) {
        if !t.kind.maybe_scalar() {
            return Err(ArgError::type_of(
                i,
                format!("azimuth and elevation are angles, not {}", t.kind.a()),
            ));
        }
    }
    Ok(Ty::new(Kind::Picture, frames))
}

fn eval_view(a: &mut Args) -> Result<Value, Diagnostic> {
    let first = a.len() - 2;
    let (az, el) = (a.scalar(first)?, a.scalar(first + 1)?);
    if !(az.is_finite() && el.is_finite()) {
        return Err(a.domain("a view needs finite angles"));
    }
    // (MATLAB's view(30, 45) is in degrees; here, as every angle, radians)
    if az.abs() > 2.0 * std::f64::consts::PI || el.abs() > std::f64::consts::PI {
        let num = |x: f64| crate::values::number::fmt_num(x, 4);
        let (az_text, el_text) = (num(az), num(el));
        a.warnings.push(
            Diagnostic::warning(
                ErrorKind::Domain,
                a.call_span,
                format!(
                    "view takes radians, as every angle in chasles: view({az_text}, {el_text}) is azimuth {}°, elevation {}°",
                    angle_text(az),
                    angle_text(el)
                ),
            )
            .with_help(format!(
                "for degrees, as MATLAB's view(az, el), write view({az_text} deg, {el_text} deg)"
            )),
        );
    }
    if first == 1 {
        let mut p = (*picture_of(a, 0)?).clone();
        p.panels.iter_mut().for_each(|q| q.view = Some((az, el)));
        p.file = None;
        return Ok(Value::Picture(Rc::new(p)));
    }
    Ok(Value::Picture(Rc::new(Picture {
        panels: vec![Panel {
            view: Some((az, el)),
            ..Panel::default()
        }],
        summary: format!(
            "view: azimuth {}°, elevation {}° (pass it to draw: draw(T, view(..)))",
            angle_text(az),
            angle_text(el)
        ),
        ..Picture::default()
    })))
}

fn save_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    if !matches!(args[0].kind, Kind::Picture | Kind::Unknown) {
        return Err(ArgError::type_of(
            0,
            format!(
                "save takes a picture made by draw, not {}",
                args[0].kind.a()
            ),
        ));
    }
    if !matches!(args[1].kind, Kind::Text | Kind::Unknown) {
        return Err(ArgError::type_of(
            1,
            format!(
                "the file name is a string such as \"pic.svg\", not {}",
                args[1].kind.a()
            ),
        ));
    }
    Ok(Ty::new(Kind::Picture, args[0].frames))
}

fn eval_save(a: &mut Args) -> Result<Value, Diagnostic> {
    let p = picture_of(a, 0)?;
    let name = match a.value(1) {
        Value::Str(t) => t.to_string(),
        v => {
            return Err(a.error(
                1,
                ErrorKind::Type,
                format!("the file name must be a string, not {}", v.kind().a()),
            ));
        }
    };
    let base = name.rsplit(['/', '\\']).next().unwrap_or("");
    if base.len() <= ".svg".len() {
        return Err(a.error(
            1,
            ErrorKind::Domain,
            format!("cannot save a picture as \"{name}\": give a file name, e.g. \"pic.svg\""),
        ));
    }
    let lower = name.to_ascii_lowercase();
    if !(lower.ends_with(".svg") || lower.ends_with(".png")) {
        return Err(a.error(
            1,
            ErrorKind::Domain,
            format!("cannot save a picture as \"{name}\": the name must end in .svg or .png"),
        ));
    }
    if p.is_view_only() {
        return Err(a.error(
            0,
            ErrorKind::Domain,
            "nothing to save: this picture is a view only; draw something with it",
        ));
    }
    let mut q = (*p).clone();
    q.save_to = Some(name);
    q.file = None;
    Ok(Value::Picture(Rc::new(q)))
}

fn beside_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    for (i, t) in args.iter().enumerate() {
        if !matches!(t.kind, Kind::Picture | Kind::Unknown) {
            return Err(ArgError::type_of(
                i,
                format!("beside takes pictures made by draw, not {}", t.kind.a()),
            ));
        }
    }
    Ok(Ty::plain(Kind::Picture))
}

fn eval_beside(a: &mut Args) -> Result<Value, Diagnostic> {
    let mut panels = Vec::new();
    for i in 0..a.len() {
        let p = picture_of(a, i)?;
        if p.is_view_only() {
            return Err(a.error(
                i,
                ErrorKind::Domain,
                "a view alone has nothing to show beside the others",
            ));
        }
        panels.extend(p.panels.iter().cloned());
    }
    Ok(Value::Picture(Rc::new(Picture {
        panels,
        ..Picture::default()
    })))
}

fn vec_kind(k: &Kind) -> bool {
    matches!(k, Kind::Vector(None | Some(2) | Some(3)) | Kind::Unknown)
}

fn arrow_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    for (i, t) in args.iter().enumerate() {
        if !vec_kind(&t.kind) {
            return Err(ArgError::type_of(
                i,
                format!("arrow takes 2- or 3-vectors, not {}", t.kind.a()),
            ));
        }
    }
    Ok(Ty::new(Kind::Picture, common_frame(args, 0)?))
}

fn eval_arrow(a: &mut Args) -> Result<Value, Diagnostic> {
    let (from, dir) = if a.len() == 2 {
        (a.value(0).clone(), a.value(1).clone())
    } else {
        let v = a.value(0).clone();
        let n = v.as_matrix().map_or(3, |m| m.nrows());
        (Value::vector(Kind::Vector(Some(n)), &vec![0.0; n]), v)
    };
    let last = a.len() - 1;
    let mut d = drawn(a, last, Style::Arrow)?;
    if not_finite(&from) {
        return Err(a.error(
            0,
            ErrorKind::Domain,
            "cannot draw a value with inf or NaN entries",
        ));
    }
    d.value = Value::Tuple(vec![from, dir]);
    Ok(one_panel(Panel {
        items: vec![d],
        ..Panel::default()
    }))
}

fn point_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    if !vec_kind(&args[0].kind) {
        return Err(ArgError::type_of(
            0,
            format!("point takes a 2- or 3-vector, not {}", args[0].kind.a()),
        ));
    }
    Ok(Ty::new(Kind::Picture, common_frame(args, 0)?))
}

fn eval_point(a: &mut Args) -> Result<Value, Diagnostic> {
    let d = drawn(a, 0, Style::Point)?;
    Ok(one_panel(Panel {
        items: vec![d],
        ..Panel::default()
    }))
}

/// The picture builtins.
pub fn builtins() -> Vec<Builtin> {
    let typing = |lo, hi, rule| Typing::Custom {
        arity: (lo, hi),
        rule,
    };
    vec![
        Builtin {
            name: "draw",
            aliases: &["plot"],
            signature: "draw(x: SE3 | SO3 | SE2 | SO2 | screw | twist | vector | list | picture | title, ...) -> picture",
            section: "§3.2.1, §3.3.1, §3.3.2.2 (docs/language.md §12)",
            doc: "a picture: T_sa draws {a} in {s} (x̂ red, ŷ green, ẑ blue), a screw axis its line through q along ŝ with the pitch",
            example: "draw(RpToTrans(Rotz(pi/2), (1, 0, 0)), ScrewToAxis((0, 2, 0), (0, 0, 1), 2))",
            area: Area::Pictures,
            typing: typing(1, 64, draw_rule),
            eval: eval_draw,
        },
        Builtin {
            name: "view",
            aliases: &[],
            signature: "view(az: scalar, el: scalar) -> view; view(pic: picture, az, el) -> picture",
            section: "docs/language.md §12",
            doc: "the direction a picture is seen from: azimuth and elevation as in MATLAB (radians; 30 deg)",
            example: "draw(Rotx(pi/6), view(30 deg, 20 deg))",
            area: Area::Pictures,
            typing: typing(2, 3, view_rule),
            eval: eval_view,
        },
        Builtin {
            name: "save",
            aliases: &[],
            signature: "save(pic: picture, name: string) -> picture",
            section: "docs/language.md §12",
            doc: "writes a picture to a file: SVG, or PNG when the name ends in .png",
            example: "save(draw(Rotz(pi/4)), \"rotz.svg\")",
            area: Area::Pictures,
            typing: typing(2, 2, save_rule),
            eval: eval_save,
        },
        Builtin {
            name: "beside",
            aliases: &[],
            signature: "beside(pic: picture, ...) -> picture",
            section: "docs/language.md §12",
            doc: "pictures side by side, each with its own reference frame (exercise 2.25's two workspaces)",
            example: "beside(draw(Rotx(pi/4)), draw(Roty(pi/4)))",
            area: Area::Pictures,
            typing: typing(1, 16, beside_rule),
            eval: eval_beside,
        },
        Builtin {
            name: "arrow",
            aliases: &[],
            signature: "arrow(v: vector) | arrow(p: vector, v: vector) -> picture",
            section: "docs/language.md §12",
            doc: "a vector drawn as an arrow from the origin, or from the point p",
            example: "draw(arrow((1, 2, 0)), arrow((1, 2, 0), (0, 0, 1)))",
            area: Area::Pictures,
            typing: typing(1, 2, arrow_rule),
            eval: eval_arrow,
        },
        Builtin {
            name: "point",
            aliases: &[],
            signature: "point(p: vector) -> picture",
            section: "docs/language.md §12",
            doc: "a point drawn as a dot",
            example: "draw(point((1, 2, 3)))",
            area: Area::Pictures,
            typing: typing(1, 1, point_rule),
            eval: eval_point,
        },
    ]
}
