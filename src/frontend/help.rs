//! `:help` (LANGUAGE.md §11), generated from the one builtin table: the
//! overview lists the topics and every function by area; `:help NAME`
//! gives a function's signature, meaning, book section and example, with
//! the example's result; keywords, units and operators are answered from
//! [`super::keywords`], commands from their table.

use super::commands::COMMANDS;
use crate::builtins::{self, Area, Builtin};
use crate::diagnostics::suggest::did_you_mean;
use crate::eval::env::Mode;
use crate::session::{Session, Settings};

/// Help topics other than functions: (name, text).
pub const TOPICS: &[(&str, &str)] = &[
    (
        "syntax",
        "\
statements end at a newline or `;`; a newline inside ( ) or [ ] continues
  x = 2 pi / 3              bind a name (juxtaposition multiplies)
  (1, 2, 3)   [1, 2, 3]     column vectors
  [1, 0; 0, 1]              a matrix; rows split by `;` or newline
  [R, p; 0, 0, 0, 1]        block matrices, as in MATLAB
  [w]   [V]                 the book's bracket: so(3), se(3)
  30 deg   30°   pi   π     angles in radians
  T.R  T.p  V.w  V.v  M.T   parts of a transform or twist; transpose
  S.w  S.v  F.m  F.f        parts of a screw axis (ω, v) and of a wrench (m, f)
  M[1, 2]  M[:, 1]  v[3]    1-based indexing, as in the book
  S[1:3]  T[1:3, 4]  v[end] ranges and `end` index too (MATLAB's)
  R (1, 0, 0)  n (n - 1)    a value before a parenthesis multiplies
  R^T (p)   Rᵀ   R^{-1}     ^T always transposes; the inverse
  √2  √(x + 1)  1/√2        square roots, as --exact prints them
  u · v   u × v             dot and cross products (also dot(u, v), cross(u, v))
  (w, th) = AxisAng3(v)     destructure a tuple
  a == b   a ≈ b (a ~= b)   exactly equal; equal within 1e-9 relative (a bool)
  a < b  a <= b  a > b  a >= b   order of numbers (a bool)
  assert T ≈ T_book         stop the script, showing both sides, when false
  f(x) = x^2                a user function
  ans                       the last result",
    ),
    (
        "frames",
        "\
a name's subscript gives its frames: T_sb is {s}←{b}, p_b and V_s one frame
  T_ab * T_bc  → {a}←{c}     inner frames must cancel, else a frame error
  R_ab * v_b   → v_a         T_ab * p_b → p_a for a point p (3.65)
  inv(T_ab), R_ab.T → {b}←{a}   T_ab.T is no transform: inv(T_ab) is
  Ad(T_ab) * V_b → V_a      Ad(T_ab).T * F_a → F_b (wrenches, Prop. 3.17)
  exp([S_s] θ) * T_sb       a displacement in {s}: {s}←{b'}
points p, q, r move with T; free vectors ω (w), v, f, m and axes ω̂, ŝ only
rotate: T_sb * ω_b is an error, write R_sb * ω_b (Ad(T_sb) * V_b for a twist);
  given u_b : free          say it for another name (given c : point)
  x_a, y_a, z_a (x̂_a)       the axes of {a}, untagged: R_sa = [x_a, y_a, z_a]
  V_s = (w_s, v_s)          named as a twist: the 6-vector (ω, v); F = (m, f)
  Rx, R1 (no subscript)     R_x would name a frame {x}
  scalars and bools (theta_b, ok_a) carry no frames
  untag(x)                  drop the frames of a value
  derive T_ce               find a chain of known transforms from {c} to {e}
:frames shows the graph of known transforms; :frames strict|warn|off sets
whether a mismatch is an error, a warning, or ignored",
    ),
    (
        "symbols",
        "\
given T_ab, T_bc : SE3      symbols with a type and frames but no numbers
  types: scalar vec3 vec6 SO3 SE3 SO2 SE2 so3 se3 twist screw wrench free point
  T_ab * T_bc               → T_ab T_bc : SE(3) {a}←{c}, checked like numbers
  inv(T_ab) * T_ab          → I
given t1, t2, L1 : scalar   symbols computed with (§7): Rotz(t1), exp([S] t1)
given α, β                  scalars: the type is needed only for other kinds
  Rotz(t1) Rotz(t2)         → [cos(t1 + t2), …]: angle sums folded, sin² + cos² = 1
  simplify(x), x == y       the canonical form; equality with no numbers
given theta(t) : scalar     a function of time: theta' is θ̇, diff(R, t) R^T = [ω_s]
:short, :latex              print c₁₂ or LaTeX (also --short, --latex)
binding numbers later makes them numeric",
    ),
];

/// The syntax of mechanisms, shown with `:help mechanisms`.
const MECH_SYNTAX: &str = "\
mech < links 4; joints 4R; planar >        Grübler's formula, step by step
mech < links 8; joints 8R P; planar >      8R = eight R joints
mech < legs 6 UPS; spatial >               a parallel mechanism
mech < links N; joints 7RP, 6 sliding; planar >   counts may be names; contacts
  joints R P H (f = 1), C U (f = 2), S (f = 3); planar, spherical, spatial
  point contacts (exercises 2.17–2.19): rolling (no slip; f = 1 planar, 3 spatial),
  sliding (frictionless; f = 2 planar, 5 spatial)
dof(m) gives the number";

/// Ranges, lists and pictures, shown with `:help pictures` (§12).
const LIST_SYNTAX: &str = "\
0:4   0:pi/8:pi                        ranges as in MATLAB, the end included
[k^2 for k in 0:4]                     a list; [f(a, b) for a in r1, b in r2] a grid
[f(a, b) for a in r1 for b in r2]      the same grid, as Python writes it
linspace(0, pi, 5)                     n numbers from a to b (a:step:b gives a step)
xs[2]   (a, b) = xs   len(xs)          index from 1, destructure
pic = draw(T_sa, S)                    written to pic.svg (--draw-dir DIR); :open shows it
save(pic, \"f.png\")   view(30 deg, 20 deg)   beside(p1, p2)
  view(az, el) takes radians, as every angle: view(30 deg, 20 deg), view(pi/6, pi/9)
[point(p) for p in ps]   draw(pts)     a list of points draws";

/// The whole `:help` answer for `arg` (trimmed); Err is the message for
/// an unknown name, with a did-you-mean.
pub fn help(arg: &str, settings: &Settings) -> Result<String, String> {
    let arg = arg.trim();
    if arg.is_empty() {
        return Ok(overview());
    }
    if let Some(b) = builtins::lookup(arg) {
        return Ok(function(b, settings));
    }
    if let Some(text) = super::keywords::keyword(arg) {
        return Ok(text.to_string());
    }
    if let Some((_, text)) = TOPICS.iter().find(|(t, _)| *t == arg) {
        return Ok(text.to_string());
    }
    if let Some(area) = area_named(arg) {
        return Ok(area_listing(area));
    }
    let bare = arg.trim_start_matches(':').trim_end_matches('!');
    if let Some(c) = COMMANDS.iter().find(|c| c.name == bare) {
        let head = format!(":{} {}", c.name, c.args);
        return Ok(format!("{}\n  {}", head.trim_end(), c.doc));
    }
    let mut names = builtins::all_names();
    names.extend(super::keywords::words());
    names.extend(TOPICS.iter().map(|(t, _)| *t));
    names.extend(COMMANDS.iter().map(|c| c.name));
    let mut msg = format!("no help for '{arg}'");
    if let Some(s) = crate::diagnostics::habits::conversion(bare) {
        msg.push_str(&format!("; {s}"));
    } else if let Some(s) = did_you_mean(bare, &names) {
        msg.push_str(&format!("; did you mean '{s}'?"));
    }
    msg.push_str(" (:help lists everything)");
    Err(msg)
}

/// The overview: commands, topics, then every function by area.
fn overview() -> String {
    let mut out = String::from("commands:\n");
    for c in COMMANDS {
        let head = format!(":{} {}", c.name, c.args);
        out.push_str(&format!("  {:<27}{}\n", head.trim_end(), c.doc));
    }
    let topics: Vec<&str> = TOPICS.iter().map(|(t, _)| *t).collect();
    out.push_str(&format!("topics: :help {}\n", topics.join(" | ")));
    let words: Vec<&str> = super::keywords::KEYWORDS
        .iter()
        .map(|(names, _)| names[0])
        .collect();
    out.push_str(&format!("words:  :help {}\n", words.join(" | ")));
    out.push_str("functions by area (:help NAME for one, :help AREA for an area):\n");
    for area in Area::ALL {
        let names: Vec<&str> = in_area(area).map(|b| b.name).collect();
        if names.is_empty() {
            continue;
        }
        out.push_str(&format!("  {} — {}\n", area_key(area), area.title()));
        out.push_str(&wrap(&names, "    ", 78));
    }
    out.trim_end().to_string()
}

/// The functions of one area with their one-line meanings.
fn area_listing(area: Area) -> String {
    let mut out = format!("{}\n", area.title());
    if area == Area::Mechanisms {
        out.push_str(MECH_SYNTAX);
        out.push('\n');
    }
    if area == Area::Pictures {
        out.push_str(LIST_SYNTAX);
        out.push('\n');
    }
    let items: Vec<&Builtin> = in_area(area).collect();
    let width = items.iter().map(|b| b.name.len()).max().unwrap_or(0);
    for b in items {
        out.push_str(&format!("  {:<width$}  {}\n", b.name, b.doc));
    }
    out.trim_end().to_string()
}

/// One function: signature and section, meaning, aliases, example and
/// the example's result (run in a fresh session with these settings).
pub fn function(b: &Builtin, settings: &Settings) -> String {
    let mut out = b.signature.to_string();
    if !b.section.is_empty() && b.section != "—" {
        out.push_str(&format!("    {}", b.section));
    }
    out.push_str(&format!("\n  {}", b.doc));
    if let Some(d) = builtins::python::difference(b.name) {
        out.push_str(&format!("\n  unlike the book's Python library: {d}"));
    }
    if !b.aliases.is_empty() {
        out.push_str(&format!("\n  also: {}", b.aliases.join(", ")));
    }
    if !b.example.is_empty() {
        out.push_str(&format!("\n  example: {}", b.example));
        let mut fresh = Session::new(Settings {
            json: false,
            ..*settings
        });
        let (res, _, errors) = fresh.run_to_strings("<example>", b.example, Mode::Run, false);
        if errors == 0 && !res.trim().is_empty() {
            for line in res.trim_end().lines() {
                out.push_str(&format!("\n    {line}"));
            }
        }
    }
    out
}

/// The builtins of an area, in table order.
fn in_area(area: Area) -> impl Iterator<Item = &'static Builtin> {
    builtins::table()
        .iter()
        .filter(move |b| b.area == area && !b.name.is_empty())
}

/// The one-word name of an area for `:help AREA`.
pub fn area_key(area: Area) -> &'static str {
    match area {
        Area::Rotations => "rotations",
        Area::Transforms => "transforms",
        Area::Twists => "twists",
        Area::Representations => "representations",
        Area::Tests => "tests",
        Area::LinearAlgebra => "linear",
        Area::Scalars => "scalars",
        Area::Mechanisms => "mechanisms",
        Area::Pictures => "pictures",
    }
}

fn area_named(name: &str) -> Option<Area> {
    Area::ALL
        .into_iter()
        .find(|a| area_key(*a).eq_ignore_ascii_case(name))
}

/// Words joined by spaces, wrapped at `width` columns after `indent`.
fn wrap(words: &[&str], indent: &str, width: usize) -> String {
    let mut out = String::new();
    let mut line = String::from(indent);
    for w in words {
        if line.len() > indent.len() && line.chars().count() + 1 + w.chars().count() > width {
            out.push_str(line.trim_end());
            out.push('\n');
            line = String::from(indent);
        }
        if line.len() > indent.len() {
            line.push(' ');
        }
        line.push_str(w);
    }
    if line.len() > indent.len() {
        out.push_str(&line);
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_area_key_is_found() {
        for a in Area::ALL {
            assert_eq!(area_named(area_key(a)), Some(a));
        }
    }

    #[test]
    fn wrap_keeps_lines_short() {
        let words = ["alpha"; 40];
        for line in wrap(&words, "  ", 30).lines() {
            assert!(line.len() <= 30, "{line}");
        }
    }
}
