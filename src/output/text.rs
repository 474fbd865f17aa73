//! Values for people (LANGUAGE.md §10): matrices in aligned columns that
//! parse back (`[1, 0; 0, 1]` with one row per line), vectors as the book
//! writes them `(1, 2, 3)`, and the type and frames after the value.

use crate::check::ty::{Kind, Ty};
use crate::eval::interp::Outcome;
pub use crate::values::format::{Style, inline};
use crate::values::value::Value;

/// A matrix in aligned columns, decimal points lined up, one row per line;
/// `indent` is the column where the `[` stands.
pub fn matrix_block(m: &nalgebra::DMatrix<f64>, style: impl Into<Style>, indent: usize) -> String {
    let style = style.into();
    let cells: Vec<Vec<String>> = m
        .row_iter()
        .map(|r| r.iter().map(|x| style.num(*x)).collect())
        .collect();
    let ncols = m.ncols();
    let split = |s: &str| -> (String, String) {
        match s.find(['.', 'e']) {
            Some(i) => (s[..i].to_string(), s[i..].to_string()),
            None => (s.to_string(), String::new()),
        }
    };
    let mut int_w = vec![0; ncols];
    let mut frac_w = vec![0; ncols];
    for row in &cells {
        for (j, c) in row.iter().enumerate() {
            let (i, f) = split(c);
            int_w[j] = int_w[j].max(i.chars().count());
            frac_w[j] = frac_w[j].max(f.chars().count());
        }
    }
    let mut out = String::from("[");
    for (ri, row) in cells.iter().enumerate() {
        if ri > 0 {
            out.push('\n');
            out.push_str(&" ".repeat(indent + 1));
        }
        let mut line = String::new();
        for (j, c) in row.iter().enumerate() {
            let (i, f) = split(c);
            line.push_str(&" ".repeat(int_w[j] - i.chars().count()));
            line.push_str(&i);
            line.push_str(&f);
            if j + 1 < ncols {
                line.push(',');
                line.push_str(&" ".repeat(frac_w[j] - f.chars().count() + 1));
            }
        }
        out.push_str(&line);
    }
    out.push(']');
    out
}

/// The type label: `SE(3) {a}←{c}`; empty for plain numbers and bools.
pub fn type_label(ty: &Ty, val: Option<&Value>) -> String {
    let kind = val.map_or_else(|| ty.kind.clone(), Value::kind);
    let kind = if matches!(val, Some(Value::Sym(_))) {
        ty.kind.clone()
    } else {
        kind
    };
    match kind {
        Kind::Scalar | Kind::Bool if ty.frames.is_none() => String::new(),
        Kind::Mechanism | Kind::Function => String::new(),
        Kind::Tuple(_) => String::new(),
        k => {
            let t = Ty::new(k, ty.frames.clone());
            t.to_string()
        }
    }
}

/// One value with its label, after `prefix` (e.g. `T_ac = `).
pub fn show_value(prefix: &str, ty: &Ty, v: &Value, style: impl Into<Style>) -> String {
    let style = style.into();
    let label = type_label(ty, Some(v));
    let tail = if label.is_empty() {
        String::new()
    } else {
        format!("  : {label}")
    };
    match v {
        Value::Num { m, .. } if m.ncols() > 1 && m.nrows() > 1 => {
            let indent = prefix.chars().count();
            format!("{prefix}{}{tail}", matrix_block(m, style, indent))
        }
        Value::Mech(mech) => {
            let body = mech.to_string();
            if prefix.is_empty() {
                body
            } else {
                format!("{}\n{body}", prefix.trim_end())
            }
        }
        _ => format!("{prefix}{}{tail}", inline(v, style)),
    }
}

/// The text printed for a statement's outcome (empty when it prints nothing).
pub fn show_outcome(o: &Outcome, style: impl Into<Style>) -> String {
    let style = style.into();
    if !o.prints {
        return String::new();
    }
    let mut out = String::new();
    if let Some(note) = &o.note {
        out.push_str(note);
        out.push('\n');
    }
    let Some(v) = &o.val else {
        // check mode: the type only
        let names = o.names.join(", ");
        let label = o.ty.to_string();
        out.push_str(&if names.is_empty() {
            label
        } else {
            format!("{names} : {label}")
        });
        return out;
    };
    match (o.names.len(), v) {
        (0, Value::Tuple(items)) => {
            let parts: Vec<String> = items
                .iter()
                .map(|x| {
                    let k = x.kind();
                    show_value("", &Ty::new(k.clone(), o.ty.frames.part(&k)), x, style)
                })
                .collect();
            out.push_str(&parts.join("\n"));
        }
        (0, _) => out.push_str(&show_value("", &o.ty, v, style)),
        (1, _) => out.push_str(&show_value(&format!("{} = ", o.names[0]), &o.ty, v, style)),
        (_, Value::Tuple(items)) => {
            let parts: Vec<String> = o
                .names
                .iter()
                .zip(items)
                .enumerate()
                .map(|(i, (n, x))| {
                    let ty = o
                        .parts
                        .get(i)
                        .cloned()
                        .unwrap_or_else(|| Ty::plain(x.kind()));
                    show_value(&format!("{n} = "), &ty, x, style)
                })
                .collect();
            out.push_str(&parts.join("\n"));
        }
        _ => out.push_str(&show_value("", &o.ty, v, style)),
    }
    out
}
