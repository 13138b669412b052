// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Squad (Shoemake 1987), uniform and non-uniform knots.

#![allow(clippy::unwrap_used, reason = "tests unwrap known-valid fixtures")]

use spherekit::glam::{DQuat, DVec3, DVec4};
use spherekit::{Curve, Manifold, Side, SplineError, Squad, UnitQuat, continuity, unflip};

use crate::support::*;

/// `q·v` for a pure quaternion `v`, as an ambient vector.
fn qv(q: UnitQuat, v: DVec3) -> DVec4 {
    DVec4::from(q.as_dquat() * DQuat::from_xyzw(v.x, v.y, v.z, 0.0))
}

fn keys(seed: u64, n: usize) -> Vec<UnitQuat> {
    let mut k = Rng(seed).walk_quat(n, 0.7);
    unflip(&mut k);
    k
}

const NONUNIFORM: [f64; 6] = [0.0, 0.4, 1.9, 2.3, 4.0, 4.1];

#[test]
fn interpolates_and_is_unit() {
    for knots in [None, Some(NONUNIFORM.to_vec())] {
        let k = keys(10, 6);
        let c = Squad::try_new(k.clone(), knots).unwrap();
        for (i, &t) in c.joints().iter().enumerate() {
            assert_eq!(c.eval(t), k[i], "eval at knot {i}");
            assert_eq!(c.jet_at(t, Side::Left).point, k[i], "left jet at knot {i}");
            assert_eq!(
                c.jet_at(t, Side::Right).point,
                k[i],
                "right jet at knot {i}"
            );
        }
        assert!(max_norm_error(&c, 200) < 1e-15, "unit norm");
        let [t0, t1] = c.domain();
        for k in 0..=100 {
            let t = t0 + (t1 - t0) * k as f64 / 100.0;
            assert!(c.jet(t).point.dist(&c.eval(t)) < 1e-15, "jet point = eval");
        }
    }
}

#[test]
fn c1_at_joints_with_the_central_difference_velocity() {
    for (seed, knots) in [
        (11, None),
        (12, Some(NONUNIFORM.to_vec())),
        (13, Some(NONUNIFORM.to_vec())),
    ] {
        let k = keys(seed, 6);
        let c = Squad::try_new(k.clone(), knots).unwrap();
        let u = c.joints().to_vec();
        let report = continuity(&c);
        assert_eq!(report.len(), 4, "interior joints");
        let mut max_c2: f64 = 0.0;
        for (j, r) in report.iter().enumerate() {
            let i = j + 1;
            assert!(r.c0 < 1e-15 && r.c1 < 1e-12, "joint {i}: {r:?}");
            max_c2 = max_c2.max(r.c2);
            let lp = (k[i].conjugate() * k[i + 1]).log_pure();
            let lm = (k[i].conjugate() * k[i - 1]).log_pure();
            let v = qv(k[i], (lp - lm) / (u[i + 1] - u[i - 1]));
            let got = c.jet_at(u[i], Side::Left).velocity;
            assert!(
                (got - v).length() < 1e-12,
                "joint velocity {got:?} vs {v:?}"
            );
        }
        assert!(max_c2 > 1e-3, "squad is not C2 in general ({max_c2})");
        // End velocities: q0·L⁺/h0 and −qn·L⁻/h_{n−1}.
        let n = k.len() - 1;
        let v0 = qv(k[0], (k[0].conjugate() * k[1]).log_pure() / (u[1] - u[0]));
        let vn = qv(
            k[n],
            -(k[n].conjugate() * k[n - 1]).log_pure() / (u[n] - u[n - 1]),
        );
        assert!(
            (c.jet(u[0]).velocity - v0).length() < 1e-13,
            "start velocity"
        );
        assert!((c.jet(u[n]).velocity - vn).length() < 1e-13, "end velocity");
    }
}

#[test]
fn derivatives_match_finite_differences() {
    for knots in [None, Some(NONUNIFORM.to_vec())] {
        let c = Squad::try_new(keys(14, 6), knots).unwrap();
        check_derivatives(&c, 97);
    }
    // One-sided finite differences at a joint confirm C¹ independently of the jets.
    let c = Squad::try_new(keys(15, 6), Some(NONUNIFORM.to_vec())).unwrap();
    let h = 1e-6;
    for &t in &c.joints()[1..5] {
        let p = |s: f64| c.eval(s).to_vector();
        let left = (p(t) * 3.0 - p(t - h) * 4.0 + p(t - 2.0 * h)) * (0.5 / h);
        let right = (p(t + h) * 4.0 - p(t) * 3.0 - p(t + 2.0 * h)) * (0.5 / h);
        let v = c.jet(t).velocity;
        assert!(
            (left - v).length() < 1e-6 * v.length().max(1.0),
            "left FD at {t}"
        );
        assert!(
            (right - v).length() < 1e-6 * v.length().max(1.0),
            "right FD at {t}"
        );
    }
}

/// Scalar squad of angles (the Euclidean analogue with lerps).
fn scalar_squad(alpha: &[f64], knots: &[f64], t: f64) -> f64 {
    let n = alpha.len() - 1;
    let mut sigma = alpha.to_vec();
    for i in 1..n {
        let (hm, hp) = (knots[i] - knots[i - 1], knots[i + 1] - knots[i]);
        sigma[i] = alpha[i]
            - (hm * (alpha[i + 1] - alpha[i]) + hp * (alpha[i - 1] - alpha[i])) / (2.0 * (hm + hp));
    }
    let i = (0..n).rev().find(|&i| knots[i] <= t).unwrap_or(0);
    let tau = (t - knots[i]) / (knots[i + 1] - knots[i]);
    let lerp = |a: f64, b: f64, s: f64| a + (b - a) * s;
    lerp(
        lerp(alpha[i], alpha[i + 1], tau),
        lerp(sigma[i], sigma[i + 1], tau),
        2.0 * tau * (1.0 - tau),
    )
}

#[test]
fn keys_on_one_great_circle_give_the_scalar_squad() {
    let alpha = [0.2, 0.9, 1.3, 0.7, 1.6, 2.4];
    let axis = DVec3::new(1.0, -2.0, 0.5).normalize();
    let base = UnitQuat::from_wxyz([0.4, 0.1, -0.7, 0.3]).unwrap();
    let on = |a: f64| base * UnitQuat::exp_pure(axis * a);
    for knots in [vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0], NONUNIFORM.to_vec()] {
        let c =
            Squad::try_new(alpha.iter().map(|&a| on(a)).collect(), Some(knots.clone())).unwrap();
        // Inner points: σᵢ = αᵢ − (αᵢ₋₁ − 2αᵢ + αᵢ₊₁)/4 for uniform knots.
        if knots[1] == 1.0 {
            let s2 = alpha[2] - (alpha[1] - 2.0 * alpha[2] + alpha[3]) / 4.0;
            assert!(c.controls()[2].dist(&on(s2)) < 1e-15, "inner point");
            // The tutorial's Euclidean squad weights at t = 0.4: 0.312, 0.288, 0.192, 0.208.
            let s1 = alpha[1] - (alpha[0] - 2.0 * alpha[1] + alpha[2]) / 4.0;
            let a = 0.312 * alpha[1] + 0.288 * s1 + 0.192 * s2 + 0.208 * alpha[2];
            assert!(c.eval(1.4).dist(&on(a)) < 1e-14, "weights at 0.4");
        }
        for k in 0..=100 {
            let t = knots[5] * k as f64 / 100.0;
            let a = scalar_squad(&alpha, &knots, t);
            assert!(c.eval(t).dist(&on(a)) < 1e-14, "great circle at {t}");
        }
    }
}

#[test]
fn bi_invariance_and_reversal() {
    let k = keys(16, 5);
    let knots = vec![0.0, 0.5, 2.0, 2.2, 3.0];
    let c = Squad::try_new(k.clone(), Some(knots.clone())).unwrap();
    let mut g = Rng(17);
    let (a, b) = (g.quat(), g.quat());
    let moved = Squad::try_new(
        k.iter().map(|&q| sandwich(a, q, b)).collect(),
        Some(knots.clone()),
    )
    .unwrap();
    let mut rk = k.clone();
    rk.reverse();
    let rknots: Vec<f64> = knots.iter().rev().map(|&u| 3.0 - u).collect();
    let rev = Squad::try_new(rk, Some(rknots)).unwrap();
    for i in 0..=60 {
        let t = 3.0 * i as f64 / 60.0;
        assert!(
            sandwich(a, c.eval(t), b).dist(&moved.eval(t)) < 1e-14,
            "bi-invariance"
        );
        assert!(
            c.eval(t).dist(&rev.eval(3.0 - t)) < 1e-14,
            "reversal at {t}"
        );
    }
}

#[test]
fn degenerate_but_valid_keys() {
    let q = UnitQuat::from_wxyz([0.3, -0.5, 0.2, 0.8]).unwrap();
    let near = UnitQuat::from_wxyz([0.3 + 1e-9, -0.5, 0.2, 0.8]).unwrap();
    let far = UnitQuat::from_wxyz([0.9, 0.1, 0.3, -0.2]).unwrap();
    // Nearly a half turn on S³ (not canonicalised): |q + q'| = 1e-8.
    let anti = UnitQuat::from_wxyz([-0.3, 0.5 + 1e-8, -0.2, -0.8]).unwrap();
    for k in [
        vec![q, q, q],
        vec![q, near, far, far],
        vec![q, far, near, q],
        vec![far, q, anti, far],
    ] {
        let c = Squad::try_new(k, None).unwrap();
        let [t0, t1] = c.domain();
        for i in 0..=50 {
            let j = c.jet(t0 + (t1 - t0) * i as f64 / 50.0);
            assert!(
                j.velocity.is_finite() && j.acceleration.is_finite(),
                "finite"
            );
            assert!((j.point.to_vector().length() - 1.0).abs() < 1e-14, "unit");
        }
    }
    let c = Squad::try_new(vec![q, q, q], None).unwrap();
    assert!(c.jet(0.7).velocity.length() < 1e-15, "equal keys: at rest");
}

#[test]
fn errors() {
    let q = UnitQuat::IDENTITY;
    let e = Squad::try_new(vec![q], None).unwrap_err();
    assert_eq!(e, SplineError::TooFewPoints { min: 2, got: 1 });
    assert!(e.to_string().contains("at least 2"), "{e}");
    let r = UnitQuat::from_wxyz([0.0, 1.0, 0.0, 0.0]).unwrap();
    assert_eq!(
        Squad::try_new(vec![q, r, -r], None).unwrap_err(),
        SplineError::Antipodal { index: 1 }
    );
    assert_eq!(
        Squad::try_new(vec![q, r], Some(vec![0.0])).unwrap_err(),
        SplineError::KnotCount {
            expected: 2,
            got: 1
        }
    );
    assert!(
        Squad::try_new(vec![q, r], Some(vec![1.0, 1.0])).is_err(),
        "knots"
    );
}
