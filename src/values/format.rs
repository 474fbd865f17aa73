//! Values and numbers on one line, for people: the [`Style`] of numbers
//! (LANGUAGE.md §10, `--digits` and the REPL's `:exact`) and [`inline`],
//! the one-line form of a value that also names constants inside symbolic
//! expressions, and symbolic values in text, shorthand or LaTeX
//! ([`formula_inline`], [`formula_latex`]). Below evaluation, so the evaluator can print without
//! importing the output layer; multi-line blocks and JSON are in `output`.

use std::fmt::Write;

use super::num::Num;
use super::number::{write_num, write_tuple};
use super::value::Value;
use crate::sym::Mat;
use crate::sym::print::{self, Mode};

/// How numbers print: `digits` decimals (trailing zeros trimmed); with
/// `exact`, values that have an exact form print it (`1/√2`, `(1/9) π`;
/// the REPL's `:exact`). A plain `usize` converts to decimals only.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Style {
    /// Decimals.
    pub digits: usize,
    /// Print exact forms (`√3/2`, `-(1/2) π`) instead of decimals.
    pub exact: bool,
    /// Symbolic values: plain text, the book's shorthand or LaTeX (§7).
    pub sym: Mode,
}

impl Style {
    /// One number in this style.
    pub fn num(self, x: f64) -> String {
        let mut s = String::new();
        self.write(&mut s, x);
        s
    }
    /// One number in this style, appended to `out` (decimals: `--exact`
    /// prints a value's exact form, which [`exact_text`] finds, never a
    /// closed form guessed from a float).
    pub fn write(self, out: &mut String, x: f64) {
        write_num(out, x, self.digits);
    }
}

/// What `--exact` prints for a value in place of its decimals.
pub struct ExactText {
    /// The entries as exact numbers.
    pub m: Mat,
    /// True when they are the simple closed forms the floats are a
    /// rounding of, not the value's exact form: printed after `≈ `.
    pub rounded: bool,
}

impl ExactText {
    /// Appends the entries after a prefix ending at column `indent` (a
    /// matrix as an aligned block, or on one line when `inline`), after
    /// `≈ ` when they are a float's rounding.
    pub fn write(&self, out: &mut String, style: Style, indent: usize, inline: bool) {
        let indent = match self.rounded {
            true => {
                out.push_str("≈ ");
                indent + 2
            }
            false => indent,
        };
        out.push_str(&super::exact::block(
            &self.m,
            sym_style(style),
            indent,
            inline,
        ));
    }
}

/// The exact form `--exact` prints for a value (LANGUAGE.md §1, §10): its
/// entries as exact numbers (`1/√2`, `(1/9) π`), when it has an exact form
/// that is not just the decimals it prints anyway (`0.866` stays `0.866`);
/// for a float with none, the simple closed forms it is a rounding of,
/// marked as such (`≈ (0, 0, π/3)`: the value is a float, and a float a
/// few units from 22√7/21 need not be it).
#[inline]
pub fn exact_text(v: &Value, style: Style) -> Option<ExactText> {
    if !style.exact || style.sym == Mode::Latex {
        return None;
    }
    if !v.may_be_exact() || v.exact_form().is_none() {
        let m = closed_form_text(v, style.digits)?;
        return Some(ExactText { m, rounded: true });
    }
    let m = exact_form_text(v, style.digits)?;
    Some(ExactText { m, rounded: false })
}

/// The simple closed forms `--exact` prints for a float with no exact form
/// ([`super::closed_form`]: a rounding of `π/3`, `1/√2`), when every
/// entry has one and they are not just the decimals it prints anyway.
#[cold]
fn closed_form_text(v: &Value, digits: usize) -> Option<Mat> {
    let Value::Num { m, .. } = v else {
        return None;
    };
    let (rows, cols) = m.shape();
    let xs: Vec<f64> = (0..rows).flat_map(|i| m.row(i)).collect();
    super::closed_form::of_floats(&xs, rows, cols)
        .filter(|f| !super::exact::prints_as_decimals(f, digits, m))
}

/// [`exact_text`] once `--exact` asks for it.
#[cold]
fn exact_form_text(v: &Value, digits: usize) -> Option<Mat> {
    let Value::Num { m: floats, .. } = v else {
        return v.exact_form();
    };
    v.exact_form()
        .filter(|m| !super::exact::prints_as_decimals(m, digits, floats))
}

impl From<usize> for Style {
    fn from(digits: usize) -> Style {
        Style {
            digits,
            exact: false,
            sym: Mode::Text,
        }
    }
}

/// A value on one line: `2`, `(1, 2, 3)`, `[1, 2; 3, 4]`.
pub fn inline(v: &Value, style: impl Into<Style>) -> String {
    let mut s = String::new();
    write_inline(&mut s, v, style.into());
    s
}

/// Numbers separated by `, `.
fn write_list(out: &mut String, xs: impl Iterator<Item = f64>, style: Style) {
    for (i, x) in xs.enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        style.write(out, x);
    }
}

/// The numbers of a value, inline, as [`write_inline`] writes them when
/// no exact form is printed: a scalar, `(1, 2, 3)` for a column vector,
/// `(1, 2).T` for a row, `[1, 2; 3, 4]` for a matrix, `zeros(r, c)` for
/// an empty one.
pub fn write_numbers(out: &mut String, m: &Num, style: Style) {
    if m.is_empty() {
        let _ = write!(out, "zeros({}, {})", m.nrows(), m.ncols());
    } else if m.len() == 1 && m.ncols() == 1 && m.nrows() == 1 {
        style.write(out, m[0])
    } else if m.ncols() == 1 {
        if !write_tuple(out, m.as_slice(), style.digits, ")") {
            out.push('(');
            write_list(out, m.iter().copied(), style);
            out.push(')');
        }
    } else if m.nrows() == 1 {
        // A row: `[a, b]` would read back as a column, so print its
        // transpose.
        if !write_tuple(out, m.as_slice(), style.digits, ").T") {
            out.push('(');
            write_list(out, m.iter().copied(), style);
            out.push_str(").T");
        }
    } else {
        out.push('[');
        for i in 0..m.nrows() {
            if i > 0 {
                out.push_str("; ");
            }
            write_list(out, m.row(i), style);
        }
        out.push(']');
    }
}

/// [`inline`], appended to `out`.
pub fn write_inline(out: &mut String, v: &Value, style: Style) {
    if let Some(t) = exact_text(v, style) {
        return t.write(out, style, 0, true);
    }
    match v {
        Value::Num { m, .. } => write_numbers(out, m, style),
        Value::Bool(b) => out.push_str(if *b { "true" } else { "false" }),
        Value::Tuple(vs) => {
            out.push('(');
            for (i, x) in vs.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                write_inline(out, x, style);
            }
            out.push(')');
        }
        Value::Mech(m) => {
            let _ = write!(out, "mech < {} >", m.joints_text());
        }
        Value::Sym(s) => {
            let _ = write!(out, "{s}");
        }
        Value::List(vs) => {
            out.push('[');
            let n = vs.len();
            for (i, x) in vs.iter().enumerate() {
                // Long lists: the first LIST_HEAD items, …, the last two.
                if n > LIST_INLINE && i >= LIST_HEAD && i < n - 2 {
                    if i == LIST_HEAD {
                        out.push_str(", …");
                    }
                    continue;
                }
                if i > 0 {
                    out.push_str(", ");
                }
                write_inline(out, x, style);
            }
            out.push(']');
        }
        Value::Str(t) => {
            let _ = write!(out, "{t:?}");
        }
        Value::Picture(p) => out.push_str(&picture(p)),
        Value::Formula { m, .. } => match super::waiting::text(v, style) {
            Some(t) => out.push_str(&t),
            None => out.push_str(&formula_inline(m, style)),
        },
    }
}

/// Lists longer than this print their first [`LIST_HEAD`] and last two
/// items.
const LIST_INLINE: usize = 12;
const LIST_HEAD: usize = 8;

/// `picture: 5 frames and 1 screw axis in {s} → pic.svg` (LANGUAGE.md §12).
fn picture(p: &super::value::Picture) -> String {
    if p.is_view_only() {
        return p.summary.clone();
    }
    // Not printed on its own (an item of a list): what it holds.
    let summary = if p.summary.is_empty() {
        describe(p)
    } else {
        p.summary.clone()
    };
    match &p.file {
        Some(f) => format!("picture: {summary} → {f}"),
        None => format!("picture: {summary}"),
    }
}

/// The items of a picture that has no summary yet: `point (1, 0, 0)`,
/// `arrow (0, 0, 1)`, `T_sa`.
fn describe(p: &super::value::Picture) -> String {
    use super::value::Style;
    let items: Vec<String> = p
        .panels
        .iter()
        .flat_map(|q| q.items.iter())
        .map(|d| match d.style {
            Style::Point => format!("point {}", inline(&d.value, 4)),
            Style::Arrow => format!("arrow {}", inline(&d.value, 4)),
            Style::Natural if !d.label.is_empty() => d.label.clone(),
            Style::Natural => d.ty.kind.to_string(),
        })
        .collect();
    if items.is_empty() {
        "nothing".into()
    } else {
        items.join(", ")
    }
}

fn sym_style(style: Style) -> print::Style {
    print::Style {
        mode: style.sym,
        digits: style.digits,
    }
}

/// A formula on one line: `cos(t)`, `(L1 cos(t1), L1 sin(t1), 0)`,
/// `[cos(t), -sin(t); sin(t), cos(t)]`; LaTeX in that mode (§7).
pub fn formula_inline(m: &Mat, style: Style) -> String {
    let st = sym_style(style);
    if st.mode == Mode::Latex {
        return formula_latex(m, style);
    }
    let cells: Vec<String> = m.data.iter().map(|e| print::expr(e, st)).collect();
    match (m.rows, m.cols) {
        (1, 1) => cells[0].clone(),
        (_, 1) => format!("({})", cells.join(", ")),
        _ => {
            let rows: Vec<String> = cells.chunks(m.cols).map(|r| r.join(", ")).collect();
            format!("[{}]", rows.join("; "))
        }
    }
}

/// LaTeX math: an expression, or a `bmatrix` (vectors as a column).
pub fn formula_latex(m: &Mat, style: Style) -> String {
    let st = print::Style {
        mode: Mode::Latex,
        digits: style.digits,
    };
    if m.data.len() == 1 {
        return print::expr(&m.data[0], st);
    }
    print::matrix(&m.row_vecs(), st, 0, usize::MAX)
}
