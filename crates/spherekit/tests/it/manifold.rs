// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Sphere geometry: points, distance, log/exp, slerp, on S², S³ and S^m, with named edge cases.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::cast_possible_truncation,
    reason = "tests: a panic is the failure report"
)]

use std::f64::consts::{FRAC_PI_2, PI};

use spherekit::glam::{DQuat, DVec3, DVec4};
use spherekit::{Ambient, Manifold, PointError, S2Point, SmPoint, UnitQuat};

use crate::support::{Rng, assert_close, assert_unit};

#[test]
fn constructors_normalise_and_reject_bad_input() {
    let p = S2Point::try_new(DVec3::new(0.0, 0.0, 5.0)).unwrap();
    assert_eq!(p, S2Point::Z);
    assert_eq!(S2Point::try_new(DVec3::ZERO), Err(PointError::ZeroLength));
    assert_eq!(
        S2Point::try_new(DVec3::new(f64::NAN, 1.0, 0.0)),
        Err(PointError::NonFinite)
    );
    assert_eq!(
        S2Point::try_new(DVec3::new(f64::INFINITY, 1.0, 0.0)),
        Err(PointError::NonFinite)
    );
    // Huge and tiny inputs neither overflow nor underflow.
    let big = S2Point::try_new(DVec3::new(1e300, 1e300, 0.0)).unwrap();
    assert_unit(&big);
    let tiny = S2Point::try_new(DVec3::new(1e-300, 0.0, 1e-300)).unwrap();
    assert_unit(&tiny);
    assert_eq!(UnitQuat::from_wxyz([0.0; 4]), Err(PointError::ZeroLength));
    assert_eq!(
        SmPoint::try_new(vec![1.0]),
        Err(PointError::WrongDimension {
            expected: 2,
            got: 1
        })
    );
    assert_eq!(
        SmPoint::try_new(vec![0.0, 0.0, 0.0]),
        Err(PointError::ZeroLength)
    );
}

fn check_pair<P: Manifold>(p: &P, q: &P) {
    let theta = p.dist(q);
    // exp(log) round trip and |log| = dist.
    let l = p.log(q);
    assert!((l.length() - theta).abs() <= 1e-14, "|log| = dist");
    assert!(l.dot(&p.to_vector()).abs() <= 1e-14, "log is tangent");
    assert_close(
        &p.exp(&l).to_vector(),
        &q.to_vector(),
        1e-14,
        "exp(log q) = q",
    );
    // Exact ends, constant speed, symmetry.
    assert_eq!(&p.slerp(q, 0.0), p);
    assert_eq!(&p.slerp(q, 1.0), q);
    for t in [0.1, 0.25, 0.5, 0.9, -0.5, 1.5] {
        let m = p.slerp(q, t);
        assert_unit(&m);
        if (0.0..=1.0).contains(&t) {
            assert!(
                (p.dist(&m) - t * theta).abs() <= 4e-15 * (1.0 + theta),
                "d(p, slerp) = tθ"
            );
            assert!(
                (m.dist(q) - (1.0 - t) * theta).abs() <= 4e-15 * (1.0 + theta),
                "d(slerp, q)"
            );
            assert_close(
                &q.slerp(p, 1.0 - t).to_vector(),
                &m.to_vector(),
                1e-14,
                "reversal",
            );
        }
    }
}

#[test]
fn random_pairs_on_every_sphere() {
    let mut rng = Rng::new(1);
    for _ in 0..200 {
        check_pair(&rng.s2(), &rng.s2());
        check_pair(&rng.quat(), &rng.quat());
        check_pair(&rng.sn(5), &rng.sn(5));
        check_pair(&rng.sn(1), &rng.sn(1));
    }
}

#[test]
fn distance_is_accurate_near_zero_and_near_pi() {
    let mut rng = Rng::new(2);
    for eps in [1e-3, 1e-8, 1e-9, 1e-12, 1e-15] {
        let p = rng.s2();
        let q = rng.s2_at_angle(p, eps);
        // The input points themselves carry rounding errors of about 1e-16.
        assert!((p.dist(&q) - eps).abs() < 1e-15, "near 0: {eps}");
        let r = rng.s2_at_angle(p, PI - eps);
        if eps >= 1e-12 {
            assert!(
                (p.dist(&r) - (PI - eps)).abs() < 1e-15 * 8.0,
                "near π: {eps}"
            );
            check_pair(&p, &q);
            check_pair(&p, &r);
        }
    }
}

#[test]
fn log_of_nearly_identical_points_keeps_its_direction() {
    // θ ≈ 1e-9: the direction comes from q − p, not from a cancelling q − cos θ·p.
    let p = S2Point::X;
    let q = S2Point::try_new(DVec3::new(1.0, 1e-9, 0.0)).unwrap();
    let l = p.log(&q);
    assert!(
        (l.y / 1e-9 - 1.0).abs() < 1e-7 && l.x.abs() < 1e-24 && l.z == 0.0,
        "{l:?}"
    );
}

#[test]
fn identical_points() {
    let p = S2Point::try_new(DVec3::new(1.0, 2.0, 3.0)).unwrap();
    assert_eq!(p.dist(&p), 0.0);
    assert_eq!(p.log(&p), DVec3::ZERO);
    assert_eq!(p.slerp(&p, 0.3), p);
}

#[test]
fn antipodal_points_have_no_geodesic() {
    let p = S2Point::X;
    let q = S2Point::try_new(-DVec3::X).unwrap();
    assert!(p.is_antipodal(&q));
    assert_eq!(p.try_log(&q), Err(PointError::Antipodal));
    assert_eq!(p.try_slerp(&q, 0.5), Err(PointError::Antipodal));
    assert!((p.dist(&q) - PI).abs() < 1e-15);
    // A half turn minus 1e-9 is still a unique geodesic.
    let r = S2Point::try_new(DVec3::new(-1.0, 1e-9, 0.0)).unwrap();
    assert!(!p.is_antipodal(&r));
    let m = p.try_slerp(&r, 0.5).unwrap();
    assert_close(
        &m.as_dvec3(),
        &DVec3::Y,
        1e-8,
        "midpoint of a near half circle",
    );
    // On S³, q and −q are antipodal points (the same rotation).
    let a = UnitQuat::from_axis_angle(DVec3::Z, 1.0).unwrap();
    assert!(a.is_antipodal(&(-a)));
}

#[test]
fn slerp_on_s3_never_flips_signs() {
    // Keys more than 90° apart on S³ (a rotation of more than π between them) are interpolated
    // along the long way round in rotation space, exactly as given.
    let a = UnitQuat::IDENTITY;
    let b = UnitQuat::from_axis_angle(DVec3::Z, 3.0 * FRAC_PI_2).unwrap();
    assert!(a.as_dquat().dot(b.as_dquat()) < 0.0);
    let m = a.slerp(&b, 0.5);
    let expected = UnitQuat::from_axis_angle(DVec3::Z, 0.75 * PI).unwrap();
    assert!(m.dist(&expected) < 1e-15, "{m:?}");
}

#[test]
fn quaternion_slerp_matches_the_power_form() {
    // G[p, q](s) = p·(p⁻¹q)^s on S³.
    let mut rng = Rng::new(3);
    for _ in 0..100 {
        let (p, q) = (rng.quat(), rng.quat());
        let s = rng.range(-0.5, 1.5);
        let power = p * (p.conjugate() * q).powf(s);
        assert!(p.slerp(&q, s).dist(&power) < 1e-13, "power form");
    }
}

#[test]
fn rotation_equivariance_of_slerp() {
    let mut rng = Rng::new(4);
    for _ in 0..50 {
        let (p, q, r) = (rng.s2(), rng.s2(), rng.rotation());
        let t = rng.uniform();
        let rot = |x: S2Point| S2Point::try_new(r * x.as_dvec3()).unwrap();
        assert_close(
            &rot(p.slerp(&q, t)).as_dvec3(),
            &rot(p).slerp(&rot(q), t).as_dvec3(),
            1e-14,
            "R·slerp = slerp(R·)",
        );
    }
}

#[test]
fn exp_and_log_of_quaternions() {
    let mut rng = Rng::new(5);
    for _ in 0..100 {
        let q = rng.quat();
        assert!(
            UnitQuat::exp_pure(q.log_pure()).dist(&q) < 1e-15,
            "exp(log q) = q"
        );
        let v =
            DVec3::new(rng.normal(), rng.normal(), rng.normal()).normalize() * rng.range(0.0, 3.1);
        assert_close(
            &UnitQuat::exp_pure(v).log_pure(),
            &v,
            1e-13,
            "log(exp v) = v",
        );
    }
    // Near the identity, relative accuracy 1e-12.
    for eps in [1e-3_f64, 1e-8] {
        let n = DVec3::new(1.0, 2.0, 2.0) / 3.0;
        let q = UnitQuat::try_new(DQuat::from_vec4((n * eps.sin()).extend(eps.cos()))).unwrap();
        assert!(
            (q.log_pure() - n * eps).length() <= 1e-12 * eps,
            "log near 1 at {eps}"
        );
    }
    assert_eq!(UnitQuat::IDENTITY.log_pure(), DVec3::ZERO);
    assert!(
        ((-UnitQuat::IDENTITY).log_pure().length() - PI).abs() < 1e-15,
        "log(−1) has length π"
    );
}

#[test]
fn rotation_action_and_angles() {
    let q = UnitQuat::from_axis_angle(DVec3::Z, FRAC_PI_2).unwrap();
    assert_close(&q.rotate(DVec3::X), &DVec3::Y, 1e-15, "R(z, π/2)·x = y");
    assert!((q.rotation_angle() - FRAC_PI_2).abs() < 1e-15);
    assert!(
        ((-q).rotation_angle() - FRAC_PI_2).abs() < 1e-15,
        "sign-independent angle"
    );
    let w = DVec3::new(0.3, -0.2, 0.1);
    assert_close(
        &UnitQuat::from_rotation_vector(w)
            .unwrap()
            .to_rotation_vector(),
        &w,
        1e-15,
        "rotvec",
    );
    let mut rng = Rng::new(6);
    for _ in 0..50 {
        let (a, b) = (rng.quat(), rng.quat());
        let v = DVec3::new(rng.normal(), rng.normal(), rng.normal());
        // Composition: (ab)·v = a·(b·v); and rotate = glam's q·v.
        assert_close(
            &(a * b).rotate(v),
            &a.rotate(b.rotate(v)),
            1e-13,
            "composition",
        );
        assert_close(&a.rotate(v), &(a.as_dquat() * v), 1e-13, "matches glam");
    }
}

#[test]
fn angular_velocity_of_a_one_parameter_subgroup() {
    // q(t) = exp(t·v)·q₀ has ω = 2v (space frame) and α = 0.
    let v = DVec3::new(0.2, -0.4, 0.7);
    let q0 = UnitQuat::from_axis_angle(DVec3::X, 0.3).unwrap();
    let q = |t: f64| UnitQuat::exp_pure(v * t) * q0;
    let h = 1e-5;
    let t = 0.4;
    let d = |a: UnitQuat, b: UnitQuat| DVec4::from(a.as_dquat()) - DVec4::from(b.as_dquat());
    let dq = d(q(t + h), q(t - h)) / (2.0 * h);
    let ddq = (d(q(t + h), q(t)) - d(q(t), q(t - h))) / (h * h);
    let (omega, alpha) = spherekit::angular_velocity_acceleration(q(t), dq, ddq);
    assert_close(&omega, &(2.0 * v), 1e-9, "ω = 2v");
    assert!(alpha.length() < 1e-4, "α = 0: {alpha:?}");
}

#[test]
fn unflip_makes_consecutive_dots_non_negative() {
    let mut rng = Rng::new(7);
    let mut keys: Vec<UnitQuat> = (0..50).map(|_| rng.quat()).collect();
    let original = keys.clone();
    spherekit::unflip(&mut keys);
    assert_eq!(keys[0], original[0]);
    for (i, w) in keys.windows(2).enumerate() {
        assert!(w[0].as_dquat().dot(w[1].as_dquat()) >= 0.0, "pair {i}");
    }
    for (k, o) in keys.iter().zip(&original) {
        assert!(k == o || *k == -*o, "same rotation");
    }
}
