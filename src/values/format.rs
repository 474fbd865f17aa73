//! Values and numbers on one line, for people: the [`Style`] of numbers
//! (LANGUAGE.md §10, `--digits` and the REPL's `:exact`) and [`inline`],
//! the one-line form of a value that also names constants inside symbolic
//! expressions. Below evaluation, so the evaluator can print without
//! importing the output layer; multi-line blocks and JSON are in `output`.

use super::number::fmt_num;
use super::value::Value;

/// How numbers print: `digits` decimals (trailing zeros trimmed), or with
/// `exact`, a closed form such as `1/√2` or `π/6` where one is within
/// 1e-12 (the REPL's `:exact`). A plain `usize` converts to decimals only.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Style {
    /// Decimals.
    pub digits: usize,
    /// Print simple closed forms (`√3/2`, `-π/2`) instead of decimals.
    pub exact: bool,
}

impl Style {
    /// One number in this style.
    pub fn num(self, x: f64) -> String {
        self.exact
            .then(|| super::exact::closed_form(x))
            .flatten()
            .unwrap_or_else(|| fmt_num(x, self.digits))
    }
}

impl From<usize> for Style {
    fn from(digits: usize) -> Style {
        Style {
            digits,
            exact: false,
        }
    }
}

/// A value on one line: `2`, `(1, 2, 3)`, `[1, 2; 3, 4]`.
pub fn inline(v: &Value, style: impl Into<Style>) -> String {
    let style = style.into();
    match v {
        Value::Num { m, .. } if m.is_empty() => format!("zeros({}, {})", m.nrows(), m.ncols()),
        Value::Num { m, .. } if m.len() == 1 && m.ncols() == 1 && m.nrows() == 1 => style.num(m[0]),
        Value::Num { m, .. } if m.ncols() == 1 => {
            let xs: Vec<String> = m.iter().map(|x| style.num(*x)).collect();
            format!("({})", xs.join(", "))
        }
        // A row: `[a, b]` would read back as a column, so print its transpose.
        Value::Num { m, .. } if m.nrows() == 1 => {
            let xs: Vec<String> = m.iter().map(|x| style.num(*x)).collect();
            format!("({}).T", xs.join(", "))
        }
        Value::Num { m, .. } => {
            let rows: Vec<String> = m
                .row_iter()
                .map(|r| {
                    r.iter()
                        .map(|x| style.num(*x))
                        .collect::<Vec<_>>()
                        .join(", ")
                })
                .collect();
            format!("[{}]", rows.join("; "))
        }
        Value::Bool(b) => b.to_string(),
        Value::Tuple(vs) => {
            let xs: Vec<String> = vs.iter().map(|x| inline(x, style)).collect();
            format!("({})", xs.join(", "))
        }
        Value::Mech(m) => format!("mech < {} >", m.joints_text()),
        Value::Sym(s) => s.to_string(),
    }
}
