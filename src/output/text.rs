//! Values for people (LANGUAGE.md §10): matrices in aligned columns that
//! parse back (`[1, 0; 0, 1]` with one row per line), vectors as the book
//! writes them `(1, 2, 3)`, and the type and frames after the value.

use super::number::fmt_num;
use crate::check::ty::{Kind, Ty};
use crate::eval::interp::Outcome;
use crate::eval::value::Value;

/// How numbers print: `digits` decimals (trailing zeros trimmed), or with
/// `exact`, a closed form such as `1/√2` or `π/6` where one is within
/// 1e-12 (the REPL's `:exact`). A plain `usize` converts to decimals only.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Style {
    /// Decimals.
    pub digits: usize,
    /// Print simple closed forms (`√3/2`, `-π/2`) instead of decimals.
    pub exact: bool,
    /// Symbolic values: plain text, the book's shorthand or LaTeX (§7).
    pub sym: crate::sym::print::Mode,
}

impl Style {
    /// One number in this style.
    pub fn num(self, x: f64) -> String {
        if self.sym == crate::sym::print::Mode::Latex {
            return fmt_num(x, self.digits);
        }
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
            sym: crate::sym::print::Mode::Text,
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
        Value::Func(f) => format!("{}({})", f.name, f.params.join(", ")),
        Value::Sym(s) => s.to_string(),
        Value::Formula { m, .. } => super::formula::inline(m, style),
    }
}

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
        Value::Formula { m, .. } => {
            let indent = prefix.chars().count();
            format!("{prefix}{}{tail}", super::formula::block(m, style, indent))
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
