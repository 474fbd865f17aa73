//! One check of a document (LANGUAGE.md §15): the whole text run through a
//! session in [`Mode::Check`] — kinds and frames inferred, no number
//! computed, no file written (the gate denies every write and the run
//! performs no effect), under an evaluation budget with a deadline — and
//! what the editor needs from it: every diagnostic, and where each name
//! was bound with its type and frames (§6).

use std::cell::RefCell;
use std::collections::HashMap;
use std::time::Duration;

use crate::budget::Budget;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::Diagnostic;
use crate::effects::Gate;
use crate::eval::env::Mode;
use crate::session::{Session, Settings};
use crate::span::Span;

use super::text::is_name_char;

/// The time one check may take before it stops with a domain error naming
/// the budget (a check computes no numbers, so this is a guard, not a
/// limit met in practice: a 2,000-line script checks in milliseconds).
pub const CHECK_TIME: Duration = Duration::from_secs(2);

/// The time hover may spend computing a binding's value: the document up to
/// the binding run with numbers under the REPL preview's caps
/// ([`Budget::preview`]), no effect performed. Past it the hover says the
/// value was not computed.
pub const VALUE_TIME: Duration = Duration::from_millis(250);

/// What a definition binds.
#[derive(Debug, Clone, PartialEq)]
pub enum DefKind {
    /// `name = expr`, `(a, b) = expr`, `derive T_ab`.
    Binding,
    /// `given T_ab : SE3`: a symbol with a type and frames, no numbers (§7).
    Given,
    /// `f(x, y) = expr`, with its parameters.
    Function(Vec<String>),
}

/// A name bound by a statement that checked without error.
#[derive(Debug, Clone, PartialEq)]
pub struct Def {
    /// The name as written (`T_ab`, `θ1`).
    pub name: String,
    /// The name where the statement writes it.
    pub span: Span,
    /// The whole statement.
    pub statement: Span,
    /// Its kind and frames (§6) as the check inferred them.
    pub ty: Ty,
    /// A binding, a given symbol or a function.
    pub kind: DefKind,
}

/// The result of checking one document.
#[derive(Debug, Clone, Default)]
pub struct Analysis {
    /// Errors (one per failing statement; the check goes on past them),
    /// warnings and notes, in the order of the text.
    pub diagnostics: Vec<Diagnostic>,
    /// The definitions, in the order of the text.
    pub defs: Vec<Def>,
    /// The statements checked.
    pub statements: usize,
    /// The bindings at the end of the check (kinds and frames, no
    /// numbers): completion types an operand such as `inv(T_ba)` in them.
    pub env: crate::eval::env::Env,
    /// The value summaries computed so far for hover, by the start of the
    /// binding's statement (this check's text only).
    values: RefCell<HashMap<usize, Option<String>>>,
}

/// A statement's outcome as far as the editor keeps it.
struct Bound {
    names: Vec<String>,
    statement: Span,
    ty: Ty,
    parts: Vec<Ty>,
    prints: bool,
}

impl Analysis {
    /// Checks `text` with `settings` (frame checking as set, `strict` by
    /// default).
    pub fn of(text: &str, settings: Settings) -> Analysis {
        let text = &*unmarked(text);
        let mut session = Session::new(settings);
        session.gate = Gate::deny();
        session.budget = Budget::new().with_timeout(CHECK_TIME);
        let mut out = Analysis::default();
        let mut bound = Vec::new();
        session.evaluate(text, Mode::Check, true, |r| {
            out.statements += 1;
            out.diagnostics.extend(r.warnings.iter().cloned());
            match &r.result {
                Err(d) => out.diagnostics.push(d.clone()),
                Ok(o) => bound.push(Bound {
                    names: o.names.iter().map(|n| n.to_string()).collect(),
                    statement: o.span,
                    ty: o.ty,
                    parts: o.parts.clone(),
                    prints: o.prints,
                }),
            }
        });
        let env = &session.env;
        for b in bound {
            let stmt = &text[b.statement.start.min(text.len())..b.statement.end.min(text.len())];
            if b.names.is_empty() && b.ty.kind == Kind::Function {
                let name: String = stmt.chars().take_while(|c| is_name_char(*c)).collect();
                let params = env
                    .func(name.as_str())
                    .map(|f| f.params.clone())
                    .unwrap_or_default();
                out.defs.push(Def {
                    span: Span::new(b.statement.start, b.statement.start + name.len()),
                    name,
                    statement: b.statement,
                    ty: b.ty,
                    kind: DefKind::Function(params),
                });
                continue;
            }
            let given = !b.prints && stmt.trim_start().starts_with("given");
            let names = if given && b.names.is_empty() {
                given_names(stmt)
            } else {
                b.names
            };
            let many = names.len();
            for (i, name) in names.into_iter().enumerate() {
                let ty = if given {
                    env.get(name.as_str()).map_or(b.ty, |x| x.ty)
                } else if many == 1 {
                    b.ty
                } else if b.parts.len() == many {
                    b.parts[i]
                } else {
                    env.get(name.as_str()).map_or(b.ty, |x| x.ty)
                };
                let at =
                    find_word(stmt, &name).map_or(b.statement.start, |i| b.statement.start + i);
                out.defs.push(Def {
                    span: Span::new(at, at + name.len()),
                    name,
                    statement: b.statement,
                    ty,
                    kind: if given {
                        DefKind::Given
                    } else {
                        DefKind::Binding
                    },
                });
            }
        }
        out.env = session.env;
        out
    }

    /// What the editor shows when the check itself failed (a bug in
    /// chasles, caught so that the server goes on): one error at the start
    /// of the text saying so, and no definitions.
    pub fn failed(text: &str) -> Analysis {
        let end = text.find('\n').unwrap_or(text.len());
        let d = Diagnostic::error(
            crate::diagnostics::ErrorKind::Domain,
            Span::new(0, end),
            "chasles could not check this file (an internal error: please report it with the file)",
        );
        Analysis {
            diagnostics: vec![d],
            ..Analysis::default()
        }
    }

    /// [`value_summary`] of `def` in `text` (the text this analysis
    /// checked), computed once and then remembered.
    pub fn value_of(&self, text: &str, def: &Def, settings: Settings) -> Option<String> {
        if let Some(v) = self.values.borrow().get(&def.statement.start) {
            return v.clone();
        }
        let v = value_summary(text, def, settings);
        self.values
            .borrow_mut()
            .insert(def.statement.start, v.clone());
        v
    }

    /// The definition of `name` in force at byte `offset`: the last one
    /// whose statement starts at or before it (a use reads the binding
    /// made before it), else the first (a name used before it is bound).
    pub fn def_at(&self, name: &str, offset: usize) -> Option<&Def> {
        let mut defs = self.defs.iter().filter(|d| d.name == name);
        let first = defs.clone().next();
        defs.rfind(|d| d.statement.start <= offset).or(first)
    }
}

/// The names `given a, b(t) : T` declares, as written.
fn given_names(stmt: &str) -> Vec<String> {
    let rest = stmt.trim_start().trim_start_matches("given");
    let list = rest.split(':').next().unwrap_or("");
    list.split(',')
        .map(|part| {
            part.trim()
                .chars()
                .take_while(|c| is_name_char(*c))
                .collect::<String>()
        })
        .filter(|n| !n.is_empty())
        .collect()
}

/// A one-line summary of the value `def` binds, computed by running `text`
/// up to the end of its statement with numbers, under the preview's caps
/// and [`VALUE_TIME`], performing no effect (no file is written, whatever
/// the script saves); `None` when it was not computed within them or the
/// binding has no value (a `given` symbol, a function).
pub fn value_summary(text: &str, def: &Def, settings: Settings) -> Option<String> {
    if def.kind != DefKind::Binding {
        return None;
    }
    let text = &*unmarked(text);
    let end = crate::span::floor_boundary(text, def.statement.end);
    let mut session = Session::new(settings);
    session.gate = Gate::deny();
    session.budget = Budget::preview().with_timeout(VALUE_TIME);
    // The binding's own statement must have run (not an earlier binding of
    // the same name, left when the budget stopped the run before it).
    let mut reached = false;
    session.evaluate(&text[..end], Mode::Run, true, |r| {
        reached |= r.result.as_ref().is_ok_and(|o| o.span == def.statement);
    });
    if !reached {
        return None;
    }
    let b = session.env.get(def.name.as_str())?;
    let v = b.val.as_ref()?;
    let shown = crate::output::text::inline(v, settings.text_style());
    let mut short: String = shown.chars().take(200).collect();
    if short.len() < shown.len() {
        short.push('…');
    }
    Some(short)
}

/// `text` with a leading byte-order mark read as blanks of its length, as
/// `chasles check` skips it (LANGUAGE.md §1): every other byte keeps its
/// offset, so spans still index the editor's text.
fn unmarked(text: &str) -> std::borrow::Cow<'_, str> {
    match text.strip_prefix('\u{feff}') {
        Some(rest) => format!("{}{rest}", " ".repeat('\u{feff}'.len_utf8())).into(),
        None => text.into(),
    }
}

/// The byte offset of `word` in `text` standing alone (not part of a longer
/// name).
fn find_word(text: &str, word: &str) -> Option<usize> {
    let mut from = 0;
    while let Some(i) = text[from..].find(word).map(|i| i + from) {
        let before = text[..i].chars().next_back();
        let after = text[i + word.len()..].chars().next();
        if !before.is_some_and(is_name_char) && !after.is_some_and(is_name_char) {
            return Some(i);
        }
        from = i + word.len();
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_failed_check_is_one_error_on_the_first_line() {
        let a = Analysis::failed("x = 1\ny = 2\n");
        assert_eq!(a.diagnostics.len(), 1);
        assert_eq!(a.diagnostics[0].span, Span::new(0, 5));
        assert!(a.defs.is_empty());
    }

    #[test]
    fn bindings_givens_functions_and_errors() {
        let src = "given T_ab, T_bc : SE3\nT_ac = T_ab * T_bc\nf(x) = 2 x\nT_ab * T_ac\n(w, th) = AxisAng3((0, 0, 2))\n";
        let a = Analysis::of(src, Settings::default());
        let names: Vec<&str> = a.defs.iter().map(|d| d.name.as_str()).collect();
        assert_eq!(names, ["T_ab", "T_bc", "T_ac", "f", "w", "th"]);
        assert_eq!(a.defs[1].kind, DefKind::Given);
        assert_eq!(a.defs[1].ty.to_string(), "SE(3) {b}←{c}");
        assert_eq!(&src[a.defs[1].span.start..a.defs[1].span.end], "T_bc");
        assert_eq!(a.defs[2].ty.to_string(), "SE(3) {a}←{c}");
        assert_eq!(a.defs[3].kind, DefKind::Function(vec!["x".into()]));
        assert_eq!(a.statements, 5);
        // The one error: T_ab * T_ac has {b} against {a}.
        let frame: Vec<_> = a
            .diagnostics
            .iter()
            .filter(|d| d.severity == crate::diagnostics::Severity::Error)
            .collect();
        assert_eq!(frame.len(), 1);
        assert_eq!(frame[0].kind.as_str(), "frame");
        let line4 = src.find("T_ab * T_ac").unwrap();
        assert!(frame[0].span.start >= line4 && frame[0].span.end <= line4 + 11);
        // Values are computed for hover only, with numbers, on demand.
        let twice = "x = 2\ny = x * 3\n";
        let b = Analysis::of(twice, Settings::default());
        assert_eq!(
            value_summary(twice, &b.defs[1], Settings::default()).as_deref(),
            Some("6")
        );
        assert_eq!(value_summary(src, &a.defs[0], Settings::default()), None);
        // Remembered by the analysis: one computation per binding and check.
        assert_eq!(
            b.value_of(twice, &b.defs[1], Settings::default())
                .as_deref(),
            Some("6")
        );
        assert_eq!(
            b.value_of(twice, &b.defs[1], Settings::default())
                .as_deref(),
            Some("6")
        );
        assert_eq!(b.values.borrow().len(), 1);
        // Long frame names in braces (§2).
        let braces = "T_{world,cam} = RpToTrans(Rotz(1), (1, 2, 3))\n";
        let c = Analysis::of(braces, Settings::default());
        assert_eq!(c.defs[0].name, "T_{world,cam}");
        assert_eq!(c.defs[0].span, Span::new(0, 13));
        assert_eq!(c.defs[0].ty.to_string(), "SE(3) {world}←{cam}");
        // Where a name is read: the binding before it.
        let use_at = src.rfind("T_ac").unwrap();
        assert_eq!(
            a.def_at("T_ac", use_at).unwrap().statement.start,
            src.find("T_ac").unwrap()
        );
    }
}
