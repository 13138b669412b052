// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Batch evaluation allocates nothing per sample (S² and S³ curves), counted by a global
//! allocator: at most one scratch buffer per call (the de Casteljau levels of `Bezier`), none
//! for every other method; and every curve keeps O(number of keys) memory. A test without the
//! libtest harness (`harness = false`): no other thread allocates while it counts.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    reason = "tests: a panic is the failure report"
)]

#[path = "../benches/data.rs"]
mod data;

use std::alloc::System;

use spherekit::{
    ArcBlend, BetaParams, BetaSpline, Bezier, BezierKim, BsplineKim, CatmullRom, CornerBlend,
    CornerBlendS3, Curve, DEFAULT_CORNER_FRACTION, GammaSpline, Gammas, GeodesicSpline, LastEdge,
    Manifold, NlerpSpline, S2Point, Squad, UnitQuat,
};
use stats_alloc::{INSTRUMENTED_SYSTEM, Region, StatsAlloc};

#[global_allocator]
static GLOBAL: &StatsAlloc<System> = &INSTRUMENTED_SYSTEM;

type Boxed<P> = Box<dyn Curve<Point = P>>;

/// Allocations made by one `eval_many` and one `jet_many` of 10 000 parameters each.
fn allocations<P: Manifold>(c: &dyn Curve<Point = P>) -> usize {
    let ts = data::params(c.domain(), 10_000);
    let first = c.jet(ts[0]);
    let mut points = vec![first.point.clone(); ts.len()];
    let mut jets = vec![first; ts.len()];
    let region = Region::new(GLOBAL);
    c.eval_many(&ts, &mut points);
    c.jet_many(&ts, &mut jets);
    region.change().allocations + region.change().reallocations
}

fn main() {
    batch_evaluation_allocates_nothing();
    memory_is_linear_in_keys();
    println!("batch_alloc: ok");
}

fn batch_evaluation_allocates_nothing() {
    let p = data::points_s2(20, 60.0, 3);
    let q = data::keys_s3(20);
    let s2: Vec<(&str, Boxed<S2Point>)> = vec![
        (
            "geodesic",
            Box::new(GeodesicSpline::try_new(p.clone(), None).unwrap()),
        ),
        (
            "nlerp",
            Box::new(NlerpSpline::try_new(p.clone(), None).unwrap()),
        ),
        (
            "bezier",
            Box::new(Bezier::try_new(p[..4].to_vec()).unwrap()),
        ),
        (
            "catmull-rom",
            Box::new(CatmullRom::try_new(p.clone(), None).unwrap()),
        ),
        (
            "beta",
            Box::new(BetaSpline::try_new(p.clone(), &BetaParams::default()).unwrap()),
        ),
        (
            "arc-blend",
            Box::new(ArcBlend::try_new(p.clone(), 2).unwrap()),
        ),
        (
            "corner-blend",
            Box::new(CornerBlend::try_new(p, 2, DEFAULT_CORNER_FRACTION).unwrap()),
        ),
    ];
    let s3: Vec<(&str, Boxed<UnitQuat>)> = vec![
        (
            "geodesic",
            Box::new(GeodesicSpline::try_new(q.clone(), None).unwrap()),
        ),
        ("bezier", Box::new(Bezier::try_new(q.clone()).unwrap())),
        ("squad", Box::new(Squad::try_new(q.clone(), None).unwrap())),
        (
            "catmull-rom",
            Box::new(CatmullRom::try_new_quaternion(q.clone(), None).unwrap()),
        ),
        (
            "bezier-kim",
            Box::new(BezierKim::try_new(q[..4].to_vec()).unwrap()),
        ),
        (
            "bspline-kim",
            Box::new(BsplineKim::try_new(q.clone()).unwrap()),
        ),
        (
            "gamma",
            Box::new(
                GammaSpline::try_new(q.clone(), None, Gammas::All(1.0), LastEdge::Formula).unwrap(),
            ),
        ),
        (
            "beta",
            Box::new(BetaSpline::try_new(q.clone(), &BetaParams::default()).unwrap()),
        ),
        (
            "arc-blend",
            Box::new(ArcBlend::try_new(q.clone(), 2).unwrap()),
        ),
        (
            "corner-blend-s3",
            Box::new(CornerBlendS3::try_new(q, 2, DEFAULT_CORNER_FRACTION).unwrap()),
        ),
    ];
    let mut failures = Vec::new();
    for (name, c) in &s2 {
        let n = allocations(c.as_ref());
        let allowed = if *name == "bezier" { 2 } else { 0 };
        if n > allowed {
            failures.push(format!("S2 {name}: {n}"));
        }
    }
    for (name, c) in &s3 {
        let n = allocations(c.as_ref());
        let allowed = if *name == "bezier" { 2 } else { 0 };
        if n > allowed {
            failures.push(format!("S3 {name}: {n}"));
        }
    }
    assert!(
        failures.is_empty(),
        "allocations in batch evaluation: {failures:?}"
    );
}

/// Bytes a curve keeps (allocated and not freed by construction, beyond the moved-in keys).
fn retained(build: &dyn Fn(Vec<UnitQuat>) -> Boxed<UnitQuat>, n: usize) -> isize {
    let keys = data::keys_s3(n);
    let region = Region::new(GLOBAL);
    let curve = build(keys);
    let change = region.change();
    drop(curve);
    isize::try_from(change.bytes_allocated).unwrap()
        - isize::try_from(change.bytes_deallocated).unwrap()
        + change.bytes_reallocated
}

/// Memory kept by each curve through 1 000 keys is at most ~10× that through 100 keys.
fn memory_is_linear_in_keys() {
    type Build = Box<dyn Fn(Vec<UnitQuat>) -> Boxed<UnitQuat>>;
    let methods: Vec<(&str, Build)> = vec![
        (
            "geodesic",
            Box::new(|k| Box::new(GeodesicSpline::try_new(k, None).unwrap())),
        ),
        (
            "nlerp",
            Box::new(|k| Box::new(NlerpSpline::try_new(k, None).unwrap())),
        ),
        (
            "squad",
            Box::new(|k| Box::new(Squad::try_new(k, None).unwrap())),
        ),
        (
            "catmull-rom",
            Box::new(|k| Box::new(CatmullRom::try_new(k, None).unwrap())),
        ),
        (
            "bspline-kim",
            Box::new(|k| Box::new(BsplineKim::try_new(k).unwrap())),
        ),
        (
            "gamma",
            Box::new(|k| {
                Box::new(
                    GammaSpline::try_new(k, None, Gammas::All(1.0), LastEdge::Formula).unwrap(),
                )
            }),
        ),
        (
            "beta",
            Box::new(|k| Box::new(BetaSpline::try_new(k, &BetaParams::default()).unwrap())),
        ),
        (
            "arc-blend",
            Box::new(|k| Box::new(ArcBlend::try_new(k, 2).unwrap())),
        ),
        (
            "corner-blend",
            Box::new(|k| Box::new(CornerBlendS3::try_new(k, 2, DEFAULT_CORNER_FRACTION).unwrap())),
        ),
    ];
    for (name, build) in &methods {
        let small = retained(build.as_ref(), 100);
        let large = retained(build.as_ref(), 1000);
        println!("{name}: keeps {small} bytes for 100 keys, {large} for 1000");
        assert!(
            small > 0 && large <= 11 * small,
            "{name}: {small} bytes for 100 keys, {large} for 1000 keys"
        );
    }
}
