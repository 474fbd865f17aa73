//! The steps of `explain` (LANGUAGE.md §14) for people (numbered lines
//! with the book's reference and this case's value), as LaTeX (`--latex`,
//! notebooks) and as the JSON `steps` list.

use serde_json::{Value as J, json};

use crate::check::ty::Ty;
use crate::eval::explain::Shown;
use crate::values::format::Style;
use crate::values::value::Value;

/// `(3.54)` for an equation, `§3.2.3.3` for a section, the rest as it is
/// (`Prop. 3.16`, `Def. 3.6`, `Table 2.1`, `App. B`).
pub fn reference(r: &str) -> String {
    let numeric = r.chars().all(|c| c.is_ascii_digit() || c == '.');
    match r.matches('.').count() {
        1 if numeric => format!("({r})"),
        n if n >= 2 && numeric => format!("§{r}"),
        _ => r.to_string(),
    }
}

/// The steps as numbered lines: the formula and its reference, then the
/// value (none for the choice of a case), then the note.
pub fn text(steps: &[Shown], style: Style) -> String {
    let mut out = String::new();
    let width = steps.len().to_string().len();
    for (i, s) in steps.iter().enumerate() {
        let n = format!("{:>width$}. ", i + 1);
        let pad = " ".repeat(n.chars().count());
        out.push_str(&n);
        out.push_str(&s.text);
        out.push_str("  ");
        out.push_str(&reference(s.reference));
        out.push('\n');
        if !matches!(s.value, Value::Str(_) | Value::Mech(_)) {
            let ty = Ty::plain(s.value.kind());
            let prefix = format!("{pad}{} = ", s.name);
            out.push_str(&crate::output::text::show_value(
                &prefix, &ty, &s.value, style,
            ));
            out.push('\n');
        }
        if let Some(note) = &s.note {
            out.push_str(&pad);
            out.push_str("note: ");
            out.push_str(note);
            out.push('\n');
        }
    }
    if out.ends_with('\n') {
        out.pop();
    }
    out
}

/// A value in LaTeX: a number, a `bmatrix`, a formula; None for a case.
fn value_latex(v: &Value, style: Style) -> Option<String> {
    match v {
        Value::Num { m, .. } if m.len() == 1 => Some(number(&style.num(m[0]))),
        Value::Num { m, .. } => {
            let rows: Vec<String> = (0..m.nrows())
                .map(|i| {
                    (0..m.ncols())
                        .map(|j| number(&style.num(m[(i, j)])))
                        .collect::<Vec<_>>()
                        .join(" & ")
                })
                .collect();
            Some(format!(
                "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
                rows.join(" \\\\ ")
            ))
        }
        Value::Formula { m, .. } => Some(crate::values::format::formula_latex(
            m,
            Style {
                sym: crate::sym::print::Mode::Latex,
                ..style
            },
        )),
        Value::Mech(m) => Some(m.dof().to_string()),
        Value::Tuple(vs) => {
            let parts: Option<Vec<String>> = vs.iter().map(|x| value_latex(x, style)).collect();
            Some(format!(r"\left({}\right)", parts?.join(", ")))
        }
        _ => None,
    }
}

/// A printed number in LaTeX (`π`, `√`, `∞`, the minus sign).
fn number(s: &str) -> String {
    s.replace('π', r"\pi ")
        .replace("inf", r"\infty")
        .replace('√', r"\sqrt")
        .replace('−', "-")
}

/// The steps as one LaTeX `align*`: formula, value and reference per line.
pub fn latex(steps: &[Shown], style: Style) -> String {
    let lines: Vec<String> = steps
        .iter()
        .map(|s| {
            let value = value_latex(&s.value, style)
                .map(|v| format!(" = {v}"))
                .unwrap_or_default();
            format!(
                r"&{}{value} && \text{{{}}}",
                s.latex,
                reference(s.reference)
            )
        })
        .collect();
    format!(
        "\\begin{{align*}}\n{}\n\\end{{align*}}",
        lines.join(" \\\\\n")
    )
}

/// The JSON `steps` list: `{"ref", "name", "text", "value", "latex"}`,
/// with `note` and `frames` when there are.
pub fn json(steps: &[Shown]) -> J {
    J::Array(
        steps
            .iter()
            .map(|s| {
                let mut o = json!({
                    "ref": s.reference,
                    "name": s.name,
                    "text": s.text,
                    "value": crate::output::json::value(&s.value),
                    "latex": s.latex,
                });
                if let Some(obj) = o.as_object_mut() {
                    if let Some(n) = &s.note {
                        obj.insert("note".into(), json!(n));
                    }
                    if !s.frames.is_empty() {
                        obj.insert("frames".into(), json!(s.frames));
                    }
                }
                o
            })
            .collect(),
    )
}
