// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The piecewise geodesic and nlerp curves.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::cast_possible_truncation,
    reason = "tests: a panic is the failure report"
)]

use spherekit::glam::DVec3;
use spherekit::{
    Curve, GeodesicSpline, Knots, Manifold, NlerpSpline, S2Point, Side, SmPoint, SplineError,
    UnitQuat,
};

use crate::support::{Rng, assert_close, assert_unit, check_derivatives_at, interior_parameters};

fn chain(rng: &mut Rng, n: usize) -> Vec<S2Point> {
    let mut p = vec![rng.s2()];
    for _ in 1..n {
        let angle = rng.range(0.1, 2.5);
        let next = rng.s2_at_angle(*p.last().unwrap(), angle);
        p.push(next);
    }
    p
}

fn check_curve<C: Curve>(c: &C, points: &[C::Point]) {
    // Interpolation at the knots, exact.
    for (k, p) in c.joints().iter().zip(points) {
        assert_eq!(&c.eval(*k), p, "interpolates at {k}");
        assert_eq!(&c.jet_at(*k, Side::Left).point, p, "left limit at {k}");
    }
    let ts = interior_parameters(c, 7);
    for &t in &ts {
        assert_unit(&c.eval(t));
    }
    check_derivatives_at(c, &ts);
}

#[test]
fn geodesic_on_every_sphere() {
    let mut rng = Rng::new(10);
    let p = chain(&mut rng, 6);
    check_curve(&GeodesicSpline::try_new(p.clone(), None).unwrap(), &p);
    let knots = vec![0.0, 0.1, 1.0, 1.05, 3.0, 10.0];
    check_curve(
        &GeodesicSpline::try_new(p.clone(), Some(knots)).unwrap(),
        &p,
    );
    let mut q: Vec<UnitQuat> = (0..5).map(|_| rng.quat()).collect();
    spherekit::unflip(&mut q);
    check_curve(&GeodesicSpline::try_new(q.clone(), None).unwrap(), &q);
    let s: Vec<SmPoint> = (0..4).map(|_| rng.sn(6)).collect();
    check_curve(&GeodesicSpline::try_new(s.clone(), None).unwrap(), &s);
}

#[test]
fn nlerp_on_every_sphere() {
    let mut rng = Rng::new(11);
    let p = chain(&mut rng, 6);
    check_curve(&NlerpSpline::try_new(p.clone(), None).unwrap(), &p);
    let knots = vec![-2.0, -1.0, 0.5, 0.6, 1e3, 1e6];
    check_curve(&NlerpSpline::try_new(p.clone(), Some(knots)).unwrap(), &p);
    let q: Vec<UnitQuat> = (0..5).map(|_| rng.quat()).collect();
    check_curve(&NlerpSpline::try_new(q.clone(), None).unwrap(), &q);
    let s: Vec<SmPoint> = (0..4).map(|_| rng.sn(3)).collect();
    check_curve(&NlerpSpline::try_new(s.clone(), None).unwrap(), &s);
}

#[test]
fn geodesic_has_constant_speed_on_each_piece() {
    let mut rng = Rng::new(12);
    let p = chain(&mut rng, 4);
    let knots = vec![0.0, 0.5, 2.0, 2.25];
    let c = GeodesicSpline::try_new(p.clone(), Some(knots.clone())).unwrap();
    for i in 0..3 {
        let rate = p[i].dist(&p[i + 1]) / (knots[i + 1] - knots[i]);
        for s in [0.0, 0.3, 0.99] {
            let t = knots[i] + s * (knots[i + 1] - knots[i]);
            assert!(
                (c.jet(t).velocity.length() - rate).abs() < 1e-13,
                "speed on piece {i}"
            );
            // d(pᵢ, c(t)) = s·d(pᵢ, pᵢ₊₁)
            assert!((p[i].dist(&c.eval(t)) - s * p[i].dist(&p[i + 1])).abs() < 1e-14);
        }
    }
}

#[test]
fn nlerp_traces_the_same_arcs_as_geodesic() {
    let mut rng = Rng::new(13);
    let p = chain(&mut rng, 4);
    let n = NlerpSpline::try_new(p.clone(), None).unwrap();
    for t in interior_parameters(&n, 5) {
        let x = n.eval(t).as_dvec3();
        let i = t.floor() as usize;
        let normal = p[i].as_dvec3().cross(p[i + 1].as_dvec3()).normalize();
        assert!(x.dot(normal).abs() < 1e-15, "on the great circle");
    }
}

#[test]
fn domain_policy_clamps() {
    let p = vec![S2Point::X, S2Point::Y, S2Point::Z];
    let c = GeodesicSpline::try_new(p, Some(vec![1.0, 2.0, 4.0])).unwrap();
    assert_eq!(c.domain(), [1.0, 4.0]);
    assert_eq!(c.eval(-10.0), S2Point::X);
    assert_eq!(c.eval(0.999), S2Point::X);
    assert_eq!(c.eval(4.001), S2Point::Z);
    assert_eq!(
        c.jet(-1.0).velocity,
        c.jet(1.0).velocity,
        "one-sided jet at the start"
    );
    assert_eq!(c.jet(5.0), c.jet(4.0));
}

#[test]
fn joints_are_c0_only_with_one_sided_derivatives() {
    let p = vec![S2Point::X, S2Point::Y, S2Point::Z];
    let c = GeodesicSpline::try_new(p, None).unwrap();
    let (l, r) = (c.jet_at(1.0, Side::Left), c.jet_at(1.0, Side::Right));
    assert_eq!(l.point, r.point);
    let half_pi = std::f64::consts::FRAC_PI_2;
    assert_close(
        &l.velocity,
        &(DVec3::new(-1.0, 0.0, 0.0) * half_pi),
        1e-15,
        "left velocity",
    );
    assert_close(&r.velocity, &(DVec3::Z * half_pi), 1e-15, "right velocity");
}

#[test]
fn rotation_equivariance_and_reversal() {
    let mut rng = Rng::new(14);
    let p = chain(&mut rng, 5);
    let r = rng.rotation();
    let rp: Vec<S2Point> = p
        .iter()
        .map(|x| S2Point::try_new(r * x.as_dvec3()).unwrap())
        .collect();
    let reversed: Vec<S2Point> = p.iter().rev().copied().collect();
    for make in [
        |v: Vec<S2Point>| -> Box<dyn Curve<Point = S2Point>> {
            Box::new(GeodesicSpline::try_new(v, None).unwrap())
        },
        |v: Vec<S2Point>| -> Box<dyn Curve<Point = S2Point>> {
            Box::new(NlerpSpline::try_new(v, None).unwrap())
        },
    ] {
        let (c, cr, crev) = (make(p.clone()), make(rp.clone()), make(reversed.clone()));
        for t in [0.0, 0.3, 1.7, 2.5, 4.0] {
            let j = c.jet(t);
            let jr = cr.jet(t);
            assert_close(
                &(r * j.point.as_dvec3()),
                &jr.point.as_dvec3(),
                1e-14,
                "R·c(t)",
            );
            assert_close(&(r * j.velocity), &jr.velocity, 1e-13, "R·c′(t)");
            assert_close(&(r * j.acceleration), &jr.acceleration, 1e-13, "R·c″(t)");
            assert_close(
                &crev.eval(4.0 - t).as_dvec3(),
                &j.point.as_dvec3(),
                1e-14,
                "reversal",
            );
        }
    }
}

#[test]
fn degenerate_but_valid_geometry() {
    let a = S2Point::try_new(DVec3::new(1.0, 2.0, 3.0)).unwrap();
    let b = S2Point::try_new(DVec3::new(1.0, 2.0, 3.0 + 1e-9)).unwrap();
    let far = S2Point::try_new(-a.as_dvec3() + DVec3::new(0.0, 1e-9, 0.0)).unwrap();
    for pts in [vec![a, a, b], vec![a, b, a], vec![a, far, a]] {
        for c in [
            Box::new(GeodesicSpline::try_new(pts.clone(), None).unwrap())
                as Box<dyn Curve<Point = S2Point>>,
            Box::new(NlerpSpline::try_new(pts.clone(), None).unwrap()),
        ] {
            for i in 0..=200 {
                let j = c.jet(f64::from(i) / 100.0);
                assert_unit(&j.point);
                assert!(
                    j.velocity.is_finite() && j.acceleration.is_finite(),
                    "{pts:?}"
                );
            }
        }
    }
    // Identical keys: zero velocity, no NaN.
    let c = GeodesicSpline::try_new(vec![a, a], None).unwrap();
    assert_eq!(c.jet(0.5).velocity, DVec3::ZERO);
}

#[test]
fn bad_input_is_a_typed_error() {
    let x = S2Point::X;
    let minus_x = S2Point::try_new(-DVec3::X).unwrap();
    assert_eq!(
        GeodesicSpline::try_new(vec![x], None).unwrap_err(),
        SplineError::TooFewPoints { min: 2, got: 1 }
    );
    assert_eq!(
        GeodesicSpline::try_new(vec![S2Point::Y, x, minus_x], None).unwrap_err(),
        SplineError::Antipodal { index: 1 }
    );
    assert_eq!(
        NlerpSpline::try_new(vec![x, minus_x], None).unwrap_err(),
        SplineError::Antipodal { index: 0 }
    );
    assert_eq!(
        GeodesicSpline::try_new(vec![x, S2Point::Y], Some(vec![0.0])).unwrap_err(),
        SplineError::KnotCount {
            expected: 2,
            got: 1
        }
    );
    assert_eq!(
        GeodesicSpline::try_new(vec![x, S2Point::Y, x], Some(vec![0.0, 1.0, 1.0])).unwrap_err(),
        SplineError::KnotsNotIncreasing { index: 2 }
    );
    assert_eq!(
        Knots::try_new(vec![0.0, f64::NAN]).unwrap_err(),
        SplineError::InvalidKnot { index: 1 }
    );
    let e = SplineError::KnotsNotIncreasing { index: 2 };
    assert_eq!(
        e.to_string(),
        "knot 2 is not greater than knot 1: knots must be strictly increasing"
    );
}

#[test]
fn quaternion_keys_q_and_minus_q() {
    // Without canonicalisation q, −q are antipodal on S³ and rejected; after unflip they coincide.
    let q = UnitQuat::from_axis_angle(DVec3::Y, 0.7).unwrap();
    let mut keys = vec![UnitQuat::IDENTITY, q, -q];
    assert_eq!(
        GeodesicSpline::try_new(keys.clone(), None).unwrap_err(),
        SplineError::Antipodal { index: 1 }
    );
    spherekit::unflip(&mut keys);
    let c = GeodesicSpline::try_new(keys, None).unwrap();
    assert!(c.eval(1.5).dist(&q) < 1e-15);
    assert_eq!(c.jet(1.5).velocity.length(), 0.0);
}
