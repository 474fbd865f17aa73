//! What the server answers about a checked document (LANGUAGE.md §15):
//! diagnostics with their help, hover, completion, go to definition and
//! document symbols, each computed from the text and its [`Analysis`],
//! with no protocol I/O (the loop in [`super`] does that).

use lsp_types::{
    CompletionItem, CompletionItemKind, DiagnosticRelatedInformation, DiagnosticSeverity,
    DocumentSymbol, Documentation, Hover, HoverContents, Location, MarkupContent, MarkupKind,
    NumberOrString, SymbolKind, Uri,
};

use crate::builtins;
use crate::check::ty::{Frame, Frames};
use crate::diagnostics::{Diagnostic, Severity};
use crate::effects::Gate;
use crate::eval::env::Mode;
use crate::frontend::{commands::COMMANDS, help, keywords};
use crate::session::{Session, Settings};

use super::analysis::{Analysis, Def, DefKind};
use super::text::{Document, Encoding, is_name_char};

/// The words of the language offered by completion (statements, units,
/// constants).
const KEYWORDS: &[&str] = &[
    "given", "derive", "explain", "mech", "assert", "for", "in", "pi", "deg", "rad", "true",
    "false",
];

/// The types `given` accepts (§7, `eval::interp::given_kind`), offered after
/// `given NAME :`.
const GIVEN_TYPES: &[&str] = &[
    "scalar", "vec3", "vec6", "SO3", "SE3", "SO2", "SE2", "so3", "se3", "so2", "se2", "twist",
    "screw", "wrench",
];

/// A diagnostic as the protocol carries it: the primary span as the range,
/// the kind (`frame`, `syntax`, …) as the code, each label and the help as
/// related information pointing into the document.
pub fn diagnostic(
    d: &Diagnostic,
    doc: &Document,
    uri: &Uri,
    enc: Encoding,
) -> lsp_types::Diagnostic {
    let at = |span| Location::new(uri.clone(), doc.range(span, enc));
    let mut related = Vec::new();
    if !d.primary_label.is_empty() {
        related.push(DiagnosticRelatedInformation {
            location: at(d.span),
            message: d.primary_label.clone(),
        });
    }
    for l in &d.labels {
        related.push(DiagnosticRelatedInformation {
            location: at(l.span),
            message: l.message.clone(),
        });
    }
    if let Some(h) = &d.help {
        related.push(DiagnosticRelatedInformation {
            location: at(d.span),
            message: format!("help: {h}"),
        });
    }
    lsp_types::Diagnostic {
        range: doc.range(d.span, enc),
        severity: Some(match d.severity {
            Severity::Error => DiagnosticSeverity::ERROR,
            Severity::Warning => DiagnosticSeverity::WARNING,
            Severity::Note => DiagnosticSeverity::INFORMATION,
        }),
        code: Some(NumberOrString::String(d.kind.as_str().into())),
        source: Some("chasles".into()),
        // as the command line's header shows it: control characters escaped
        message: crate::diagnostics::escape::controls(&d.message).into_owned(),
        related_information: (!related.is_empty()).then_some(related),
        ..Default::default()
    }
}

/// What a binding's frames mean, in the book's words (§3.2, §3.3).
fn frames_meaning(f: &Frames) -> Option<String> {
    Some(match f {
        Frames::None => return None,
        Frames::One(a) => format!("expressed in {{{a}}}"),
        Frames::Pair(a, b) => {
            format!("maps coordinates in {{{b}}} to {{{a}}}: {{{b}}} as seen from {{{a}}}")
        }
        Frames::Disp(a) => format!("a displacement expressed in {{{a}}}"),
        Frames::Transposed(a, b) => {
            format!("the transpose of a map {{{a}}}←{{{b}}}: not a map between frames")
        }
    })
}

/// The hover of a definition: its type and frames, its value (computed on
/// demand within [`super::analysis::VALUE_TIME`], once per check), where it
/// was bound.
fn def_hover(
    def: &Def,
    analysis: &Analysis,
    doc: &Document,
    enc: Encoding,
    settings: Settings,
) -> String {
    let line = doc.position(def.statement.start, enc).line + 1;
    let stmt = doc.text[def.statement.start..def.statement.end.min(doc.text.len())].trim();
    let mut out = match &def.kind {
        DefKind::Function(params) => format!("**{}**({}) : function", def.name, params.join(", ")),
        DefKind::Given => format!(
            "**{}** : `{}` (given: a symbol, no numbers)",
            def.name, def.ty
        ),
        DefKind::Binding => format!("**{}** : `{}`", def.name, def.ty),
    };
    if let Some(m) = frames_meaning(&def.ty.frames) {
        out.push_str(&format!("\n\n{m}"));
    }
    if def.kind == DefKind::Binding {
        match analysis.value_of(&doc.text, def, settings) {
            Some(v) => out.push_str(&format!("\n\n= `{v}`")),
            None => out.push_str(
                "\n\nvalue not computed within the editor's budget (`chasles run` computes it)",
            ),
        }
    }
    let shown: String = stmt.chars().take(120).collect();
    out.push_str(&format!("\n\nbound on line {line}: `{shown}`"));
    out
}

/// The hover at byte `offset`: a binding's type, frames and definition; a
/// builtin's `:help` text (signature, book section, meaning, example); a
/// keyword's help.
pub fn hover(
    doc: &Document,
    analysis: &Analysis,
    offset: usize,
    enc: Encoding,
    settings: Settings,
) -> Option<Hover> {
    let span = doc.word_at(offset)?;
    let word = &doc.text[span.start..span.end];
    let text = if let Some(def) = analysis.def_at(word, offset) {
        def_hover(def, analysis, doc, enc, settings)
    } else if let Some(b) = builtins::lookup(word) {
        format!("```\n{}\n```", help::function(b, &settings))
    } else {
        keywords::keyword(word)?.to_string()
    };
    Some(Hover {
        contents: HoverContents::Markup(MarkupContent {
            kind: MarkupKind::Markdown,
            value: text,
        }),
        range: Some(doc.range(span, enc)),
    })
}

/// The location of the definition of the name at `offset`.
pub fn definition(
    doc: &Document,
    analysis: &Analysis,
    offset: usize,
    uri: &Uri,
    enc: Encoding,
) -> Option<Location> {
    let span = doc.word_at(offset)?;
    let def = analysis.def_at(&doc.text[span.start..span.end], offset)?;
    Some(Location::new(uri.clone(), doc.range(def.span, enc)))
}

/// The bindings and user functions of the document, in order.
#[allow(deprecated)] // `DocumentSymbol::deprecated` is a field the protocol still requires
pub fn symbols(doc: &Document, analysis: &Analysis, enc: Encoding) -> Vec<DocumentSymbol> {
    analysis
        .defs
        .iter()
        .map(|d| DocumentSymbol {
            name: d.name.clone(),
            detail: Some(match &d.kind {
                DefKind::Function(p) => format!("({})", p.join(", ")),
                _ => d.ty.to_string(),
            }),
            kind: match d.kind {
                DefKind::Function(_) => SymbolKind::FUNCTION,
                DefKind::Given => SymbolKind::CONSTANT,
                DefKind::Binding => SymbolKind::VARIABLE,
            },
            tags: None,
            deprecated: None,
            range: doc.range(d.statement, enc),
            selection_range: doc.range(d.span, enc),
            children: None,
        })
        .collect()
}

/// The operand that ends `t`: a name, or a bracketed group with the name
/// before it (`T_ab`, `inv(T_ba)`, `Ad(T_sb)`, `(T_ab T_bc)`, `T_sb.R`).
fn last_operand(t: &str) -> &str {
    let mut depth = 0usize;
    let mut start = t.len();
    for (i, c) in t.char_indices().rev() {
        match c {
            ')' | ']' => depth += 1,
            '(' | '[' if depth == 0 => break,
            '(' | '[' => depth -= 1,
            c if depth == 0 && !(is_name_char(c) || c == '.') => break,
            _ => {}
        }
        start = i;
    }
    &t[start..]
}

/// The frame that names after the text before the cursor should start
/// from: after `T_ab *` (or `T_ab ` multiplying by juxtaposition, or
/// `inv(T_ba) *`) the inner frame {b} of the operand, so that the product
/// cancels (§6). A name is looked up where it is read; any other operand
/// is typed, in check mode, in the bindings the check ended with.
fn wanted_frame(
    before: &str,
    analysis: &Analysis,
    offset: usize,
    settings: Settings,
) -> Option<Frame> {
    let t = before.trim_end();
    let t = t.strip_suffix('*').unwrap_or(t).trim_end();
    let operand = last_operand(t);
    if operand.is_empty() {
        return None;
    }
    let frames = if operand.chars().all(is_name_char) {
        analysis.def_at(operand, offset)?.ty.frames
    } else {
        let mut session = Session::new(settings);
        session.gate = Gate::deny();
        session.env = analysis.env.clone();
        let mut frames = None;
        session.evaluate(operand, Mode::Check, false, |r| {
            frames = r.result.as_ref().ok().map(|o| o.ty.frames);
        });
        frames?
    };
    match frames {
        Frames::Pair(_, inner) => Some(inner),
        _ => None,
    }
}

/// The outer frame of a type: {a} of a map {a}←{b}, of a vector in {a}.
fn outer(f: &Frames) -> Option<Frame> {
    match f {
        Frames::One(a) | Frames::Pair(a, _) | Frames::Disp(a) => Some(*a),
        _ => None,
    }
}

/// Completions at byte `offset`: `:` commands at the start of a line; the
/// types after `given NAME :`; otherwise the bindings made before the cursor (after `T_ab *`, those
/// whose outer frame is {b} first), the builtins with their signatures,
/// and keywords — each starting with the word typed (ignoring case).
pub fn completion(
    doc: &Document,
    analysis: &Analysis,
    offset: usize,
    settings: Settings,
) -> Vec<CompletionItem> {
    let offset = crate::span::floor_boundary(&doc.text, offset);
    let line_start = doc.text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let before = &doc.text[line_start..offset];
    if before.trim_start().starts_with(':') {
        let typed = before.trim_start().trim_start_matches(':');
        return COMMANDS
            .iter()
            .filter(|c| c.name.starts_with(typed))
            .map(|c| CompletionItem {
                label: format!(":{}", c.name),
                insert_text: Some(c.name.into()),
                kind: Some(CompletionItemKind::KEYWORD),
                detail: Some(format!(":{} {}", c.name, c.args).trim_end().into()),
                documentation: Some(Documentation::String(c.doc.into())),
                ..Default::default()
            })
            .collect();
    }
    let word_start = before
        .char_indices()
        .rev()
        .take_while(|(_, c)| is_name_char(*c))
        .last()
        .map_or(before.len(), |(i, _)| i);
    let typed = before[word_start..].to_lowercase();
    let fits = |name: &str| name.to_lowercase().starts_with(&typed);
    let lead = before[..word_start].trim_end();
    if lead.trim_start().starts_with("given") && lead.contains(':') {
        return GIVEN_TYPES
            .iter()
            .filter(|t| fits(t))
            .filter(|t| crate::eval::interp::given_kind(t).is_some())
            .map(|t| CompletionItem {
                label: (*t).into(),
                kind: Some(CompletionItemKind::TYPE_PARAMETER),
                ..Default::default()
            })
            .collect();
    }
    // A `:` of a range or a type, with nothing typed after it: no list.
    if typed.is_empty() && lead.ends_with(':') {
        return Vec::new();
    }
    let want = wanted_frame(&before[..word_start], analysis, offset, settings);
    let mut items = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for d in analysis
        .defs
        .iter()
        .rev()
        .filter(|d| d.statement.start < offset)
    {
        if !fits(&d.name) || !seen.insert(d.name.as_str()) {
            continue;
        }
        let follows = want.is_some() && outer(&d.ty.frames) == want;
        items.push(CompletionItem {
            label: d.name.clone(),
            kind: Some(match d.kind {
                DefKind::Function(_) => CompletionItemKind::FUNCTION,
                _ => CompletionItemKind::VARIABLE,
            }),
            detail: Some(d.ty.to_string()),
            sort_text: Some(format!("{}{}", if follows { "0" } else { "1" }, d.name)),
            preselect: follows.then_some(true),
            ..Default::default()
        });
    }
    for b in builtins::table() {
        for name in b.names().filter(|n| !n.is_empty() && fits(n)) {
            items.push(CompletionItem {
                label: name.into(),
                kind: Some(CompletionItemKind::FUNCTION),
                detail: Some(b.signature.into()),
                documentation: Some(Documentation::String(if b.section.is_empty() {
                    b.doc.into()
                } else {
                    format!("{} ({})", b.doc, b.section)
                })),
                sort_text: Some(format!("2{name}")),
                ..Default::default()
            });
        }
    }
    for k in KEYWORDS.iter().filter(|k| fits(k)) {
        items.push(CompletionItem {
            label: (*k).into(),
            kind: Some(CompletionItemKind::KEYWORD),
            documentation: keywords::keyword(k).map(|t| Documentation::String(t.into())),
            sort_text: Some(format!("3{k}")),
            ..Default::default()
        });
    }
    items
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_operand_before_the_cursor() {
        assert_eq!(last_operand("x = T_ab"), "T_ab");
        assert_eq!(last_operand("x = inv(T_ba)"), "inv(T_ba)");
        assert_eq!(last_operand("T_ab T_bc"), "T_bc");
        assert_eq!(last_operand("y = (T_ab T_bc)"), "(T_ab T_bc)");
        assert_eq!(last_operand("f(T_sb.R"), "T_sb.R");
        assert_eq!(last_operand("x = "), "");
    }

    #[test]
    fn after_a_product_the_names_that_cancel_come_first() {
        let src = "given T_ab, T_ca, T_bc : SE3\nw_a = (0, 0, 1)\nx = inv(T_ca) * \n";
        let doc = Document::new(src.into(), 1);
        let a = Analysis::of(src, Settings::default());
        let items = completion(&doc, &a, src.len() - 1, Settings::default());
        let mut first: Vec<&str> = items
            .iter()
            .filter(|i| i.preselect == Some(true))
            .map(|i| i.label.as_str())
            .collect();
        first.sort();
        // inv(T_ca) is {a}←{c}: what follows it starts from {c}, as T_ca does.
        assert_eq!(first, ["T_ca"]);
        let src = "given T_ab, T_ca, T_bc : SE3\nw_b = (0, 0, 1)\nx = Ad(T_ab) * \n";
        let doc = Document::new(src.into(), 1);
        let a = Analysis::of(src, Settings::default());
        let items = completion(&doc, &a, src.len() - 1, Settings::default());
        let first: Vec<&str> = items
            .iter()
            .filter(|i| i.preselect == Some(true))
            .map(|i| i.label.as_str())
            .collect();
        assert!(
            first.contains(&"T_bc") && first.contains(&"w_b"),
            "{first:?}"
        );
        assert!(!first.contains(&"T_ca"), "{first:?}");
    }
}
