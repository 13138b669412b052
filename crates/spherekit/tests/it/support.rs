// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Shared helpers for the integration tests: one deterministic generator of random points,
//! rotations and key sequences, and the derivative and continuity checks every curve runs.

#![allow(dead_code, reason = "each test file uses a different subset")]
#![allow(
    unreachable_pub,
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::cast_precision_loss,
    reason = "test support module: a panic is the failure report"
)]

use spherekit::glam::{DMat3, DQuat, DVec3, DVec4};
use spherekit::{Ambient, Curve, Manifold, S2Point, Side, SmPoint, UnitQuat, VecN};

/// Relative tolerance for derivatives against central differences.
pub const FD_TOLERANCE: f64 = 1e-6;

/// A small deterministic generator (splitmix64; any seed works, 0 included), so the tests need
/// no dependency and give the same data on every target.
pub struct Rng(pub u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [a, b).
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.uniform()
    }

    /// Standard normal (Box–Muller).
    pub fn normal(&mut self) -> f64 {
        let u = self.uniform().max(1e-300);
        let v = self.uniform();
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }

    /// `n` standard normals.
    pub fn vec(&mut self, n: usize) -> Vec<f64> {
        (0..n).map(|_| self.normal()).collect()
    }

    /// A uniformly random unit vector of ℝ^dim.
    pub fn unit(&mut self, dim: usize) -> Vec<f64> {
        let v = self.vec(dim);
        let l = v.iter().map(|a| a * a).sum::<f64>().sqrt();
        v.into_iter().map(|a| a / l).collect()
    }

    /// A vector with coordinates uniform in [−scale, scale).
    pub fn vec3(&mut self, scale: f64) -> DVec3 {
        DVec3::new(
            self.range(-scale, scale),
            self.range(-scale, scale),
            self.range(-scale, scale),
        )
    }

    /// A uniformly random unit vector of ℝ³.
    pub fn unit3(&mut self) -> DVec3 {
        DVec3::new(self.normal(), self.normal(), self.normal()).normalize()
    }

    pub fn s2(&mut self) -> S2Point {
        S2Point::try_new(self.unit3()).unwrap()
    }

    pub fn quat(&mut self) -> UnitQuat {
        UnitQuat::from_wxyz([self.normal(), self.normal(), self.normal(), self.normal()]).unwrap()
    }

    pub fn sn(&mut self, m: usize) -> SmPoint {
        SmPoint::try_new(self.vec(m + 1)).unwrap()
    }

    /// A random rotation matrix.
    pub fn rotation(&mut self) -> DMat3 {
        DMat3::from_quat(self.quat().as_dquat())
    }

    /// A point at angle `angle` from `p` in a random direction.
    pub fn s2_at_angle(&mut self, p: S2Point, angle: f64) -> S2Point {
        let t = p.project_tangent(&self.unit3()).normalize();
        p.exp(&(t * angle))
    }

    /// A random walk on S² with steps of about `step` radians.
    pub fn walk_s2(&mut self, n: usize, step: f64) -> Vec<S2Point> {
        let mut p = self.s2();
        let mut out = vec![p];
        for _ in 1..n {
            let v = DVec3::new(self.normal(), self.normal(), self.normal()) * step;
            p = p.exp(&p.project_tangent(&v));
            out.push(p);
        }
        out
    }

    /// A random walk of rotations with steps of about `step` radians.
    pub fn walk_quat(&mut self, n: usize, step: f64) -> Vec<UnitQuat> {
        let mut p = self.quat();
        let mut out = vec![p];
        for _ in 1..n {
            let w = DVec3::new(self.normal(), self.normal(), self.normal()) * step;
            p = UnitQuat::exp_pure(w) * p;
            out.push(p);
        }
        out
    }

    /// A random walk on S^m with steps of about `step` radians.
    pub fn walk_sm(&mut self, n: usize, m: usize, step: f64) -> Vec<SmPoint> {
        let mut p = self.sn(m);
        let mut out = vec![p.clone()];
        for _ in 1..n {
            let v = VecN::new(self.vec(m + 1)) * step;
            p = p.exp(&p.project_tangent(&v));
            out.push(p.clone());
        }
        out
    }

    /// Quaternion keys whose consecutive steps are between 0.05 and `step` radians on S³.
    pub fn chain(&mut self, n: usize, step: f64) -> Vec<UnitQuat> {
        let mut q = vec![self.quat()];
        for _ in 1..n {
            let v = self.unit3() * self.range(0.05, step);
            let last = *q.last().unwrap();
            q.push(last * UnitQuat::exp_pure(v));
        }
        q
    }

    /// `l + 1` increasing knots with spacings in [0.5, 2].
    pub fn knots(&mut self, l: usize) -> Vec<f64> {
        let mut u = vec![self.range(-1.0, 1.0)];
        for _ in 0..l {
            let d = self.range(0.5, 2.0);
            u.push(u.last().unwrap() + d);
        }
        u
    }
}

/// Asserts `|a − b| ≤ tol` for ambient vectors, printing both.
#[track_caller]
pub fn assert_close<V: Ambient>(a: &V, b: &V, tol: f64, what: &str) {
    let d = (a.clone() - b.clone()).length();
    assert!(d <= tol, "{what}: |{a:?} − {b:?}| = {d:e} > {tol:e}");
}

/// Checks `|p| = 1` to 1e-14.
#[track_caller]
pub fn assert_unit<P: Manifold>(p: &P) {
    let l = p.to_vector().length();
    assert!((l - 1.0).abs() <= 1e-14, "not unit: |{p:?}| = {l}");
}

/// Largest |‖c(t)‖ − 1| over `samples + 1` parameters spread over the domain.
pub fn max_norm_error<C: Curve>(c: &C, samples: usize) -> f64 {
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

/// The relative errors of the exact velocity and acceleration at `t` against central
/// differences with step `h`: of points for the velocity, of exact velocities for the
/// acceleration, each relative to the size of the derivative (floor 1).
pub fn fd_errors_with<C: Curve>(c: &C, t: f64, h: f64) -> (f64, f64) {
    let j = c.jet(t);
    let p = |s: f64| c.eval(s).to_vector();
    let v = |s: f64| c.jet(s).velocity;
    let d1 = (p(t + h) - p(t - h)) * (0.5 / h);
    let d2 = (v(t + h) - v(t - h)) * (0.5 / h);
    let e1 = (j.velocity.clone() - d1).length() / j.velocity.length().max(1.0);
    let e2 = (j.acceleration.clone() - d2).length() / j.acceleration.length().max(1.0);
    (e1, e2)
}

/// [`fd_errors_with`] with `h = 1e-5`.
pub fn fd_errors<C: Curve>(c: &C, t: f64) -> (f64, f64) {
    fd_errors_with(c, t, 1e-5)
}

/// Checks the exact jet at each of `ts` (away from joints): derivatives against central
/// differences to [`FD_TOLERANCE`] relative, unit norm, tangent velocity, and the normal part of
/// the acceleration `c·c″ = −|c′|²`.
#[track_caller]
pub fn check_derivatives_at<C: Curve>(c: &C, ts: &[f64]) {
    // Small against the shortest piece (corner blends can be short and strongly curved).
    let shortest = c
        .joints()
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(f64::MAX, f64::min);
    let h = (1e-5 * shortest).min(1e-5);
    for &t in ts {
        let (e1, e2) = fd_errors_with(c, t, h);
        assert!(
            e1 < FD_TOLERANCE,
            "velocity at t = {t}: relative error {e1:e}"
        );
        assert!(
            e2 < FD_TOLERANCE,
            "acceleration at t = {t}: relative error {e2:e}"
        );
        let jet = c.jet(t);
        let p = jet.point.to_vector();
        let (sv, sa) = (
            jet.velocity.length().max(1.0),
            jet.acceleration.length().max(1.0),
        );
        assert!((p.length() - 1.0).abs() < 1e-14, "unit norm at t = {t}");
        assert!(
            p.dot(&jet.velocity).abs() < 1e-12 * sv,
            "velocity not tangent at t = {t}"
        );
        let normal = p.dot(&jet.acceleration) + jet.velocity.dot(&jet.velocity);
        assert!(
            normal.abs() <= 1e-10 * sa.max(sv * sv),
            "normal acceleration at t = {t}: {normal}"
        );
    }
}

/// [`check_derivatives_at`] on `samples` parameters spread over the domain, skipping any within
/// 1e-4 of a joint (one-sided pieces differ there).
#[track_caller]
pub fn check_derivatives<C: Curve>(c: &C, samples: usize) {
    let [t0, t1] = c.domain();
    let ts: Vec<f64> = (0..samples)
        .map(|i| t0 + (t1 - t0) * (i as f64 + 0.37) / samples as f64)
        .filter(|t| {
            c.joints()
                .iter()
                .all(|j| (j - t).abs() > 1e-4 * (t1 - t0).min(1.0))
        })
        .collect();
    check_derivatives_at(c, &ts);
}

/// Parameters strictly inside each piece of a curve, `per_piece` of them.
pub fn interior_parameters<C: Curve>(c: &C, per_piece: usize) -> Vec<f64> {
    let j = c.joints();
    j.windows(2)
        .flat_map(|w| {
            (1..=per_piece).map(move |k| w[0] + (w[1] - w[0]) * k as f64 / (per_piece + 1) as f64)
        })
        .collect()
}

/// The jumps of point, velocity and acceleration at `t`.
pub fn jumps<C: Curve>(c: &C, t: f64) -> (f64, f64, f64) {
    let l = c.jet_at(t, Side::Left);
    let r = c.jet_at(t, Side::Right);
    (
        (l.point.to_vector() - r.point.to_vector()).length(),
        (l.velocity - r.velocity).length(),
        (l.acceleration - r.acceleration).length(),
    )
}

/// Asserts Cⁿ at every joint in `joints` and a jump of order n + 1, with the exact one-sided
/// derivatives of any order from `deriv(t, side, order)`; also checks that orders 0…2 agree
/// with the curve's jets.
///
/// Cⁿ means relative jumps below 1e-11 (rounding); "a jump" means above 1e-6, five orders of
/// magnitude above that floor. The size of the order-(n+1) jump depends on the data: it is small
/// where the circles through consecutive triples nearly coincide.
#[track_caller]
pub fn check_continuity<C: Curve>(
    c: &C,
    deriv: impl Fn(f64, Side, usize) -> Vec<<C::Point as Manifold>::Vector>,
    n: usize,
    joints: &[f64],
) {
    for &t in joints {
        let (l, r) = (deriv(t, Side::Left, n + 1), deriv(t, Side::Right, n + 1));
        for (k, (a, b)) in l.iter().zip(&r).enumerate() {
            let scale = a.length().max(b.length()).max(1.0);
            let jump = (a.clone() - b.clone()).length() / scale;
            if k <= n {
                assert!(jump < 1e-11, "order {k} jump {jump} at t = {t} (n = {n})");
            } else {
                assert!(
                    jump > 1e-6,
                    "order {k} should jump at t = {t} (n = {n}): {jump}"
                );
            }
        }
        for side in [Side::Left, Side::Right] {
            let (jet, d) = (c.jet_at(t, side), deriv(t, side, 2));
            let err = (jet.point.to_vector() - d[0].clone()).length()
                + (jet.velocity.clone() - d[1].clone()).length() / jet.velocity.length().max(1.0)
                + (jet.acceleration.clone() - d[2].clone()).length()
                    / jet.acceleration.length().max(1.0);
            assert!(err < 1e-12, "jet vs exact derivatives at t = {t}: {err}");
        }
    }
}

/// The quaternion as glam's `DQuat`.
pub fn dq(q: UnitQuat) -> DQuat {
    q.as_dquat()
}

/// The quaternion as an ambient 4-vector.
pub fn v4(q: UnitQuat) -> DVec4 {
    DVec4::from(q.as_dquat())
}

/// `a·q·b` as a unit quaternion (an orthogonal map of ℝ⁴ applied to `q`).
pub fn sandwich(a: UnitQuat, q: UnitQuat, b: UnitQuat) -> UnitQuat {
    a * q * b
}

/// A Householder reflection of ℝ^(m+1) applied to a point of S^m (an orthogonal map).
pub fn reflect(n: &[f64], p: &SmPoint) -> SmPoint {
    let nn: f64 = n.iter().map(|a| a * a).sum();
    let d: f64 = n.iter().zip(p.coords()).map(|(a, b)| a * b).sum();
    SmPoint::try_new(
        p.coords()
            .iter()
            .zip(n)
            .map(|(x, a)| x - 2.0 * d / nn * a)
            .collect(),
    )
    .unwrap()
}
