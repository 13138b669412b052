// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The interpolation solvers of the spherical Beta spline on S²: Newton to a residual of
//! 1e-12 and the paper's Jacobi iteration to 1e-10 (stopping when Σ‖Δdᵢ‖² < 1e-22), for
//! n = 10, 1 000 and 100 000 random points whose neighbours are 10°–60° apart.
//!
//! `cargo bench -p spherekit --bench solve`. Each solver's iterations and final residual are
//! printed once per size before it is timed. `SPHEREKIT_BENCH_SKIP_JACOBI_100K=1` skips Jacobi
//! at n = 100 000 (seconds per solve).

#![allow(missing_docs, reason = "criterion macros")]

#[path = "data.rs"]
mod data;

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use spherekit::{BetaParams, BetaSolver, BetaSpline};

fn solvers(c: &mut Criterion) {
    let mut group = c.benchmark_group("beta solve");
    group.sample_size(10);
    let jacobi_100k = std::env::var_os("SPHEREKIT_BENCH_SKIP_JACOBI_100K").is_none();
    for n in [10, 1000, 100_000] {
        let points = data::points_s2(n, 60.0, 1);
        group.throughput(Throughput::Elements(n as u64));
        let newton = BetaParams::default();
        report("newton", n, &points, &newton);
        group.bench_with_input(BenchmarkId::new("newton 1e-12", n), &points, |b, p| {
            b.iter(|| BetaSpline::try_new(black_box(p.clone()), &newton).expect("newton"));
        });
        if n < 100_000 || jacobi_100k {
            let jacobi = BetaParams {
                solver: BetaSolver::Jacobi,
                // Stop once the steps are ~1e-11 rad (Σ‖Δdᵢ‖² < 1e-22) instead of the default
                // 1e-26, so that Jacobi is not made to iterate past the accuracy it is asked for.
                tolerance: Some(1e-22),
                residual_tolerance: Some(1e-10),
                ..BetaParams::default()
            };
            report("jacobi", n, &points, &jacobi);
            group.bench_with_input(BenchmarkId::new("jacobi 1e-10", n), &points, |b, p| {
                b.iter(|| BetaSpline::try_new(black_box(p.clone()), &jacobi).expect("jacobi"));
            });
        }
    }
    group.finish();
}

/// Prints the solver's iterations, residual and the wall time of one solve.
fn report(name: &str, n: usize, points: &[spherekit::S2Point], params: &BetaParams) {
    let start = std::time::Instant::now();
    let c = BetaSpline::try_new(points.to_vec(), params).expect("solves");
    let time = start.elapsed().as_secs_f64() * 1e3;
    let info = c.solve_info().expect("interpolating");
    println!(
        "{name} n = {n}: {} iterations, residual {:.1e} rad, one solve {time:.2} ms",
        info.iterations, info.residual
    );
}

criterion_group!(benches, solvers);
criterion_main!(benches);
