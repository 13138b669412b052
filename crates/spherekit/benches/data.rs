// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The deterministic inputs shared by the criterion benches and the `bench_json` example (and
//! through it, the peer comparison of `just bench-compare`).

#![allow(dead_code, reason = "each user takes a subset")]

use spherekit::glam::{DQuat, DVec3};
use spherekit::{Manifold, S2Point, UnitQuat};

/// A small deterministic generator (`SplitMix64`).
pub(crate) struct Rng(pub u64);

impl Rng {
    /// A uniform number in `[0, 1)`.
    pub(crate) fn next_f64(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `count` orientations, each a rotation of 0.4 to 1.2 rad about a random axis after the
/// previous one: consecutive quaternions have positive dot products (no sign flips).
pub(crate) fn keys_s3(count: usize) -> Vec<UnitQuat> {
    let mut rng = Rng(7);
    let mut out = vec![UnitQuat::IDENTITY];
    while out.len() < count {
        let z = 2.0 * rng.next_f64() - 1.0;
        let phi = core::f64::consts::TAU * rng.next_f64();
        let r = (1.0 - z * z).sqrt();
        let axis = DVec3::new(r * phi.cos(), r * phi.sin(), z);
        let angle = 0.4 + 0.8 * rng.next_f64();
        let last = out[out.len() - 1];
        let q = UnitQuat::from_axis_angle(axis, angle).expect("unit axis");
        out.push(q * last);
    }
    out
}

/// A random walk of `count` points on S² whose consecutive points are 10° to `max_deg` apart.
pub(crate) fn points_s2(count: usize, max_deg: f64, seed: u64) -> Vec<S2Point> {
    let mut rng = Rng(seed);
    let mut p = DVec3::Z;
    let mut out = vec![S2Point::try_new(p).expect("unit vector")];
    while out.len() < count {
        let a = (10.0 + (max_deg - 10.0) * rng.next_f64()).to_radians();
        let phi = core::f64::consts::TAU * rng.next_f64();
        let e1 = p.any_orthonormal_vector();
        let e2 = p.cross(e1);
        let t = e1 * phi.cos() + e2 * phi.sin();
        p = (p * a.cos() + t * a.sin()).normalize();
        out.push(S2Point::try_new(p).expect("unit vector"));
    }
    out
}

/// `count` increasing parameters spread over `[t0, t1]` (midpoints of equal cells).
pub(crate) fn params([t0, t1]: [f64; 2], count: usize) -> Vec<f64> {
    (0..count)
        .map(|k| t0 + (t1 - t0) * (k as f64 + 0.5) / count as f64)
        .collect()
}

/// The glam quaternion of a key.
pub(crate) fn dquat(q: &UnitQuat) -> DQuat {
    q.as_dquat()
}

/// Distance check used by the users: the key chain has no near-antipodal neighbours.
pub(crate) fn max_step(keys: &[UnitQuat]) -> f64 {
    keys.windows(2)
        .map(|w| w[0].dist(&w[1]))
        .fold(0.0, f64::max)
}
