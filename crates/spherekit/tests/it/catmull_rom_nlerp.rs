// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The normalised ambient Catmull-Rom spline (Gortler 2012, §9.3's ℝ⁴ alternative): C¹ and
//! interpolating like the spherical one, but not constant speed and off the great circles.

#![allow(clippy::unwrap_used, reason = "tests unwrap known-valid fixtures")]

use core::f64::consts::PI;

use spherekit::glam::DVec3;
use spherekit::{
    Ambient, CatmullRom, CatmullRomNlerp, Curve, Manifold, S2Point, Side, SplineError, UnitQuat,
    continuity, unflip,
};

use crate::support::*;

fn on_equator(angle: f64) -> S2Point {
    S2Point::try_new(DVec3::new(angle.cos(), angle.sin(), 0.0)).unwrap()
}

/// Interpolation, unit norm, C¹ with the projected Euclidean tangent at the keys, not C², exact
/// derivatives against finite differences.
fn check<P: Manifold>(c: &CatmullRomNlerp<P>) {
    let pts = c.points().to_vec();
    let k = c.knots().to_vec();
    let n = k.len() - 1;
    let span = |i: usize| match i {
        0 => 2.0 * (k[1] - k[0]),
        _ if i == n => 2.0 * (k[n] - k[n - 1]),
        _ => k[i + 1] - k[i - 1],
    };
    for i in 0..=n {
        let key = pts[i + 1].to_vector();
        let tangent = (pts[i + 2].to_vector() - pts[i].to_vector()) * (1.0 / span(i));
        let projected = tangent.clone() - key.clone() * key.dot(&tangent);
        for side in [Side::Left, Side::Right] {
            let j = c.jet_at(k[i], side);
            assert!(j.point.dist(&pts[i + 1]) < 1e-15, "interpolates key {i}");
            let e = (j.velocity - projected.clone()).length();
            assert!(e < 1e-13, "velocity at key {i} ({side:?}): {e:e}");
        }
    }
    assert!(max_norm_error(c, 200) < 1e-15, "unit");
    let report = continuity(c);
    assert!(report.iter().all(|r| r.c1 < 1e-13), "C¹: {report:?}");
    if n > 2 {
        assert!(report.iter().any(|r| r.c2 > 1e-3), "not C²: {report:?}");
    }
    check_derivatives(c, 97);
}

#[test]
fn interpolates_and_is_c1_on_every_sphere() {
    let mut rng = Rng::new(7);
    check(&CatmullRomNlerp::try_new(rng.walk_s2(7, 0.7), None).unwrap());
    check(
        &CatmullRomNlerp::try_new(rng.walk_s2(7, 0.5), Some(vec![0.0, 0.4, 1.9, 2.3, 4.0]))
            .unwrap(),
    );
    let mut keys = rng.walk_quat(7, 0.6);
    unflip(&mut keys);
    check(&CatmullRomNlerp::try_new(keys, None).unwrap());
    check(&CatmullRomNlerp::try_new(rng.walk_sm(6, 5, 0.6), None).unwrap());
}

/// On keys equally spaced along one great circle the spherical Catmull-Rom runs at constant
/// speed; the normalised one stays on the circle but its speed rises and falls on every segment
/// (the nlerp law of the chord's projection).
#[test]
fn speed_is_not_constant() {
    let step = 0.9;
    let keys: Vec<S2Point> = (0..6).map(|i| on_equator(step * f64::from(i))).collect();
    let flat = CatmullRomNlerp::try_new(keys.clone(), None).unwrap();
    let spherical = CatmullRom::try_new(keys, None).unwrap();
    let speeds = |c: &dyn Fn(f64) -> f64| {
        let s: Vec<f64> = (0..=300).map(|i| c(3.0 * f64::from(i) / 300.0)).collect();
        let (lo, hi) = s
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
        (lo, hi)
    };
    let (lo, hi) = speeds(&|t| spherical.jet(t).velocity.length());
    assert!(
        (hi - lo) < 1e-12 && (lo - step).abs() < 1e-12,
        "spherical: constant speed {lo}..{hi}"
    );
    let (lo, hi) = speeds(&|t| flat.jet(t).velocity.length());
    assert!(hi / lo > 1.04, "normalised: speed from {lo} to {hi}");
    // Still on the great circle of the keys (the ambient curve stays in its plane).
    for i in 0..=300 {
        let p = flat.eval(3.0 * f64::from(i) / 300.0);
        assert!(p.as_dvec3().z.abs() < 1e-16, "on the equator");
    }
}

/// Orientation keys about one fixed axis: the slerp Catmull-Rom turns at constant angular
/// speed; the normalised one keeps the axis but not the speed.
#[test]
fn quaternion_keys_about_one_axis_keep_the_axis_not_the_speed() {
    let axis = DVec3::new(1.0, 2.0, -0.5).normalize();
    let keys: Vec<UnitQuat> = (0..6)
        .map(|i| UnitQuat::from_axis_angle(axis, 1.2 * f64::from(i)).unwrap())
        .collect();
    let flat = CatmullRomNlerp::try_new(keys.clone(), None).unwrap();
    let spherical = CatmullRom::try_new_quaternion(keys, None).unwrap();
    let mut rates = Vec::new();
    for i in 0..=90 {
        let t = 3.0 * f64::from(i) / 90.0;
        let j = flat.jet(t);
        let (w, _) = spherekit::angular_velocity_acceleration(j.point, j.velocity, j.acceleration);
        assert!(w.cross(axis).length() < 1e-13, "about the axis");
        rates.push(w.length());
        let js = spherical.jet(t);
        let (ws, _) =
            spherekit::angular_velocity_acceleration(js.point, js.velocity, js.acceleration);
        assert!(
            (ws.length() - 1.2).abs() < 1e-12,
            "slerp version: 1.2 rad per step"
        );
    }
    let (lo, hi) = rates
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
    assert!(hi - lo > 0.05, "normalised: angular speed {lo}..{hi}");
}

/// Off the great circles: with keys off one great circle, the curve between two keys leaves the
/// great arc joining them, and differs from the spherical Catmull-Rom on the same keys.
#[test]
fn leaves_the_great_circles_and_differs_from_the_spherical_spline() {
    let mut rng = Rng::new(11);
    let keys = rng.walk_s2(6, 0.8);
    let flat = CatmullRomNlerp::try_new(keys.clone(), None).unwrap();
    let spherical = CatmullRom::try_new(keys.clone(), None).unwrap();
    let (mut off, mut apart) = (0.0f64, 0.0f64);
    for i in 0..3 {
        let (a, b) = (keys[i + 1].as_dvec3(), keys[i + 2].as_dvec3());
        let normal = a.cross(b).normalize();
        let p = flat.eval(i as f64 + 0.5);
        off = off.max(p.as_dvec3().dot(normal).abs());
        apart = apart.max(p.dist(&spherical.eval(i as f64 + 0.5)));
    }
    assert!(off > 1e-2, "distance from the great arcs {off}");
    assert!(
        apart > 1e-3,
        "differs from the spherical Catmull-Rom by {apart}"
    );
}

/// Equivariance under orthogonal maps of the ambient space: the construction is linear, then a
/// normalisation.
#[test]
fn rotation_equivariance() {
    let mut rng = Rng::new(3);
    let keys = rng.walk_s2(6, 0.7);
    let r = rng.rotation();
    let moved: Vec<S2Point> = keys
        .iter()
        .map(|p| S2Point::try_new(r * p.as_dvec3()).unwrap())
        .collect();
    let (a, b) = (
        CatmullRomNlerp::try_new(keys, None).unwrap(),
        CatmullRomNlerp::try_new(moved, None).unwrap(),
    );
    for i in 0..=60 {
        let t = 3.0 * f64::from(i) / 60.0;
        assert!(
            (r * a.eval(t).as_dvec3() - b.eval(t).as_dvec3()).length() < 1e-14,
            "R·q(t)"
        );
    }
}

/// Near-identical keys and a near half turn between keys stay finite.
#[test]
fn close_and_far_keys_stay_finite() {
    let close: Vec<S2Point> = (0..5).map(|i| on_equator(1e-9 * f64::from(i))).collect();
    let c = CatmullRomNlerp::try_new(close, None).unwrap();
    check_derivatives(&c, 31);
    let far: Vec<S2Point> = (0..5)
        .map(|i| on_equator(0.95 * PI * f64::from(i)))
        .collect();
    let c = CatmullRomNlerp::try_new(far, None).unwrap();
    for i in 0..=40 {
        let j = c.jet(2.0 * f64::from(i) / 40.0);
        assert!(
            j.velocity.is_finite() && j.acceleration.is_finite(),
            "finite"
        );
    }
}

#[test]
fn bad_input_is_a_typed_error() {
    assert_eq!(
        CatmullRomNlerp::try_new(vec![S2Point::X, S2Point::Y, S2Point::Z], None).unwrap_err(),
        SplineError::TooFewPoints { min: 4, got: 3 }
    );
    let anti = vec![
        S2Point::X,
        S2Point::Y,
        S2Point::try_new(-DVec3::Y).unwrap(),
        S2Point::Z,
    ];
    assert_eq!(
        CatmullRomNlerp::try_new(anti, None).unwrap_err(),
        SplineError::Antipodal { index: 1 }
    );
    // Keys 100°, 170° and 110° apart: the ambient curve passes within 0.02 of the origin.
    let deg = PI / 180.0;
    let zigzag = vec![
        on_equator(100.0 * deg),
        on_equator(0.0),
        on_equator(170.0 * deg),
        on_equator(60.0 * deg),
    ];
    let e = CatmullRomNlerp::try_new(zigzag, None).unwrap_err();
    assert_eq!(e, SplineError::ThroughOrigin { index: 1, next: 2 });
    assert!(e.to_string().contains("point 1 to point 2"), "{e}");
    let e = CatmullRomNlerp::try_new(vec![S2Point::X; 4], Some(vec![0.0, 0.0])).unwrap_err();
    assert_eq!(e, SplineError::KnotsNotIncreasing { index: 1 });
}
