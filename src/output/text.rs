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
        Value::Func(f) => format!("{}({})", f.name, f.params.join(", ")),
        Value::Sym(s) => s.to_string(),
        Value::List(vs) => {
            let shown = |v: &Value| inline(v, style);
            let xs: Vec<String> = if vs.len() > LIST_INLINE {
                let mut xs: Vec<String> = vs[..LIST_HEAD].iter().map(shown).collect();
                xs.push("…".into());
                xs.extend(vs[vs.len() - 2..].iter().map(shown));
                xs
            } else {
                vs.iter().map(shown).collect()
            };
            format!("[{}]", xs.join(", "))
        }
        Value::Str(t) => format!("{t:?}"),
        Value::Picture(p) => picture(p),
    }
}

/// Lists longer than this print their first [`LIST_HEAD`] and last two
/// items.
const LIST_INLINE: usize = 12;
const LIST_HEAD: usize = 8;

/// `picture: 5 frames and 1 screw axis in {s} → pic.svg`.
fn picture(p: &crate::eval::value::Picture) -> String {
    if p.is_view_only() {
        return p.summary.clone();
    }
    match &p.file {
        Some(f) => format!("picture: {} → {f}", p.summary),
        None => format!("picture: {}", p.summary),
    }
}

/// The label of a list: `list of 5 SE(3) {s}←{b'}`.
fn list_label(ty: &Ty, vs: &[Value]) -> String {
    let kind = crate::eval::value::common_kind(vs);
    let n = vs.len();
    let what = match kind {
        _ if n == 0 => "empty list".to_string(),
        Kind::Unknown => format!("list of {n} values"),
        Kind::Scalar if n == 1 => "list of 1 number".to_string(),
        k => Kind::List(Box::new(k))
            .to_string()
            .replacen("list of ", &format!("list of {n} "), 1),
    };
    if ty.frames.is_none() {
        what
    } else {
        format!("{what} {}", ty.frames)
    }
}

/// A list whose items are matrices: one item per block, numbered.
fn list_block(prefix: &str, ty: &Ty, vs: &[Value], style: Style) -> String {
    let mut out = format!("{prefix}{}:", list_label(ty, vs));
    let numbered: Vec<(usize, &Value)> = vs.iter().enumerate().collect();
    let shown: Vec<&(usize, &Value)> = if numbered.len() > LIST_INLINE {
        numbered[..3]
            .iter()
            .chain(numbered[numbered.len() - 2..].iter())
            .collect()
    } else {
        numbered.iter().collect()
    };
    let mut last = 0;
    for (i, v) in shown {
        if *i > last + 1 {
            out.push_str("\n  …");
        }
        last = *i;
        let head = format!("  [{}] ", i + 1);
        let body = match v {
            Value::Num { m, .. } if m.ncols() > 1 && m.nrows() > 1 => {
                matrix_block(m, style, head.chars().count())
            }
            other => inline(other, style),
        };
        out.push('\n');
        out.push_str(&head);
        out.push_str(&body);
    }
    out
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
        Kind::Mechanism | Kind::Function | Kind::Picture | Kind::Text => String::new(),
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
        Value::List(vs)
            if vs
                .iter()
                .any(|x| matches!(x, Value::Num { m, .. } if m.ncols() > 1 && m.nrows() > 1)) =>
        {
            list_block(prefix, ty, vs, style)
        }
        Value::List(vs) => format!("{prefix}{}  : {}", inline(v, style), list_label(ty, vs)),
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
