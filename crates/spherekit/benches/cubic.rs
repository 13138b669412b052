// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The C² cubic spline (`CubicSpline`, scipy ends, S³): construction for 1 000 and 100 000 keys
//! (linear: time per key), and `jet_many` at 200 000 increasing parameters on 20 keys.
//!
//! `cargo bench -p spherekit --bench cubic -- --warm-up-time 1 --measurement-time 3`. Newton's
//! iterations and residual are printed once per size.

#![allow(missing_docs, reason = "criterion macros")]

#[path = "data.rs"]
mod data;

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use spherekit::{CubicEnd, CubicSpline, Curve, UnitQuat};

fn build(keys: Vec<UnitQuat>) -> CubicSpline<UnitQuat> {
    CubicSpline::try_new(keys, None, CubicEnd::Scipy, false).expect("cubic")
}

fn construction(c: &mut Criterion) {
    let mut group = c.benchmark_group("cubic build");
    group.sample_size(10);
    for n in [1000, 100_000] {
        let keys = data::keys_s3(n);
        let info = build(keys.clone()).solve_info();
        println!(
            "n = {n}: {} iterations, {} factorisations, residual {:.1e}",
            info.iterations, info.factorizations, info.residual
        );
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::new("scipy ends", n), &keys, |b, k| {
            b.iter(|| build(black_box(k.clone())));
        });
    }
    group.finish();
}

fn evaluation(c: &mut Criterion) {
    let curve = build(data::keys_s3(20));
    let ts = data::params(curve.domain(), 200_000);
    let mut jets = vec![curve.jet(0.0); ts.len()];
    let mut points = vec![UnitQuat::IDENTITY; ts.len()];
    let mut group = c.benchmark_group("cubic eval");
    group.throughput(Throughput::Elements(ts.len() as u64));
    group.bench_function("jet_many 20 keys", |b| {
        b.iter(|| curve.jet_many(black_box(&ts), &mut jets));
    });
    let mut rates = vec![curve.point_velocity(0.0); ts.len()];
    group.bench_function("point_velocity_many 20 keys", |b| {
        b.iter(|| curve.point_velocity_many(black_box(&ts), &mut rates));
    });
    group.bench_function("eval_many 20 keys", |b| {
        b.iter(|| curve.eval_many(black_box(&ts), &mut points));
    });
    group.finish();
}

criterion_group!(benches, construction, evaluation);
criterion_main!(benches);
