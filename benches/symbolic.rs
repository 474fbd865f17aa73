//! Speed of the symbolic engine (issue 15): the UR5's product of six
//! exponentials with symbolic joint angles, built, simplified and printed
//! through the whole pipeline. `cargo bench --bench symbolic`.

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};
use criterion::{Criterion, criterion_group, criterion_main};

const UR5: &str = include_str!("ur5.chs");

fn ur5(c: &mut Criterion) {
    c.bench_function("ur5_symbolic_poe_printed", |b| {
        b.iter(|| {
            let mut session = Session::new(Settings::default());
            let (out, _, errors) = session.run_to_strings("ur5.chs", UR5, Mode::Run, false);
            assert_eq!(errors, 0);
            out
        })
    });
}

criterion_group!(benches, ur5);
criterion_main!(benches);
