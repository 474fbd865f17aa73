//! Speed of the whole pipeline (parse → check → evaluate → print) on long
//! scripts, to show that time grows linearly with length (issue 3 §8):
//! `script/run_and_print` and `script/check` run issue 14's script,
//! `script/run_silenced` the same with every statement ended by `;`,
//! `script/book_run_and_print` issue 3's. `draw/svg` lays out and renders
//! a picture of 1k, 10k and 20k frames, to show that drawing is linear in
//! the number of frames (issue 23).
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
        let silent = common::silent_screw_script(n);
        group.bench_with_input(BenchmarkId::new("run_silenced", n), &silent, |b, src| {
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

/// A picture of `n` frames along a spiral path, as `draw` makes it.
fn frames(n: usize) -> std::rc::Rc<chasles::eval::value::Picture> {
    let mut session = Session::new(Settings::default());
    let src = format!("pic = draw([RpToTrans(Rotz(a / 100), (a / 1000, 0, 0)) for a in 1:{n}])");
    let (_, err, errors) = session.run_to_strings("bench.chs", &src, Mode::Run, false);
    assert_eq!(errors, 0, "{err}");
    match session.env.get("pic").and_then(|b| b.val.as_ref()) {
        Some(chasles::eval::value::Value::Picture(p)) => p.clone(),
        _ => panic!("draw makes a picture"),
    }
}

fn drawing(c: &mut Criterion) {
    let mut group = c.benchmark_group("draw");
    group.sample_size(10);
    for n in [1_000usize, 10_000, 20_000] {
        let pic = frames(n);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::new("svg", n), &pic, |b, pic| {
            b.iter(|| chasles::draw::svg(pic).expect("it draws"))
        });
    }
    group.finish();
}

criterion_group!(benches, pipeline, drawing);
criterion_main!(benches);
