// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Shared helpers for the integration tests: a deterministic generator, random points and
//! rotations, and derivative checks against central finite differences.

#![allow(dead_code, reason = "each test file uses a different subset")]
#![allow(
    clippy::unwrap_used,
    reason = "test helpers: a panic is the failure report"
)]
#![allow(unreachable_pub, reason = "test support module")]

use spherekit::glam::{DMat3, DQuat, DVec3};
use spherekit::{Ambient, Curve, Manifold, S2Point, Side, SnPoint, UnitQuat};

/// Relative tolerance for derivatives against central differences.
pub const FD_TOLERANCE: f64 = 1e-6;

/// A small deterministic xorshift generator (no dependencies, same on every target).
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }

    pub fn next_u64(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
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

    pub fn s2(&mut self) -> S2Point {
        S2Point::try_new(DVec3::new(self.normal(), self.normal(), self.normal())).unwrap()
    }

    pub fn quat(&mut self) -> UnitQuat {
        UnitQuat::from_wxyz([self.normal(), self.normal(), self.normal(), self.normal()]).unwrap()
    }

    pub fn sn(&mut self, m: usize) -> SnPoint {
        SnPoint::try_new((0..=m).map(|_| self.normal()).collect()).unwrap()
    }

    /// A random rotation matrix.
    pub fn rotation(&mut self) -> DMat3 {
        DMat3::from_quat(self.quat().as_dquat())
    }

    /// A point at angle `angle` from `p` in a random direction.
    pub fn s2_at_angle(&mut self, p: S2Point, angle: f64) -> S2Point {
        let t = p.project_tangent(&self.s2().as_dvec3()).normalize();
        p.exp(&(t * angle))
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

/// Compares the exact velocity and acceleration of `c` at `t` with central differences of
/// points and of exact velocities, relative to `max(1, |value|)`.
#[track_caller]
pub fn check_derivatives<C: Curve>(c: &C, t: f64) {
    let h = 1e-5;
    let side = Side::Right;
    let jet = c.jet_at(t, side);
    let p = |s: f64| c.jet_at(s, side).point.to_vector();
    let v = |s: f64| c.jet_at(s, side).velocity;
    let v_fd = (p(t + h) - p(t - h)) * (0.5 / h);
    let a_fd = (v(t + h) - v(t - h)) * (0.5 / h);
    let scale_v = jet.velocity.length().max(1.0);
    let scale_a = jet.acceleration.length().max(1.0);
    assert_close(
        &jet.velocity,
        &v_fd,
        FD_TOLERANCE * scale_v,
        &format!("velocity at t = {t}"),
    );
    assert_close(
        &jet.acceleration,
        &a_fd,
        FD_TOLERANCE * scale_a,
        &format!("acceleration at t = {t}"),
    );
    // The velocity is tangent, and the normal part of the acceleration is −|c′|²·c.
    let pt = jet.point.to_vector();
    assert!(
        pt.dot(&jet.velocity).abs() <= 1e-12 * scale_v,
        "velocity not tangent at {t}"
    );
    let normal = pt.dot(&jet.acceleration) + jet.velocity.dot(&jet.velocity);
    assert!(
        normal.abs() <= 1e-10 * scale_a.max(scale_v * scale_v),
        "normal acceleration at {t}: {normal}"
    );
}

/// Parameters strictly inside each piece of a curve, away from the joints by more than `h`.
pub fn interior_parameters<C: Curve>(c: &C, per_piece: usize) -> Vec<f64> {
    let j = c.joints();
    j.windows(2)
        .flat_map(|w| {
            (1..=per_piece).map(move |k| w[0] + (w[1] - w[0]) * k as f64 / (per_piece + 1) as f64)
        })
        .collect()
}

/// A quaternion as a rotation of the body axes (for equivariance tests on S³).
pub fn quat_mul(a: UnitQuat, b: UnitQuat) -> UnitQuat {
    UnitQuat::try_new(a.as_dquat() * b.as_dquat()).unwrap()
}

pub fn dquat(q: UnitQuat) -> DQuat {
    q.as_dquat()
}
