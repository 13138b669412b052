// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Kim–Kim–Shin cumulative-form Bézier and B-spline quaternion curves.

#![allow(clippy::unwrap_used, reason = "tests: a panic is the failure report")]

use spherekit::glam::{DQuat, DVec3, DVec4};
use spherekit::{
    BezierKim, BsplineKim, Curve, Manifold, Side, SplineError, UnitQuat,
    angular_velocity_acceleration,
};

use crate::support::Rng;

fn v4(q: UnitQuat) -> DVec4 {
    q.to_vector()
}

/// Central differences of points and velocities against the exact derivatives.
fn check_derivatives<C: Curve<Point = UnitQuat>>(c: &C, ts: &[f64]) {
    let h = 1e-5;
    for &t in ts {
        let j = c.jet(t);
        let fd1 = (v4(c.eval(t + h)) - v4(c.eval(t - h))) / (2.0 * h);
        let fd2 = (c.jet(t + h).velocity - c.jet(t - h).velocity) / (2.0 * h);
        let e1 = (fd1 - j.velocity).length() / j.velocity.length().max(1.0);
        let e2 = (fd2 - j.acceleration).length() / j.acceleration.length().max(1.0);
        assert!(e1 < 1e-6, "d1 at t={t}: relative error {e1}");
        assert!(e2 < 1e-6, "d2 at t={t}: relative error {e2}");
        // Tangency and unit norm.
        assert!((v4(j.point).length() - 1.0).abs() < 1e-15, "norm at {t}");
        assert!(v4(j.point).dot(j.velocity).abs() < 1e-13, "tangency at {t}");
        // The normal part of the acceleration is −|q′|².
        let n = v4(j.point).dot(j.acceleration) + j.velocity.length_squared();
        assert!(
            n.abs() < 1e-12 * j.velocity.length_squared().max(1.0),
            "normal part at {t}"
        );
    }
}

/// De Casteljau spherical Bézier by repeated slerp (Shoemake 1985).
fn de_casteljau(ctrl: &[UnitQuat], t: f64) -> UnitQuat {
    let mut p = ctrl.to_vec();
    while p.len() > 1 {
        p = p.windows(2).map(|w| w[0].slerp(&w[1], t)).collect();
    }
    p[0]
}

fn pw(x: f64, k: usize) -> f64 {
    (0..k).fold(1.0, |a, _| a * x)
}

fn params(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..=n).map(|k| a + (b - a) * k as f64 / n as f64).collect()
}

#[test]
fn bezier_interpolates_ends_with_end_derivatives() {
    let mut rng = Rng(0x1234_5678);
    for n in 1..=6 {
        let q = rng.chain(n + 1, 1.2);
        let c = BezierKim::try_new(q.clone()).unwrap();
        assert_eq!(c.degree(), n);
        assert_eq!(c.eval(0.0), q[0]);
        assert_eq!(c.eval(1.0), q[n]);
        // The product itself telescopes to qₙ (not only the exact endpoint return).
        assert!(c.eval(1.0 - 1e-15).dist(&q[n]) < 1e-14, "n={n}");
        let w1 = c.omegas()[0];
        let wn = c.omegas()[n - 1];
        let nf = n as f64;
        let d0 = v4(q[0] * UnitQuat::exp_pure(w1 * 1e-8)) - v4(q[0]);
        let v0 = c.jet(0.0).velocity;
        assert!(
            (v0 - d0 * (nf / 1e-8)).length() < 1e-6 * v0.length(),
            "q'(0) n={n}"
        );
        let v1 = c.jet(1.0).velocity;
        let d1 = v4(q[n]) - v4(q[n] * UnitQuat::exp_pure(-wn * 1e-8));
        assert!(
            (v1 - d1 * (nf / 1e-8)).length() < 1e-6 * v1.length(),
            "q'(1) n={n}"
        );
    }
}

#[test]
fn bezier_derivatives_match_finite_differences() {
    let mut rng = Rng(99);
    for n in [1, 2, 3, 4, 5, 7, 17, 20] {
        let q = rng.chain(n + 1, 1.5);
        let c = BezierKim::try_new(q).unwrap();
        check_derivatives(&c, &params(0.01, 0.99, 13));
    }
}

#[test]
fn bezier_degree_one_is_slerp() {
    let mut rng = Rng(7);
    let q = rng.chain(2, 2.5);
    let c = BezierKim::try_new(q.clone()).unwrap();
    for t in params(0.0, 1.0, 10) {
        assert!(c.eval(t).dist(&q[0].slerp(&q[1], t)) < 1e-15, "t={t}");
    }
}

#[test]
fn bezier_equals_de_casteljau_on_a_great_circle() {
    let mut rng = Rng(42);
    for n in [2, 3, 5] {
        let q0 = rng.quat();
        let axis = DVec3::new(0.3, -0.8, 0.5).normalize();
        let mut alpha = vec![rng.range(-1.0, 1.0)];
        for _ in 0..n {
            let a = *alpha.last().unwrap() + rng.range(-2.5, 2.5);
            alpha.push(a);
        }
        let ctrl: Vec<UnitQuat> = alpha
            .iter()
            .map(|&a| q0 * UnitQuat::exp_pure(axis * a))
            .collect();
        let c = BezierKim::try_new(ctrl.clone()).unwrap();
        for t in params(0.0, 1.0, 20) {
            let k = c.eval(t);
            assert!(k.dist(&de_casteljau(&ctrl, t)) < 1e-14, "n={n} t={t}");
            // Both are q₀·exp((Σ Bᵢ αᵢ)·v).
            let s: f64 = (0..=n)
                .map(|i| {
                    let b = (0..i).fold(1.0, |c, j| c * (n - j) as f64 / (j + 1) as f64);
                    b * pw(1.0 - t, n - i) * pw(t, i) * alpha[i]
                })
                .sum();
            assert!(
                k.dist(&(q0 * UnitQuat::exp_pure(axis * s))) < 1e-14,
                "n={n} t={t}"
            );
        }
    }
}

#[test]
fn bezier_differs_from_de_casteljau_in_general() {
    let mut rng = Rng(5);
    let q = rng.chain(4, 1.5);
    let c = BezierKim::try_new(q.clone()).unwrap();
    let gap = params(0.0, 1.0, 20)
        .into_iter()
        .map(|t| c.eval(t).dist(&de_casteljau(&q, t)))
        .fold(0.0, f64::max);
    assert!(gap > 1e-3, "the curves should differ, gap {gap}");
    // ... but share the end first derivatives.
    assert!(c.eval(0.0).dist(&de_casteljau(&q, 0.0)) < 1e-15, "start");
}

#[test]
fn bezier_is_bi_invariant() {
    let mut rng = Rng(11);
    let q = rng.chain(5, 1.3);
    let (a, b) = (rng.quat(), rng.quat());
    let c = BezierKim::try_new(q.clone()).unwrap();
    let left = BezierKim::try_new(q.iter().map(|&x| a * x).collect()).unwrap();
    let both = BezierKim::try_new(q.iter().map(|&x| (a * x) * b).collect()).unwrap();
    for t in params(0.0, 1.0, 17) {
        let j = c.jet(t);
        let jl = left.jet(t);
        assert!(jl.point.dist(&(a * j.point)) < 1e-14, "left at {t}");
        // Velocity and acceleration transform by the same left multiplication.
        let av = lmul(a, j.velocity);
        assert!((jl.velocity - av).length() < 1e-13, "left velocity at {t}");
        let aa = lmul(a, j.acceleration);
        assert!((jl.acceleration - aa).length() < 1e-12, "left accel at {t}");
        assert!(both.eval(t).dist(&(a * j.point * b)) < 1e-14, "both at {t}");
    }
}

/// The quaternion product `a · v` for an ambient quaternion vector `v`.
fn lmul(a: UnitQuat, v: DVec4) -> DVec4 {
    DVec4::from(a.as_dquat() * DQuat::from_vec4(v))
}

#[test]
fn bezier_near_identical_controls_are_finite() {
    let q0 = UnitQuat::from_wxyz([0.3, 0.5, -0.2, 0.7]).unwrap();
    let tiny = DVec3::new(1e-9, -2e-9, 5e-10);
    let q1 = q0 * UnitQuat::exp_pure(tiny);
    let q2 = q1;
    let q3 = q1 * UnitQuat::exp_pure(DVec3::new(0.0, 0.0, 1e-12));
    let c = BezierKim::try_new(vec![q0, q1, q2, q3]).unwrap();
    for t in params(0.0, 1.0, 10) {
        let j = c.jet(t);
        assert!(
            j.velocity.is_finite() && j.acceleration.is_finite(),
            "t={t}"
        );
        assert!((v4(j.point).length() - 1.0).abs() < 1e-15, "t={t}");
        assert!(j.point.dist(&q0) < 1e-8, "t={t}");
    }
    // Angular velocity: 2·n·ω₁ rotated to the space frame at t = 0.
    let j = c.jet(0.0);
    let (w, a) = angular_velocity_acceleration(j.point, j.velocity, j.acceleration);
    assert!((w - q0.rotate(6.0 * tiny)).length() < 1e-15, "{w:?}");
    assert!(a.is_finite(), "alpha");
}

#[test]
fn bezier_near_antipodal_is_finite_and_antipodal_is_an_error() {
    let q0 = UnitQuat::from_wxyz([0.3, 0.5, -0.2, 0.7]).unwrap();
    let near = -q0 * UnitQuat::exp_pure(DVec3::new(1e-7, 0.0, 0.0));
    let c = BezierKim::try_new(vec![q0, near, q0]).unwrap();
    for t in params(0.0, 1.0, 10) {
        let j = c.jet(t);
        assert!(
            j.velocity.is_finite() && j.acceleration.is_finite(),
            "t={t}"
        );
    }
    assert_eq!(
        BezierKim::try_new(vec![q0, q0, -q0]).unwrap_err(),
        SplineError::Antipodal { index: 1 }
    );
    assert_eq!(
        BezierKim::try_new(vec![q0]).unwrap_err(),
        SplineError::TooFewPoints { min: 2, got: 1 }
    );
}

#[test]
fn bezier_clamps_outside_the_domain() {
    let mut rng = Rng(3);
    let c = BezierKim::try_new(rng.chain(4, 1.0)).unwrap();
    assert_eq!(c.eval(-1.0), c.eval(0.0));
    assert_eq!(c.eval(2.0), c.eval(1.0));
    assert_eq!(c.joints(), &[0.0, 1.0]);
}

#[test]
fn bspline_is_c2_at_joints() {
    let mut rng = Rng(77);
    let q = rng.chain(9, 2.0);
    let c = BsplineKim::try_new(q).unwrap();
    assert_eq!(c.domain(), [0.0, 6.0]);
    assert_eq!(c.joints().len(), 7);
    for &u in &c.joints()[1..6] {
        let (l, r) = (c.jet_at(u, Side::Left), c.jet_at(u, Side::Right));
        assert!(l.point.dist(&r.point) < 1e-15, "C0 at {u}");
        assert!((l.velocity - r.velocity).length() < 1e-14, "C1 at {u}");
        assert!(
            (l.acceleration - r.acceleration).length() < 1e-13,
            "C2 at {u}"
        );
    }
}

#[test]
fn bspline_derivatives_match_finite_differences() {
    let mut rng = Rng(2024);
    let c = BsplineKim::try_new(rng.chain(7, 2.0)).unwrap();
    check_derivatives(&c, &params(0.01, 3.99, 29));
}

#[test]
fn bspline_on_one_axis_is_the_scalar_bspline() {
    let axis = DVec3::new(1.0, 2.0, -1.0).normalize();
    let alpha = [0.1, -0.4, 0.9, 1.7, 1.2, 2.5];
    let q: Vec<UnitQuat> = alpha
        .iter()
        .map(|&a| UnitQuat::exp_pure(axis * a))
        .collect();
    let c = BsplineKim::try_new(q).unwrap();
    for t in params(0.0, 3.0, 30) {
        let i = [1.0, 2.0].iter().filter(|&&k| t >= k).count();
        let s = t - i as f64;
        let b = [
            (1.0 - s).powi(3) / 6.0,
            (3.0 * s.powi(3) - 6.0 * s * s + 4.0) / 6.0,
            (-3.0 * s.powi(3) + 3.0 * s * s + 3.0 * s + 1.0) / 6.0,
            s.powi(3) / 6.0,
        ];
        let a: f64 = (0..4).map(|k| b[k] * alpha[i + k]).sum();
        assert!(
            c.eval(t).dist(&UnitQuat::exp_pure(axis * a)) < 1e-14,
            "t={t}"
        );
    }
}

#[test]
fn bspline_is_left_invariant_and_validates() {
    let mut rng = Rng(8);
    let q = rng.chain(6, 1.0);
    let r = rng.quat();
    let c = BsplineKim::try_new(q.clone()).unwrap();
    let rc = BsplineKim::try_new(q.iter().map(|&x| r * x).collect()).unwrap();
    for t in params(0.0, 3.0, 19) {
        assert!(rc.eval(t).dist(&(r * c.eval(t))) < 1e-14, "t={t}");
    }
    assert_eq!(
        BsplineKim::try_new(q[..3].to_vec()).unwrap_err(),
        SplineError::TooFewPoints { min: 4, got: 3 }
    );
    let mut bad = q;
    bad[3] = -bad[2];
    assert_eq!(
        BsplineKim::try_new(bad).unwrap_err(),
        SplineError::Antipodal { index: 2 }
    );
}

#[test]
fn angular_velocity_of_a_one_axis_bezier() {
    // Rotation about z by angle 2α(t) with α(t) = Σ Bᵢ αᵢ: ω = 2α′(t)·z, α_acc = 2α″(t)·z.
    let alpha = [0.0, 0.3, 0.5, 1.1];
    let q: Vec<UnitQuat> = alpha
        .iter()
        .map(|&a| UnitQuat::exp_pure(DVec3::Z * a))
        .collect();
    let c = BezierKim::try_new(q).unwrap();
    for t in params(0.0, 1.0, 8) {
        let u = 1.0 - t;
        let d1 = 3.0
            * (u * u * (alpha[1] - alpha[0])
                + 2.0 * u * t * (alpha[2] - alpha[1])
                + t * t * (alpha[3] - alpha[2]));
        let d2 = 6.0
            * (u * (alpha[2] - 2.0 * alpha[1] + alpha[0])
                + t * (alpha[3] - 2.0 * alpha[2] + alpha[1]));
        let j = c.jet(t);
        let (w, a) = angular_velocity_acceleration(j.point, j.velocity, j.acceleration);
        assert!((w - 2.0 * d1 * DVec3::Z).length() < 1e-14, "omega at {t}");
        assert!((a - 2.0 * d2 * DVec3::Z).length() < 1e-13, "alpha at {t}");
    }
}
