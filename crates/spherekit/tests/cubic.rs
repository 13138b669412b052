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
    reason = "tests: a panic is the failure report"
)]

mod support;

use spherekit::glam::{DMat3, DVec3, DVec4};
use spherekit::{
    Ambient, CubicEnd, CubicSpline, Curve, Manifold, S2Point, Side, SnPoint, SplineError,
    UnitQuat, VecN, angular_velocity_acceleration_body, continuity, unflip,
};
use support::{Rng, check_derivatives, check_derivatives_at, interior_parameters};

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
        assert!(c0 <= 1e-12 && c1 <= 1e-10 && c2 <= 1e-10, "seam: {c0:e} {c1:e} {c2:e}");
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
        check_curve(&CubicSpline::try_new(p.clone(), knots.clone(), end.clone(), false).unwrap(), &p);
        let q = rng.chain(6, 1.2);
        let qe = match end {
            CubicEnd::Natural => CubicEnd::Natural,
            _ => CubicEnd::Scipy,
        };
        check_curve(&CubicSpline::try_new(q.clone(), knots.clone(), qe.clone(), false).unwrap(), &q);
        let s = rng.walk_sn(6, 5, 0.5);
        let se = match end {
            CubicEnd::Natural => CubicEnd::Natural,
            _ => CubicEnd::Scipy,
        };
        check_curve(&CubicSpline::try_new(s.clone(), knots.clone(), se, false).unwrap(), &s);
    }
}

#[test]
fn closed_curves_are_c2_at_the_seam() {
    let mut rng = Rng::new(2);
    let mut k = KNOTS6.to_vec();
    k.push(6.5);
    let p = walk_s2(&mut rng, 6, 1.5);
    check_curve(&CubicSpline::try_new(p.clone(), Some(k.clone()), CubicEnd::Natural, true).unwrap(), &p);
    let q = rng.chain(6, 1.0);
    check_curve(&CubicSpline::try_new(q.clone(), Some(k.clone()), CubicEnd::Natural, true).unwrap(), &q);
    let s = rng.walk_sn(6, 5, 0.6);
    check_curve(&CubicSpline::try_new(s.clone(), Some(k), CubicEnd::Natural, true).unwrap(), &s);
    // Uniform default knots: one more than the points, closing spacing 1.
    let c = CubicSpline::try_new(q.clone(), None, CubicEnd::Natural, true).unwrap();
    assert_eq!(c.knots(), &[0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    assert_eq!(c.domain(), [0.0, 6.0]);
    assert_eq!(c.segment_count(), 6);
    check_curve(&c, &q);
}

/// The quaternion from scalar-first components.
fn wxyz(v: &serde_json::Value) -> UnitQuat {
    let a: Vec<f64> = v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    UnitQuat::from_wxyz([a[0], a[1], a[2], a[3]]).unwrap()
}

fn vec3(v: &serde_json::Value) -> DVec3 {
    let a: Vec<f64> = v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    DVec3::new(a[0], a[1], a[2])
}

fn floats(v: &serde_json::Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

/// `CubicEnd::Scipy` on S³ against scipy 1.17.1's `RotationSpline` (fixture written by
/// `scripts/scipy_rotation_spline_fixture.py`): 4, 7, 20 and 20 keys, non-uniform times, about
/// 50 parameters each. Measured (2026-12-01): rotation angle ≤ 8.2e-12 rad, body rate error
/// ≤ 1.4e-11 and acceleration error ≤ 2.7e-11 relative to the largest rate and acceleration of
/// the case — the size of scipy's own distance from its fixed point (`converged_to`, up to
/// 3.2e-11: scipy stops its iteration at a change of 1e-9). Run with `-- --nocapture` to print.
#[test]
fn scipy_agreement() {
    let text = include_str!("data/rotation_spline_scipy.json");
    let data: serde_json::Value = serde_json::from_str(text).unwrap();
    let (mut worst_angle, mut worst_rate, mut worst_acc) = (0.0_f64, 0.0_f64, 0.0_f64);
    for case in data["cases"].as_array().unwrap() {
        let mut keys: Vec<UnitQuat> = case["keys"].as_array().unwrap().iter().map(wxyz).collect();
        unflip(&mut keys);
        let times = floats(&case["times"]);
        let c = CubicSpline::try_new(keys, Some(times), CubicEnd::Scipy, false).unwrap();
        let ts = floats(&case["ts"]);
        let quats: Vec<UnitQuat> = case["quats"].as_array().unwrap().iter().map(wxyz).collect();
        let rates: Vec<DVec3> = case["rates"].as_array().unwrap().iter().map(vec3).collect();
        let accs: Vec<DVec3> = case["accelerations"].as_array().unwrap().iter().map(vec3).collect();
        let rate_scale = rates.iter().map(|r| r.length()).fold(0.0, f64::max);
        let acc_scale = accs.iter().map(|r| r.length()).fold(0.0, f64::max);
        let (mut angle, mut rate, mut acc) = (0.0_f64, 0.0_f64, 0.0_f64);
        for (k, &t) in ts.iter().enumerate() {
            let j = c.jet(t);
            angle = angle.max(j.point.inverse().mul(quats[k]).rotation_angle());
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
    println!("worst: angle {worst_angle:.1e} rad, rate {worst_rate:.1e}, acceleration {worst_acc:.1e}");
    assert!(worst_angle <= 1e-8, "angle {worst_angle:e}");
    assert!(worst_rate <= 1e-7 && worst_acc <= 1e-7, "rate {worst_rate:e}, acceleration {worst_acc:e}");
}
