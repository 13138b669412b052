// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The smoothing spline and key reduction (`CubicSpline::try_fit`): the facts of the problem
//! against independent small solvers written here.

use spherekit::glam::{DQuat, DVec3};
use spherekit::{
    Ambient, CubicEnd, CubicSpline, Curve, FitKeys, FitOptions, Manifold, S2Point, SmPoint,
    Smoothing, SplineError, UnitQuat,
};

/// A deterministic pseudo-random sequence in [−1, 1].
fn noise(i: usize, seed: u64) -> f64 {
    let mut x = (i as u64 + 1).wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ seed.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x ^= x >> 31;
    x = x.wrapping_mul(0x94D0_49BB_1331_11EB);
    x ^= x >> 29;
    (x >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}

/// Dense Gauss–Jordan solve of `a·x = b` (n × n).
fn dense_solve(mut a: Vec<f64>, mut b: Vec<f64>, n: usize) -> Vec<f64> {
    for c in 0..n {
        let p = (c..n)
            .max_by(|&i, &j| a[i * n + c].abs().total_cmp(&a[j * n + c].abs()))
            .unwrap_or(c);
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
    smoothing_values(&q, &r, m, y, w, lambda)
}

/// The smoothing spline's values from Reinsch's `Q` (`n × m`) and `R` (`m × m`): the dense
/// solve of `(W + λ·Q R⁻¹ Qᵀ) g = W y`.
fn smoothing_values(q: &[f64], r: &[f64], m: usize, y: &[f64], w: &[f64], lambda: f64) -> Vec<f64> {
    let n = y.len();
    // K = Q R⁻¹ Qᵀ, column by column.
    let mut k = vec![0.0; n * n];
    for col in 0..n {
        let rhs: Vec<f64> = (0..m).map(|a| q[col * m + a]).collect();
        let z = dense_solve(r.to_vec(), rhs, m);
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
    let theta: Vec<f64> = t
        .iter()
        .enumerate()
        .map(|(i, &s)| 0.9 * s + 0.3 * (1.3 * s).sin() + 0.05 * noise(i, seed))
        .collect();
    let w: Vec<f64> = (0..n).map(|i| 0.5 + noise(i, seed + 3).abs()).collect();
    let (u, v) = (DVec3::new(1.0, 0.0, 0.0), DVec3::new(0.0, 0.6, 0.8));
    let pts = theta
        .iter()
        .map(|&a| S2Point::try_new(u * a.cos() + v * a.sin()).expect("a point"))
        .collect();
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
        let (curve, report) =
            CubicSpline::try_fit(pts.clone(), t.clone(), &options, false).unwrap();
        let expect = reinsch_values(&t, &theta, &w, lam);
        let mut worst: f64 = 0.0;
        for (k, key) in curve.points().iter().enumerate() {
            let a = angle_on_circle(key.as_dvec3(), expect[k]);
            worst = worst.max((a - expect[k]).abs());
            // On the circle.
            let off = key.as_dvec3().dot(DVec3::new(0.0, -0.8, 0.6)).abs();
            assert!(
                off < 1e-9,
                "λ {lam} key {k} off {off:e} it {}",
                report.iterations
            );
        }
        assert!(worst < 1e-9, "λ {lam}: {worst:e}");
    }
}

/// Rotations about one axis: the rotation angle `φ` (twice the quaternion angle) along it.
#[test]
fn one_axis_rotation_fit_is_the_euclidean_smoothing_spline_of_the_angle() {
    let (t, theta, _, w) = great_circle(25, 2);
    let axis = DVec3::new(0.3, -0.5, 0.8).normalize();
    // Rotation angles up to several turns, each sample's sign arbitrary.
    let phi: Vec<f64> = theta.iter().map(|a| 2.5 * a).collect();
    let samples: Vec<UnitQuat> = phi
        .iter()
        .enumerate()
        .map(|(i, &a)| {
            let q = UnitQuat::from_axis_angle(axis, a).unwrap();
            if i % 3 == 1 { -q } else { q }
        })
        .collect();
    for lam in [0.01, 0.5, 20.0] {
        let options = FitOptions {
            smoothing: Some(Smoothing::Lambda(lam)),
            weights: Some(w.clone()),
            keys: FitKeys::Samples,
        };
        let (curve, _) = CubicSpline::try_fit(samples.clone(), t.clone(), &options, false).unwrap();
        let expect = reinsch_values(&t, &phi, &w, lam);
        for (k, key) in curve.points().iter().enumerate() {
            let (ax, angle) = key.as_dquat().to_axis_angle();
            let angle = if ax.dot(axis) < 0.0 { -angle } else { angle };
            let tau = 2.0 * std::f64::consts::TAU;
            let a = angle + tau * ((expect[k] - angle) / tau).round();
            // The same rotation: the angle modulo a full turn.
            let diff = (a - expect[k]).rem_euclid(std::f64::consts::TAU);
            let diff = diff.min(std::f64::consts::TAU - diff);
            assert!(diff < 1e-8, "λ {lam} key {k}: {a} vs {}", expect[k]);
        }
    }
}

#[test]
fn lambda_near_zero_is_the_interpolating_cubic() {
    let (t, _, pts, _) = great_circle(12, 3);
    // Off the circle too: a general track.
    let pts: Vec<S2Point> = pts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            S2Point::try_new(p.as_dvec3() + DVec3::new(0.0, 0.1 * noise(i, 9), 0.1 * noise(i, 10)))
                .unwrap()
        })
        .collect();
    let (fit, report) =
        CubicSpline::try_fit(pts.clone(), t.clone(), &lambda(1e-13), false).unwrap();
    let interp =
        CubicSpline::try_new(pts.clone(), Some(t.clone()), CubicEnd::Natural, false).unwrap();
    for j in 0..200 {
        let s = t[0] + (t[t.len() - 1] - t[0]) * f64::from(j) / 199.0;
        assert!(fit.eval(s).dist(&interp.eval(s)) < 1e-10);
    }
    assert!(report.rms < 1e-10);
    assert_eq!(report.edf.map(|e| (e / 2.0).round()), Some(12.0));
}

/// The best constant-speed geodesic `Exp_p((t − t̄)·v)` by an independent Gauss–Newton on
/// `(p, v)` with numerical derivatives (small problems only).
fn geodesic_regression(t: &[f64], y: &[S2Point]) -> Vec<DVec3> {
    let tbar = t.iter().sum::<f64>() / t.len() as f64;
    let curve = |x: &[f64; 5], s: f64| -> DVec3 {
        let p = DVec3::new(x[0], x[1], x[2]).normalize();
        let v = DVec3::new(x[3], x[4], 0.0);
        let v = v - p * p.dot(v);
        let w = v * (s - tbar);
        let a = w.length();
        if a < 1e-300 {
            p
        } else {
            p * a.cos() + w * (a.sin() / a)
        }
    };
    let resid = |x: &[f64; 5]| -> Vec<f64> {
        t.iter()
            .zip(y)
            .map(|(&s, q)| curve(x, s).dot(q.as_dvec3()).clamp(-1.0, 1.0).acos())
            .collect()
    };
    let cost = |x: &[f64; 5]| resid(x).iter().map(|r| r * r).sum::<f64>();
    let (first, last) = (y[0].as_dvec3(), y[y.len() - 1].as_dvec3());
    let mid = (first + last).normalize();
    let v0 = (last - first) / (t[t.len() - 1] - t[0]);
    let mut x = [mid.x, mid.y, mid.z, v0.x, v0.y];
    let mut damping = 1e-3;
    for _ in 0..500 {
        let r = resid(&x);
        let mut jac = vec![[0.0; 5]; r.len()];
        for c in 0..5 {
            let (mut a, mut b) = (x, x);
            a[c] += 1e-7;
            b[c] -= 1e-7;
            let (ra, rb) = (resid(&a), resid(&b));
            for i in 0..r.len() {
                jac[i][c] = (ra[i] - rb[i]) / 2e-7;
            }
        }
        // Levenberg–Marquardt on the 5 parameters (one is redundant: the scale of p).
        let mut a = vec![0.0; 25];
        let mut g = vec![0.0; 5];
        for i in 0..r.len() {
            for p in 0..5 {
                g[p] -= jac[i][p] * r[i];
                for q in 0..5 {
                    a[p * 5 + q] += jac[i][p] * jac[i][q];
                }
            }
        }
        for p in 0..5 {
            a[p * 5 + p] += damping;
        }
        let step = dense_solve(a, g, 5);
        let mut trial = x;
        for p in 0..5 {
            trial[p] += step[p];
        }
        if cost(&trial) < cost(&x) {
            x = trial;
            damping = (damping * 0.3).max(1e-12);
        } else {
            damping *= 10.0;
        }
    }
    t.iter().map(|&s| curve(&x, s)).collect()
}

#[test]
fn lambda_large_tends_to_the_geodesic_regression() {
    let n = 15;
    let t: Vec<f64> = (0..n).map(|i| 0.3 * i as f64).collect();
    let pts: Vec<S2Point> = t
        .iter()
        .enumerate()
        .map(|(i, &s)| {
            S2Point::try_new(DVec3::new(
                (0.4 * s).cos(),
                (0.4 * s).sin(),
                0.3 + 0.2 * noise(i, 4) + 0.1 * s,
            ))
            .unwrap()
        })
        .collect();
    let expect = geodesic_regression(&t, &pts);
    let (fit, _) = CubicSpline::try_fit(pts, t.clone(), &lambda(1e9), false).unwrap();
    for (s, e) in t.iter().zip(&expect) {
        let d = fit.eval(*s).as_dvec3().dot(*e).clamp(-1.0, 1.0).acos();
        assert!(d < 1e-5, "{d:e}");
    }
}

#[test]
fn the_fit_rotates_with_the_samples_and_ignores_quaternion_signs() {
    let (t, _, pts, w) = great_circle(14, 5);
    let pts: Vec<S2Point> = pts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            S2Point::try_new(p.as_dvec3() + DVec3::new(0.0, 0.2 * noise(i, 11), 0.1 * noise(i, 12)))
                .unwrap()
        })
        .collect();
    let options = FitOptions {
        smoothing: Some(Smoothing::Lambda(0.3)),
        weights: Some(w.clone()),
        keys: FitKeys::Samples,
    };
    let (a, _) = CubicSpline::try_fit(pts.clone(), t.clone(), &options, false).unwrap();
    let r = DQuat::from_axis_angle(DVec3::new(1.0, 2.0, -0.5).normalize(), 1.1);
    let rotated: Vec<S2Point> = pts
        .iter()
        .map(|p| S2Point::try_new(r * p.as_dvec3()).unwrap())
        .collect();
    let (b, _) = CubicSpline::try_fit(rotated, t.clone(), &options, false).unwrap();
    for (ka, kb) in a.points().iter().zip(b.points()) {
        let d = (r * ka.as_dvec3() - kb.as_dvec3()).length();
        assert!(d < 1e-8, "{d:e}");
    }
    // S³: flipping signs changes no rotation of the fit.
    let qs: Vec<UnitQuat> = t
        .iter()
        .enumerate()
        .map(|(i, &s)| {
            UnitQuat::from_rotation_vector(DVec3::new(
                0.7 * s,
                0.3 * (s * 1.3).sin() + 0.05 * noise(i, 1),
                0.2 + 0.05 * noise(i, 2),
            ))
            .unwrap()
        })
        .collect();
    let flipped: Vec<UnitQuat> = qs
        .iter()
        .enumerate()
        .map(|(i, &q)| if i % 2 == 0 { -q } else { q })
        .collect();
    let (qa, ra) = CubicSpline::try_fit(qs, t.clone(), &options, false).unwrap();
    let (qb, rb) = CubicSpline::try_fit(flipped, t.clone(), &options, false).unwrap();
    assert!((ra.rms - rb.rms).abs() < 1e-12);
    for j in 0..50 {
        let s = t[0] + (t[t.len() - 1] - t[0]) * f64::from(j) / 49.0;
        assert!(
            qa.eval(s)
                .dist(&qb.eval(s))
                .min(qa.eval(s).dist(&-qb.eval(s)))
                < 1e-9
        );
    }
}

#[test]
fn the_rms_target_is_reached_and_gcv_minimises_its_score() {
    let (t, theta, pts, w) = great_circle(40, 6);
    let sigma = 0.03;
    let options = FitOptions {
        smoothing: Some(Smoothing::Rms(sigma)),
        weights: Some(w.clone()),
        keys: FitKeys::Samples,
    };
    let (_, report) = CubicSpline::try_fit(pts.clone(), t.clone(), &options, false).unwrap();
    assert!((report.rms / sigma - 1.0).abs() < 1e-6, "{}", report.rms);
    // GCV: the chosen λ minimises N·Σwr²/(N − tr A)² of the Euclidean problem on the circle.
    let options = FitOptions {
        smoothing: Some(Smoothing::Gcv),
        weights: Some(w.clone()),
        keys: FitKeys::Samples,
    };
    let (_, report) = CubicSpline::try_fit(pts.clone(), t.clone(), &options, false).unwrap();
    let n = t.len() as f64;
    let score = |lam: f64| {
        let g = reinsch_values(&t, &theta, &w, lam);
        let rss: f64 = (0..t.len()).map(|i| w[i] * (g[i] - theta[i]).powi(2)).sum();
        // tr A by finite differences of the linear map y ↦ g, column by column.
        let mut tr = 0.0;
        for i in 0..t.len() {
            let mut e = vec![0.0; t.len()];
            e[i] = 1.0;
            tr += reinsch_values(&t, &e, &w, lam)[i];
        }
        n * rss / (n - tr).powi(2)
    };
    let l = report.lambda;
    let (s0, s1, s2) = (score(l), score(l * 1.01), score(l / 1.01));
    assert!(s0 <= s1 && s0 <= s2, "{s0} {s1} {s2}");
    assert!(
        (report.edf.unwrap() / 2.0
            - (0..t.len())
                .map(|i| {
                    let mut e = vec![0.0; t.len()];
                    e[i] = 1.0;
                    reinsch_values(&t, &e, &w, l)[i]
                })
                .sum::<f64>())
        .abs()
            < 1e-8
    );
}

#[test]
fn key_reduction_stays_within_the_bound() {
    // A dense smooth S² track and a closed S³ loop (one turn about a wobbling axis).
    let n = 400;
    let t: Vec<f64> = (0..n).map(|i| 0.01 * i as f64).collect();
    let track: Vec<S2Point> = t
        .iter()
        .map(|&s| {
            S2Point::try_new(DVec3::new(
                (1.3 * s).cos(),
                (1.3 * s).sin(),
                0.4 * (2.0 * s).sin(),
            ))
            .unwrap()
        })
        .collect();
    for eps in [0.002, 0.01] {
        let options = FitOptions {
            smoothing: None,
            weights: None,
            keys: FitKeys::MaxError(eps),
        };
        let (c, report) = CubicSpline::try_fit(track.clone(), t.clone(), &options, false).unwrap();
        assert!(report.max <= eps && report.keys < n / 4, "{report:?}");
        for i in 0..n - 1 {
            assert!(c.eval(t[i]).dist(&track[i]) <= eps);
            let mid = track[i].slerp(&track[i + 1], 0.5);
            assert!(c.eval(0.5 * (t[i] + t[i + 1])).dist(&mid) <= eps);
        }
    }
    let period = 4.0;
    let mut times: Vec<f64> = (0..n).map(|i| period * i as f64 / n as f64).collect();
    times.push(period);
    let tau = std::f64::consts::TAU;
    let loop_: Vec<UnitQuat> = times[..n]
        .iter()
        .map(|&s| {
            UnitQuat::from_rotation_vector(
                DVec3::new(0.3 * (tau * s / period).sin(), 0.2, 1.0)
                    * (2.0 * tau * s / period).sin(),
            )
            .unwrap()
        })
        .collect();
    let options = FitOptions {
        smoothing: None,
        weights: None,
        keys: FitKeys::MaxError(0.01),
    };
    let (c, report) = CubicSpline::try_fit(loop_.clone(), times.clone(), &options, true).unwrap();
    assert!(report.max <= 0.01 && report.keys < n / 4, "{report:?}");
    for i in 0..n {
        assert!(c.eval(times[i]).dist(&loop_[i]) * 2.0 <= 0.01 + 1e-12);
    }
}

#[test]
fn a_closed_fit_is_c2_at_the_seam_and_smooths_on_every_sphere() {
    let n = 30;
    let mut t: Vec<f64> = (0..n).map(|i| 0.1 * i as f64).collect();
    t.push(3.0);
    let tau = std::f64::consts::TAU;
    let pts: Vec<SmPoint> = t[..n]
        .iter()
        .enumerate()
        .map(|(i, &s)| {
            let a = tau * s / 3.0;
            SmPoint::try_new(vec![
                a.cos(),
                a.sin(),
                0.3 + 0.05 * noise(i, 1),
                0.2 * (2.0 * a).sin(),
                0.05 * noise(i, 2),
            ])
            .unwrap()
        })
        .collect();
    let (c, report) = CubicSpline::try_fit(pts, t.clone(), &lambda(0.01), true).unwrap();
    assert!(report.rms > 0.0 && report.rms < 0.06);
    let (a, b) = (
        c.jet_at(0.0, spherekit::Side::Right),
        c.jet_at(3.0, spherekit::Side::Left),
    );
    assert!((a.velocity - b.velocity).length() < 1e-9);
    assert!((a.acceleration - b.acceleration).length() < 1e-8);
    for j in spherekit::continuity(&c) {
        assert!(j.c1 < 1e-10 && j.c2 < 1e-8);
    }
}

#[test]
fn bad_fit_input_is_a_typed_error() {
    let (t, _, pts, _) = great_circle(10, 8);
    let err = |options: FitOptions, t: Vec<f64>| {
        CubicSpline::try_fit(pts.clone(), t, &options, false).unwrap_err()
    };
    let name = |e: SplineError| match e {
        SplineError::InvalidParameter { name, .. } => name,
        e => panic!("{e:?}"),
    };
    let with = |smoothing: Smoothing| FitOptions {
        smoothing: Some(smoothing),
        ..FitOptions::default()
    };
    assert_eq!(
        name(err(with(Smoothing::Lambda(-1.0)), t.clone())),
        "smoothing"
    );
    assert_eq!(
        name(err(with(Smoothing::Lambda(f64::NAN)), t.clone())),
        "smoothing"
    );
    assert_eq!(name(err(with(Smoothing::Rms(0.0)), t.clone())), "smoothing");
    assert_eq!(
        name(err(with(Smoothing::Rms(10.0)), t.clone())),
        "smoothing"
    );
    let weights = |w: Vec<f64>| FitOptions {
        weights: Some(w),
        ..FitOptions::default()
    };
    assert_eq!(name(err(weights(vec![1.0; 3]), t.clone())), "weights");
    let mut w = vec![1.0; 10];
    w[4] = 0.0;
    assert_eq!(name(err(weights(w), t.clone())), "weights");
    let keys = |k: FitKeys| FitOptions {
        keys: k,
        ..FitOptions::default()
    };
    let gcv_count = FitOptions {
        keys: FitKeys::Count(4),
        smoothing: Some(Smoothing::Gcv),
        ..FitOptions::default()
    };
    assert_eq!(name(err(gcv_count, t.clone())), "smoothing");
    assert_eq!(name(err(keys(FitKeys::Count(1)), t.clone())), "keys");
    let count = |k: FitKeys| FitOptions {
        keys: k,
        smoothing: Some(Smoothing::Lambda(0.0)),
        ..FitOptions::default()
    };
    assert_eq!(name(err(count(FitKeys::Count(1)), t.clone())), "keys");
    assert_eq!(name(err(count(FitKeys::Count(11)), t.clone())), "keys");
    assert_eq!(
        name(err(count(FitKeys::MaxError(0.0)), t.clone())),
        "max_error"
    );
    let mut bad = t.clone();
    bad[3] = bad[2];
    assert!(matches!(
        err(FitOptions::default(), bad),
        SplineError::KnotsNotIncreasing { index: 3 }
    ));
    let mut bad = t.clone();
    bad[3] = f64::NAN;
    assert!(matches!(
        err(FitOptions::default(), bad),
        SplineError::InvalidKnot { index: 3 }
    ));
    assert!(matches!(
        err(FitOptions::default(), t[..9].to_vec()),
        SplineError::KnotCount { .. }
    ));
    // Identical samples: the constant curve.
    let same = vec![pts[0]; 10];
    let (c, report) = CubicSpline::try_fit(same, t.clone(), &FitOptions::default(), false).unwrap();
    assert!(report.rms == 0.0 && c.eval(t[5]).dist(&pts[0]) < 1e-15);
}

#[test]
fn exact_samples_fit_without_residual_open_closed_and_by_gcv() {
    // Samples on a smooth closed track with no noise: every smoothing fits them, to rounding.
    let n = 24;
    let mut t: Vec<f64> = (0..n).map(|i| 0.25 * f64::from(i)).collect();
    t.push(6.0);
    let tau = std::f64::consts::TAU;
    let pts: Vec<S2Point> = t[..n as usize]
        .iter()
        .map(|&s| {
            let a = tau * s / 6.0;
            S2Point::try_new(DVec3::new(a.cos(), a.sin(), 0.5 + 0.2 * (2.0 * a).sin()))
                .expect("a point")
        })
        .collect();
    for (closed, times) in [(true, t.clone()), (false, t[..n as usize].to_vec())] {
        for smoothing in [
            Smoothing::Lambda(0.0),
            Smoothing::Lambda(1e-6),
            Smoothing::Gcv,
        ] {
            let options = FitOptions {
                smoothing: Some(smoothing.clone()),
                ..FitOptions::default()
            };
            let (_, report) = CubicSpline::try_fit(pts.clone(), times.clone(), &options, closed)
                .unwrap_or_else(|e| panic!("closed {closed} {smoothing:?}: {e}"));
            assert!(
                report.max < 1e-3,
                "closed {closed} {smoothing:?}: {report:?}"
            );
        }
    }
}

#[test]
fn a_repeated_sample_weighs_twice() {
    // Times increase strictly, so the repeat is a hair later; as the gap closes the fit tends
    // to the fit with that sample's weight doubled (the gap's segment, of energy ~ |Δ|²/δ³,
    // ties the two keys together).
    let (t, _, pts, _) = great_circle(16, 13);
    let pts: Vec<S2Point> = pts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            S2Point::try_new(
                p.as_dvec3() + DVec3::new(0.0, 0.15 * noise(i, 21), 0.1 * noise(i, 22)),
            )
            .expect("a point")
        })
        .collect();
    let k = 7;
    let mut w = vec![1.0; 16];
    w[k] = 2.0;
    let options = |w: Vec<f64>| FitOptions {
        smoothing: Some(Smoothing::Lambda(0.05)),
        weights: Some(w),
        keys: FitKeys::Samples,
    };
    let (doubled, _) =
        CubicSpline::try_fit(pts.clone(), t.clone(), &options(w), false).expect("a fit");
    let mut errors = Vec::new();
    for gap in [1e-3, 1e-4] {
        let mut t2 = t.clone();
        t2.insert(k + 1, t[k] + gap);
        let mut p2 = pts.clone();
        p2.insert(k + 1, pts[k]);
        let (repeated, _) =
            CubicSpline::try_fit(p2, t2, &options(vec![1.0; 17]), false).expect("a fit");
        let worst = t
            .iter()
            .map(|&s| repeated.eval(s).dist(&doubled.eval(s)))
            .fold(0.0, f64::max);
        errors.push(worst);
    }
    // First order in the gap.
    assert!(
        errors[1] < 3e-5 && errors[1] < 0.2 * errors[0],
        "{errors:?}"
    );
}

/// The periodic Euclidean smoothing spline's values (period `t[n] − t[0]`), dense.
fn periodic_reinsch_values(t: &[f64], y: &[f64], w: &[f64], lambda: f64) -> Vec<f64> {
    let n = y.len();
    let h: Vec<f64> = t.windows(2).map(|p| p[1] - p[0]).collect();
    let mut q = vec![0.0; n * n];
    let mut r = vec![0.0; n * n];
    for j in 0..n {
        let (p, next) = ((j + n - 1) % n, (j + 1) % n);
        q[p * n + j] += 1.0 / h[p];
        q[j * n + j] += -1.0 / h[p] - 1.0 / h[j];
        q[next * n + j] += 1.0 / h[j];
        r[j * n + j] += (h[p] + h[j]) / 3.0;
        r[j * n + next] += h[j] / 6.0;
        r[next * n + j] += h[j] / 6.0;
    }
    smoothing_values(&q, &r, n, y, w, lambda)
}

#[test]
fn a_full_turn_orbit_is_fitted_as_a_loop_in_so3() {
    // One turn about an axis in T, the rotation angle 2πt/T plus a periodic wobble and noise:
    // the fit is 2πt/T plus the periodic smoothing spline of the rest (the linear part has no
    // second derivative).
    let n = 30;
    let period = 6.0;
    let mut t = vec![0.0];
    for i in 1..=n {
        t.push(t[i - 1] + 0.15 + 0.1 * noise(i, 31).abs());
    }
    let scale = period / t[n];
    for s in &mut t {
        *s *= scale;
    }
    let tau = std::f64::consts::TAU;
    let rest: Vec<f64> = (0..n)
        .map(|i| 0.3 * (tau * t[i] / period).sin() + 0.05 * noise(i, 32))
        .collect();
    let w: Vec<f64> = (0..n).map(|i| 0.5 + noise(i, 33).abs()).collect();
    let axis = DVec3::new(0.2, 0.3, 1.0).normalize();
    let samples: Vec<UnitQuat> = (0..n)
        .map(|i| {
            let q =
                UnitQuat::from_axis_angle(axis, tau * t[i] / period + rest[i]).expect("a rotation");
            if i % 4 == 3 { -q } else { q }
        })
        .collect();
    for lam in [0.01, 0.3] {
        let options = FitOptions {
            smoothing: Some(Smoothing::Lambda(lam)),
            weights: Some(w.clone()),
            keys: FitKeys::Samples,
        };
        let (orbit, report) =
            CubicSpline::try_fit_loop(samples.clone(), t.clone(), &options).expect("a fit");
        assert!(orbit.is_antiperiodic());
        assert_eq!(
            (report.keys, report.key_times.len(), report.residuals.len()),
            (n, n + 1, n)
        );
        let expect = periodic_reinsch_values(&t, &rest, &w, lam);
        for i in 0..n {
            let want = UnitQuat::from_axis_angle(axis, tau * t[i] / period + expect[i])
                .expect("a rotation");
            let got = orbit.eval(t[i]);
            let d = got.dist(&want).min(got.dist(&-want));
            assert!(d < 1e-8, "λ {lam} sample {i}: {d:e}");
        }
        // Closed in SO(3): C² across the seam up to the sign.
        let (a, b) = (
            orbit.jet_at(t[0], spherekit::Side::Right),
            orbit.jet_at(t[n], spherekit::Side::Left),
        );
        assert!(
            (a.velocity + b.velocity).length() < 1e-9
                && (a.acceleration + b.acceleration).length() < 1e-8
        );
    }
    // GCV, an rms target and key reduction work on the loop too.
    for options in [
        FitOptions {
            smoothing: Some(Smoothing::Gcv),
            ..FitOptions::default()
        },
        FitOptions {
            smoothing: Some(Smoothing::Rms(0.04)),
            ..FitOptions::default()
        },
        FitOptions {
            smoothing: Some(Smoothing::Lambda(0.0)),
            keys: FitKeys::MaxError(0.12),
            ..FitOptions::default()
        },
    ] {
        let (orbit, report) =
            CubicSpline::try_fit_loop(samples.clone(), t.clone(), &options).expect("a fit");
        assert!(
            orbit.is_antiperiodic() && report.rms < 0.1,
            "{options:?}: {report:?}"
        );
        if let FitKeys::MaxError(eps) = options.keys {
            assert!(report.max <= eps && report.keys < n, "{report:?}");
        }
        if let Some(Smoothing::Rms(sigma)) = options.smoothing {
            assert!((report.rms / sigma - 1.0).abs() < 1e-6);
        }
    }
}

/// The Euclidean penalised least-squares cubic spline with the knots `knots` (all cubic splines
/// on them, ends free) at the times `t`: minimising `Σ wᵢ(yᵢ − g(tᵢ))² + λ∫g″²` over the
/// truncated-power basis `1, u, u², u³, (u − κⱼ)³₊` (`u` the time scaled to [0, 1]), by a dense
/// solve of the normal equations; `∫g″²` by two-point Gauss quadrature on each knot interval
/// (exact: `g″` is linear there).
fn lsq_spline_values(knots: &[f64], t: &[f64], y: &[f64], w: &[f64], lambda: f64) -> Vec<f64> {
    let (t0, span) = (knots[0], knots[knots.len() - 1] - knots[0]);
    let inner: Vec<f64> = knots[1..knots.len() - 1]
        .iter()
        .map(|k| (k - t0) / span)
        .collect();
    let m = 4 + inner.len();
    let basis = |s: f64| -> (Vec<f64>, Vec<f64>) {
        let u = (s - t0) / span;
        let mut b = vec![1.0, u, u * u, u * u * u];
        // Second derivatives in the time t.
        let mut b2 = vec![0.0, 0.0, 2.0, 6.0 * u];
        for &k in &inner {
            let p = (u - k).max(0.0);
            b.push(p * p * p);
            b2.push(6.0 * p);
        }
        (b, b2.into_iter().map(|x| x / (span * span)).collect())
    };
    let mut a = vec![0.0; m * m];
    let mut rhs = vec![0.0; m];
    for i in 0..t.len() {
        let (b, _) = basis(t[i]);
        for r in 0..m {
            rhs[r] += w[i] * b[r] * y[i];
            for c in 0..m {
                a[r * m + c] += w[i] * b[r] * b[c];
            }
        }
    }
    let g = 0.5 / 3f64.sqrt();
    for k in knots.windows(2) {
        let h = k[1] - k[0];
        for s in [0.5 - g, 0.5 + g] {
            let (_, b2) = basis(k[0] + s * h);
            for r in 0..m {
                for c in 0..m {
                    a[r * m + c] += lambda * 0.5 * h * b2[r] * b2[c];
                }
            }
        }
    }
    let beta = dense_solve(a, rhs, m);
    t.iter()
        .map(|&s| basis(s).0.iter().zip(&beta).map(|(b, x)| b * x).sum())
        .collect()
}

#[test]
fn fewer_keys_than_samples_is_the_least_squares_cubic_spline_with_free_ends() {
    let (t, theta, pts, w) = great_circle(40, 5);
    for (keys, lam) in [(6, 0.0), (9, 0.0), (9, 0.05), (15, 1.0)] {
        let options = FitOptions {
            smoothing: Some(Smoothing::Lambda(lam)),
            weights: Some(w.clone()),
            keys: FitKeys::Count(keys),
        };
        let (curve, report) =
            CubicSpline::try_fit(pts.clone(), t.clone(), &options, false).unwrap();
        assert_eq!(report.keys, keys);
        assert!(matches!(curve.end(), CubicEnd::Clamped { .. }));
        let expect = lsq_spline_values(&report.key_times, &t, &theta, &w, lam);
        let mut worst: f64 = 0.0;
        for (i, &s) in t.iter().enumerate() {
            let a = angle_on_circle(curve.eval(s).as_dvec3(), expect[i]);
            worst = worst.max((a - expect[i]).abs());
        }
        assert!(worst < 1e-8, "{keys} keys, λ {lam}: {worst:e}");
    }
    // A key at every sample: the smoothing spline, natural ends.
    let options = FitOptions {
        keys: FitKeys::Count(40),
        ..lambda(0.05)
    };
    let (curve, _) = CubicSpline::try_fit(pts, t, &options, false).unwrap();
    assert!(matches!(curve.end(), CubicEnd::Natural));
}

#[test]
fn every_key_count_of_a_few_samples_fits() {
    // Keys from two to every sample, with end segments with and without samples between their
    // keys (free end velocities only with), λ = 0 (least squares, interpolation at every sample)
    // and λ > 0, on S² and on noisy rotations.
    for n in [3_usize, 4, 5, 6, 8, 13] {
        let t: Vec<f64> = (0..n)
            .map(|i| 0.2 * i as f64 + 0.01 * ((i * 7) % 3) as f64)
            .collect();
        let s2: Vec<S2Point> = t
            .iter()
            .map(|&x| {
                S2Point::try_new(DVec3::new(x.cos(), x.sin(), 0.3 * (2.0 * x).sin())).unwrap()
            })
            .collect();
        let s3: Vec<UnitQuat> = t
            .iter()
            .enumerate()
            .map(|(i, &x)| {
                let wobble = DVec3::new(0.01 * noise(i, 9), 0.0, 0.005);
                UnitQuat::from_rotation_vector(DVec3::new(x, 0.2 * x * x, 0.1)).unwrap()
                    * UnitQuat::from_rotation_vector(wobble).unwrap()
            })
            .collect();
        for m in 2..=n {
            for lam in [0.0, 1e-3] {
                let options = FitOptions {
                    keys: FitKeys::Count(m),
                    ..lambda(lam)
                };
                let (c2, r2) = CubicSpline::try_fit(s2.clone(), t.clone(), &options, false)
                    .unwrap_or_else(|e| panic!("S² {n} samples, {m} keys, λ {lam}: {e}"));
                let (c3, r3) = CubicSpline::try_fit(s3.clone(), t.clone(), &options, false)
                    .unwrap_or_else(|e| panic!("S³ {n} samples, {m} keys, λ {lam}: {e}"));
                assert!(r2.max.is_finite() && r3.max.is_finite());
                assert!(c2.eval(t[n / 2]).as_dvec3().is_finite());
                assert!(c3.eval(t[n / 2]).to_vector().is_finite());
                if lam == 0.0 && m == n {
                    assert!(r2.max < 1e-9 && r3.max < 1e-9, "{n}: {} {}", r2.max, r3.max);
                }
            }
        }
    }
}

#[test]
fn few_keys_with_a_large_lambda_or_an_rms_target_stay_least_squares() {
    let t: Vec<f64> = (0..40).map(|i| f64::from(i) * 0.1).collect();
    // Two keys on rotations (signs mixed): every λ from 1e6 on is about the best constant-speed
    // geodesic, whether the free-end fit copes or natural ends take over.
    let q: Vec<UnitQuat> = t
        .iter()
        .enumerate()
        .map(|(i, &x)| {
            let v = DVec3::new(x, 0.3 * x * x, 0.2 * (3.0 * x).sin())
                + DVec3::splat(0.01 * noise(i, 5));
            let r = UnitQuat::from_rotation_vector(v).unwrap();
            if noise(i, 6) > 0.0 { -r } else { r }
        })
        .collect();
    let rms_at = |lam: f64| {
        let options = FitOptions {
            keys: FitKeys::Count(2),
            ..lambda(lam)
        };
        CubicSpline::try_fit(q.clone(), t.clone(), &options, false)
            .unwrap()
            .1
            .rms
    };
    let geodesic = rms_at(1e6);
    for lam in [1e8, 1e10] {
        let r = rms_at(lam);
        assert!(r < geodesic * 1.01, "λ {lam:e}: rms {r} against {geodesic}");
    }
    // Four keys on S² with a target rms that λ = 64 reaches (natural ends: the search for λ
    // does not free them).
    let y: Vec<S2Point> = t
        .iter()
        .enumerate()
        .map(|(i, &x)| {
            let p = DVec3::new(x.cos(), (1.3 * x).sin(), 0.5 * (2.0 * x).sin() + 0.3);
            S2Point::try_new(p + DVec3::splat(0.01 * noise(i, 1))).unwrap()
        })
        .collect();
    let options = FitOptions {
        smoothing: Some(Smoothing::Rms(0.43)),
        weights: None,
        keys: FitKeys::Count(4),
    };
    // (Within 1e-4 here: the search's one-step trials on four keys are cruder than with a key
    // at every sample, where the target is met to 1e-6.)
    let (_, report) = CubicSpline::try_fit(y, t, &options, false).unwrap();
    assert!((report.rms / 0.43 - 1.0).abs() < 1e-3, "{report:?}");
}
