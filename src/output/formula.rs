//! Symbolic values for people (LANGUAGE.md §7): a scalar as its canonical
//! expression, wrapped at `+`/`-` with continuation lines aligned; a
//! matrix with aligned columns, or one entry per line when a row is too
//! wide; in `--latex` a `bmatrix`. The mathematics of printing is in
//! [`crate::sym::print`]; this adapts it to the output settings.

use crate::sym::Mat;
use crate::sym::print::{self, Mode};
use crate::values::format::{Style, formula_inline as inline, formula_latex as latex};

/// Lines of text output are wrapped to this width.
pub const WIDTH: usize = 100;

/// `NAME = ` before a value; in LaTeX the name as LaTeX (`R_sb` is
/// `R_{sb}`, `theta1` is `\theta_1`), so the line stays valid LaTeX.
pub fn name_prefix(prefix: &str, style: Style) -> String {
    match prefix.strip_suffix(" = ") {
        Some(name) if style.sym == Mode::Latex && !name.is_empty() => {
            let st = print::Style {
                mode: Mode::Latex,
                digits: style.digits,
            };
            format!("{} = ", print::symbol(&crate::sym::Symbol::new(name), st))
        }
        _ => prefix.to_string(),
    }
}

/// A formula as the value of a statement, starting at column `indent`.
pub fn block(m: &Mat, style: Style, indent: usize) -> String {
    let st = print::Style {
        mode: style.sym,
        digits: style.digits,
    };
    if st.mode == Mode::Latex {
        return latex(m, style);
    }
    match (m.rows, m.cols) {
        (1, 1) => {
            crate::sym::layout::join_from(&print::terms(&m.data[0], st), WIDTH, indent, indent)
        }
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
