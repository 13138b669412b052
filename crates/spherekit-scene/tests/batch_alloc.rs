// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Batch evaluation allocates nothing per sample, for every registered method, parameter
//! choice and sphere, counted by a global allocator: at most one scratch buffer per call (the
//! de Casteljau levels of `bezier`, a point of S^m), and every curve keeps O(number of keys)
//! memory. With the crate's `compact` feature the methods written for every sphere evaluate
//! their S² and S³ curves through S^m, whose points are on the heap, so only the others are
//! held to this. A test without the libtest harness (`harness = false`): no other thread
//! allocates while it counts.

use std::alloc::System;

use spherekit::{Curve, Manifold};
use spherekit_scene::{BuiltCurve, METHODS, Scene, Spaces};
use stats_alloc::{INSTRUMENTED_SYSTEM, Region, StatsAlloc};

#[global_allocator]
static GLOBAL: &StatsAlloc<System> = &INSTRUMENTED_SYSTEM;

#[path = "support/cases.rs"]
mod cases;

/// Allocations made by one `eval_many` and one `jet_many` of 10 000 parameters each.
fn allocations<P: Manifold>(c: &dyn Curve<Point = P>) -> usize {
    let [t0, t1] = c.domain();
    let ts: Vec<f64> = (0..10_000)
        .map(|i| t0 + (t1 - t0) * f64::from(i) / 9_999.0)
        .collect();
    let first = c.jet(ts[0]);
    let mut points = vec![first.point.clone(); ts.len()];
    let mut jets = vec![first; ts.len()];
    let region = Region::new(GLOBAL);
    c.eval_many(&ts, &mut points);
    c.jet_many(&ts, &mut jets);
    region.change().allocations + region.change().reallocations
}

/// Whether the case `name` (`"<method id> <sphere> …"`) evaluates through S^m: with the
/// `compact` feature, the methods written for every sphere.
fn through_s_m(name: &str) -> bool {
    cfg!(feature = "compact")
        && METHODS
            .iter()
            .any(|m| m.spaces == Spaces::All && name.split(' ').next() == Some(m.id))
}

fn per_call(curve: &BuiltCurve) -> usize {
    match curve {
        BuiltCurve::S2(b) => allocations(&*b.curve),
        BuiltCurve::S3(b) => allocations(&*b.curve),
        BuiltCurve::Sm(_) => 0,
    }
}

/// Bytes the built curve of `scene` keeps (allocated while building and not freed).
fn bytes_kept(scene: &Scene) -> usize {
    let region = Region::new(GLOBAL);
    let built = scene.build();
    let change = region.change();
    drop(built);
    change
        .bytes_allocated
        .saturating_sub(change.bytes_deallocated)
}

fn main() {
    let mut failures = Vec::new();
    let mut counted = 0;
    for (name, _, curves) in cases::built(20) {
        // S^m points are vectors on the heap: only S² and S³ are allocation-free.
        if through_s_m(&name) {
            continue;
        }
        counted += 1;
        let n = per_call(&curves[0]);
        // Bézier allocates its de Casteljau scratch once per batch call; the arc-length adapter
        // calls the curve's batch once per 256 samples (its parameters live on the stack), and
        // the curve's one-sided jet at the end s = L once.
        let allowed = match (name.starts_with("bezier "), name.contains("arclength")) {
            (true, false) => 2,
            (true, true) => 2 * (10_000_usize.div_ceil(256) + 1),
            _ => 0,
        };
        if n > allowed {
            failures.push(format!(
                "{name}: {n} allocations in one eval_many + jet_many"
            ));
        }
    }
    // Memory linear in the keys: 1 000 keys keep at most 11× what 100 keep.
    for (name, scene) in cases::scenes(100) {
        if name.contains('=')
            || name.ends_with("knots")
            || scene["method"] == "bezier"
            || scene["method"] == "bezier-kim"
        {
            continue;
        }
        let mut big = scene.clone();
        big["points"] =
            serde_json::json!(cases::points(scene["space"].as_str().unwrap_or("S2"), 1000));
        let (Ok(small), Ok(large)) = (
            Scene::from_json(&scene.to_string()),
            Scene::from_json(&big.to_string()),
        ) else {
            failures.push(format!("{name}: scene does not read"));
            continue;
        };
        let (a, b) = (bytes_kept(&small), bytes_kept(&large));
        if b > 11 * a.max(1) + 4096 {
            failures.push(format!("{name}: {b} bytes for 1 000 keys, {a} for 100"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(counted > 0, "no case was counted");
    println!("batch_alloc: ok, {counted} cases counted");
}
