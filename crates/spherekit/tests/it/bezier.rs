// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Spherical Bézier curves by de Casteljau (Shoemake 1985) and the differentiated slerp.

#![allow(clippy::unwrap_used, reason = "tests unwrap known-valid fixtures")]

use spherekit::glam::DVec3;
use spherekit::{
    Ambient, Bezier, Curve, GeodesicSpline, Jet, Manifold, S2Point, ScalarJet, SmPoint,
    SplineError, UnitQuat, cubic_jet, de_casteljau, de_casteljau_jet, slerp_jet,
};

use crate::support::*;

fn check_basic<P: Manifold>(ctrl: Vec<P>) {
    let n = ctrl.len() - 1;
    let c = Bezier::try_new(ctrl.clone()).unwrap();
    assert_eq!(c.degree(), n, "degree");
    assert_eq!(c.eval(0.0), ctrl[0], "start");
    assert_eq!(c.eval(1.0), ctrl[n], "end");
    assert_eq!(c.jet(0.0).point, ctrl[0], "jet start");
    assert_eq!(c.jet(1.0).point, ctrl[n], "jet end");
    assert!(max_norm_error(&c, 50) < 1e-15, "unit norm");
    // End tangents: n·log_{p0}(p1) and −n·log_{pn}(pn−1).
    let v0 = c.jet(0.0).velocity;
    let v1 = c.jet(1.0).velocity;
    let e0 = (v0 - ctrl[0].log(&ctrl[1]) * n as f64).length();
    let e1 = (v1 + ctrl[n].log(&ctrl[n - 1]) * n as f64).length();
    assert!(e0 < 1e-13 && e1 < 1e-13, "end tangents {e0:e} {e1:e}");
    // Point of the jet = eval.
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        assert!(
            c.jet(t).point.dist(&c.eval(t)) < 1e-15,
            "jet point vs eval at {t}"
        );
    }
    check_derivatives(&c, 13);
    // Reversal symmetry.
    let mut rev = ctrl.clone();
    rev.reverse();
    let r = Bezier::try_new(rev).unwrap();
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        assert!(c.eval(t).dist(&r.eval(1.0 - t)) < 1e-14, "reversal at {t}");
        let (a, b) = (c.jet(t), r.jet(1.0 - t));
        assert!(
            (a.velocity + b.velocity).length() < 1e-12,
            "reversed velocity"
        );
        assert!(
            (a.acceleration - b.acceleration).length() < 1e-11,
            "reversed acceleration"
        );
    }
}

#[test]
fn s2_all_degrees() {
    let mut g = Rng(1);
    for n in 1..=6 {
        check_basic(g.walk_s2(n + 1, 0.7));
    }
}

#[test]
fn s3_all_degrees() {
    let mut g = Rng(2);
    for n in 1..=5 {
        check_basic(g.walk_quat(n + 1, 0.6));
    }
}

#[test]
fn sn_all_degrees() {
    let mut g = Rng(3);
    for (n, m) in [(1, 1), (2, 4), (3, 5), (4, 7)] {
        check_basic(g.walk_sm(n + 1, m, 0.7));
    }
}

#[test]
fn degree_one_is_the_geodesic() {
    let mut g = Rng(4);
    for _ in 0..5 {
        let p = g.walk_s2(2, 1.5);
        let b = Bezier::try_new(p.clone()).unwrap();
        let s = GeodesicSpline::try_new(p, None).unwrap();
        for k in 0..=20 {
            let t = k as f64 / 20.0;
            let (x, y) = (b.jet(t), s.jet(t));
            assert!(x.point.dist(&y.point) < 1e-15, "point");
            assert!((x.velocity - y.velocity).length() < 1e-14, "velocity");
            assert!(
                (x.acceleration - y.acceleration).length() < 1e-14,
                "acceleration"
            );
        }
    }
}

#[test]
fn great_circle_reduces_to_the_euclidean_bezier_of_angles() {
    let alpha = [0.1, 1.2, 0.4, 2.0, 2.5];
    let on_circle = |a: f64| S2Point::try_new(DVec3::new(a.cos(), a.sin(), 0.0)).unwrap();
    let c = Bezier::try_new(alpha.iter().map(|&a| on_circle(a)).collect()).unwrap();
    let binom = [1.0, 4.0, 6.0, 4.0, 1.0];
    for k in 0..=20 {
        let t = k as f64 / 20.0;
        let a: f64 = (0..=4_i32)
            .zip(binom.iter().zip(&alpha))
            .map(|(i, (b, a))| b * (1.0 - t).powi(4 - i) * t.powi(i) * a)
            .sum();
        assert!(c.eval(t).dist(&on_circle(a)) < 1e-14, "angle at {t}");
    }
}

#[test]
fn rotation_equivariance() {
    let mut g = Rng(5);
    // S²: rotations.
    let ctrl = g.walk_s2(4, 0.8);
    let rot = g.quat();
    let c = Bezier::try_new(ctrl.clone()).unwrap();
    let rc = Bezier::try_new(
        ctrl.iter()
            .map(|p| S2Point::try_new(rot.rotate(p.as_dvec3())).unwrap())
            .collect(),
    )
    .unwrap();
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        let (a, b) = (c.jet(t), rc.jet(t));
        assert!(
            (rot.rotate(a.point.as_dvec3()) - b.point.as_dvec3()).length() < 1e-14,
            "S2 point"
        );
        assert!(
            (rot.rotate(a.velocity) - b.velocity).length() < 1e-13,
            "S2 velocity"
        );
        assert!(
            (rot.rotate(a.acceleration) - b.acceleration).length() < 1e-12,
            "S2 accel"
        );
    }
    // S³: bi-invariance q ↦ a·q·b.
    let ctrl = g.walk_quat(4, 0.7);
    let (l, r) = (g.quat(), g.quat());
    let c = Bezier::try_new(ctrl.clone()).unwrap();
    let rc = Bezier::try_new(ctrl.iter().map(|&q| sandwich(l, q, r)).collect()).unwrap();
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        assert!(
            sandwich(l, c.eval(t), r).dist(&rc.eval(t)) < 1e-14,
            "S3 bi-invariance"
        );
    }
    // S^m: a reflection (orientation reversing).
    let ctrl = g.walk_sm(4, 5, 0.7);
    let nrm = g.vec(6);
    let c = Bezier::try_new(ctrl.clone()).unwrap();
    let rc = Bezier::try_new(ctrl.iter().map(|p| reflect(&nrm, p)).collect()).unwrap();
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        assert!(
            reflect(&nrm, &c.eval(t)).dist(&rc.eval(t)) < 1e-14,
            "S^m reflection"
        );
    }
}

#[test]
fn cubic_helpers_agree() {
    let mut g = Rng(6);
    let p = g.walk_quat(4, 0.9);
    let c = Bezier::try_new(p.clone()).unwrap();
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        let a = c.jet(t);
        let b = cubic_jet([&p[0], &p[1], &p[2], &p[3]], ScalarJet::param(t, 1.0));
        let d = de_casteljau_jet(&p, ScalarJet::param(t, 1.0));
        assert_eq!(a, d, "generic jet");
        assert!(a.point.dist(&b.point) < 1e-16, "cubic point");
        assert!((a.velocity - b.velocity).length() < 1e-15, "cubic velocity");
        assert!(
            (a.acceleration - b.acceleration).length() < 1e-14,
            "cubic accel"
        );
        assert!(de_casteljau(&p, t).dist(&a.point) < 1e-15, "point form");
        // Reparametrised: u = 2t − 1 on a segment of width 1/2 doubles the velocity.
        let r = cubic_jet([&p[0], &p[1], &p[2], &p[3]], ScalarJet::param(t, 2.0));
        assert!(
            (r.velocity - a.velocity * 2.0).length() < 1e-13,
            "rate 2 velocity"
        );
        assert!(
            (r.acceleration - a.acceleration * 4.0).length() < 1e-12,
            "rate 2 accel"
        );
    }
}

#[test]
fn coincident_and_close_control_points() {
    // All equal: a point at rest.
    let q = UnitQuat::from_wxyz([0.3, -0.5, 0.2, 0.8]).unwrap();
    let c = Bezier::try_new(vec![q; 4]).unwrap();
    for k in 0..=10 {
        let j = c.jet(k as f64 / 10.0);
        assert!(j.point.dist(&q) < 1e-15, "rest point");
        assert!(
            j.velocity.length() < 1e-15 && j.acceleration.length() < 1e-15,
            "rest"
        );
    }
    // Partly equal and 1e-9 apart: finite, unit, derivatives match finite differences.
    let x = S2Point::X;
    let near = S2Point::try_new(DVec3::new(1.0, 1e-9, 0.0)).unwrap();
    let near2 = S2Point::try_new(DVec3::new(1.0, 0.0, 1e-9)).unwrap();
    for ctrl in [
        vec![x, x, S2Point::Y],
        vec![x, near, S2Point::Z, S2Point::Z],
        vec![x, near, near2],
    ] {
        let c = Bezier::try_new(ctrl).unwrap();
        for k in 0..=20 {
            let j = c.jet(k as f64 / 20.0);
            assert!(
                j.velocity.is_finite() && j.acceleration.is_finite(),
                "finite"
            );
            assert!((j.point.as_dvec3().length() - 1.0).abs() < 1e-15, "unit");
        }
        check_derivatives(&c, 9);
    }
}

#[test]
fn near_antipodal_control_points_are_finite() {
    // |p + q| = 1e-8: valid, nearly a half turn.
    let p = S2Point::X;
    let q = S2Point::try_new(DVec3::new(-1.0, 1e-8, 0.0)).unwrap();
    let c = Bezier::try_new(vec![p, q, S2Point::Z]).unwrap();
    for k in 0..=20 {
        let j = c.jet(k as f64 / 20.0);
        assert!(
            j.point.as_dvec3().is_finite() && j.velocity.is_finite(),
            "finite"
        );
        assert!(j.acceleration.is_finite(), "finite acceleration");
        assert!((j.point.as_dvec3().length() - 1.0).abs() < 1e-14, "unit");
    }
}

#[test]
fn errors() {
    let e = Bezier::<S2Point>::try_new(vec![S2Point::X]).unwrap_err();
    assert_eq!(e, SplineError::TooFewPoints { min: 2, got: 1 });
    assert!(e.to_string().contains("at least 2"), "{e}");
    assert!(Bezier::<S2Point>::try_new(vec![]).is_err(), "empty");
    let anti = S2Point::try_new(-DVec3::Y).unwrap();
    assert_eq!(
        Bezier::try_new(vec![S2Point::X, S2Point::Y, anti]).unwrap_err(),
        SplineError::Antipodal { index: 1 }
    );
    let q = UnitQuat::from_wxyz([0.5, 0.5, 0.5, 0.5]).unwrap();
    assert_eq!(
        Bezier::try_new(vec![q, -q]).unwrap_err(),
        SplineError::Antipodal { index: 0 }
    );
    let p = SmPoint::try_new(vec![1.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
    let mp = SmPoint::try_new(vec![-1.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
    assert!(Bezier::try_new(vec![p, mp]).is_err(), "S^m antipodal");
}

#[test]
fn slerp_jet_with_moving_coincident_endpoints() {
    // a(t) = b(t) + O(t) crossing at t = 0: G is smooth, the jet must be finite and exact.
    let a = Jet {
        point: S2Point::X,
        velocity: DVec3::Y,
        acceleration: -DVec3::X,
    };
    let b = Jet {
        point: S2Point::X,
        velocity: DVec3::Z * 2.0,
        acceleration: -DVec3::X * 4.0,
    };
    let j = slerp_jet(&a, &b, ScalarJet::constant(0.25)).unwrap();
    // At coincidence, G ≈ (1 − u)a + u b to first order: velocity (0.75·y + 0.5·z).
    assert!(
        (j.velocity - DVec3::new(0.0, 0.75, 0.5)).length() < 1e-15,
        "{:?}",
        j.velocity
    );
    assert!(j.acceleration.is_finite(), "finite acceleration");
    // Compare with the exact curves a(t) = (cos t, sin t, 0), b(t) = (cos 2t, 0, sin 2t).
    let g = |t: f64| {
        let pa = S2Point::try_new(DVec3::new(t.cos(), t.sin(), 0.0)).unwrap();
        let pb = S2Point::try_new(DVec3::new((2.0 * t).cos(), 0.0, (2.0 * t).sin())).unwrap();
        pa.slerp(&pb, 0.25).as_dvec3()
    };
    let h = 1e-4;
    let dd = (g(h) - 2.0 * g(0.0) + g(-h)) / (h * h);
    assert!(
        (j.acceleration - dd).length() < 1e-6,
        "{:?} vs {dd:?}",
        j.acceleration
    );
}
