// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Helpers shared by the Pobegailo tests.

#![allow(dead_code, reason = "each test file uses a subset")]
#![allow(unreachable_pub, clippy::unwrap_used, reason = "test support module")]

use spherekit::{Ambient, Curve, Manifold, Side};

/// Central finite differences of points (d1) and velocities (d2) against the exact jet, relative.
pub fn check_derivatives<C: Curve>(c: &C, samples: usize) {
    let [t0, t1] = c.domain();
    // Small against the shortest piece (corner blends can be short and strongly curved).
    let shortest = c
        .joints()
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(f64::MAX, f64::min);
    let h = (1e-5 * shortest).min(1e-5);
    for i in 0..samples {
        let t = t0 + (t1 - t0) * (i as f64 + 0.37) / samples as f64;
        // Skip samples too close to a joint (one-sided pieces differ there at order n+1).
        if c.joints().iter().any(|&j| (j - t).abs() < 3.0 * h) {
            continue;
        }
        let jet = c.jet(t);
        let fd1 = (c.eval(t + h).to_vector() - c.eval(t - h).to_vector()) * (0.5 / h);
        let fd2 = (c.jet(t + h).velocity - c.jet(t - h).velocity) * (0.5 / h);
        let s1 = jet.velocity.length().max(1e-3);
        let s2 = jet.acceleration.length().max(1e-3);
        assert!(
            (fd1 - jet.velocity.clone()).length() < 1e-6 * s1,
            "velocity at t = {t}: {:?}",
            jet.velocity
        );
        assert!(
            (fd2 - jet.acceleration.clone()).length() < 1e-6 * s2,
            "acceleration at t = {t}: {:?}",
            jet.acceleration
        );
        assert!(
            (jet.point.to_vector().length() - 1.0).abs() < 1e-14,
            "unit norm"
        );
        assert!(
            jet.point.to_vector().dot(&jet.velocity).abs() < 1e-12 * s1,
            "velocity tangent"
        );
    }
}

/// Asserts Cⁿ at every joint in `joints` and a jump of order n + 1, with the exact one-sided
/// derivatives of any order from `deriv(t, side, order)`; also checks that orders 0…2 agree
/// with the curve's jets.
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
                    jump > 1e-3,
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

/// A small deterministic generator (xorshift) for random data.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_f64(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    pub fn normal(&mut self) -> f64 {
        // Box–Muller-free approximation is enough here: sum of uniforms.
        (0..6).map(|_| self.next_f64()).sum::<f64>() - 3.0
    }
}
