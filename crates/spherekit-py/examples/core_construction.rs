// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The core alone on the keys `scripts/bench_python.py` times construction with: how much of
//! the Python constructors' time is the binding (see BENCHMARKS.md, section 7).
//!
//! ```text
//! bash scripts/setup-python.sh python scripts/bench_python.py   # writes target/bench_python_keys.txt
//! cargo run --release -p spherekit-py --example core_construction -- target/bench_python_keys.txt
//! ```
//!
//! The file has one key a line: its time and the scalar-last quaternion `x y z w`. Each figure
//! is the best of many repetitions (wall clock), as the Python script reports its own.

use std::hint::black_box;
use std::time::Instant;

use spherekit::glam::DQuat;
use spherekit::{CubicEnd, CubicSpline, GeodesicSpline, UnitQuat, unflip};

fn best(repeat: usize, mut f: impl FnMut()) -> f64 {
    (0..repeat)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

/// The keys as the binding makes them: normalised, then canonicalised.
fn keys(rows: &[[f64; 5]]) -> Vec<UnitQuat> {
    let mut keys: Vec<UnitQuat> = rows
        .iter()
        .map(|&[_, x, y, z, w]| {
            UnitQuat::try_new(DQuat::from_xyzw(x, y, z, w)).expect("a unit quaternion")
        })
        .collect();
    unflip(&mut keys);
    keys
}

fn main() {
    let path = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "target/bench_python_keys.txt".into());
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("{path}: {e} (run scripts/bench_python.py first)"));
    let rows: Vec<[f64; 5]> = text
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let v: Vec<f64> = l
                .split_whitespace()
                .map(|x| x.parse().expect("a number"))
                .collect();
            v.try_into().expect("five numbers a line: t x y z w")
        })
        .collect();
    let times: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    let ready = keys(&rows);
    println!("{} keys from {path}", rows.len());
    let us = |s: f64| s * 1e6;
    println!(
        "keys (UnitQuat::try_new, unflip): {:.1} µs",
        us(best(2000, || {
            black_box(keys(&rows));
        }))
    );
    println!(
        "GeodesicSpline::try_new: {:.1} µs",
        us(best(2000, || {
            black_box(GeodesicSpline::try_new(ready.clone(), Some(times.clone())).ok());
        }))
    );
    println!(
        "CubicSpline::try_new (scipy ends): {:.1} µs",
        us(best(200, || {
            let spline =
                CubicSpline::try_new(ready.clone(), Some(times.clone()), CubicEnd::Scipy, false);
            black_box(spline.ok());
        }))
    );
}
