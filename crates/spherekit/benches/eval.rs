// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Evaluation and construction of every method on S³, 20 keys, 200 000 increasing parameters:
//! one `eval` call per sample, `eval_many` and `jet_many` over the whole batch, and
//! construction through 20 and 1 000 keys (and 100 000 for the Pobegailo blends). `glam::DQuat::slerp` per call is the floor.
//!
//! `cargo bench -p spherekit --bench eval` (add `-- --warm-up-time 1 --measurement-time 2`
//! while developing). Throughput is per sample, so criterion's "thrpt" is samples per second.

#![allow(missing_docs, reason = "criterion macros")]

#[path = "curves.rs"]
mod curves;
#[path = "data.rs"]
mod data;

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use spherekit::UnitQuat;

/// Samples per batch.
const SAMPLES: usize = 200_000;

fn evaluation(c: &mut Criterion) {
    let keys = data::keys_s3(20);
    let mut group = c.benchmark_group("eval");
    group.sample_size(10);
    group.throughput(Throughput::Elements(SAMPLES as u64));
    for m in curves::METHODS {
        let curve = (m.build)(keys.clone());
        let ts = data::params(curve.domain(), SAMPLES);
        let first = curve.jet(ts[0]);
        let mut points = vec![UnitQuat::IDENTITY; SAMPLES];
        let mut jets = vec![first; SAMPLES];
        group.bench_function(BenchmarkId::new("per sample", m.name), |b| {
            b.iter(|| {
                for (o, &t) in points.iter_mut().zip(&ts) {
                    *o = curve.eval(black_box(t));
                }
            });
        });
        group.bench_function(BenchmarkId::new("eval_many", m.name), |b| {
            b.iter(|| curve.eval_many(black_box(&ts), &mut points));
        });
        group.bench_function(BenchmarkId::new("jet_many", m.name), |b| {
            b.iter(|| curve.jet_many(black_box(&ts), &mut jets));
        });
        black_box(&points);
    }
    group.finish();
}

fn slerp_floor(c: &mut Criterion) {
    let keys: Vec<_> = data::keys_s3(20).iter().map(data::dquat).collect();
    let ts = data::params([0.0, 1.0], SAMPLES);
    let mut out = vec![keys[0]; SAMPLES];
    let mut group = c.benchmark_group("eval");
    group.sample_size(10);
    group.throughput(Throughput::Elements(SAMPLES as u64));
    group.bench_function("glam DQuat::slerp", |b| {
        b.iter(|| {
            for (k, (o, &t)) in out.iter_mut().zip(&ts).enumerate() {
                let i = k % 19;
                *o = black_box(keys[i]).slerp(keys[i + 1], t);
            }
        });
    });
    black_box(&out);
    group.finish();
}

fn construction(c: &mut Criterion) {
    let mut group = c.benchmark_group("construct");
    group.sample_size(10);
    for n in [20, 1000] {
        let keys = data::keys_s3(n);
        for m in curves::METHODS {
            if n > 20 && m.name.starts_with("bezier") {
                continue; // one cubic: the count of keys is irrelevant
            }
            group.bench_with_input(BenchmarkId::new(m.name, n), &keys, |b, keys| {
                b.iter(|| (m.build)(black_box(keys.clone())));
            });
        }
    }
    // Long sequences: the book's arc-blend knots are not representable there, so this is the
    // arc-length timing with its time warps (and corner-blend, the other Pobegailo blend).
    let n = 100_000;
    let keys = data::keys_s3(n);
    for m in curves::METHODS {
        if m.name == "arc-blend" || m.name == "corner-blend" {
            group.bench_with_input(BenchmarkId::new(m.name, n), &keys, |b, keys| {
                b.iter(|| (m.build)(black_box(keys.clone())));
            });
        }
    }
    let points = data::points_s2(n, 60.0, 3);
    group.bench_with_input(BenchmarkId::new("arc-blend S2", n), &points, |b, p| {
        b.iter(|| curves::build_s2("arc-blend", black_box(p.clone())));
    });
    group.finish();
}

criterion_group!(benches, evaluation, slerp_floor, construction);
criterion_main!(benches);
