// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Rendering benchmarks: `cargo bench -p spherekit-render` (or `./run bench`).

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use spherekit_scene::Scene;

/// A 512×512 S³ scene: three body-axis trajectories (flattened to 2e-4 rad, about 300 points
/// each) and the speed plot strip.
fn s3_scene() -> Scene {
    Scene::from_json(
        r#"{"space":"S3","method":"geodesic",
            "points":[[1,0,0,0],[0.9239,0,0,0.3827],[0.7071,0.5,0.5,0],[0.5,-0.5,0.5,0.5],
                      [0,0,1,0],[0.3,0.8,0.1,-0.5],[0.6,0.2,-0.7,0.3]],
            "view":{"plot":"speed","accuracy":0.0002}}"#,
    )
    .expect("valid scene")
}

fn render(c: &mut Criterion) {
    let scene = s3_scene();
    let curves = scene.build().expect("builds");
    // The sphere and graticule are kept per thread for the last size and camera, as when a
    // point is dragged; alternating two sizes redraws them every time, as after a camera move.
    c.bench_function("render s3 512 with plot", |b| {
        b.iter(|| spherekit_render::render_built(black_box(&scene), &curves, 512))
    });
    let mut size = 512;
    c.bench_function("render s3 512/513 with plot, backdrop redrawn", |b| {
        b.iter(|| {
            size = 1025 - size;
            spherekit_render::render_built(black_box(&scene), &curves, size)
        })
    });
}

criterion_group!(benches, render);
criterion_main!(benches);
