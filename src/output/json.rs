//! JSON lines (LANGUAGE.md §1): one object per statement that yields a
//! value or an error, numbers at full precision.

use serde_json::{Value as J, json};

use crate::check::ty::Kind;
use crate::diagnostics::{Diagnostic, Severity};
use crate::eval::interp::Outcome;
use crate::values::value::Value;

fn number(x: f64) -> J {
    if x.is_finite() {
        // Integers print without a fraction; -0 as 0.
        if x == x.trunc() && x.abs() < 1e15 {
            json!(x as i64)
        } else {
            json!(x)
        }
    } else if x.is_nan() {
        json!("NaN")
    } else if x > 0.0 {
        json!("inf")
    } else {
        json!("-inf")
    }
}

/// A value as JSON: number, vector list, matrix as a list of rows, tuple
/// as a list, mechanism as an object, symbolic as its printed expression.
pub fn value(v: &Value) -> J {
    match v {
        Value::Num { m, .. } if m.len() == 1 => number(m[0]),
        Value::Num { m, .. } if m.ncols() == 1 => J::Array(m.iter().map(|x| number(*x)).collect()),
        Value::Num { m, .. } => J::Array(
            (0..m.nrows())
                .map(|i| J::Array(m.row(i).map(number).collect()))
                .collect(),
        ),
        Value::Bool(b) => json!(b),
        Value::Tuple(vs) => J::Array(vs.iter().map(value).collect()),
        Value::Mech(m) => m.to_json(),
        Value::Sym(s) => json!(s.to_string()),
        Value::List(vs) => J::Array(vs.iter().map(value).collect()),
        Value::Str(t) => json!(t.as_ref()),
        Value::Picture(p) => json!({
            "file": p.file,
            "shows": p.summary,
            "panels": p.panels.len(),
        }),
        Value::Formula { m, .. } => json!(
            crate::values::waiting::text(v, 17.into())
                .unwrap_or_else(|| crate::values::format::formula_inline(m, 17.into()))
        ),
    }
}

/// The JSON object for a successful statement (None when it prints nothing).
pub fn outcome(o: &Outcome, line: usize) -> Option<J> {
    if !o.prints {
        return None;
    }
    let name = match o.names.len() {
        0 => J::Null,
        1 => json!(o.names[0].as_str()),
        _ => json!(format!("({})", o.names.join(", "))),
    };
    let ty = match o.val.as_deref() {
        Some(Value::Sym(_) | Value::Formula { .. }) => "symbolic",
        Some(v) => type_name(&v.kind()),
        None => type_name(&o.ty.kind),
    };
    let mut out = json!({
        "line": line,
        "name": name,
        "type": ty,
        "frames": o.ty.frames.to_list(),
        "value": o.val.as_deref().map_or(J::Null, value),
    });
    // A symbolic value carries its LaTeX and what it is (§7).
    if let (Some(Value::Formula { m, kind, .. }), Some(obj)) =
        (o.val.as_deref(), out.as_object_mut())
    {
        let style = crate::values::format::Style {
            sym: crate::sym::print::Mode::Latex,
            ..17.into()
        };
        let waiting = o
            .val
            .as_deref()
            .and_then(|v| crate::values::waiting::text(v, style));
        obj.insert(
            "latex".into(),
            json!(waiting.unwrap_or_else(|| crate::values::format::formula_latex(m, 17.into()))),
        );
        obj.insert("kind".into(), json!(kind.json_name()));
    }
    // `derive T_ce`: the chain it used, as text prints it (§6)
    if let (Some(note), Some(obj)) = (o.note.as_deref(), out.as_object_mut()) {
        let chain = note.split_once(" = ").map_or(note, |(_, c)| c);
        obj.insert("chain".into(), json!(chain));
    }
    // `explain`: the book's steps (§14)
    if let (Some(steps), Some(obj)) = (o.steps.as_deref(), out.as_object_mut()) {
        obj.insert("steps".into(), super::steps::json(steps));
    }
    // a call kept over its symbols is what the checker says it is
    if let (Some(Value::Sym(_)), Some(obj)) = (o.val.as_deref(), out.as_object_mut()) {
        obj.insert("kind".into(), json!(o.ty.kind.json_name()));
    }
    Some(out)
}

fn type_name(k: &Kind) -> &'static str {
    k.json_name()
}

/// A statement's notes and warnings as JSON (LANGUAGE.md §1): each
/// `{"kind": "note"|"warning", "message", "help"?}`, in the order text
/// output prints them.
pub fn warnings(ws: &[Diagnostic]) -> J {
    J::Array(
        ws.iter()
            .map(|w| {
                let kind = match w.severity {
                    Severity::Note => "note",
                    // (an error among a statement's warnings is never
                    // made; were it, it is still only reported)
                    Severity::Warning | Severity::Error => "warning",
                };
                let mut o = json!({ "kind": kind, "message": shown(&w.message) });
                if let (Some(h), Some(obj)) = (&w.help, o.as_object_mut()) {
                    obj.insert("help".into(), json!(h));
                }
                o
            })
            .collect(),
    )
}

/// Adds `"warnings"` to a statement's JSON object when it has any (the
/// key is absent otherwise, as in the contract's example lines).
pub fn add_warnings(obj: &mut J, ws: &[Diagnostic]) {
    if let (false, Some(o)) = (ws.is_empty(), obj.as_object_mut()) {
        o.insert("warnings".into(), warnings(ws));
    }
}

/// The JSON object for a statement that prints no value (`given`, a
/// function definition, an `assert` that holds) but has notes or warnings:
/// `{"line": N, "warnings": [...]}`, so that nothing text output prints is
/// lost. None when it has none.
pub fn silent(line: usize, ws: &[Diagnostic]) -> Option<J> {
    (!ws.is_empty()).then(|| json!({ "line": line, "warnings": warnings(ws) }))
}

/// The JSON object for an error.
pub fn error(d: &Diagnostic, line: usize, col: usize) -> J {
    json!({
        "line": line,
        "error": {
            "kind": d.kind.as_str(),
            "message": shown(&d.message),
            "col": col,
            "help": d.help,
        }
    })
}

/// A message as the text header shows it: one line, its control characters
/// escaped (`found '\0'`, LANGUAGE.md §1), so both outputs say the same.
fn shown(message: &str) -> std::borrow::Cow<'_, str> {
    crate::diagnostics::escape::controls(message)
}
