//! Speed of the whole pipeline (parse → check → evaluate → print) on long
//! scripts, to show that time grows linearly with length (issue 3 §8):
//! `script/run_and_print` and `script/check` run issue 14's script,
//! `script/book_run_and_print` issue 3's.
//! `cargo bench --bench language`.

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

mod common;

fn pipeline(c: &mut Criterion) {
    let mut group = c.benchmark_group("script");
    group.sample_size(10);
    for n in [1_000usize, 10_000, 100_000] {
        let src = common::screw_script(n);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::new("run_and_print", n), &src, |b, src| {
            b.iter(|| {
                let mut session = Session::new(Settings::default());
                session.run_to_strings("bench.chs", src, Mode::Run, false)
            })
        });
        group.bench_with_input(BenchmarkId::new("check", n), &src, |b, src| {
            b.iter(|| {
                let mut session = Session::new(Settings::default());
                session.run(src, Mode::Check, false, |_| {})
            })
        });
        let book = common::book_script(n);
        group.bench_with_input(
            BenchmarkId::new("book_run_and_print", n),
            &book,
            |b, src| {
                b.iter(|| {
                    let mut session = Session::new(Settings::default());
                    session.run_to_strings("bench.chs", src, Mode::Run, false)
                })
            },
        );
    }
    group.finish();
}

criterion_group!(benches, pipeline);
criterion_main!(benches);
