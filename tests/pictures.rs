//! Pictures (LANGUAGE.md §12): every picture of the example scripts is
//! rendered with resvg and checked at the pixels where the projected frame
//! origins and axis tips must be (so a blank, clipped or mis-projected
//! picture fails), its SVG text is snapshotted, the projection is checked
//! against the view's geometry, and bad input is a clear error that writes
//! no file.

use std::path::Path;

use chasles::draw::{self, Probe};
use chasles::eval::env::Mode;
use chasles::eval::value::Value;
use chasles::session::{Session, Settings};

mod common;
use common::{run_in, scratch};

/// Runs `src` in a session that writes pictures into `dir`; returns each
/// picture with the statement's line.
fn pictures(src: &str, dir: &Path) -> Vec<(usize, chasles::eval::value::Picture)> {
    let mut s = Session::new(Settings::default());
    s.gate = chasles::effects::Gate::anywhere(Some(dir.to_path_buf()));
    let mut out = Vec::new();
    s.run(src, Mode::Run, false, |r| match &r.result {
        Ok(o) => {
            if let Some(Value::Picture(p)) = o.val.as_deref() {
                out.push((r.line(), (**p).clone()));
            }
        }
        Err(d) => panic!("line {}: {}", r.line(), d.message),
    });
    out
}

/// The picture rendered by resvg (no fonts needed: the checks are on lines).
fn render(svg: &str) -> resvg::tiny_skia::Pixmap {
    let tree =
        resvg::usvg::Tree::from_str(svg, &resvg::usvg::Options::default()).expect("the SVG parses");
    let size = tree.size().to_int_size();
    let mut pm = resvg::tiny_skia::Pixmap::new(size.width(), size.height()).expect("a pixmap");
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::default(),
        &mut pm.as_mut(),
    );
    pm
}

fn near(a: (u8, u8, u8), b: (u8, u8, u8)) -> bool {
    let d = |x: u8, y: u8| (i32::from(x) - i32::from(y)).abs();
    d(a.0, b.0) <= 40 && d(a.1, b.1) <= 40 && d(a.2, b.2) <= 40
}

/// Whether the probe's colour shows within 2 pixels of it.
fn shows(pm: &resvg::tiny_skia::Pixmap, p: &Probe) -> bool {
    shows_any(pm, p, &[p.rgb])
}

/// Whether one of `colours` shows within 2 pixels of the probe.
fn shows_any(pm: &resvg::tiny_skia::Pixmap, p: &Probe, colours: &[(u8, u8, u8)]) -> bool {
    for dy in -2..=2 {
        for dx in -2..=2 {
            let (x, y) = (p.x.round() as i64 + dx, p.y.round() as i64 + dy);
            if x < 0 || y < 0 {
                continue;
            }
            if let Some(c) = pm.pixel(x as u32, y as u32) {
                let c = c.demultiply();
                if colours
                    .iter()
                    .any(|k| near((c.red(), c.green(), c.blue()), *k))
                {
                    return true;
                }
            }
        }
    }
    false
}

/// Checks a picture's pixels at its probes: every probe lies inside the
/// image and on a frame axis (its own colour, or another axis that crosses
/// it: frames at one origin in 3.1(h), axes passing in front in 3.48), and
/// at least three quarters show their own axis colour.
fn check_pixels(name: &str, svg: &str, probes: &[Probe]) {
    check_pixmap(name, &render(svg), probes);
}

/// [`check_pixels`] on a rendered picture.
fn check_pixmap(name: &str, pm: &resvg::tiny_skia::Pixmap, probes: &[Probe]) {
    assert!(!probes.is_empty(), "{name}: no axis to check");
    let any_axis: Vec<(u8, u8, u8)> = draw::AXIS_RGB
        .iter()
        .chain(draw::REF_RGB.iter())
        .copied()
        .collect();
    let mut covered = Vec::new();
    for p in probes {
        assert!(
            p.x >= 0.0 && p.y >= 0.0 && p.x < f64::from(pm.width()) && p.y < f64::from(pm.height()),
            "{name}: {} is outside the picture at ({}, {})",
            p.what,
            p.x,
            p.y
        );
        assert!(
            shows_any(pm, p, &any_axis),
            "{name}: no axis where {} must be, at ({:.0}, {:.0})",
            p.what,
            p.x,
            p.y
        );
        if !shows(pm, p) {
            covered.push(p.what.clone());
        }
    }
    assert!(
        covered.len() * 4 <= probes.len(),
        "{name}: {} of {} axis pixels show another axis: {covered:?}",
        covered.len(),
        probes.len()
    );
}

/// The labels of an SVG as boxes (at the renderer's estimate of 9 pixels a
/// character, 15 high): no two overlap.
fn labels_apart(name: &str, svg: &str) {
    let mut boxes: Vec<(f64, f64, f64, f64, String)> = Vec::new();
    let mut lines = svg.lines();
    while let Some(line) = lines.next() {
        let Some(rest) = line.strip_prefix("<text x=\"") else {
            continue;
        };
        let num = |s: &str| s.split('"').next().and_then(|n| n.parse::<f64>().ok());
        let x = num(rest).expect("x");
        let y = num(rest.split("y=\"").nth(1).expect("y")).expect("y");
        let text = lines
            .next()
            .unwrap_or("")
            .replace("&apos;", "'")
            .replace("&quot;", "\"")
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&amp;", "&");
        let w = text.chars().count() as f64 * 9.0;
        boxes.push((x, y, x + w, y + 15.0, text));
    }
    for (i, a) in boxes.iter().enumerate() {
        for b in &boxes[i + 1..] {
            let apart = a.2 <= b.0 || b.2 <= a.0 || a.3 <= b.1 || b.3 <= a.1;
            assert!(apart, "{name}: labels '{}' and '{}' overlap", a.4, b.4);
        }
    }
}

#[test]
fn example_pictures_render_with_their_axes_where_projected() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = scratch("example-pictures");
    let mut checked = 0;
    for script in [
        "ch3_exercise48_screw_motion",
        "ch3_exercises_drawn",
        "ch2_exercise25_workspace",
    ] {
        let src = std::fs::read_to_string(root.join("examples").join(format!("{script}.chs")))
            .expect("the example exists");
        // save() paths are relative to the current folder: the repo root.
        let pics = pictures(&src, &dir);
        assert!(!pics.is_empty(), "{script} draws nothing");
        for (_, p) in pics {
            let (svg, probes) = draw::svg(&p).expect("the picture draws");
            // Named by the file written: stable when lines move.
            let stem = p
                .file
                .as_deref()
                .and_then(|f| Path::new(f).file_stem())
                .map(|s| s.to_string_lossy().to_string())
                .unwrap_or_default();
            let name = format!("{script}__{stem}");
            check_pixels(&name, &svg, &probes);
            labels_apart(&name, &svg);
            // The file written is the SVG drawn, byte for byte.
            let file = p.file.clone().expect("the picture was written");
            let written = if Path::new(&file).is_absolute() || Path::new(&file).exists() {
                std::fs::read_to_string(&file)
            } else {
                std::fs::read_to_string(root.join(&file))
            }
            .expect("the written file reads");
            assert_eq!(written, svg, "{name}: file {file}");
            insta::assert_snapshot!(name, svg);
            checked += 1;
        }
    }
    assert_eq!(checked, 7);
    // The README's picture is the one exercise 3.48 saves.
    assert!(root.join("docs/ch3_exercise48_screw_motion.svg").is_file());
}

fn one(src: &str) -> (String, Vec<Probe>) {
    let pics = pictures(src, &scratch("one"));
    let (_, p) = pics.last().expect("a picture").clone();
    draw::svg(&p).expect("draws")
}

fn probe<'a>(probes: &'a [Probe], what: &str) -> &'a Probe {
    probes
        .iter()
        .find(|p| p.what == what)
        .unwrap_or_else(|| panic!("no probe '{what}' in {probes:?}"))
}

#[test]
fn the_default_view_draws_frames_as_the_book_does() {
    // x̂ out of the page to the lower left, ŷ to the right, ẑ straight up.
    let (svg, probes) = one("T_sa = Trans((0, 0, 0))\np = draw(T_sa)");
    let at = |axis: &str, end: &str| probe(&probes, &format!("{{a}} {axis} axis near its {end}"));
    let (x0, x) = (at("x", "origin"), at("x", "tip"));
    let (y0, y) = (at("y", "origin"), at("y", "tip"));
    let (z0, z) = (at("z", "origin"), at("z", "tip"));
    assert!(
        x.x < x0.x && x.y > x0.y,
        "x̂ goes lower left: {x:?} from {x0:?}"
    );
    assert!(y.x > y0.x, "ŷ goes right: {y:?}");
    assert!(
        (z.x - z0.x).abs() < 1.5 && z.y < z0.y - 50.0,
        "ẑ goes straight up: {z:?}"
    );
    assert_eq!(x.rgb, draw::AXIS_RGB[0]);
    check_pixels("identity", &svg, &probes);
}

#[test]
fn a_top_view_and_the_plane_put_x_right_and_y_up() {
    for src in ["p = draw(Rotz(0), view(0, pi/2))", "p = draw(SE2(0, 0, 0))"] {
        let (svg, probes) = one(src);
        let x0 = probe(&probes, "reference x axis near its origin");
        let x = probe(&probes, "reference x axis near its tip");
        let y0 = probe(&probes, "reference y axis near its origin");
        let y = probe(&probes, "reference y axis near its tip");
        assert!(
            x.x > x0.x + 50.0 && (x.y - x0.y).abs() < 1.5,
            "{src}: {x:?}"
        );
        assert!(
            y.y < y0.y - 50.0 && (y.x - y0.x).abs() < 1.5,
            "{src}: {y:?}"
        );
        check_pixels(src, &svg, &probes);
    }
    // The plane has no ẑ.
    let (_, probes) = one("p = draw(SE2(pi/2, 1, 2))");
    assert!(probes.iter().all(|p| !p.what.contains(" z axis")));
    // A rotated frame: Rot(ẑ, π/2) seen from above sends x̂ up.
    let (_, probes) = one("R_sb = Rotz(pi/2)\np = draw(R_sb, view(0, pi/2))");
    let o = probe(&probes, "{b} x axis near its origin");
    let x = probe(&probes, "{b} x axis near its tip");
    assert!(x.y < o.y - 50.0 && (x.x - o.x).abs() < 1.5, "{x:?}");
}

#[test]
fn the_output_is_deterministic_and_says_what_it_shows() {
    let src = "S = ScrewToAxis((3, 0, 0), (0, 0, 1), 2)\np = draw(S, Trans((1, 2, 3)))";
    let (a, _) = one(src);
    let (b, _) = one(src);
    assert_eq!(a, b);
    assert!(a.starts_with("<svg"));
    let pics = pictures(src, &scratch("summary"));
    assert_eq!(pics[0].1.summary, "1 frame and 1 screw axis in {s}");
    assert!(a.contains("h = 2"), "the pitch is written beside the axis");
}

#[test]
fn printed_pictures_are_written_where_the_line_says() {
    let dir = scratch("cli-default");
    let (code, out, err) = run_in(&["-e", "pic = draw(Rotx(pi/4))\ndraw(Roty(1))"], &dir);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("pic = picture: 1 frame in {s} → pic.svg"),
        "{out}"
    );
    assert!(
        out.contains("picture: 1 frame in {s} → draw-2.svg"),
        "{out}"
    );
    assert!(dir.join("pic.svg").is_file() && dir.join("draw-2.svg").is_file());
    // --draw-dir, created when missing; save() writes PNG by the name.
    let (code, out, err) = run_in(
        &[
            "--draw-dir",
            "figs",
            "-e",
            "p = draw(Rotx(1))\nsave(p, \"p.png\")",
        ],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("→ figs/p.svg"), "{out}");
    assert!(out.contains("→ p.png"), "{out}");
    let png = std::fs::read(dir.join("p.png")).expect("the PNG");
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    // JSON names the type and the file.
    let (_, out, _) = run_in(&["--json", "-e", "q = draw(Rotz(1))"], &dir);
    assert!(out.contains("\"type\":\"picture\""), "{out}");
    assert!(out.contains("\"file\":\"q.svg\""), "{out}");
    // A --draw-dir that cannot be made is bad usage (exit 2).
    std::fs::write(dir.join("a-file"), "x").expect("writes");
    let (code, _, err) = run_in(&["--draw-dir", "a-file/sub", "-e", "1"], &dir);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("cannot use --draw-dir 'a-file/sub'"), "{err}");
    std::fs::remove_file(dir.join("a-file")).expect("removes");
    // No temporary files are left behind.
    let stray: Vec<_> = std::fs::read_dir(&dir)
        .expect("lists")
        .flatten()
        .filter(|e| e.file_name().to_string_lossy().ends_with(".tmp"))
        .collect();
    assert!(stray.is_empty());
}

/// `view(30, 45)`, MATLAB's habit (degrees), is 30 and 45 radians here,
/// as every angle (§2): the view is made, with a warning that says so and
/// gives `view(30 deg, 45 deg)` (it was silent: a picture seen from
/// azimuth 1718.87°). Angles within a turn are not warned about.
#[test]
fn a_view_in_degrees_is_warned_to_be_radians() {
    let dir = scratch("view-degrees");
    let (code, out, err) = run_in(&["--no-write", "-e", "draw(Rotz(1), view(30, 45))"], &dir);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        err.contains("warning: view takes radians, as every angle in chasles: view(30, 45) is azimuth 1718.87°, elevation 2578.31°"),
        "{err}"
    );
    assert!(
        err.contains("help: for degrees, as MATLAB's view(az, el), write view(30 deg, 45 deg)"),
        "{err}"
    );
    for src in ["view(30 deg, 45 deg)", "view(-3, 1.5)", "view(0, pi/2)"] {
        let (code, _, err) = run_in(&["-e", src], &dir);
        assert_eq!(code, 0, "{src}");
        assert!(!err.contains("radians"), "{src}: {err}");
    }
}

#[test]
fn bad_input_is_a_clear_error_and_no_file() {
    let dir = scratch("cli-errors");
    let cases: &[(&str, &str)] = &[
        ("draw(3)", "type error: cannot draw a scalar"),
        (
            "draw((inf, 0, 0))",
            "domain error: cannot draw a value with inf or NaN entries",
        ),
        ("draw(view(0, 1))", "nothing to draw"),
        (
            "save(draw(Rotz(1)), \"/no/such/folder/x.svg\")",
            "cannot write '/no/such/folder/x.svg': no such folder",
        ),
        (
            "save(draw(Rotz(1)), \"x.pdf\")",
            "the name must end in .svg or .png",
        ),
        (
            "xs = 0:1e7",
            "the list would have 10000001 items; lists are limited to 1000000",
        ),
        (
            "[k for k in 0:1000, j in 0:10000]",
            "the list would have 10011001 items",
        ),
        (
            "[[a * b for a in 0:999] for b in 0:999]",
            "the comprehensions would evaluate more than 2000000 items",
        ),
        (
            "T_sa = Trans((1, 0, 0))\nT_bc = Trans((0, 1, 0))\ndraw(T_sa, T_bc)",
            "frame error: one picture has one reference frame, but argument 1 is in {s} and argument 2 in {b}",
        ),
    ];
    for (src, want) in cases {
        let (code, out, err) = run_in(&["-e", src], &dir);
        assert_eq!(code, 1, "{src}: {out}{err}");
        assert!(err.contains(want), "{src}: {err}");
    }
    let files: Vec<_> = std::fs::read_dir(&dir).expect("lists").flatten().collect();
    assert!(files.is_empty(), "no file written: {files:?}");
}

#[test]
fn the_repl_writes_pictures_and_opens_the_last_one() {
    use chasles::repl::commands::execute;
    let dir = scratch("repl");
    let mut s = Session::new(Settings::default());
    s.gate = chasles::effects::Gate::anywhere(Some(dir.clone()));
    let r = execute(&mut s, ":open");
    assert!(r.err.contains("no picture yet"), "{r:?}");
    let r = execute(&mut s, "pic = draw(Rotz(pi/4))");
    assert!(r.out.contains("pic = picture: 1 frame in {s} →"), "{r:?}");
    assert!(dir.join("pic.svg").is_file());
    assert_eq!(
        s.last_picture.as_deref(),
        Some(dir.join("pic.svg").to_str().unwrap())
    );
    let help = execute(&mut s, ":help pictures");
    assert!(
        help.out.contains("0:pi/8:pi") && help.out.contains("draw"),
        "{help:?}"
    );
}

/// The marks of the last picture of `src`.
fn marks(src: &str) -> Vec<draw::marks::Mark> {
    let mut s = Session::new(Settings::default());
    let mut last = None;
    s.run(src, Mode::Run, false, |r| {
        if let Ok(o) = &r.result
            && let Some(Value::Picture(p)) = o.val.as_deref()
        {
            last = Some((**p).clone());
        }
    });
    let p = last.expect("a picture");
    let (scenes, _) = draw::scenes(&p).expect("draws");
    scenes.into_iter().flat_map(|s| s.marks).collect()
}

fn close(a: &nalgebra::Vector3<f64>, b: [f64; 3]) -> bool {
    (a - nalgebra::Vector3::from(b)).norm() < 1e-12
}

#[test]
fn marks_follow_the_book() {
    use draw::marks::Mark;
    // 3.26: the axis through q = (3, 0, 0) along ẑ, pitch 2.
    let m = marks("draw(ScrewToAxis((3, 0, 0), (0, 0, 1), 2))");
    let [Mark::Screw { q, s, pitch, .. }] = m.as_slice() else {
        panic!("{m:?}")
    };
    assert!(close(q, [3.0, 0.0, 0.0]) && close(s, [0.0, 0.0, 1.0]) && (pitch - 2.0).abs() < 1e-12);
    // 3.27: V = (0, 2, 2, 4, 0, 0): q = ω × v/‖ω‖² = (0, 1, −1), h = 0.
    let m = marks("draw((0, 2, 2, 4, 0, 0))");
    let [Mark::Screw { q, s, pitch, .. }] = m.as_slice() else {
        panic!("{m:?}")
    };
    let r = 0.5f64.sqrt();
    assert!(close(q, [0.0, 1.0, -1.0]) && close(s, [0.0, r, r]) && pitch.abs() < 1e-12);
    // A pure translation: pitch ∞ along v̂.
    let m = marks("draw(twist((0, 0, 0), (0, 3, 0)))");
    let [Mark::Screw { s, pitch, .. }] = m.as_slice() else {
        panic!("{m:?}")
    };
    assert!(close(s, [0.0, 1.0, 0.0]) && pitch.is_infinite());
    // T_sa draws {a} at its pose, labelled from the tag.
    let m = marks("T_sa = RpToTrans(Rotz(pi/2), (1, 2, 3))\ndraw(T_sa)");
    let [
        Mark::Frame {
            origin,
            axes,
            label,
        },
    ] = m.as_slice()
    else {
        panic!("{m:?}")
    };
    assert!(close(origin, [1.0, 2.0, 3.0]) && close(&axes[0], [0.0, 1.0, 0.0]));
    assert_eq!(label, "{a}");
    // The plane: SE(2) at (x, y), and a planar twist's centre of rotation:
    // V = (ω, vx, vy) = (1, 0, -2) turns about (2, 0), since v = −ω × c.
    let m = marks("draw(SE2(pi/2, 1, 2), se2(1, 0, -2))");
    let [Mark::Frame { origin, .. }, Mark::Centre { at, .. }] = m.as_slice() else {
        panic!("{m:?}")
    };
    assert!(close(origin, [1.0, 2.0, 0.0]) && close(at, [2.0, 0.0, 0.0]));
    // A vector is an arrow; the vectors of a list are points.
    let m = marks("draw((1, 2, 3), [(k, 0, 0) for k in 1:2], arrow((1, 0, 0), (0, 1, 0)))");
    assert!(matches!(m[0], Mark::Arrow { .. }));
    assert!(matches!(m[1], Mark::Dot { .. }) && matches!(m[2], Mark::Dot { .. }));
    let Mark::Arrow { from, dir, .. } = &m[3] else {
        panic!("{m:?}")
    };
    assert!(close(from, [1.0, 0.0, 0.0]) && close(dir, [0.0, 1.0, 0.0]));
    // A path of frames is labelled in order ({b} moved by an untagged T).
    let m = marks("T_sb = Trans((1, 0, 0))\ndraw([T_sb * Trans((0, 0, k)) for k in 0:2])");
    let labels: Vec<&str> = m
        .iter()
        .filter_map(|x| match x {
            Mark::Frame { label, .. } => Some(label.as_str()),
            _ => None,
        })
        .collect();
    // ... and joined by the path through their origins.
    assert!(
        matches!(m.last(), Some(Mark::Path { points }) if points.len() == 3 && close(&points[2], [1.0, 0.0, 2.0])),
        "{m:?}"
    );
    assert_eq!(labels, ["{b'}₁", "{b'}₂", "{b'}₃"]);
}

#[test]
fn a_png_shows_the_axes_where_the_svg_has_them() {
    let dir = scratch("png");
    let src = format!(
        "T_sa = RpToTrans(Rotz(0.5), (1, 1, 0))\npic = draw(T_sa, ScrewToAxis((0, 1, 0), (0, 0, 1), 1))\nsave(pic, \"{}\")",
        dir.join("pic.png").display()
    );
    let pics = pictures(&src, &dir);
    let (_, p) = pics.last().expect("saved");
    assert_eq!(
        p.file.as_deref(),
        Some(dir.join("pic.png").to_str().unwrap())
    );
    let (_, probes) = draw::svg(p).expect("draws");
    let png = std::fs::read(dir.join("pic.png")).expect("the PNG");
    let pm = resvg::tiny_skia::Pixmap::decode_png(&png).expect("a PNG");
    assert_eq!((pm.width(), pm.height()), (draw::PANEL_W, draw::PANEL_H));
    check_pixmap("pic.png", &pm, &probes);
}
