//! Times the interpolation solvers of `BetaSpline` on random S² data (release mode:
//! `cargo run --release -p spherekit --example beta_timing`).
//!
//! Data: a random walk on S² whose consecutive points are between 10° and 60° apart.

use std::time::Instant;

use spherekit::glam::DVec3;
use spherekit::{BetaParams, BetaSolver, BetaSpline, Manifold, S2Point};

/// A small deterministic generator (`SplitMix64`).
struct Rng(u64);

impl Rng {
    fn next_f64(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn random_walk(n: usize, max_deg: f64, seed: u64) -> Vec<S2Point> {
    let mut rng = Rng(seed);
    let mut p = DVec3::Z;
    let mut out = vec![S2Point::try_new(p).expect("unit vector")];
    for _ in 0..n {
        let a = (10.0 + (max_deg - 10.0) * rng.next_f64()).to_radians();
        let phi = std::f64::consts::TAU * rng.next_f64();
        let e1 = p.any_orthonormal_vector();
        let e2 = p.cross(e1);
        let t = e1 * phi.cos() + e2 * phi.sin();
        p = (p * a.cos() + t * a.sin()).normalize();
        out.push(S2Point::try_new(p).expect("unit vector"));
    }
    out
}

fn time(points: &[S2Point], params: &BetaParams, reps: usize) -> (f64, String) {
    let mut best = f64::INFINITY;
    let mut info = String::new();
    for _ in 0..reps {
        let t0 = Instant::now();
        let r = BetaSpline::try_new(points.to_vec(), params);
        let dt = t0.elapsed().as_secs_f64() * 1e3;
        best = best.min(dt);
        info = match r {
            Ok(c) => {
                let s = c.solve_info().expect("interpolating");
                format!("{} iterations, residual {:.1e}", s.iterations, s.residual)
            }
            Err(e) => format!("error: {e}"),
        };
    }
    (best, info)
}

fn main() {
    if std::env::args().nth(1).as_deref() == Some("newton") {
        // Profiling mode: Newton only, n = 1000.
        let pts = random_walk(1000, 60.0, 1);
        let (t, info) = time(&pts, &BetaParams::default(), 200);
        println!("n = 1000: newton {t:.3} ms ({info})");
        return;
    }
    for &n in &[250, 500, 1000, 2000, 4000] {
        for seed in 1..=3 {
            let pts = random_walk(n, 60.0, seed);
            let max = pts.windows(2).map(|w| w[0].dist(&w[1])).fold(0.0, f64::max);
            assert!(max <= 60f64.to_radians() + 1e-12, "walk step");
            let newton = BetaParams::default();
            let jacobi = BetaParams {
                solver: BetaSolver::Jacobi,
                residual_tolerance: Some(1e-12),
                ..BetaParams::default()
            };
            let (tn, inf_n) = time(&pts, &newton, 5);
            let (tj, inf_j) = time(&pts, &jacobi, 2);
            println!(
                "n = {n:5} seed {seed}: newton {tn:8.3} ms ({inf_n}); jacobi {tj:8.3} ms ({inf_j})"
            );
        }
    }
}
