//! Rendering of diagnostics: the contract's header line
//! `FILE:LINE:COL: kind error: message`, then the source line with carets
//! and labels (codespan-reporting), then `= help: …`.

use codespan_reporting::diagnostic::{Diagnostic as CsDiagnostic, Label as CsLabel};
use codespan_reporting::files::SimpleFile;
use codespan_reporting::term::{self, Config};

use super::{Diagnostic, Severity};

/// 1-based line and column (in characters) of a byte offset.
pub fn line_col(src: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(src.len());
    let mut offset = offset;
    while !src.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &src[..offset];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let col = src[line_start..offset].chars().count() + 1;
    (line, col)
}

/// Line starts of a text, for line numbers in O(log n) (a long script
/// must not cost O(n) per statement).
#[derive(Debug, Clone)]
pub struct LineIndex {
    starts: Vec<usize>,
}

impl LineIndex {
    pub fn new(src: &str) -> LineIndex {
        let mut starts = vec![0];
        starts.extend(
            src.bytes()
                .enumerate()
                .filter(|(_, b)| *b == b'\n')
                .map(|(i, _)| i + 1),
        );
        LineIndex { starts }
    }
    /// 1-based line of a byte offset.
    pub fn line(&self, offset: usize) -> usize {
        match self.starts.binary_search(&offset) {
            Ok(i) => i + 1,
            Err(i) => i,
        }
    }
}

/// The header line alone: `ex.chs:3:8: frame error: frames do not cancel`.
pub fn header(d: &Diagnostic, file: &str, src: &str) -> String {
    let (line, col) = line_col(src, d.span.start);
    let what = match d.severity {
        Severity::Error => format!("{} error", d.kind.as_str()),
        Severity::Warning => "warning".to_string(),
    };
    format!("{file}:{line}:{col}: {what}: {}", d.message)
}

/// The full text of a diagnostic, ending in a newline.
pub fn text(d: &Diagnostic, file: &str, src: &str) -> String {
    let files = SimpleFile::new(file, src);
    let clamp = |a: usize, b: usize| {
        let a = a.min(src.len());
        let b = b.max(a).min(src.len());
        a..b
    };
    let mut labels = vec![
        CsLabel::primary((), clamp(d.span.start, d.span.end)).with_message(d.primary_label.clone()),
    ];
    for l in &d.labels {
        labels.push(
            CsLabel::secondary((), clamp(l.span.start, l.span.end)).with_message(l.message.clone()),
        );
    }
    let base = match d.severity {
        Severity::Error => CsDiagnostic::error(),
        Severity::Warning => CsDiagnostic::warning(),
    };
    let mut cs = base.with_message(d.message.clone()).with_labels(labels);
    if let Some(h) = &d.help {
        cs = cs.with_notes(vec![format!("help: {h}")]);
    }
    let config = Config::default();
    let body = term::emit_into_string(&config, &files, &cs).unwrap_or_default();
    // codespan's own first line repeats the message; the contract's header replaces it.
    let body = body.split_once('\n').map_or("", |(_, rest)| rest);
    let mut out = header(d, file, src);
    out.push('\n');
    out.push_str(body);
    if !out.ends_with('\n') {
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostics::ErrorKind;
    use crate::syntax::ast::Span;

    #[test]
    fn header_has_file_line_col() {
        let src = "x = 1\nT_ab * T_cb\n";
        let d = Diagnostic::error(ErrorKind::Frame, Span::new(11, 12), "frames do not cancel");
        let t = text(&d, "ex.chs", src);
        assert!(
            t.starts_with("ex.chs:2:6: frame error: frames do not cancel\n"),
            "{t}"
        );
        assert!(t.contains("T_ab * T_cb"), "{t}");
        assert!(t.contains('^'), "{t}");
    }

    #[test]
    fn line_col_counts_characters() {
        assert_eq!(line_col("θ = 1", 3), (1, 3));
        assert_eq!(line_col("a\nbc", 3), (2, 2));
    }
}
