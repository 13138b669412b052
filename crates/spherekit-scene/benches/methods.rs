// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Every registered method, through the scene layer: construction and batch evaluation with
//! derivatives, on S² and S³ (`cargo bench -p spherekit-scene`). A new method is benchmarked by
//! its registry entry alone; the core's `benches/` hold the per-construction tables.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use serde_json::json;
use spherekit::Curve;
use spherekit_scene::{BuiltCurve, METHODS, Scene};

#[path = "../tests/support/cases.rs"]
mod cases;

fn jets(curve: &BuiltCurve, ts: &[f64]) -> f64 {
    fn run<P: spherekit::Manifold>(c: &dyn Curve<Point = P>, ts: &[f64]) -> f64 {
        let mut out = vec![c.jet(ts[0]); ts.len()];
        c.jet_many(ts, &mut out);
        out.len() as f64
    }
    match curve {
        BuiltCurve::S2(b) => run(&*b.curve, ts),
        BuiltCurve::S3(b) => run(&*b.curve, ts),
        BuiltCurve::Sm(b) => run(&*b.curve, ts),
    }
}

fn methods(c: &mut Criterion) {
    for m in METHODS {
        for space in ["S2", "S3"] {
            if !cases::spaces(m).contains(&space) {
                continue;
            }
            let n = if m.single_piece { 4 } else { 20 };
            let scene =
                json!({ "space": space, "method": m.id, "points": cases::points(space, n) });
            let Ok(scene) = Scene::from_json(&scene.to_string()) else {
                continue;
            };
            c.bench_function(&format!("{} {space} build, {n} keys", m.id), |b| {
                b.iter(|| black_box(&scene).build())
            });
            let Ok(curves) = scene.build() else { continue };
            let [t0, t1] = curves[0].domain();
            let ts: Vec<f64> = (0..10_000)
                .map(|i| t0 + (t1 - t0) * f64::from(i) / 9_999.0)
                .collect();
            c.bench_function(
                &format!("{} {space} jet_many, 10 000 parameters", m.id),
                |b| b.iter(|| jets(black_box(&curves[0]), &ts)),
            );
        }
    }
}

criterion_group!(benches, methods);
criterion_main!(benches);
