// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The smoothing spline and key reduction (`CubicSpline::try_fit`): the facts of the problem
//! against independent small solvers written here.

use spherekit::glam::{DVec3, DVec4};
use spherekit::{
    CubicEnd, CubicSpline, Curve, FitKeys, FitOptions, Manifold, S2Point, SmPoint, Smoothing,
    SplineError, UnitQuat,
};

/// A deterministic pseudo-random sequence in [−1, 1].
fn noise(i: usize, seed: u64) -> f64 {
    let mut x = (i as u64 + 1).wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ seed.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x ^= x >> 31;
    x = x.wrapping_mul(0x94D0_49BB_1331_11EB);
    x ^= x >> 29;
    (x >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}

/// Dense Gauss–Jordan solve of `a·x = b` (n × n).
fn dense_solve(mut a: Vec<f64>, mut b: Vec<f64>, n: usize) -> Vec<f64> {
    for c in 0..n {
        let p = (c..n).max_by(|&i, &j| a[i * n + c].abs().total_cmp(&a[j * n + c].abs())).unwrap();
        for k in 0..n {
            a.swap(c * n + k, p * n + k);
        }
        b.swap(c, p);
        for r in 0..n {
            if r != c {
                let f = a[r * n + c] / a[c * n + c];
                for k in 0..n {
                    a[r * n + k] -= f * a[c * n + k];
                }
                b[r] -= f * b[c];
            }
        }
    }
    (0..n).map(|i| b[i] / a[i * n + i]).collect()
}

/// The Euclidean natural cubic smoothing spline's values at the knots (Reinsch 1967),
/// minimising `Σ wᵢ(yᵢ − gᵢ)² + λ∫g″²`, by a dense solve of `(W + λ·Q R⁻¹ Qᵀ) g = W y`.
fn reinsch_values(t: &[f64], y: &[f64], w: &[f64], lambda: f64) -> Vec<f64> {
    let n = t.len();
    let m = n - 2;
    let h: Vec<f64> = t.windows(2).map(|p| p[1] - p[0]).collect();
    let mut q = vec![0.0; n * m];
    let mut r = vec![0.0; m * m];
    for a in 0..m {
        let j = a + 1;
        q[(j - 1) * m + a] = 1.0 / h[j - 1];
        q[j * m + a] = -1.0 / h[j - 1] - 1.0 / h[j];
        q[(j + 1) * m + a] = 1.0 / h[j];
        r[a * m + a] = (h[j - 1] + h[j]) / 3.0;
        if a + 1 < m {
            r[a * m + a + 1] = h[j] / 6.0;
            r[(a + 1) * m + a] = h[j] / 6.0;
        }
    }
    // K = Q R⁻¹ Qᵀ, column by column.
    let mut k = vec![0.0; n * n];
    for col in 0..n {
        let rhs: Vec<f64> = (0..m).map(|a| q[col * m + a]).collect();
        let z = dense_solve(r.clone(), rhs, m);
        for row in 0..n {
            k[row * n + col] = (0..m).map(|a| q[row * m + a] * z[a]).sum();
        }
    }
    let mut sys = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            sys[i * n + j] = lambda * k[i * n + j] + if i == j { w[i] } else { 0.0 };
        }
    }
    let rhs = (0..n).map(|i| w[i] * y[i]).collect();
    dense_solve(sys, rhs, n)
}

fn lambda(l: f64) -> FitOptions {
    FitOptions {
        smoothing: Some(Smoothing::Lambda(l)),
        ..FitOptions::default()
    }
}

/// Samples along a great circle of S² tilted out of the equator, angle θᵢ plus noise.
fn great_circle(n: usize, seed: u64) -> (Vec<f64>, Vec<f64>, Vec<S2Point>, Vec<f64>) {
    let mut t = vec![0.0];
    for i in 1..n {
        t.push(t[i - 1] + 0.2 + 0.1 * noise(i, seed + 7).abs());
    }
    let theta: Vec<f64> = t.iter().enumerate().map(|(i, &s)| 0.9 * s + 0.3 * (1.3 * s).sin() + 0.05 * noise(i, seed)).collect();
    let w: Vec<f64> = (0..n).map(|i| 0.5 + noise(i, seed + 3).abs()).collect();
    let (u, v) = (DVec3::new(1.0, 0.0, 0.0), DVec3::new(0.0, 0.6, 0.8));
    let pts = theta.iter().map(|&a| S2Point::try_new(u * a.cos() + v * a.sin()).unwrap()).collect();
    (t, theta, pts, w)
}

/// The angle along the great circle of a fitted point, unwrapped against a reference angle.
fn angle_on_circle(p: DVec3, reference: f64) -> f64 {
    let (u, v) = (DVec3::new(1.0, 0.0, 0.0), DVec3::new(0.0, 0.6, 0.8));
    let a = p.dot(v).atan2(p.dot(u));
    let tau = std::f64::consts::TAU;
    a + tau * ((reference - a) / tau).round()
}

#[test]
fn great_circle_fit_is_the_euclidean_smoothing_spline() {
    let (t, theta, pts, w) = great_circle(30, 1);
    for lam in [1e-3, 0.05, 1.0, 30.0] {
        let options = FitOptions {
            smoothing: Some(Smoothing::Lambda(lam)),
            weights: Some(w.clone()),
            keys: FitKeys::Samples,
        };
        let (curve, report) = CubicSpline::try_fit(pts.clone(), t.clone(), &options, false).unwrap();
        let expect = reinsch_values(&t, &theta, &w, lam);
        let mut worst: f64 = 0.0;
        for (k, key) in curve.points().iter().enumerate() {
            let a = angle_on_circle(key.as_dvec3(), expect[k]);
            worst = worst.max((a - expect[k]).abs());
            // On the circle.
            let off = key.as_dvec3().dot(DVec3::new(0.0, -0.8, 0.6)).abs();
            assert!(off < 1e-10, "λ {lam} key {k} off {off:e} it {}", report.iterations);
        }
        eprintln!("λ {lam}: worst {worst:e}, iterations {}", report.iterations);
        assert!(worst < 1e-9, "λ {lam}: {worst:e}");
    }
}
