//! Symbolic values for people (LANGUAGE.md §7): a scalar as its canonical
//! expression, wrapped at `+`/`-` with continuation lines aligned; a
//! matrix with aligned columns, or one entry per line when a row is too
//! wide; in `--latex` a `bmatrix`. The mathematics of printing is in
//! [`crate::sym::print`]; this adapts it to the output settings.

use super::text::Style;
use crate::sym::Mat;
use crate::sym::print::{self, Mode};

/// Lines of text output are wrapped to this width.
pub const WIDTH: usize = 100;

fn sym_style(style: Style) -> print::Style {
    print::Style {
        mode: style.sym,
        digits: style.digits,
    }
}

/// A formula on one line: `cos(t)`, `(L1 cos(t1), L1 sin(t1), 0)`,
/// `[cos(t), -sin(t); sin(t), cos(t)]`.
pub fn inline(m: &Mat, style: Style) -> String {
    let st = sym_style(style);
    if st.mode == Mode::Latex {
        return latex(m, style);
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
pub fn latex(m: &Mat, style: Style) -> String {
    let st = print::Style {
        mode: Mode::Latex,
        digits: style.digits,
    };
    if m.data.len() == 1 {
        return print::expr(&m.data[0], st);
    }
    print::matrix(&m.row_vecs(), st, 0, usize::MAX)
}

/// A formula as the value of a statement, starting at column `indent`.
pub fn block(m: &Mat, style: Style, indent: usize) -> String {
    let st = sym_style(style);
    if st.mode == Mode::Latex {
        return latex(m, style);
    }
    match (m.rows, m.cols) {
        (1, 1) => print::join(&print::terms(&m.data[0], st), WIDTH, indent),
        (_, 1) => {
            let one = inline(m, style);
            if one.chars().count() + indent <= WIDTH {
                one
            } else {
                print::matrix(&m.row_vecs(), st, indent, WIDTH)
            }
        }
        _ => print::matrix(&m.row_vecs(), st, indent, WIDTH),
    }
}
