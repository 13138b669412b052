// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Arc-length parametrisation of every method on S³ (the keys of the `eval` bench): one `jet`
//! of the curve per sample against one `jet` of its [`ArcLength`] adapter at equal steps of
//! rotation angle, and the construction of the adapter through 20 and 1 000 keys.
//!
//! `cargo bench -p spherekit --bench arclen -- --warm-up-time 1 --measurement-time 2`.
//! Throughput is per sample.

#![allow(missing_docs, reason = "criterion macros")]

#[path = "curves.rs"]
mod curves;
#[path = "data.rs"]
mod data;

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use spherekit::{ArcLength, Curve, Jet, Side, UnitQuat};

/// Samples per batch.
const SAMPLES: usize = 20_000;

/// A boxed method as a sized curve, so that the adapter can own it.
#[derive(Debug)]
struct Dyn(curves::Boxed);

impl Curve for Dyn {
    type Point = UnitQuat;
    fn domain(&self) -> [f64; 2] {
        self.0.domain()
    }
    fn joints(&self) -> &[f64] {
        self.0.joints()
    }
    fn jet_at(&self, t: f64, side: Side) -> Jet<UnitQuat> {
        self.0.jet_at(t, side)
    }
}

fn evaluation(c: &mut Criterion) {
    let keys = data::keys_s3(20);
    let mut group = c.benchmark_group("arclen");
    group.sample_size(10);
    group.throughput(Throughput::Elements(SAMPLES as u64));
    for m in curves::METHODS {
        let curve = Dyn((m.build)(keys.clone()));
        let ts = data::params(curve.domain(), SAMPLES);
        let first = curve.jet(ts[0]);
        let mut jets = vec![first; SAMPLES];
        group.bench_function(BenchmarkId::new("curve jet", m.name), |b| {
            b.iter(|| {
                for (o, &t) in jets.iter_mut().zip(&ts) {
                    *o = curve.jet(black_box(t));
                }
            });
        });
        let arc = ArcLength::try_new(curve).expect("arc length");
        let ss = data::params(arc.domain(), SAMPLES);
        group.bench_function(BenchmarkId::new("arclen jet", m.name), |b| {
            b.iter(|| {
                for (o, &s) in jets.iter_mut().zip(&ss) {
                    *o = arc.jet(black_box(s));
                }
            });
        });
        group.bench_function(BenchmarkId::new("param_at", m.name), |b| {
            b.iter(|| ss.iter().map(|&s| arc.param_at(black_box(s))).sum::<f64>());
        });
        black_box(&jets);
    }
    group.finish();
}

fn construction(c: &mut Criterion) {
    let mut group = c.benchmark_group("arclen construct");
    group.sample_size(10);
    for n in [20, 1000] {
        let keys = data::keys_s3(n);
        for m in curves::METHODS {
            if n > 20 && m.name.starts_with("bezier") {
                continue; // one cubic of 4 keys
            }
            let curve = std::rc::Rc::new(Dyn((m.build)(keys.clone())));
            group.bench_function(BenchmarkId::new(m.name, n), |b| {
                b.iter(|| ArcLength::try_new(Shared(curve.clone())).expect("arc length"));
            });
        }
    }
    group.finish();
}

/// A shared curve (construction is timed without rebuilding the method).
#[derive(Debug)]
struct Shared(std::rc::Rc<Dyn>);

impl Curve for Shared {
    type Point = UnitQuat;
    fn domain(&self) -> [f64; 2] {
        self.0.domain()
    }
    fn joints(&self) -> &[f64] {
        self.0.joints()
    }
    fn jet_at(&self, t: f64, side: Side) -> Jet<UnitQuat> {
        self.0.jet_at(t, side)
    }
}

criterion_group!(benches, evaluation, construction);
criterion_main!(benches);
