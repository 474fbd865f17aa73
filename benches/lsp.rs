//! The language server's latency after an edit (issue 39, LANGUAGE.md §15):
//! a script of about 100, 1,000 and 2,000 lines — the book's example
//! scripts one after another, cut at a blank line — edited on a middle line
//! as one keystroke does (`Document::apply` of an incremental change),
//! re-checked in full (`Analysis::of`: check mode, no numbers) and its
//! diagnostics converted to the protocol's. The target is under 50 ms at
//! 2,000 lines. `cargo bench --bench lsp`.

use chasles::lsp::analysis::Analysis;
use chasles::lsp::features;
use chasles::lsp::text::{Document, Encoding};
use chasles::session::Settings;
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use lsp_types::{Position, Range, TextDocumentContentChangeEvent, Uri};

/// The example scripts' lines, in order and again, up to the first blank
/// line after `n` lines.
fn script(n: usize) -> String {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("the examples folder")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "chs"))
        .collect();
    files.sort();
    let texts: Vec<String> = files
        .iter()
        .map(|p| std::fs::read_to_string(p).expect("an example"))
        .collect();
    let mut out = String::new();
    for (count, line) in texts.iter().cycle().flat_map(|t| t.lines()).enumerate() {
        if count >= n && line.trim().is_empty() {
            break;
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}

fn after_an_edit(c: &mut Criterion) {
    let mut group = c.benchmark_group("lsp");
    group.sample_size(20);
    let uri: Uri = "file:///bench.chs".parse().expect("a URI");
    for n in [100usize, 1_000, 2_000] {
        let mut doc = Document::new(script(n), 1);
        let line = (doc.lines() / 2) as u32;
        let mut toggle = false;
        group.throughput(Throughput::Elements(doc.lines() as u64));
        group.bench_function(BenchmarkId::new("edit_and_recheck", n), |b| {
            b.iter(|| {
                // Type a space at the start of the middle line, then delete it.
                toggle = !toggle;
                let start = Position::new(line, 0);
                let change = TextDocumentContentChangeEvent {
                    range: Some(Range::new(start, Position::new(line, u32::from(!toggle)))),
                    range_length: None,
                    text: if toggle { " ".into() } else { String::new() },
                };
                doc.apply(&change, Encoding::Utf16);
                let analysis = Analysis::of(&doc.text, Settings::default());
                let diagnostics: Vec<_> = analysis
                    .diagnostics
                    .iter()
                    .map(|d| features::diagnostic(d, &doc, &uri, Encoding::Utf16))
                    .collect();
                (analysis.statements, diagnostics.len())
            })
        });
    }
    group.finish();
}

criterion_group!(benches, after_an_edit);
criterion_main!(benches);
