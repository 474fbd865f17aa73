//! Rendering of diagnostics: the contract's header line
//! `FILE:LINE:COL: kind error: message`, then the source line with carets
//! and labels (codespan-reporting), then `= help: …`. Control characters
//! are shown escaped everywhere, and a long line is echoed as windows
//! around its spans ([`super::view`]).

use codespan_reporting::diagnostic::{Diagnostic as CsDiagnostic, Label as CsLabel};
use std::ops::Range;

use codespan_reporting::files::{Error as FilesError, Files, SimpleFile};
use codespan_reporting::term::{self, Config};

use super::{Diagnostic, Severity, escape};

use crate::span::floor_boundary;
pub use crate::span::{Anchor, line_col, line_col_from};

/// The header line alone: `ex.chs:3:8: frame error: frames do not cancel`.
pub fn header(d: &Diagnostic, file: &str, src: &str) -> String {
    header_from(d, file, src, Anchor::START)
}

fn header_from(d: &Diagnostic, file: &str, src: &str, anchor: Anchor) -> String {
    let (line, col) = line_col_from(src, d.span.start, anchor);
    let what = match d.severity {
        Severity::Error => format!("{} error", d.kind.as_str()),
        Severity::Warning => "warning".to_string(),
        Severity::Note => "note".to_string(),
    };
    format!(
        "{}:{line}:{col}: {what}: {}",
        escape::controls(file),
        escape::controls(&d.message)
    )
}

/// The full text of a diagnostic, ending in a newline.
pub fn text(d: &Diagnostic, file: &str, src: &str) -> String {
    text_from(d, file, src, Anchor::START)
}

/// The lines of the source a diagnostic shows, for codespan: only they are
/// indexed, and their line numbers start at `first_line` (a long script is
/// not indexed again for every error).
struct Window<'a> {
    file: SimpleFile<&'a str, &'a str>,
    first_line: usize,
    /// The primary span's start in the echoed text, and its column in the
    /// source (the echoed text may be escaped or cut: the `┌─` line must
    /// name the same column as the header).
    primary: (usize, usize),
}

impl<'a> Files<'a> for Window<'a> {
    type FileId = ();
    type Name = &'a str;
    type Source = &'a str;
    fn name(&'a self, _: ()) -> Result<&'a str, FilesError> {
        Ok(self.file.name())
    }
    fn source(&'a self, _: ()) -> Result<&'a str, FilesError> {
        Ok(self.file.source())
    }
    fn line_index(&'a self, id: (), byte_index: usize) -> Result<usize, FilesError> {
        self.file.line_index(id, byte_index)
    }
    fn line_number(&'a self, _: (), line_index: usize) -> Result<usize, FilesError> {
        Ok(self.first_line + line_index)
    }
    fn line_range(&'a self, id: (), line_index: usize) -> Result<Range<usize>, FilesError> {
        self.file.line_range(id, line_index)
    }
    fn column_number(
        &'a self,
        id: (),
        line_index: usize,
        byte_index: usize,
    ) -> Result<usize, FilesError> {
        if byte_index == self.primary.0 {
            return Ok(self.primary.1);
        }
        let range = self.line_range(id, line_index)?;
        Ok(codespan_reporting::files::column_index(self.file.source(), range, byte_index) + 1)
    }
}

/// [`text`], counting line numbers from `anchor` (see [`Anchor`]).
pub fn text_from(d: &Diagnostic, file: &str, src: &str, anchor: Anchor) -> String {
    let clamp = |a: usize, b: usize| {
        let a = floor_boundary(src, a);
        let b = floor_boundary(src, b.max(a));
        a..b
    };
    let spans = std::iter::once(d.span).chain(d.labels.iter().map(|l| l.span));
    let lo = spans.clone().map(|s| clamp(s.start, s.end).start).min();
    let hi = spans.map(|s| clamp(s.start, s.end).end).max();
    let (lo, hi) = (lo.unwrap_or(0), hi.unwrap_or(0));
    // The window: whole lines from the first label to the last.
    let base = src[..lo].rfind('\n').map_or(0, |i| i + 1);
    let end = src[hi..].find('\n').map_or(src.len(), |i| hi + i);
    let first_line = line_col_from(src, base, anchor).0;
    // The echoed text: controls escaped, long lines cut around the spans;
    // every span carried over to it.
    let spans: Vec<Range<usize>> = std::iter::once(d.span)
        .chain(d.labels.iter().map(|l| l.span))
        .map(|s| clamp(s.start, s.end))
        .collect();
    let points: Vec<usize> = spans.iter().flat_map(|r| [r.start, r.end]).collect();
    let (shown, at) = super::view::view(src, base, end, &points);
    let name = escape::controls(file);
    let window = Window {
        file: SimpleFile::new(&name, shown.as_str()),
        first_line,
        primary: (at[0], line_col_from(src, spans[0].start, anchor).1),
    };
    let shift = |i: usize| at[2 * i]..at[2 * i + 1];
    let one_line = |m: &str| escape::controls(m).into_owned();
    let mut labels = vec![CsLabel::primary((), shift(0)).with_message(one_line(&d.primary_label))];
    for (i, l) in d.labels.iter().enumerate() {
        labels.push(CsLabel::secondary((), shift(i + 1)).with_message(one_line(&l.message)));
    }
    let base_diag = match d.severity {
        Severity::Error => CsDiagnostic::error(),
        Severity::Warning => CsDiagnostic::warning(),
        Severity::Note => CsDiagnostic::note(),
    };
    let mut cs = base_diag.with_message(String::new()).with_labels(labels);
    if let Some(h) = &d.help {
        cs = cs.with_notes(vec![format!("help: {}", escape::controls_keep_lines(h))]);
    }
    let config = Config::default();
    let body = term::emit_into_string(&config, &window, &cs).unwrap_or_default();
    // codespan's own first line repeats the message; the contract's header replaces it.
    let body = body.split_once('\n').map_or("", |(_, rest)| rest);
    let mut out = header_from(d, file, src, anchor);
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
    use crate::span::Span;

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
}
