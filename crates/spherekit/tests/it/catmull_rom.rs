// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Catmull-Rom splines (Gortler 2012, §9.2–9.3): the intrinsic rule on any sphere and the textbook
//! quaternion rule on S³, uniform and non-uniform knots.

#![allow(clippy::unwrap_used, reason = "tests unwrap known-valid fixtures")]

use spherekit::glam::{DQuat, DVec3, DVec4};
use spherekit::{
    Ambient, CatmullRom, Curve, Manifold, S2Point, Side, SplineError, UnitQuat, continuity, unflip,
};

use crate::support::*;

fn qv(q: UnitQuat, v: DVec3) -> DVec4 {
    DVec4::from(DQuat::from_xyzw(v.x, v.y, v.z, 0.0) * q.as_dquat())
}

const NONUNIFORM: [f64; 6] = [0.0, 0.4, 1.9, 2.3, 4.0, 4.1];

/// Extended knots t₋₁ … tₙ₊₁ (end intervals mirrored).
fn ext(knots: &[f64]) -> Vec<f64> {
    let n = knots.len() - 1;
    let mut e = vec![knots[0] - (knots[1] - knots[0])];
    e.extend_from_slice(knots);
    e.push(knots[n] + knots[n] - knots[n - 1]);
    e
}

/// Interpolation, unit norm, C¹ with the given joint/end velocities, not C², FD derivatives.
fn check<P: Manifold>(c: &CatmullRom<P>, tangent: impl Fn(usize) -> P::Vector) {
    let pts = c.points().to_vec();
    let u = c.joints().to_vec();
    let n = u.len() - 1;
    assert_eq!(c.controls().len(), 3 * n + 1, "controls");
    for i in 0..=n {
        assert_eq!(c.eval(u[i]), pts[i + 1], "interpolation at {i}");
        assert_eq!(c.controls()[3 * i], pts[i + 1], "controls[3i] = c_i");
        for side in [Side::Left, Side::Right] {
            let j = c.jet_at(u[i], side);
            assert_eq!(j.point, pts[i + 1], "jet point at {i}");
            let e = (j.velocity.clone() - tangent(i)).length();
            assert!(e < 1e-12, "velocity at knot {i} ({side:?}): {e:e}");
        }
    }
    assert!(max_norm_error(c, 200) < 1e-15, "unit");
    let report = continuity(c);
    assert_eq!(report.len(), n - 1, "interior joints");
    assert!(
        report.iter().all(|r| r.c0 < 1e-15 && r.c1 < 1e-12),
        "C1: {report:?}"
    );
    if n > 2 {
        assert!(
            report.iter().any(|r| r.c2 > 1e-3),
            "not C2 in general: {report:?}"
        );
    }
    check_derivatives(c, 97);
}

#[test]
fn s2_intrinsic_rule() {
    for (seed, knots) in [(20, None), (21, Some(NONUNIFORM.to_vec()))] {
        let pts = Rng(seed).walk_s2(8, 0.6);
        let c = CatmullRom::try_new(pts.clone(), knots).unwrap();
        let e = ext(c.joints());
        check(&c, |i| {
            let p = &pts[i + 1];
            (p.log(&pts[i + 2]) - p.log(&pts[i])) / (e[i + 2] - e[i])
        });
    }
}

#[test]
fn sn_intrinsic_rule() {
    for (seed, knots) in [(22, None), (23, Some(NONUNIFORM.to_vec()))] {
        let pts = Rng(seed).walk_sm(8, 5, 0.6);
        let c = CatmullRom::try_new(pts.clone(), knots).unwrap();
        let e = ext(c.joints());
        check(&c, |i| {
            let p = &pts[i + 1];
            (p.log(&pts[i + 2]) - p.log(&pts[i])) * (1.0 / (e[i + 2] - e[i]))
        });
    }
}

#[test]
fn s3_textbook_rule() {
    // Canonicalised and raw keys; the raw walk has steps large enough to trigger the
    // short-path rule on X_i = c_{i+1}·c_{i−1}⁻¹.
    for (seed, knots, canon) in [
        (24, None, true),
        (25, Some(NONUNIFORM.to_vec()), true),
        (26, None, false),
        (27, Some(NONUNIFORM.to_vec()), false),
    ] {
        let mut pts = Rng(seed).walk_quat(8, 0.9);
        if canon {
            unflip(&mut pts);
        }
        let c = CatmullRom::try_new_quaternion(pts.clone(), knots).unwrap();
        let e = ext(c.joints());
        check(&c, |i| {
            let mut x = pts[i + 2] * pts[i].conjugate();
            if x.scalar() < 0.0 {
                x = -x;
            }
            qv(pts[i + 1], x.log_pure() / (e[i + 2] - e[i]))
        });
        // Uniform knots: dᵢ = Xᵢ^(1/6)·cᵢ and eᵢ = Xᵢ₊₁^(−1/6)·cᵢ₊₁ exactly as in the book.
        if c.joints()[1] == 1.0 {
            for i in 0..5 {
                let x = |j: usize| {
                    let x = pts[j + 2] * pts[j].conjugate();
                    if x.scalar() < 0.0 { -x } else { x }
                };
                let d = x(i).powf(1.0 / 6.0) * pts[i + 1];
                let e = x(i + 1).powf(-1.0 / 6.0) * pts[i + 2];
                assert!(c.controls()[3 * i + 1].dist(&d) < 1e-15, "d_{i}");
                assert!(c.controls()[3 * i + 2].dist(&e) < 1e-15, "e_{i}");
            }
        }
    }
}

/// Scalar (Euclidean) Catmull-Rom of values `c₋₁ … cₙ₊₁` with the same knot rule.
fn scalar_cr(v: &[f64], knots: &[f64], t: f64) -> f64 {
    let e = ext(knots);
    let n = knots.len() - 1;
    let m = |k: usize| (v[k + 2] - v[k]) / (e[k + 2] - e[k]);
    let i = (0..n).rev().find(|&i| knots[i] <= t).unwrap_or(0);
    let h = knots[i + 1] - knots[i];
    let s = (t - knots[i]) / h;
    let b = [
        v[i + 1],
        v[i + 1] + h * m(i) / 3.0,
        v[i + 2] - h * m(i + 1) / 3.0,
        v[i + 2],
    ];
    let w = [
        (1.0 - s).powi(3),
        3.0 * s * (1.0 - s).powi(2),
        3.0 * s * s * (1.0 - s),
        s.powi(3),
    ];
    (0..4).map(|k| w[k] * b[k]).sum()
}

#[test]
fn great_circle_reduces_to_the_scalar_spline() {
    let alpha = [-0.3, 0.1, 0.5, 0.6, 1.2, 1.5, 1.4, 2.0];
    let axis = DVec3::new(0.3, -1.0, 0.5).normalize();
    let base = UnitQuat::from_wxyz([0.4, 0.1, -0.7, 0.3]).unwrap();
    let on = |a: f64| base * UnitQuat::exp_pure(axis * a);
    let s2 = |a: f64| S2Point::try_new(DVec3::new(a.cos(), 0.0, a.sin())).unwrap();
    for knots in [vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0], NONUNIFORM.to_vec()] {
        let keys: Vec<UnitQuat> = alpha.iter().map(|&a| on(a)).collect();
        let q = CatmullRom::try_new_quaternion(keys.clone(), Some(knots.clone())).unwrap();
        let g = CatmullRom::try_new(keys, Some(knots.clone())).unwrap();
        let c2 = CatmullRom::try_new(alpha.iter().map(|&a| s2(a)).collect(), Some(knots.clone()))
            .unwrap();
        for k in 0..=100 {
            let t = knots[5] * k as f64 / 100.0;
            let a = scalar_cr(&alpha, &knots, t);
            assert!(q.eval(t).dist(&on(a)) < 1e-14, "quaternion rule at {t}");
            assert!(
                g.eval(t).dist(&on(a)) < 1e-14,
                "intrinsic rule on S3 at {t}"
            );
            assert!(c2.eval(t).dist(&s2(a)) < 1e-14, "S2 at {t}");
        }
    }
    // The textbook's weights at τ = 0.3: 0.343, 0.441, 0.189, 0.027 of (c₀, d₀, e₀, c₁).
    let q = CatmullRom::try_new_quaternion(alpha.iter().map(|&a| on(a)).collect(), None).unwrap();
    let b = [
        alpha[1],
        alpha[1] + (alpha[2] - alpha[0]) / 6.0,
        alpha[2] - (alpha[3] - alpha[1]) / 6.0,
        alpha[2],
    ];
    let a = 0.343 * b[0] + 0.441 * b[1] + 0.189 * b[2] + 0.027 * b[3];
    assert!(q.eval(0.3).dist(&on(a)) < 1e-15, "Fig. 9.3 weights");
}

#[test]
fn equivariance_and_reversal() {
    let mut g = Rng(30);
    // S²: rotation.
    let pts = g.walk_s2(7, 0.7);
    let rot = g.quat();
    let c = CatmullRom::try_new(pts.clone(), Some(NONUNIFORM[..5].to_vec())).unwrap();
    let r = CatmullRom::try_new(
        pts.iter()
            .map(|p| S2Point::try_new(rot.rotate(p.as_dvec3())).unwrap())
            .collect(),
        Some(NONUNIFORM[..5].to_vec()),
    )
    .unwrap();
    // S³: both rules bi-invariant.
    let mut keys = g.walk_quat(7, 0.8);
    unflip(&mut keys);
    let (a, b) = (g.quat(), g.quat());
    let moved: Vec<UnitQuat> = keys.iter().map(|&q| sandwich(a, q, b)).collect();
    let q = CatmullRom::try_new_quaternion(keys.clone(), None).unwrap();
    let qm = CatmullRom::try_new_quaternion(moved.clone(), None).unwrap();
    let i = CatmullRom::try_new(keys.clone(), None).unwrap();
    let im = CatmullRom::try_new(moved, None).unwrap();
    // Reversal (points and knots reversed).
    let knots = NONUNIFORM[..5].to_vec();
    let rknots: Vec<f64> = knots.iter().rev().map(|&u| 4.0 - u).collect();
    let mut rkeys = keys.clone();
    rkeys.reverse();
    let qk = CatmullRom::try_new_quaternion(keys.clone(), Some(knots.clone())).unwrap();
    let qr = CatmullRom::try_new_quaternion(rkeys.clone(), Some(rknots.clone())).unwrap();
    let ik = CatmullRom::try_new(keys, Some(knots)).unwrap();
    let ir = CatmullRom::try_new(rkeys, Some(rknots)).unwrap();
    for k in 0..=80 {
        let t = 4.0 * k as f64 / 80.0;
        let (x, y) = (c.jet(t), r.jet(t));
        assert!(
            (rot.rotate(x.point.as_dvec3()) - y.point.as_dvec3()).length() < 1e-14,
            "S2 rot"
        );
        assert!(
            (rot.rotate(x.velocity) - y.velocity).length() < 1e-12,
            "S2 rot velocity"
        );
        assert!(
            sandwich(a, q.eval(t), b).dist(&qm.eval(t)) < 1e-14,
            "quaternion rule"
        );
        assert!(
            sandwich(a, i.eval(t), b).dist(&im.eval(t)) < 1e-14,
            "intrinsic rule"
        );
        assert!(
            qk.eval(t).dist(&qr.eval(4.0 - t)) < 1e-14,
            "reversal, quaternion rule"
        );
        assert!(
            ik.eval(t).dist(&ir.eval(4.0 - t)) < 1e-14,
            "reversal, intrinsic rule"
        );
    }
}

#[test]
fn degenerate_but_valid_points() {
    let x = S2Point::X;
    let near = S2Point::try_new(DVec3::new(1.0, 1e-9, 0.0)).unwrap();
    let anti = S2Point::try_new(DVec3::new(-1.0, 1e-8, 0.0)).unwrap();
    for pts in [
        vec![x; 4],
        vec![x, x, near, S2Point::Y, S2Point::Y],
        vec![S2Point::Z, x, anti, S2Point::Y],
    ] {
        let c = CatmullRom::try_new(pts, None).unwrap();
        let [t0, t1] = c.domain();
        for i in 0..=50 {
            let j = c.jet(t0 + (t1 - t0) * i as f64 / 50.0);
            assert!(
                j.velocity.is_finite() && j.acceleration.is_finite(),
                "finite"
            );
            assert!((j.point.as_dvec3().length() - 1.0).abs() < 1e-14, "unit");
        }
    }
    let q = UnitQuat::from_wxyz([0.3, -0.5, 0.2, 0.8]).unwrap();
    let qn = UnitQuat::from_wxyz([0.3 + 1e-9, -0.5, 0.2, 0.8]).unwrap();
    let c = CatmullRom::try_new_quaternion(vec![q, q, qn, q, q], None).unwrap();
    for i in 0..=20 {
        let j = c.jet(i as f64 / 10.0);
        assert!(
            j.velocity.is_finite() && j.acceleration.is_finite(),
            "finite"
        );
        assert!(j.point.dist(&q) < 1e-8, "stays put");
    }
}

#[test]
fn errors() {
    let p = vec![S2Point::X, S2Point::Y, S2Point::Z];
    let e = CatmullRom::try_new(p, None).unwrap_err();
    assert_eq!(e, SplineError::TooFewPoints { min: 4, got: 3 });
    assert!(e.to_string().contains("at least 4"), "{e}");
    let q = vec![UnitQuat::IDENTITY; 3];
    assert_eq!(
        CatmullRom::try_new_quaternion(q, None).unwrap_err(),
        SplineError::TooFewPoints { min: 4, got: 3 }
    );
    let mz = S2Point::try_new(-DVec3::Z).unwrap();
    assert_eq!(
        CatmullRom::try_new(vec![S2Point::X, S2Point::Y, S2Point::Z, mz], None).unwrap_err(),
        SplineError::Antipodal { index: 2 }
    );
    let r = UnitQuat::from_wxyz([0.0, 0.0, 1.0, 0.0]).unwrap();
    let i = UnitQuat::IDENTITY;
    assert_eq!(
        CatmullRom::try_new_quaternion(vec![-r, r, i, i], None).unwrap_err(),
        SplineError::Antipodal { index: 0 }
    );
    // n + 1 knots for n + 3 points.
    assert_eq!(
        CatmullRom::try_new(vec![S2Point::X; 5], Some(vec![0.0, 1.0, 2.0, 3.0])).unwrap_err(),
        SplineError::KnotCount {
            expected: 3,
            got: 4
        }
    );
}
