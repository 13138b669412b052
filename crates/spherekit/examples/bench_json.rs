// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The Rust side of `just bench-compare` (`scripts/bench_compare.py`): times every method on the
//! benches' keys and parameters and prints JSON with the keys, the timings (best of several
//! runs, ns per sample or per construction) and the geodesic and squad values at a subset of
//! the parameters, for the accuracy check against the peers.
//!
//! `cargo run --release -p spherekit --example bench_json [SAMPLES] [KEYS]`
//!
//! `bench_json paired` answers each line it reads, `build N` or `rates N`, with one timing in
//! ns: after one untimed run, the best of `N` constructions of the cubic (scipy ends) on the
//! benches' 1 000 keys, or of `N` runs of its rates per sample (as in the main report): the
//! paired rounds of `bench_compare.py`, which alternate them with scipy's `RotationSpline` on the
//! same keys, both in processes that stay up.

#![allow(
    clippy::cast_precision_loss,
    clippy::unwrap_used,
    reason = "a measuring tool: counts are small, a panic is the report"
)]

#[path = "../benches/curves.rs"]
mod curves;
#[path = "../benches/data.rs"]
mod data;

use std::hint::black_box;
use std::time::Instant;

use serde_json::json;
use spherekit::glam::DVec3;
use spherekit::{CubicEnd, CubicSpline, Curve, UnitQuat, angular_velocity_acceleration_body};

/// The best time of `reps` runs of `f`, in nanoseconds, divided by `per`.
fn best(reps: usize, per: usize, mut f: impl FnMut()) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..reps {
        let start = Instant::now();
        f();
        best = best.min(start.elapsed().as_nanos() as f64);
    }
    best / per as f64
}

fn wxyz(q: &UnitQuat) -> [f64; 4] {
    let d = q.as_dquat();
    [d.w, d.x, d.y, d.z]
}

fn main() {
    let mut args = std::env::args().skip(1).peekable();
    if args.peek().is_some_and(|a| a == "paired") {
        paired();
        return;
    }
    let samples: usize = args.next().map_or(200_000, |s| s.parse().unwrap());
    let count: usize = args.next().map_or(20, |s| s.parse().unwrap());
    let reps = 21;
    let keys = data::keys_s3(count);
    let mut methods = Vec::new();
    let mut values = serde_json::Map::new();
    let check_every = 100;
    for m in curves::METHODS {
        let curve = (m.build)(keys.clone());
        let ts = data::params(curve.domain(), samples);
        let mut points = vec![UnitQuat::IDENTITY; samples];
        let mut jets = vec![curve.jet(ts[0]); samples];
        let scalar = best(reps, samples, || {
            for (o, &t) in points.iter_mut().zip(&ts) {
                *o = curve.eval(black_box(t));
            }
        });
        let batch = best(reps, samples, || {
            curve.eval_many(black_box(&ts), &mut points)
        });
        let jet = best(reps, samples, || curve.jet_many(black_box(&ts), &mut jets));
        let build = |n: usize| {
            let k = data::keys_s3(n);
            // Best of 21 for 1 000 keys: as many runs as the peer's `RotationSpline` gets.
            let r = if n > 100 { 21 } else { 200 };
            best(r, 1, || {
                black_box((m.build)(black_box(k.clone())));
            })
        };
        let build_1000 = if m.name.starts_with("bezier") {
            None
        } else {
            Some(build(1000))
        };
        if matches!(m.name, "geodesic" | "squad" | "bezier") {
            let sub: Vec<_> = points.iter().step_by(check_every).map(wxyz).collect();
            values.insert(m.name.into(), json!(sub));
        }
        methods.push(json!({
            "name": m.name,
            "slerps": m.slerps,
            "domain": curve.domain(),
            "eval_ns": scalar,
            "eval_many_ns": batch,
            "jet_many_ns": jet,
            "build_20_ns": build(20),
            "build_1000_ns": build_1000,
        }));
    }
    // The floor: one glam slerp per sample between consecutive keys.
    let dq: Vec<_> = keys.iter().map(data::dquat).collect();
    let us = data::params([0.0, 1.0], samples);
    let mut out = vec![dq[0]; samples];
    let slerp = best(reps, samples, || {
        for (k, (o, &u)) in out.iter_mut().zip(&us).enumerate() {
            let i = k % (count - 1);
            *o = black_box(dq[i]).slerp(dq[i + 1], u);
        }
    });
    black_box(&out);
    // The cubic spline with scipy's end condition against `RotationSpline` on the same keys and
    // times 0 … n − 1: the point with the body-frame rate and acceleration per sample (scipy's
    // `rs(t)`, `rs(t, 1)`, `rs(t, 2)`) (its construction is the method table's `build_1000_ns`).
    let cubic = CubicSpline::try_new(keys.clone(), None, CubicEnd::Scipy, false).unwrap();
    let ts = data::params(cubic.domain(), samples);
    let mut jets = vec![cubic.jet(ts[0]); samples];
    let mut rates = vec![(DVec3::ZERO, DVec3::ZERO); samples];
    let cubic_rates_ns = best(reps, samples, || {
        cubic.jet_many(black_box(&ts), &mut jets);
        for (o, j) in rates.iter_mut().zip(&jets) {
            *o = angular_velocity_acceleration_body(j.point, j.velocity, j.acceleration);
        }
    });
    let cubic_values = json!({
        "quats": jets.iter().step_by(check_every).map(|j| wxyz(&j.point)).collect::<Vec<_>>(),
        "rates": rates.iter().step_by(check_every).map(|r| r.0.to_array()).collect::<Vec<_>>(),
        "accelerations": rates.iter().step_by(check_every).map(|r| r.1.to_array()).collect::<Vec<_>>(),
    });
    let report = json!({
        "samples": samples,
        "keys": keys.iter().map(wxyz).collect::<Vec<_>>(),
        "keys_1000": data::keys_s3(1000).iter().map(wxyz).collect::<Vec<_>>(),
        "check_every": check_every,
        "methods": methods,
        "glam_slerp_ns": slerp,
        "values": values,
        "cubic": {
            "rates_ns": cubic_rates_ns,
            "values": cubic_values,
        },
    });
    println!("{report}");
}

/// The `paired` mode (see the module documentation).
fn paired() {
    let samples = 200_000;
    let keys_1000 = data::keys_s3(1000);
    let cubic = CubicSpline::try_new(data::keys_s3(20), None, CubicEnd::Scipy, false).unwrap();
    let ts = data::params(cubic.domain(), samples);
    let mut jets = vec![cubic.jet(ts[0]); samples];
    let mut rates = vec![(DVec3::ZERO, DVec3::ZERO); samples];
    for line in std::io::stdin().lines() {
        let line = line.unwrap();
        let (request, runs) = line.split_once(' ').unwrap();
        let runs: usize = runs.parse().unwrap();
        let build = || {
            black_box(
                CubicSpline::try_new(black_box(keys_1000.clone()), None, CubicEnd::Scipy, false)
                    .unwrap(),
            );
        };
        let mut rates_run = || {
            cubic.jet_many(black_box(&ts), &mut jets);
            for (o, j) in rates.iter_mut().zip(&jets) {
                *o = angular_velocity_acceleration_body(j.point, j.velocity, j.acceleration);
            }
        };
        let ns = match request {
            "build" => {
                build();
                best(runs, 1, build)
            }
            "rates" => {
                rates_run();
                best(runs, samples, rates_run)
            }
            other => panic!("unknown request {other:?}"),
        };
        println!("{ns}");
    }
}
