// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Shared helpers for the tests of the classic curves (Bézier, squad, Catmull-Rom).

#![allow(dead_code, reason = "each test file uses a different subset")]
#![allow(
    clippy::unwrap_used,
    reason = "test helpers unwrap known-valid fixtures"
)]

use spherekit::glam::{DQuat, DVec3};
use spherekit::{Ambient, Curve, Manifold, S2Point, Side, SnPoint, UnitQuat};

/// A small deterministic generator (64-bit LCG), so the tests need no extra dependency.
pub(crate) struct Lcg(pub(crate) u64);

impl Lcg {
    pub(crate) fn next_f64(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Roughly normal: sum of uniforms.
    pub(crate) fn normal(&mut self) -> f64 {
        (0..6).map(|_| self.next_f64()).sum::<f64>() - 3.0
    }
    pub(crate) fn vec(&mut self, n: usize) -> Vec<f64> {
        (0..n).map(|_| self.normal()).collect()
    }
    pub(crate) fn s2(&mut self) -> S2Point {
        let v = self.vec(3);
        S2Point::try_new(DVec3::new(v[0], v[1], v[2])).unwrap()
    }
    pub(crate) fn quat(&mut self) -> UnitQuat {
        let v = self.vec(4);
        UnitQuat::from_wxyz([v[0], v[1], v[2], v[3]]).unwrap()
    }
    pub(crate) fn sn(&mut self, m: usize) -> SnPoint {
        SnPoint::try_new(self.vec(m + 1)).unwrap()
    }
    /// A random walk on S² with steps of about `step` radians.
    pub(crate) fn walk_s2(&mut self, n: usize, step: f64) -> Vec<S2Point> {
        let mut p = self.s2();
        let mut out = vec![p];
        for _ in 1..n {
            let v = DVec3::new(self.normal(), self.normal(), self.normal()) * step;
            let t = p.project_tangent(&v);
            p = p.exp(&t);
            out.push(p);
        }
        out
    }
    pub(crate) fn walk_quat(&mut self, n: usize, step: f64) -> Vec<UnitQuat> {
        let mut p = self.quat();
        let mut out = vec![p];
        for _ in 1..n {
            let w = DVec3::new(self.normal(), self.normal(), self.normal()) * step;
            p = UnitQuat::exp(w).mul(p);
            out.push(p);
        }
        out
    }
    pub(crate) fn walk_sn(&mut self, n: usize, m: usize, step: f64) -> Vec<SnPoint> {
        let mut p = self.sn(m);
        let mut out = vec![p.clone()];
        for _ in 1..n {
            let v = spherekit::VecN::new(self.vec(m + 1)) * step;
            let t = p.project_tangent(&v);
            p = p.exp(&t);
            out.push(p.clone());
        }
        out
    }
}

/// Largest |‖c(t)‖ − 1| over a sample of the domain.
pub(crate) fn max_norm_error<C: Curve>(c: &C, samples: usize) -> f64 {
    let [t0, t1] = c.domain();
    (0..=samples)
        .map(|k| {
            let t = t0 + (t1 - t0) * k as f64 / samples as f64;
            (c.eval(t).to_vector().length() - 1.0)
                .abs()
                .max((c.jet(t).point.to_vector().length() - 1.0).abs())
        })
        .fold(0.0, f64::max)
}

/// Checks the analytic velocity and acceleration at `t` against central differences: of points
/// (h = 1e-5) for the velocity, of analytic velocities for the acceleration. Relative to the
/// size of the derivative (with a floor of 1 for near-zero derivatives). Returns the errors.
pub(crate) fn fd_errors<C: Curve>(c: &C, t: f64) -> (f64, f64) {
    let h = 1e-5;
    let j = c.jet(t);
    let p = |s: f64| c.eval(s).to_vector();
    let v = |s: f64| c.jet(s).velocity;
    let d1 = (p(t + h) - p(t - h)) * (0.5 / h);
    let d2 = (v(t + h) - v(t - h)) * (0.5 / h);
    let e1 = (j.velocity.clone() - d1).length() / j.velocity.length().max(1.0);
    let e2 = (j.acceleration.clone() - d2).length() / j.acceleration.length().max(1.0);
    (e1, e2)
}

/// Asserts `fd_errors` below `tol` at interior sample points, avoiding the joints by 3h.
pub(crate) fn assert_derivatives<C: Curve>(c: &C, samples: usize, tol: f64) {
    let [t0, t1] = c.domain();
    let joints = c.joints().to_vec();
    for k in 0..samples {
        let t = t0 + (t1 - t0) * (k as f64 + 0.5) / samples as f64;
        if joints.iter().any(|&u| (u - t).abs() < 1e-4) {
            continue;
        }
        let (e1, e2) = fd_errors(c, t);
        assert!(
            e1 < tol && e2 < tol,
            "t = {t}: d1 error {e1:e}, d2 error {e2:e}"
        );
    }
}

/// The jumps of point, velocity and acceleration at `t`.
pub(crate) fn jumps<C: Curve>(c: &C, t: f64) -> (f64, f64, f64) {
    let l = c.jet_at(t, Side::Left);
    let r = c.jet_at(t, Side::Right);
    (
        (l.point.to_vector() - r.point.to_vector()).length(),
        (l.velocity - r.velocity).length(),
        (l.acceleration - r.acceleration).length(),
    )
}

pub(crate) fn dq(q: UnitQuat) -> DQuat {
    q.as_dquat()
}

/// `a·q·b` as a unit quaternion (an orthogonal map of ℝ⁴ applied to `q`).
pub(crate) fn sandwich(a: UnitQuat, q: UnitQuat, b: UnitQuat) -> UnitQuat {
    a.mul(q).mul(b)
}

/// A Householder reflection of ℝ^(m+1) applied to a point of S^m (an orthogonal map).
pub(crate) fn reflect(n: &[f64], p: &SnPoint) -> SnPoint {
    let nn: f64 = n.iter().map(|a| a * a).sum();
    let d: f64 = n.iter().zip(p.coords()).map(|(a, b)| a * b).sum();
    SnPoint::try_new(
        p.coords()
            .iter()
            .zip(n)
            .map(|(x, a)| x - 2.0 * d / nn * a)
            .collect(),
    )
    .unwrap()
}
