//! What a notebook shows for one statement's value (LANGUAGE.md §13): a
//! MIME bundle with `text/plain` as the terminal prints it,
//! `application/json` as `--json` prints it, `text/latex` for matrices,
//! vectors and symbolic values (a `bmatrix` with the name, the type and
//! the frames), and `image/svg+xml` for a picture. Only printing: the
//! values come from the session.

use serde_json::{Map, Value as J, json};

use crate::check::ty::Ty;
use crate::eval::interp::Outcome;
use crate::output::{formula, json as json_out, text};
use crate::session::Settings;
use crate::sym::print::Mode;
use crate::values::format::{Style, formula_latex};
use crate::values::num::Num;
use crate::values::value::Value;

/// The MIME bundle of a statement's outcome (None when it prints nothing).
pub fn bundle(o: &Outcome, line: usize, settings: &Settings) -> Option<Map<String, J>> {
    if !o.prints {
        return None;
    }
    let style = Settings {
        json: false,
        ..*settings
    }
    .text_style();
    let mut data = Map::new();
    data.insert("text/plain".into(), json!(text::show_outcome(o, style)));
    if let Some(latex) = outcome_latex(o, style) {
        data.insert("text/latex".into(), json!(latex));
    }
    if let Some(Value::Picture(p)) = o.val.as_deref()
        && !p.is_view_only()
        && let Ok((svg, _)) = crate::draw::svg(p)
    {
        data.insert("image/svg+xml".into(), json!(svg));
    }
    if let Some(j) = json_out::outcome(o, line) {
        data.insert("application/json".into(), j);
    }
    Some(data)
}

/// The LaTeX of an outcome with one value (bound to one name or none):
/// `$T_{sb} = \begin{bmatrix} … \end{bmatrix} \quad \text{SE(3)}\ \{s\}\leftarrow\{b\}$`.
/// None for values that read as well in text (numbers, tuples, lists,
/// mechanisms, pictures).
pub fn outcome_latex(o: &Outcome, style: Style) -> Option<String> {
    if !o.steps().is_empty() {
        return Some(crate::output::steps::latex(o.steps(), style));
    }
    let v = o.val.as_deref()?;
    let body = value_latex(v, style)?;
    let name = match o.names.as_slice() {
        [] => String::new(),
        [n] => formula::name_prefix(
            &format!("{n} = "),
            Style {
                sym: Mode::Latex,
                ..style
            },
        ),
        _ => return None,
    };
    Some(format!("${name}{body}{}$", label_latex(&o.ty, v)))
}

/// A value's LaTeX body: a symbolic value as its formula, a numeric
/// matrix or vector as a `bmatrix` of its printed numbers.
pub fn value_latex(v: &Value, style: Style) -> Option<String> {
    // `:exact`: a value with an exact form prints it (LANGUAGE.md §10).
    if style.exact
        && v.may_be_exact()
        && let Some(m) = v.exact_form().filter(|m| match v {
            Value::Num { m: floats, .. } => {
                !crate::values::exact::prints_as_decimals(m, style.digits, floats)
            }
            _ => true,
        })
    {
        return Some(formula_latex(&m, style));
    }
    match v {
        Value::Formula { m, .. } => Some(
            crate::values::waiting::text(
                v,
                Style {
                    sym: crate::sym::print::Mode::Latex,
                    ..style
                },
            )
            .unwrap_or_else(|| formula_latex(m, style)),
        ),
        Value::Num { m, .. } if m.len() > 1 => Some(matrix_latex(m, style)),
        _ => None,
    }
}

/// A numeric matrix (a vector as a column) as a `bmatrix`, each entry as
/// the terminal prints it (digits, `:exact` closed forms).
pub fn matrix_latex(m: &Num, style: Style) -> String {
    let rows: Vec<String> = (0..m.nrows())
        .map(|i| {
            (0..m.ncols())
                .map(|j| number_latex(&style.num(m[(i, j)])))
                .collect::<Vec<_>>()
                .join(" & ")
        })
        .collect();
    format!(
        "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
        rows.join(" \\\\ ")
    )
}

/// A printed number as LaTeX: `π` as `\pi`, `√3` as `\sqrt{3}`, `inf`
/// as `\infty`.
pub fn number_latex(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 8);
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            'π' => out.push_str("\\pi "),
            '√' => {
                let mut arg = String::new();
                while let Some(&d) = chars.peek() {
                    if d.is_ascii_digit() || d == '.' {
                        arg.push(d);
                        chars.next();
                    } else {
                        break;
                    }
                }
                out.push_str(&format!("\\sqrt{{{arg}}}"));
            }
            '−' => out.push('-'),
            _ => out.push(c),
        }
    }
    match out.trim() {
        "inf" => "\\infty".into(),
        "-inf" => "-\\infty".into(),
        "NaN" => "\\text{NaN}".into(),
        t => t.trim_end().to_string(),
    }
}

/// The type and frames after a value: `\quad \text{SE(3)}\ \{s\}\leftarrow\{b\}`.
fn label_latex(ty: &Ty, v: &Value) -> String {
    let label = text::type_label(ty, Some(v));
    if label.is_empty() {
        return String::new();
    }
    let (kind, frames) = match label.find(" {") {
        Some(i) => (&label[..i], &label[i + 1..]),
        None => (label.as_str(), ""),
    };
    let kind = kind
        .split('×')
        .map(|part| format!("\\text{{{part}}}"))
        .collect::<Vec<_>>()
        .join("{\\times}");
    let mut out = format!(" \\quad {kind}");
    if !frames.is_empty() {
        let frames = frames
            .replace('{', "\\{")
            .replace('}', "\\}")
            .replace('←', "\\leftarrow ");
        out.push_str(&format!("\\ {frames}"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_as_latex() {
        assert_eq!(number_latex("√3/2"), "\\sqrt{3}/2");
        assert_eq!(number_latex("-π/6"), "-\\pi /6");
        assert_eq!(number_latex("0.866"), "0.866");
        assert_eq!(number_latex("inf"), "\\infty");
    }
}
