//! Criterion benchmarks of the Lie-group core: SO(3) and SE(3) exp/log,
//! the adjoint, composition (4×4 product) and inverse.

use chasles::lie::{Vec3, Vec6, se3, so3};
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;

fn benches(c: &mut Criterion) {
    let w = Vec3::new(0.3, -1.2, 0.7);
    let r = so3::exp(&w);
    let r_pi = so3::exp(&(Vec3::new(1.0, 2.0, 3.0).normalize() * (std::f64::consts::PI - 1e-9)));
    let v = Vec6::new(0.3, -1.2, 0.7, 1.0, 2.0, -3.0);
    let t = se3::exp(&v);
    let t2 = se3::exp(&Vec6::new(-0.5, 0.1, 0.9, 0.2, -4.0, 1.5));

    c.bench_function("so3_exp", |b| b.iter(|| so3::exp(black_box(&w))));
    c.bench_function("so3_log", |b| b.iter(|| so3::log(black_box(&r))));
    c.bench_function("so3_log_near_pi", |b| b.iter(|| so3::log(black_box(&r_pi))));
    c.bench_function("se3_exp", |b| b.iter(|| se3::exp(black_box(&v))));
    c.bench_function("se3_log", |b| b.iter(|| se3::log(black_box(&t))));
    c.bench_function("se3_adjoint", |b| b.iter(|| se3::adjoint(black_box(&t))));
    c.bench_function("se3_compose", |b| b.iter(|| black_box(&t) * black_box(&t2)));
    c.bench_function("se3_inv", |b| b.iter(|| se3::inv(black_box(&t))));
}

criterion_group!(lie, benches);
criterion_main!(lie);
