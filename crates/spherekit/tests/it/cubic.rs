// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The C² cubic spline (`CubicSpline`): interpolation, C² at keys and at the seam, end
//! conditions, reductions to the Euclidean cubic spline on a great circle, symmetries, exact
//! derivatives, edge cases and agreement with scipy's `RotationSpline`.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::cast_precision_loss,
    clippy::cast_possible_truncation,
    clippy::too_many_lines,
    clippy::needless_range_loop,
    reason = "tests: a panic is the failure report"
)]

use spherekit::glam::{DMat3, DVec3, DVec4};
use spherekit::{
    Ambient, CubicEnd, CubicSpline, Curve, Manifold, S2Point, Side, SmPoint, SplineError, UnitQuat,
    VecN, angular_velocity_acceleration_body, continuity, unflip,
};

use crate::support::{self, Rng, check_derivatives, check_derivatives_at, interior_parameters};

const KNOTS6: [f64; 6] = [0.0, 0.5, 2.0, 3.0, 5.0, 5.5];

/// Largest relative velocity and acceleration jumps at the interior joints.
fn c2_jumps<C: Curve>(c: &C) -> (f64, f64) {
    continuity(c).iter().fold((0.0, 0.0), |(a, b), j| {
        let l = c.jet_at(j.t, Side::Left);
        let sv = l.velocity.length().max(1e-300);
        let sa = l.acceleration.length().max(1e-300);
        (a.max(j.c1 / sv), b.max(j.c2 / sa))
    })
}

/// Relative velocity and acceleration jumps at the seam of a closed curve.
fn seam_jumps<C: Curve>(c: &C) -> (f64, f64, f64) {
    let [t0, t1] = c.domain();
    let (a, b) = (c.jet_at(t1, Side::Left), c.jet_at(t0, Side::Right));
    (
        (a.point.to_vector() - b.point.to_vector()).length(),
        (a.velocity.clone() - b.velocity.clone()).length() / b.velocity.length(),
        (a.acceleration.clone() - b.acceleration.clone()).length() / b.acceleration.length(),
    )
}

/// The tangential part of the acceleration at parameter `t` from `side`.
fn tangential_acceleration<C: Curve>(c: &C, t: f64, side: Side) -> f64 {
    let j = c.jet_at(t, side);
    let p = j.point.to_vector();
    (j.acceleration.clone() - p.clone() * p.dot(&j.acceleration)).length()
}

/// Interpolation at the keys, C², derivatives against finite differences, on the manifold.
#[track_caller]
fn check_curve<P: Manifold>(c: &CubicSpline<P>, keys: &[P]) {
    let k = c.knots();
    for (i, p) in keys.iter().enumerate() {
        for side in [Side::Left, Side::Right] {
            let q = c.jet_at(k[i], side).point;
            assert!(q.dist(p) <= 1e-12, "key {i} from {side:?}: {}", q.dist(p));
        }
        assert!(c.eval(k[i]).dist(p) <= 1e-12, "eval at key {i}");
    }
    if c.closed() {
        assert!(c.eval(k[keys.len()]).dist(&keys[0]) <= 1e-12, "closing key");
        let (c0, c1, c2) = seam_jumps(c);
        assert!(
            c0 <= 1e-12 && c1 <= 1e-10 && c2 <= 1e-10,
            "seam: {c0:e} {c1:e} {c2:e}"
        );
    }
    let (j1, j2) = c2_jumps(c);
    assert!(j1 <= 1e-10 && j2 <= 1e-10, "C² jumps {j1:e} {j2:e}");
    check_derivatives(c, 40);
    check_derivatives_at(c, &interior_parameters(c, 3));
    assert!(c.solve_info().residual <= 1e-12, "{:?}", c.solve_info());
}

fn walk_s2(rng: &mut Rng, n: usize, step: f64) -> Vec<S2Point> {
    let mut p = vec![rng.s2()];
    for _ in 1..n {
        let angle = rng.range(0.2, step);
        let next = rng.s2_at_angle(*p.last().unwrap(), angle);
        p.push(next);
    }
    p
}

#[test]
fn interpolates_and_is_c2_on_s2_s3_s5() {
    let mut rng = Rng::new(1);
    let knots = Some(KNOTS6.to_vec());
    for end in [CubicEnd::Natural, CubicEnd::Scipy] {
        let p = walk_s2(&mut rng, 6, 1.5);
        check_curve(
            &CubicSpline::try_new(p.clone(), knots.clone(), end.clone(), false).unwrap(),
            &p,
        );
        let q = rng.chain(6, 1.2);
        let qe = match end {
            CubicEnd::Natural => CubicEnd::Natural,
            _ => CubicEnd::Scipy,
        };
        check_curve(
            &CubicSpline::try_new(q.clone(), knots.clone(), qe.clone(), false).unwrap(),
            &q,
        );
        let s = rng.walk_sm(6, 5, 0.5);
        let se = match end {
            CubicEnd::Natural => CubicEnd::Natural,
            _ => CubicEnd::Scipy,
        };
        check_curve(
            &CubicSpline::try_new(s.clone(), knots.clone(), se, false).unwrap(),
            &s,
        );
    }
}

/// `point_velocity` is the jet without its acceleration: the same bits, at keys, inside
/// segments and at the ends, on every sphere.
fn check_point_velocity<P: Manifold>(c: &CubicSpline<P>) {
    let [t0, t1] = c.domain();
    let mut ts: Vec<f64> = (0..=97)
        .map(|k| t0 + (t1 - t0) * f64::from(k) / 97.0)
        .collect();
    ts.extend_from_slice(c.knots());
    ts.sort_by(f64::total_cmp);
    let mut batch = vec![c.point_velocity(t0); ts.len()];
    c.point_velocity_many(&ts, &mut batch);
    for (&t, (p, v)) in ts.iter().zip(&batch) {
        let jet = c.jet(t);
        let (q, w) = c.point_velocity(t);
        assert!(
            jet.point == q && jet.velocity == w,
            "point_velocity at t = {t}"
        );
        assert!(*p == q && *v == w, "point_velocity_many at t = {t}");
    }
}

#[test]
fn point_velocity_is_the_jet_without_acceleration() {
    let mut rng = Rng::new(5);
    let knots = Some(KNOTS6.to_vec());
    let p = walk_s2(&mut rng, 6, 1.5);
    check_point_velocity(
        &CubicSpline::try_new(p, knots.clone(), CubicEnd::Natural, false).unwrap(),
    );
    let q = rng.chain(6, 1.2);
    check_point_velocity(
        &CubicSpline::try_new(q.clone(), knots.clone(), CubicEnd::Scipy, false).unwrap(),
    );
    let mut closed_knots = KNOTS6.to_vec();
    closed_knots.push(KNOTS6[5] + 1.0);
    check_point_velocity(
        &CubicSpline::try_new(q, Some(closed_knots), CubicEnd::Natural, true).unwrap(),
    );
    let s = rng.walk_sm(6, 5, 0.5);
    check_point_velocity(&CubicSpline::try_new(s, knots, CubicEnd::Natural, false).unwrap());
}

#[test]
fn closed_curves_are_c2_at_the_seam() {
    let mut rng = Rng::new(2);
    let mut k = KNOTS6.to_vec();
    k.push(6.5);
    let p = walk_s2(&mut rng, 6, 1.5);
    check_curve(
        &CubicSpline::try_new(p.clone(), Some(k.clone()), CubicEnd::Natural, true).unwrap(),
        &p,
    );
    let q = rng.chain(6, 1.0);
    check_curve(
        &CubicSpline::try_new(q.clone(), Some(k.clone()), CubicEnd::Natural, true).unwrap(),
        &q,
    );
    let s = rng.walk_sm(6, 5, 0.6);
    check_curve(
        &CubicSpline::try_new(s.clone(), Some(k), CubicEnd::Natural, true).unwrap(),
        &s,
    );
    // Uniform default knots: one more than the points, closing spacing 1.
    let c = CubicSpline::try_new(q.clone(), None, CubicEnd::Natural, true).unwrap();
    assert_eq!(c.knots(), &[0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    assert_eq!(c.domain(), [0.0, 6.0]);
    assert_eq!(c.segment_count(), 6);
    check_curve(&c, &q);
}

/// The quaternion from scalar-first components.
fn wxyz(v: &serde_json::Value) -> UnitQuat {
    let a: Vec<f64> = v
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    UnitQuat::from_wxyz([a[0], a[1], a[2], a[3]]).unwrap()
}

fn vec3(v: &serde_json::Value) -> DVec3 {
    let a: Vec<f64> = v
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    DVec3::new(a[0], a[1], a[2])
}

fn floats(v: &serde_json::Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

/// `CubicEnd::Scipy` on S³ against scipy 1.17.1's `RotationSpline` (fixture written by
/// `scripts/scipy_rotation_spline_fixture.py`): 4, 7, 20 and 20 keys, non-uniform times, about
/// 50 parameters each. Measured (2026-12-01): rotation angle ≤ 8.2e-12 rad, body rate error
/// ≤ 1.4e-11 and acceleration error ≤ 2.7e-11 relative to the largest rate and acceleration of
/// the case — the size of scipy's own distance from its fixed point (`converged_to`, up to
/// 3.2e-11: scipy stops its iteration at a change of 1e-9). Run with `-- --nocapture` to print.
#[test]
fn scipy_agreement_whatever_the_key_signs() {
    let text = include_str!("../data/rotation_spline_scipy.json");
    let data: serde_json::Value = serde_json::from_str(text).unwrap();
    let (mut worst_angle, mut worst_rate, mut worst_acc) = (0.0_f64, 0.0_f64, 0.0_f64);
    for case in data["cases"].as_array().unwrap() {
        // Rotations with random quaternion signs: scipy never sees them, nor does the curve.
        let mut keys: Vec<UnitQuat> = case["keys"].as_array().unwrap().iter().map(wxyz).collect();
        let mut rng = Rng::new(keys.len() as u64);
        for q in &mut keys {
            if rng.uniform() < 0.5 {
                *q = -*q;
            }
        }
        let times = floats(&case["times"]);
        let c = CubicSpline::try_new_rotations(keys.clone(), Some(times.clone()), CubicEnd::Scipy)
            .unwrap();
        unflip(&mut keys);
        let unflipped = CubicSpline::try_new(keys, Some(times), CubicEnd::Scipy, false).unwrap();
        assert_eq!(
            c.eval(0.3),
            unflipped.eval(0.3),
            "the curve of the keys unflipped"
        );
        let ts = floats(&case["ts"]);
        let quats: Vec<UnitQuat> = case["quats"].as_array().unwrap().iter().map(wxyz).collect();
        let rates: Vec<DVec3> = case["rates"].as_array().unwrap().iter().map(vec3).collect();
        let accs: Vec<DVec3> = case["accelerations"]
            .as_array()
            .unwrap()
            .iter()
            .map(vec3)
            .collect();
        let rate_scale = rates.iter().map(|r| r.length()).fold(0.0, f64::max);
        let acc_scale = accs.iter().map(|r| r.length()).fold(0.0, f64::max);
        let (mut angle, mut rate, mut acc) = (0.0_f64, 0.0_f64, 0.0_f64);
        for (k, &t) in ts.iter().enumerate() {
            let j = c.jet(t);
            angle = angle.max((j.point.inverse() * quats[k]).rotation_angle());
            let (w, a) = angular_velocity_acceleration_body(j.point, j.velocity, j.acceleration);
            rate = rate.max((w - rates[k]).length() / rate_scale);
            acc = acc.max((a - accs[k]).length() / acc_scale);
        }
        println!(
            "{}: angle {angle:.1e} rad, rate {rate:.1e}, acceleration {acc:.1e} (relative); scipy converged to {:.1e}; {:?}",
            case["name"].as_str().unwrap(),
            case["converged_to"].as_f64().unwrap(),
            c.solve_info()
        );
        worst_angle = worst_angle.max(angle);
        worst_rate = worst_rate.max(rate);
        worst_acc = worst_acc.max(acc);
    }
    println!(
        "worst: angle {worst_angle:.1e} rad, rate {worst_rate:.1e}, acceleration {worst_acc:.1e}"
    );
    assert!(worst_angle <= 1e-8, "angle {worst_angle:e}");
    assert!(
        worst_rate <= 1e-7 && worst_acc <= 1e-7,
        "rate {worst_rate:e}, acceleration {worst_acc:e}"
    );
}

#[test]
fn natural_ends_have_zero_tangential_acceleration() {
    let mut rng = Rng::new(3);
    let k = Some(KNOTS6.to_vec());
    let p = walk_s2(&mut rng, 6, 1.5);
    let c = CubicSpline::try_new(p, k.clone(), CubicEnd::Natural, false).unwrap();
    let q = rng.chain(6, 1.2);
    let cq = CubicSpline::try_new(q, k.clone(), CubicEnd::Natural, false).unwrap();
    let s = rng.walk_sm(6, 5, 0.5);
    let cs = CubicSpline::try_new(s, k, CubicEnd::Natural, false).unwrap();
    for (t, side) in [(0.0, Side::Right), (5.5, Side::Left)] {
        assert!(tangential_acceleration(&c, t, side) <= 1e-12, "S² at {t}");
        assert!(tangential_acceleration(&cq, t, side) <= 1e-12, "S³ at {t}");
        assert!(tangential_acceleration(&cs, t, side) <= 1e-12, "S⁵ at {t}");
    }
    // … and a non-zero one elsewhere, including at the interior keys.
    assert!(tangential_acceleration(&c, 2.0, Side::Right) > 1e-3);
}

#[test]
fn clamped_ends_have_the_given_velocity() {
    let mut rng = Rng::new(4);
    let k = Some(KNOTS6.to_vec());
    let p = walk_s2(&mut rng, 6, 1.5);
    let (v0, v1) = (
        p[0].project_tangent(&rng.vec3(2.0)),
        p[5].project_tangent(&rng.vec3(2.0)),
    );
    let c = CubicSpline::try_new(
        p.clone(),
        k.clone(),
        CubicEnd::Clamped {
            start_velocity: v0,
            end_velocity: v1,
        },
        false,
    )
    .unwrap();
    check_curve(&c, &p);
    assert!((c.jet(0.0).velocity - v0).length() <= 1e-12);
    assert!((c.jet(5.5).velocity - v1).length() <= 1e-12);
    // S³ from body-frame angular velocities.
    let q = rng.chain(6, 1.2);
    let (w0, w1) = (rng.vec3(1.0), rng.vec3(1.0));
    let end = CubicEnd::clamped_angular_body(q[0], w0, q[5], w1);
    let c = CubicSpline::try_new(q.clone(), k.clone(), end, false).unwrap();
    check_curve(&c, &q);
    for (t, w) in [(0.0, w0), (5.5, w1)] {
        let j = c.jet(t);
        let (wb, _) = angular_velocity_acceleration_body(j.point, j.velocity, j.acceleration);
        assert!((wb - w).length() <= 1e-12, "body rate at {t}");
    }
    let end = CubicEnd::clamped_angular(q[0], w0, q[5], w1);
    let c = CubicSpline::try_new(q.clone(), k.clone(), end, false).unwrap();
    let j = c.jet(0.0);
    let (ws, _) = spherekit::angular_velocity_acceleration(j.point, j.velocity, j.acceleration);
    assert!((ws - w0).length() <= 1e-12, "space rate");
    // S⁵.
    let s = rng.walk_sm(6, 5, 0.5);
    let (a, b) = (
        s[0].project_tangent(&VecN::new(rng.vec(6))),
        s[5].project_tangent(&VecN::new(rng.vec(6))),
    );
    let c = CubicSpline::try_new(
        s.clone(),
        k,
        CubicEnd::Clamped {
            start_velocity: a.clone(),
            end_velocity: b.clone(),
        },
        false,
    )
    .unwrap();
    check_curve(&c, &s);
    assert!((c.jet(0.0).velocity - a).length() <= 1e-12);
    assert!((c.jet(5.5).velocity - b).length() <= 1e-12);
}

#[test]
fn clamped_velocity_errors_name_the_end() {
    let p = vec![S2Point::X, S2Point::Y, S2Point::Z];
    let bad = |start: DVec3, end: DVec3| {
        CubicSpline::try_new(
            p.clone(),
            None,
            CubicEnd::Clamped {
                start_velocity: start,
                end_velocity: end,
            },
            false,
        )
        .unwrap_err()
    };
    let e = bad(DVec3::new(0.1, 1.0, 0.0), DVec3::X);
    assert_eq!(
        e.to_string(),
        "the start velocity is not tangent to the first key"
    );
    let e = bad(DVec3::Y, DVec3::new(0.0, 0.0, 1e-6));
    assert_eq!(
        e.to_string(),
        "the end velocity is not tangent to the last key"
    );
    let e = bad(DVec3::new(0.0, f64::NAN, 0.0), DVec3::X);
    assert_eq!(
        e.to_string(),
        "the start velocity has a non-finite coordinate"
    );
    // Within the tolerance: accepted and projected.
    let c = CubicSpline::try_new(
        p.clone(),
        None,
        CubicEnd::Clamped {
            start_velocity: DVec3::new(1e-12, 1.0, 0.0),
            end_velocity: DVec3::X,
        },
        false,
    )
    .unwrap();
    assert!(c.jet(0.0).velocity.x.abs() < 1e-300 + 1e-20);
    // S^m: a velocity of the wrong dimension.
    let s = vec![
        SmPoint::try_new(vec![1.0, 0.0, 0.0]).unwrap(),
        SmPoint::try_new(vec![0.0, 1.0, 0.0]).unwrap(),
    ];
    let e = CubicSpline::try_new(
        s,
        None,
        CubicEnd::Clamped {
            start_velocity: VecN::new(vec![0.0, 1.0]),
            end_velocity: VecN::new(vec![1.0, 0.0, 0.0]),
        },
        false,
    )
    .unwrap_err();
    assert!(
        matches!(e, SplineError::InvalidEndVelocity { start: true, .. }),
        "{e}"
    );
}

#[test]
fn construction_errors() {
    let p = vec![S2Point::X, S2Point::Y, S2Point::Z];
    let nat = || CubicEnd::Natural;
    let err = |p: Vec<S2Point>, k: Option<Vec<f64>>, closed| {
        CubicSpline::try_new(p, k, nat(), closed).unwrap_err()
    };
    assert_eq!(
        err(p[..1].to_vec(), None, false),
        SplineError::TooFewPoints { min: 2, got: 1 }
    );
    assert_eq!(
        err(p[..2].to_vec(), None, true),
        SplineError::TooFewPoints { min: 3, got: 2 }
    );
    assert_eq!(
        err(p.clone(), Some(vec![0.0, 1.0, 2.0]), true),
        SplineError::KnotCount {
            expected: 4,
            got: 3
        }
    );
    assert_eq!(
        err(p.clone(), Some(vec![0.0, 1.0, 2.0, 3.0]), false),
        SplineError::KnotCount {
            expected: 3,
            got: 4
        }
    );
    assert_eq!(
        err(p.clone(), Some(vec![0.0, 1.0, 1.0]), false),
        SplineError::KnotsNotIncreasing { index: 2 }
    );
    assert_eq!(
        err(p.clone(), Some(vec![0.0, f64::NAN, 1.0]), false),
        SplineError::InvalidKnot { index: 1 }
    );
    let anti = vec![S2Point::X, S2Point::Y, S2Point::try_new(-DVec3::Y).unwrap()];
    assert_eq!(err(anti, None, false), SplineError::Antipodal { index: 1 });
    let closing = vec![S2Point::X, S2Point::Y, S2Point::try_new(-DVec3::X).unwrap()];
    assert!(CubicSpline::try_new(closing.clone(), None, nat(), false).is_ok());
    let e = err(closing, None, true);
    assert_eq!(e, SplineError::AntipodalClosing);
    assert_eq!(
        e.to_string(),
        "the last and the first point are antipodal: the closing geodesic is not unique"
    );
    let e = CubicSpline::try_new(p, None, CubicEnd::Scipy, true).unwrap_err();
    assert!(
        matches!(e, SplineError::InvalidParameter { name: "end", .. }),
        "{e}"
    );
}

/// A small dense solve (Gaussian elimination with partial pivoting) for the scalar splines.
fn dense_solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Vec<f64> {
    let n = b.len();
    for c in 0..n {
        let p = (c..n)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap();
        a.swap(c, p);
        b.swap(c, p);
        for r in c + 1..n {
            let f = a[r][c] / a[c][c];
            for k in c..n {
                a[r][k] -= f * a[c][k];
            }
            b[r] -= f * b[c];
        }
    }
    let mut x = vec![0.0; n];
    for r in (0..n).rev() {
        let s: f64 = (r + 1..n).map(|k| a[r][k] * x[k]).sum();
        x[r] = (b[r] - s) / a[r][r];
    }
    x
}

/// The Euclidean cubic spline of `y` at times `t` in moment form, natural or periodic (then
/// `t` and `y` have one more entry: the closing time and value); returns `S(s)`.
fn scalar_spline(t: &[f64], y: &[f64], periodic: bool) -> impl Fn(f64) -> f64 {
    let n = t.len();
    let h: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    let d: Vec<f64> = (0..n - 1).map(|i| (y[i + 1] - y[i]) / h[i]).collect();
    let moments = if periodic {
        // Unknowns M₀ … M_{n−2}, M_{n−1} = M₀.
        let m = n - 1;
        let mut a = vec![vec![0.0; m]; m];
        let mut b = vec![0.0; m];
        for i in 0..m {
            let ip = (i + m - 1) % m;
            a[i][ip] += h[ip];
            a[i][i] += 2.0 * (h[ip] + h[i]);
            a[i][(i + 1) % m] += h[i];
            b[i] = 6.0 * (d[i] - d[ip]);
        }
        let mut mm = dense_solve(a, b);
        mm.push(mm[0]);
        mm
    } else {
        let mut a = vec![vec![0.0; n]; n];
        let mut b = vec![0.0; n];
        a[0][0] = 1.0;
        a[n - 1][n - 1] = 1.0;
        for i in 1..n - 1 {
            a[i][i - 1] = h[i - 1];
            a[i][i] = 2.0 * (h[i - 1] + h[i]);
            a[i][i + 1] = h[i];
            b[i] = 6.0 * (d[i] - d[i - 1]);
        }
        dense_solve(a, b)
    };
    let (t, y) = (t.to_vec(), y.to_vec());
    move |s: f64| {
        let i = t.partition_point(|&x| x <= s).saturating_sub(1).min(n - 2);
        let (a, b, hi) = (t[i + 1] - s, s - t[i], h[i]);
        moments[i] * a * a * a / (6.0 * hi)
            + moments[i + 1] * b * b * b / (6.0 * hi)
            + (y[i] / hi - moments[i] * hi / 6.0) * a
            + (y[i + 1] / hi - moments[i + 1] * hi / 6.0) * b
    }
}

#[test]
fn great_circle_natural_is_the_euclidean_natural_spline_of_the_angle() {
    let t = KNOTS6.to_vec();
    let phi = [0.3, 1.5, 0.9, 2.8, 4.4, 3.9];
    let tilt = DMat3::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.7);
    let on_circle = |a: f64| S2Point::try_new(tilt * DVec3::new(a.cos(), a.sin(), 0.0)).unwrap();
    let keys: Vec<S2Point> = phi.iter().map(|&a| on_circle(a)).collect();
    let c = CubicSpline::try_new(keys, Some(t.clone()), CubicEnd::Natural, false).unwrap();
    let s = scalar_spline(&t, &phi, false);
    for k in 0..=550 {
        let x = f64::from(k) / 100.0;
        let d = c.eval(x).dist(&on_circle(s(x)));
        assert!(d <= 1e-13, "at {x}: {d:e}");
    }
    // Closed: the keys wind once around the circle; the angle gains 2π per period.
    let phi = [0.0, 1.0, 2.2, 3.5, 4.6, 5.5];
    let mut tc = t.clone();
    tc.push(6.7);
    let keys: Vec<S2Point> = phi.iter().map(|&a| on_circle(a)).collect();
    let c = CubicSpline::try_new(keys, Some(tc.clone()), CubicEnd::Natural, true).unwrap();
    let mut y = phi.to_vec();
    y.push(std::f64::consts::TAU);
    let s = scalar_spline(&tc, &y, true);
    for k in 0..=670 {
        let x = f64::from(k) / 100.0;
        let d = c.eval(x).dist(&on_circle(s(x)));
        assert!(d <= 1e-13, "closed at {x}: {d:e}");
    }
}

#[test]
fn rotation_equivariance() {
    let mut rng = Rng::new(5);
    let k = Some(KNOTS6.to_vec());
    let ts: Vec<f64> = (0..=55).map(|i| f64::from(i) / 10.0).collect();
    let p = walk_s2(&mut rng, 6, 1.5);
    let r = rng.rotation();
    let rp: Vec<S2Point> = p
        .iter()
        .map(|x| S2Point::try_new(r * x.as_dvec3()).unwrap())
        .collect();
    for closed in [false, true] {
        let kk = if closed {
            Some([KNOTS6.as_slice(), &[6.0]].concat())
        } else {
            k.clone()
        };
        let a = CubicSpline::try_new(p.clone(), kk.clone(), CubicEnd::Natural, closed).unwrap();
        let b = CubicSpline::try_new(rp.clone(), kk, CubicEnd::Natural, closed).unwrap();
        for &t in &ts {
            let (ja, jb) = (a.jet(t), b.jet(t));
            assert!((r * ja.point.as_dvec3() - jb.point.as_dvec3()).length() <= 1e-13);
            assert!(
                (r * ja.velocity - jb.velocity).length() <= 1e-12 * ja.velocity.length().max(1.0)
            );
            assert!(
                (r * ja.acceleration - jb.acceleration).length()
                    <= 1e-11 * ja.acceleration.length().max(1.0)
            );
        }
    }
    // S³: q ↦ a·q·b is an orthogonal map of ℝ⁴.
    let q = rng.chain(6, 1.2);
    let (qa, qb) = (rng.quat(), rng.quat());
    let mq: Vec<UnitQuat> = q.iter().map(|&x| support::sandwich(qa, x, qb)).collect();
    let a = CubicSpline::try_new(q, k.clone(), CubicEnd::Scipy, false).unwrap();
    let b = CubicSpline::try_new(mq, k.clone(), CubicEnd::Scipy, false).unwrap();
    for &t in &ts {
        let d = support::sandwich(qa, a.eval(t), qb).dist(&b.eval(t));
        assert!(d <= 1e-13, "S³ at {t}: {d:e}");
    }
    // S⁵: a reflection.
    let s = rng.walk_sm(6, 5, 0.5);
    let nrm = rng.vec(6);
    let ms: Vec<SmPoint> = s.iter().map(|x| support::reflect(&nrm, x)).collect();
    let a = CubicSpline::try_new(s, k.clone(), CubicEnd::Natural, false).unwrap();
    let b = CubicSpline::try_new(ms, k, CubicEnd::Natural, false).unwrap();
    for &t in &ts {
        let d = support::reflect(&nrm, &a.eval(t)).dist(&b.eval(t));
        assert!(d <= 1e-13, "S⁵ at {t}: {d:e}");
    }
}

/// Largest point distance between a curve and the one built from the reversed keys and times.
fn reversal_gap<P: Manifold>(p: &[P], k: &[f64], end: &dyn Fn() -> CubicEnd<P::Vector>) -> f64 {
    let rk: Vec<f64> = k.iter().rev().map(|t| -t).collect();
    let rp: Vec<P> = p.iter().rev().cloned().collect();
    let a = CubicSpline::try_new(p.to_vec(), Some(k.to_vec()), end(), false).unwrap();
    let b = CubicSpline::try_new(rp, Some(rk), end(), false).unwrap();
    let [t0, t1] = a.domain();
    (0..=200)
        .map(|i| {
            let t = t0 + (t1 - t0) * f64::from(i) / 200.0;
            a.eval(t).dist(&b.eval(-t))
        })
        .fold(0.0, f64::max)
}

/// Reversal is **not** a symmetry of this construction: each segment is a cubic in the tangent
/// space of its first key, and reversing the keys moves it to the other key's tangent space
/// (scipy's `RotationSpline` has the same asymmetry). It is exact on a great circle (the
/// Euclidean spline of the angle is reversal symmetric); off it the gap shrinks like the cube of
/// the step. Measured on S² (natural ends, times [0, 0.5, 2, 3, 5, 5.5]): 2.5e-1 rad for steps
/// up to 1.5 rad, 1.1e-4 rad for steps up to 0.15 rad. scipy 1.17.1 shows the same: 6.9e-2 rad
/// (rotation angle) for rotation steps up to 2.4 rad, 2.5e-4 for steps up to 0.24.
#[test]
fn reversal_symmetry_holds_on_a_great_circle_only() {
    let k = KNOTS6.to_vec();
    let on_circle = |a: f64| S2Point::try_new(DVec3::new(a.cos(), a.sin(), 0.0)).unwrap();
    let circle: Vec<S2Point> = [0.3, 1.5, 0.9, 2.8, 4.4, 3.9]
        .iter()
        .map(|&a| on_circle(a))
        .collect();
    for end in [CubicEnd::Natural, CubicEnd::Scipy] {
        let gap = reversal_gap(&circle, &k, &|| end.clone());
        assert!(gap <= 1e-13, "great circle, {end:?}: {gap:e}");
    }
    let mut rng = Rng::new(6);
    let big = walk_s2(&mut rng, 6, 1.5);
    let g_big = reversal_gap(&big, &k, &|| CubicEnd::Natural);
    let small: Vec<S2Point> = {
        let mut p = vec![rng.s2()];
        for _ in 1..6 {
            let angle = rng.range(0.02, 0.15);
            let next = rng.s2_at_angle(*p.last().unwrap(), angle);
            p.push(next);
        }
        p
    };
    let g_small = reversal_gap(&small, &k, &|| CubicEnd::Natural);
    println!("reversal gap: {g_big:.1e} rad (steps ≤ 1.5), {g_small:.1e} rad (steps ≤ 0.15)");
    assert!(g_big > 1e-3 && g_big < 1.0, "{g_big:e}");
    assert!(g_small < 1e-3 && g_small < 1e-2 * g_big, "{g_small:e}");
    let q = rng.chain(6, 1.2);
    let g_q = reversal_gap(&q, &k, &|| CubicEnd::Scipy);
    println!("reversal gap on S³ (scipy ends, steps ≤ 1.2): {g_q:.1e} rad");
    assert!(g_q > 1e-6 && g_q < 1.0, "{g_q:e}");
}

#[test]
fn two_keys_give_the_geodesic() {
    let mut rng = Rng::new(7);
    let p = walk_s2(&mut rng, 2, 2.5);
    let g = spherekit::GeodesicSpline::try_new(p.clone(), Some(vec![1.0, 3.0])).unwrap();
    for end in [CubicEnd::Natural, CubicEnd::Scipy] {
        let c = CubicSpline::try_new(p.clone(), Some(vec![1.0, 3.0]), end, false).unwrap();
        assert!(continuity(&c).is_empty());
        for i in 0..=20 {
            let t = 1.0 + f64::from(i) / 10.0;
            let (a, b) = (c.jet(t), g.jet(t));
            assert!(a.point.dist(&b.point) <= 1e-15 && (a.velocity - b.velocity).length() <= 1e-14);
            assert!((a.acceleration - b.acceleration).length() <= 1e-14);
        }
    }
}

#[test]
fn identical_consecutive_keys_are_allowed() {
    // A zero segment (Log = 0): the curve leaves the key and comes back to it, still C².
    let mut rng = Rng::new(8);
    let mut p = walk_s2(&mut rng, 5, 1.2);
    p.insert(2, p[2]);
    let c =
        CubicSpline::try_new(p.clone(), Some(KNOTS6.to_vec()), CubicEnd::Natural, false).unwrap();
    check_curve(&c, &p);
    let q = vec![UnitQuat::IDENTITY; 4];
    let c = CubicSpline::try_new(q.clone(), None, CubicEnd::Scipy, false).unwrap();
    assert_eq!(c.eval(1.7), UnitQuat::IDENTITY);
    assert_eq!(c.jet(1.7).velocity, DVec4::ZERO);
    check_curve(&c, &q);
}

#[test]
fn nearly_antipodal_keys() {
    // Consecutive keys π − 1e-6 apart on S²: dExp⁻¹ grows like 1/(π − θ), the curve stays C².
    let a = std::f64::consts::PI - 1e-6;
    let p: Vec<S2Point> = (0..4)
        .map(|i| {
            let phi = a * f64::from(i);
            S2Point::try_new(DVec3::new(phi.cos(), phi.sin(), 0.1 * f64::from(i % 2))).unwrap()
        })
        .collect();
    let c = CubicSpline::try_new(p.clone(), None, CubicEnd::Natural, false).unwrap();
    for (i, key) in p.iter().enumerate() {
        assert!(c.eval(i as f64).dist(key) <= 1e-12);
    }
    let (j1, j2) = c2_jumps(&c);
    assert!(j1 <= 1e-10 && j2 <= 1e-10, "{j1:e} {j2:e}");
    assert!(c.solve_info().residual <= 1e-12);
}

#[test]
fn near_half_turn_quaternions() {
    // Rotations by π − 1e-9 between keys (quaternion angle just below π/2), and one of exactly π.
    let mut rng = Rng::new(9);
    let mut q = vec![rng.quat()];
    for i in 0..6 {
        let angle = if i == 3 {
            std::f64::consts::PI
        } else {
            std::f64::consts::PI - 1e-9
        };
        let axis = rng.unit3();
        let last = *q.last().unwrap();
        q.push(last * UnitQuat::from_axis_angle(axis, angle).unwrap());
    }
    unflip(&mut q);
    let c = CubicSpline::try_new(
        q.clone(),
        Some([KNOTS6.as_slice(), &[6.0]].concat()),
        CubicEnd::Scipy,
        false,
    )
    .unwrap();
    check_curve(&c, &q);
}

#[test]
fn tiny_and_huge_time_spacings_scale_the_parameter() {
    let mut rng = Rng::new(10);
    let p = walk_s2(&mut rng, 6, 1.5);
    let base =
        CubicSpline::try_new(p.clone(), Some(KNOTS6.to_vec()), CubicEnd::Scipy, false).unwrap();
    for scale in [1e-9, 1e-40, 1e9, 1e40] {
        let k: Vec<f64> = KNOTS6.iter().map(|t| t * scale).collect();
        let c = CubicSpline::try_new(p.clone(), Some(k), CubicEnd::Scipy, false).unwrap();
        assert!(c.solve_info().residual <= 1e-12);
        for i in 0..=55 {
            let t = f64::from(i) / 10.0;
            let (a, b) = (base.jet(t), c.jet(t * scale));
            assert!(a.point.dist(&b.point) <= 1e-13, "scale {scale} at {t}");
            assert!(
                (a.velocity - b.velocity * scale).length() <= 1e-12 * a.velocity.length().max(1.0)
            );
            assert!(
                (a.acceleration - b.acceleration * (scale * scale)).length()
                    <= 1e-11 * a.acceleration.length().max(1.0)
            );
        }
    }
}

#[test]
fn batch_equals_scalar_and_the_domain_clamps() {
    let mut rng = Rng::new(11);
    let q = rng.chain(20, 1.2);
    let c = CubicSpline::try_new(q, None, CubicEnd::Scipy, false).unwrap();
    let ts: Vec<f64> = (0..500).map(|i| -1.0 + f64::from(i) * 0.043).collect();
    let mut jets = vec![c.jet(0.0); ts.len()];
    c.jet_many(&ts, &mut jets);
    let mut pts = vec![UnitQuat::IDENTITY; ts.len()];
    c.eval_many(&ts, &mut pts);
    for (k, &t) in ts.iter().enumerate() {
        assert_eq!(jets[k], c.jet(t));
        assert_eq!(pts[k], c.eval(t));
        assert_eq!(pts[k], jets[k].point);
    }
    assert_eq!(c.jet(-3.0), c.jet(0.0));
    assert_eq!(c.jet(40.0), c.jet_at(19.0, Side::Left));
    assert_eq!(c.key_velocities().len(), 20);
    assert_eq!(c.end(), &CubicEnd::Scipy);
    assert!(!c.closed());
}

/// Built from rotations, a clamped end's velocity stays the given angular velocity when the
/// canonicalisation flips the last key (the velocity is negated with its key).
#[test]
fn rotations_keep_clamped_angular_velocities_when_keys_flip() {
    let keys: Vec<UnitQuat> = (0..4)
        .map(|k| UnitQuat::from_axis_angle(DVec3::new(0.3, 1.0, 0.5), 0.9 * f64::from(k)).unwrap())
        .collect();
    let (w0, w1) = (DVec3::new(0.2, -0.1, 0.4), DVec3::new(-0.3, 0.5, 0.1));
    for flip_last in [false, true] {
        let mut given = keys.clone();
        if flip_last {
            given[3] = -given[3];
        }
        let end = CubicEnd::clamped_angular_body(given[0], w0, given[3], w1);
        let c = CubicSpline::try_new_rotations(given, None, end).unwrap();
        for (t, w) in [(0.0, w0), (3.0, w1)] {
            let j = c.jet_at(t, if t == 0.0 { Side::Right } else { Side::Left });
            let (rate, _) = angular_velocity_acceleration_body(j.point, j.velocity, j.acceleration);
            assert!(
                (rate - w).length() <= 1e-12,
                "flip {flip_last}, t = {t}: {rate} vs {w}"
            );
        }
    }
}
