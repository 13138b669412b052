// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! A rough timing of arc-blend evaluation (run with
//! `cargo test --release --test pobegailo_timing -- --ignored --nocapture`); criterion benches
//! come later.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::cast_possible_truncation,
    reason = "tests: a panic is the failure report"
)]

use std::time::Instant;

use spherekit::glam::DVec3;
use spherekit::{ArcBlend, CornerBlendS3, Curve, Manifold, UnitQuat};

fn keys(count: usize) -> Vec<UnitQuat> {
    let mut out = vec![UnitQuat::IDENTITY];
    for i in 1..count {
        let f = i as f64;
        let step = DVec3::new(
            0.3 * f.sin(),
            0.4 * (0.7 * f).cos(),
            0.2 + 0.1 * (1.3 * f).sin(),
        );
        let last = out[out.len() - 1];
        out.push(UnitQuat::exp(step).mul(last));
    }
    out
}

#[test]
#[ignore = "timing; run in release by hand"]
fn arc_blend_s3_evaluation_time() {
    let c = ArcBlend::try_new(keys(20), 2).unwrap();
    let [t0, t1] = c.domain();
    let samples = 1_000_000;
    let start = Instant::now();
    let mut acc = 0.0;
    for i in 0..samples {
        let t = t0 + (t1 - t0) * (i as f64 + 0.5) / samples as f64;
        let j = c.jet(core::hint::black_box(t));
        acc += j.point.to_vector().x + j.acceleration.y;
    }
    let jet_ns = start.elapsed().as_nanos() as f64 / samples as f64;
    let start = Instant::now();
    for i in 0..samples {
        let t = t0 + (t1 - t0) * (i as f64 + 0.5) / samples as f64;
        acc += c.eval(core::hint::black_box(t)).to_vector().y;
    }
    let eval_ns = start.elapsed().as_nanos() as f64 / samples as f64;
    let start = Instant::now();
    for _ in 0..1000 {
        acc += ArcBlend::try_new(core::hint::black_box(keys(200)), 2)
            .unwrap()
            .knots()[1];
    }
    let build_us = start.elapsed().as_nanos() as f64 / 1000.0 / 1000.0;
    let cb = CornerBlendS3::try_new(keys(20), 2, 0.25).unwrap();
    let [c0, c1] = cb.domain();
    let start = Instant::now();
    for i in 0..samples {
        let t = c0 + (c1 - c0) * (i as f64 + 0.5) / samples as f64;
        acc += cb.jet(core::hint::black_box(t)).velocity.z;
    }
    let corner_ns = start.elapsed().as_nanos() as f64 / samples as f64;
    println!(
        "ArcBlend<UnitQuat> 20 keys, n = 2: jet {jet_ns:.0} ns, eval {eval_ns:.0} ns; build 200 keys {build_us:.1} µs; CornerBlendS3 jet {corner_ns:.0} ns ({acc})"
    );
    assert!(jet_ns < 300.0, "jet under 300 ns");
}
