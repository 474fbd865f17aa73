//! Speed of the whole pipeline (parse → check → evaluate → print) on long
//! scripts, to show that time grows linearly with length (issue 3 §8).
//! `cargo bench --bench language`.

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

/// A script of `n` statements in the book's style.
pub fn script(n: usize) -> String {
    let lines = [
        "T_sb = RpToTrans(Rotz(30 deg), (1, 2, 0))",
        "p_s = T_sb * (1, 0, 0)",
        "x = 2 * 3 + 1",
        "w = MatrixLog3(Rotz(0.1) * Rotx(0.2))",
        "V_s = Ad(T_sb) * (0, 0, 1, 1, 0, 0)",
    ];
    let mut s = String::with_capacity(n * 40);
    for i in 0..n {
        s.push_str(lines[i % lines.len()]);
        s.push('\n');
    }
    s
}

fn pipeline(c: &mut Criterion) {
    let mut group = c.benchmark_group("script");
    group.sample_size(10);
    for n in [1_000usize, 10_000, 100_000] {
        let src = script(n);
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
    }
    group.finish();
}

criterion_group!(benches, pipeline);
criterion_main!(benches);
