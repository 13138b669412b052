// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `CubicSpline::try_hermite`: keys with a velocity at each, on every sphere, open and closed.

use spherekit::glam::DVec3;
use spherekit::{
    Ambient, CubicEnd, CubicSpline, Curve, Manifold, SplineError, UnitQuat,
    angular_velocity_acceleration_body, continuity, velocity_from_angular_body,
};

use crate::support::{Rng, check_derivatives};

/// A random tangent velocity at each key, of size up to `scale`.
fn velocities<P: Manifold>(rng: &mut Rng, keys: &[P], scale: f64) -> Vec<P::Vector> {
    keys.iter()
        .map(|p| {
            let v = p.to_vector();
            let raw = v.with_coords(&rng.vec(v.dim()));
            p.project_tangent(&raw) * scale
        })
        .collect()
}

/// Interpolation of keys and velocities at the key times (from both sides at the joints), C¹
/// joints, exact derivatives, and no solve.
fn check<P: Manifold>(keys: Vec<P>, vel: Vec<P::Vector>, knots: Vec<f64>, closed: bool) {
    let c = CubicSpline::try_hermite(keys.clone(), vel.clone(), Some(knots.clone()), closed)
        .expect("builds");
    assert_eq!(c.solve_info().iterations, 0, "no solve");
    let n = keys.len();
    for k in 0..=n {
        let (key, v) = if k < n {
            (&keys[k], &vel[k])
        } else if closed {
            (&keys[0], &vel[0])
        } else {
            continue;
        };
        for side in [spherekit::Side::Left, spherekit::Side::Right] {
            let j = c.jet_at(knots[k], side);
            let dp = (j.point.to_vector() - key.to_vector()).length();
            let dv = (j.velocity.clone() - v.clone()).length();
            assert!(dp < 1e-12, "key {k} ({side:?}): |c − p| = {dp:e}");
            assert!(
                dv < 1e-12 * v.length().max(1.0),
                "key {k} ({side:?}): |c′ − V| = {dv:e}"
            );
        }
    }
    for joint in continuity(&c) {
        assert!(joint.c0 < 1e-12 && joint.c1 < 1e-11, "C¹ at {}", joint.t);
    }
    check_derivatives(&c, 37);
}

#[test]
fn hermite_interpolates_keys_and_velocities_on_every_sphere() {
    let mut rng = Rng::new(36);
    for closed in [false, true] {
        for n in [2, 3, 7] {
            if closed && n < 3 {
                continue;
            }
            let l = n + usize::from(closed);
            let knots = rng.knots(l - 1);
            let keys = rng.walk_s2(n, 0.8);
            let vel = velocities(&mut rng, &keys, 1.3);
            check(keys, vel, knots.clone(), closed);
            let keys = rng.walk_quat(n, 0.6);
            let vel = velocities(&mut rng, &keys, 0.7);
            check(keys, vel, knots.clone(), closed);
            let keys = rng.walk_sm(n, 5, 0.7);
            let vel = velocities(&mut rng, &keys, 0.9);
            check(keys, vel, knots, closed);
        }
    }
}

/// Given the velocities that the C² spline solves for, the Hermite spline is that spline.
#[test]
fn hermite_with_the_solved_velocities_is_the_c2_spline() {
    let mut rng = Rng::new(7);
    for closed in [false, true] {
        let keys = rng.walk_quat(9, 0.7);
        let knots = rng.knots(8 + usize::from(closed));
        let c2 = CubicSpline::try_new(keys.clone(), Some(knots.clone()), CubicEnd::Natural, closed)
            .unwrap();
        let h = CubicSpline::try_hermite(keys, c2.key_velocities().to_vec(), Some(knots), closed)
            .unwrap();
        let [t0, t1] = c2.domain();
        for i in 0..=200 {
            let t = t0 + (t1 - t0) * f64::from(i) / 200.0;
            let (a, b) = (c2.jet(t), h.jet(t));
            assert!(a.point.dist(&b.point) < 1e-13, "t {t}");
            assert!((a.velocity - b.velocity).length() < 1e-12, "t {t}");
            assert!((a.acceleration - b.acceleration).length() < 1e-10, "t {t}");
        }
    }
}

/// Gyroscope rates at attitude keys: the body angular velocity at each key is the given rate.
#[test]
fn hermite_takes_body_rates_on_s3() {
    let mut rng = Rng::new(11);
    let keys = rng.walk_quat(6, 0.5);
    let rates: Vec<DVec3> = (0..6).map(|_| rng.vec3(1.0)).collect();
    let vel = keys
        .iter()
        .zip(&rates)
        .map(|(q, w)| velocity_from_angular_body(*q, *w))
        .collect();
    let knots: Vec<f64> = (0..6).map(|i| 0.1 * f64::from(i)).collect();
    let c = CubicSpline::try_hermite(keys, vel, Some(knots.clone()), false).unwrap();
    for (t, w) in knots.iter().zip(&rates) {
        let j = c.jet(*t);
        let (omega, _) = angular_velocity_acceleration_body(j.point, j.velocity, j.acceleration);
        assert!((omega - *w).length() < 1e-12, "ω at {t}: {omega} vs {w}");
    }
}

/// Identical keys with zero velocities: a constant curve; with a velocity: a loop out and back.
#[test]
fn hermite_identical_keys() {
    let p = UnitQuat::from_rotation_vector(DVec3::new(0.1, 0.2, 0.3)).unwrap();
    let zero = p.to_vector().zeros_like();
    let c = CubicSpline::try_hermite(vec![p; 3], vec![zero; 3], None, false).unwrap();
    assert!(c.eval(0.7).dist(&p) < 1e-15 && c.jet(1.3).velocity.length() == 0.0);
    let v = velocity_from_angular_body(p, DVec3::new(0.0, 0.0, 1.0));
    let c = CubicSpline::try_hermite(vec![p; 3], vec![v, zero, v], None, false).unwrap();
    assert!((c.jet(0.0).velocity - v).length() < 1e-12);
    assert!(c.eval(1.0).dist(&p) < 1e-15);
}

#[test]
fn hermite_bad_velocities_name_the_key() {
    let mut rng = Rng::new(3);
    let keys = rng.walk_s2(4, 0.5);
    let mut vel = velocities(&mut rng, &keys, 1.0);
    let err = CubicSpline::try_hermite(keys.clone(), vel[..3].to_vec(), None, false).unwrap_err();
    assert!(
        matches!(
            err,
            SplineError::InvalidParameter {
                name: "velocities",
                ..
            }
        ),
        "{err}"
    );
    assert!(err.to_string().contains("4 keys, got 3"), "{err}");
    vel[2] = DVec3::new(f64::NAN, 0.0, 0.0);
    let err = CubicSpline::try_hermite(keys.clone(), vel.clone(), None, false).unwrap_err();
    assert!(
        matches!(err, SplineError::InvalidKeyVelocity { index: 2, .. }),
        "{err}"
    );
    vel[2] = keys[2].as_dvec3();
    let err = CubicSpline::try_hermite(keys.clone(), vel.clone(), None, false).unwrap_err();
    assert_eq!(
        err.to_string(),
        "the velocity at point 2 is not tangent to its key"
    );
    vel[2] = DVec3::new(1e308, 1e308, 0.0);
    // Finite but huge: a curve whose every point is finite, or a typed error; never NaN.
    match CubicSpline::try_hermite(keys, vel, None, false) {
        Ok(c) => {
            for i in 0..=30 {
                let j = c.jet(3.0 * f64::from(i) / 30.0);
                assert!(j.point.to_vector().is_finite(), "finite point");
            }
        }
        Err(e) => assert!(!e.to_string().is_empty()),
    }
}

#[test]
fn hermite_tiny_velocities_are_judged_by_their_direction() {
    // |v|² underflows below 1e-154: the tangency test is made on the direction of v, so a
    // tangent velocity of size 1e-300 is taken and a radial one still rejected.
    let mut rng = Rng::new(8);
    let keys = rng.walk_s2(3, 0.5);
    let mut vel = velocities(&mut rng, &keys, 1e-300);
    let c = CubicSpline::try_hermite(keys.clone(), vel.clone(), None, false).expect("tangent");
    assert!((c.eval(1.0).as_dvec3() - keys[1].as_dvec3()).length() < 1e-15);
    vel[1] = keys[1].as_dvec3() * 1e-300;
    let err = CubicSpline::try_hermite(keys, vel, None, false).unwrap_err();
    assert_eq!(
        err.to_string(),
        "the velocity at point 1 is not tangent to its key"
    );
}
