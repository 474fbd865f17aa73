//! Speed of the symbolic engine (issue 15): the UR5's product of six
//! exponentials with symbolic joint angles, built, simplified and printed
//! through the whole pipeline; a power and a 6-joint chain with tilted
//! axes whose results pass the expression limit, refused before the work
//! (issue 21). `cargo bench --bench symbolic`.

use chasles::eval::env::Mode;
use chasles::session::{Session, Settings};
use criterion::{Criterion, criterion_group, criterion_main};

const UR5: &str = include_str!("ur5.chs");
const TILTED6: &str = include_str!("tilted6.chs");

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

/// Issue 21's size limits: work that would pass the expression limit is
/// refused before it is done (the power's and the adjoint's terms are
/// counted first), so these take milliseconds, not seconds.
fn refusals(c: &mut Criterion) {
    let run = |src: &str| {
        let mut session = Session::new(Settings::default());
        let (_, err, errors) = session.run_to_strings("t.chs", src, Mode::Run, false);
        assert_eq!(errors, 1, "{err}");
        assert!(err.contains("too large"), "{err}");
    };
    c.bench_function("power_20_of_a_sum_of_cosines_refused", |b| {
        b.iter(|| run("given a, b, c : scalar\nx = (cos(a) + cos(b) + cos(c) + 1)^20"))
    });
    c.bench_function("tilted_6_joint_chain_adjoint_refused", |b| {
        b.iter(|| run(TILTED6))
    });
}

criterion_group!(benches, ur5, refusals);
criterion_main!(benches);
